#!/bin/bash
# usage (from data/model_runs/issue111k): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs the check; keeps the FIRST program that checks with exit 0
# as run/NN_name.first_valid.aidl (+ .check.txt) and renders its PNG; a failed check before
# it is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
n="$1"
A="env PYTHONPATH=/work/wt-models-k /work/main/.venv/bin/aidl"
src="drafts/$n.aidl"
out=$(mktemp)
$A check "$src" >"$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
echo "$(date -u +%H:%M:%S) $n exit=$rc errors=$errs warnings=$warns" >> drafts/log.txt
cat "$out"
if [ ! -f "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$src" "run/$n.first_valid.aidl"; cp "$out" "run/$n.first_valid.check.txt"
    $A render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
    echo "FIRST VALID kept"
  else
    k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "drafts/$n.attempt$k.aidl"; cp "$out" "drafts/$n.attempt$k.check.txt"
    echo "failed attempt $k kept"
  fi
fi
rm -f "$out"
exit $rc
