#!/bin/bash
# usage (from data/model_runs/issue111z3): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl with this tree's CLI, logs one line to drafts/log.txt, keeps the
# FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before it is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
n="$1"
export PYTHONPATH=/work/wt-models-z3
A=/work/main/.venv/bin/aidl
f="drafts/$n.aidl"
out=$($A check "$f" 2>&1); rc=$?
ne=$(printf '%s\n' "$out" | grep -c 'error\[E')
nw=$(printf '%s\n' "$out" | grep -c 'warning\[W')
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $n exit=$rc errors=$ne warnings=$nw" >> drafts/log.txt
printf '%s\n' "$out"
if [ ! -e "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"
    printf '%s\n' "$out" > "run/$n.first_valid.check.txt"
    $A render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
  else
    k=1; while [ -e "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"
    printf '%s\n' "$out" > "drafts/$n.attempt$k.check.txt"
  fi
fi
exit $rc
