#!/bin/bash
# usage (from data/model_runs/issue111j): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs one line, keeps the first valid program and its PNG,
# keeps a failed attempt before the first valid one as drafts/NN_name.attemptK.aidl
set -u
n="$1"
A="env PYTHONPATH=/work/wt-models-j /work/main/.venv/bin/aidl"
f="drafts/$n.aidl"
out=$($A check "$f" 2>&1); rc=$?
ne=$(printf '%s\n' "$out" | grep -c 'error\[E')
nw=$(printf '%s\n' "$out" | grep -c 'warning\[W')
echo "$(date -u +%FT%TZ) $n rc=$rc errors=$ne warnings=$nw" >> drafts/log.txt
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
echo "rc=$rc"
