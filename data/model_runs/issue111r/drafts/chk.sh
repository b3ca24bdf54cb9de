#!/bin/bash
# usage (from data/model_runs/issue111r): drafts/chk.sh NN_name
N=$1
export PYTHONPATH=/work/wt-models-r
A=/work/main/.venv/bin/aidl
F=drafts/$N.aidl
OUT=$($A check $F 2>&1); RC=$?
E=$(echo "$OUT" | grep -c 'error\[E'); W=$(echo "$OUT" | grep -c 'warning\[W')
echo "$(date -u +%FT%TZ) $N exit=$RC errors=$E warnings=$W" >> drafts/log.txt
echo "$OUT"
if [ ! -f run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    cp $F run/$N.first_valid.aidl; echo "$OUT" > run/$N.first_valid.check.txt
    $A render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200
  else
    K=1; while [ -f drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp $F drafts/$N.attempt$K.aidl; echo "$OUT" > drafts/$N.attempt$K.check.txt
  fi
fi
