#!/bin/bash
# usage (from issue111m/): drafts/chk.sh NN_name   -- checks drafts/NN_name.aidl, logs, keeps the first valid
set -u
N=$1
export PYTHONPATH=/work/wt-models-m
A=/work/main/.venv/bin/aidl
F=drafts/$N.aidl
OUT=$($A check "$F" 2>&1); RC=$?
E=$(printf '%s\n' "$OUT" | grep -c 'error\[E')
W=$(printf '%s\n' "$OUT" | grep -c 'warning\[W')
echo "$(date -u +%FT%TZ) $N rc=$RC errors=$E warnings=$W" >> drafts/log.txt
printf '%s\n' "$OUT"
if [ ! -f run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" run/$N.first_valid.aidl
    printf '%s\n' "$OUT" > run/$N.first_valid.check.txt
    $A render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 2>&1 | tail -3
  else
    K=1; while [ -f drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp "$F" drafts/$N.attempt$K.aidl
    printf '%s\n' "$OUT" > drafts/$N.attempt$K.check.txt
  fi
fi
echo "rc=$RC"
