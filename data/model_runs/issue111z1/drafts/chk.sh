#!/bin/bash
# usage (from data/model_runs/issue111z1): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl with this tree's CLI, logs the check, keeps the FIRST valid program
set -u
N="$1"
export PYTHONPATH=/work/wt-models-z1
A=/work/main/.venv/bin/aidl
F="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$E warnings=$W" >> drafts/log.txt
cat "$OUT"
if [ ! -f "run/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 && echo "rendered run/$N.first_valid.png"
  else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    echo "kept as drafts/$N.attempt$K.aidl"
  fi
fi
rm -f "$OUT"
exit $RC
