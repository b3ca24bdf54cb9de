#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111z8)
# checks drafts/NN_name.aidl, logs it, keeps the FIRST program that checks with exit 0 in run/
set -u
N=$1
export PYTHONPATH=/work/wt-models-z8
A=/work/main/.venv/bin/aidl
F=drafts/$N.aidl
OUT=$(mktemp)
$A check "$F" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N exit=$RC errors=$NE warnings=$NW" >> drafts/log.txt
cat "$OUT"
if [ ! -f run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" run/$N.first_valid.aidl
    cp "$OUT" run/$N.first_valid.check.txt
    $A render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200
    echo "FIRST VALID kept"
  else
    K=1; while [ -f drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp "$F" drafts/$N.attempt$K.aidl
    cp "$OUT" drafts/$N.attempt$K.check.txt
    echo "failed attempt $K kept"
  fi
fi
rm -f "$OUT"
exit $RC
