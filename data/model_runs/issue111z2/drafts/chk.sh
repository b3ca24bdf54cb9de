#!/bin/bash
# usage (from data/model_runs/issue111z2): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl with this tree's CLI, logs one line per check in drafts/log.txt,
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid one is kept as drafts/NN_name.attemptK.aidl (+ .check.txt)
set -u
N=$1
WT=/work/wt-models-z2
AIDL="env PYTHONPATH=$WT /work/main/.venv/bin/aidl"
F=drafts/$N.aidl
OUT=$($AIDL check "$F" 2>&1); RC=$?
NE=$(printf '%s\n' "$OUT" | grep -c 'error\[E')
NW=$(printf '%s\n' "$OUT" | grep -c 'warning\[W')
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N exit=$RC errors=$NE warnings=$NW" >> drafts/log.txt
printf '%s\n' "$OUT"
echo "[exit $RC]"
if [ ! -e run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" run/$N.first_valid.aidl
    printf '%s\n' "$OUT" > run/$N.first_valid.check.txt
    $AIDL render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 && echo "rendered run/$N.first_valid.png"
  else
    K=1; while [ -e drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp "$F" drafts/$N.attempt$K.aidl
    printf '%s\n' "$OUT" > drafts/$N.attempt$K.check.txt
  fi
fi
