#!/bin/bash
# usage (from data/model_runs/issue111g): drafts/chk.sh NN_name
# Checks drafts/NN_name.aidl, logs one line to drafts/log.txt; keeps the FIRST program that
# checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, + .png at 1200 px);
# a failed check before that is kept as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
n="$1"
A="env PYTHONPATH=/work/wt-models-g /work/main/.venv/bin/aidl"
src="drafts/$n.aidl"
out=$(mktemp)
$A check "$src" >"$out" 2>&1
rc=$?
e=$(grep -c '^error' "$out")
w=$(grep -c '^warning' "$out")
fv="run/$n.first_valid.aidl"
if [ -e "$fv" ]; then kind="fix"
elif [ $rc -eq 0 ]; then kind="first_valid"
else kind="attempt"; fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $n rc=$rc e=$e w=$w $kind" >> drafts/log.txt
if [ "$kind" = "first_valid" ]; then
  cp "$src" "$fv"; cp "$out" "run/$n.first_valid.check.txt"
  $A render "$fv" -o "run/$n.first_valid.png" --png-width 1200
elif [ "$kind" = "attempt" ]; then
  k=1; while [ -e "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
  cp "$src" "drafts/$n.attempt$k.aidl"; cp "$out" "drafts/$n.attempt$k.check.txt"
fi
cat "$out"; echo "rc=$rc"
rm -f "$out"
