#!/bin/bash
# usage (from data/model_runs/issue111x): drafts/chk.sh NN_name
# Checks drafts/NN_name.aidl, logs one line, keeps the FIRST program that checks with exit 0
# as run/NN_name.first_valid.aidl (+ .check.txt, .png); failed checks before it as drafts/NN_name.attemptK.aidl.
set -u
n="$1"
A="env PYTHONPATH=/work/wt-models-x /work/main/.venv/bin/aidl"
f="drafts/$n.aidl"
out=$($A check "$f" 2>&1); rc=$?
e=$(printf '%s\n' "$out" | grep -c 'error\[E'); w=$(printf '%s\n' "$out" | grep -c 'warning\[W')
echo "$(date -u) $n exit=$rc errors=$e warnings=$w" >> drafts/log.txt
printf '%s\n' "$out"
if [ ! -f "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"; printf '%s\n' "$out" > "run/$n.first_valid.check.txt"
    $A render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
  else
    k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"; printf '%s\n' "$out" > "drafts/$n.attempt$k.check.txt"
  fi
fi
echo "rc=$rc"
