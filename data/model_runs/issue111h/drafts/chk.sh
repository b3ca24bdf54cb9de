#!/bin/bash
# usage (from data/model_runs/issue111h): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs the check, keeps the first valid program in run/
# and each failed check before it as drafts/NN_name.attemptK.aidl + .check.txt
set -u
n="$1"
AIDL="env PYTHONPATH=/work/wt-models-h /work/main/.venv/bin/aidl"
src="drafts/$n.aidl"
out=$($AIDL check "$src" 2>&1); rc=$?
e=$(printf '%s\n' "$out" | grep -c 'error\[E')
w=$(printf '%s\n' "$out" | grep -c 'warning\[W')
echo "$(date -u +%H:%M:%S) $n rc=$rc e=$e w=$w" >> drafts/log.txt
printf '%s\n' "$out"
if [ ! -f "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$src" "run/$n.first_valid.aidl"
    printf '%s\n' "$out" > "run/$n.first_valid.check.txt"
    $AIDL render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
    echo "FIRST VALID kept"
  else
    k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "drafts/$n.attempt$k.aidl"
    printf '%s\n' "$out" > "drafts/$n.attempt$k.check.txt"
    echo "FAILED attempt $k kept"
  fi
fi
