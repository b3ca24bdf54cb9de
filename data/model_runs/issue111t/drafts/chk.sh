#!/bin/bash
# usage (from data/model_runs/issue111t): drafts/chk.sh NN_name
# logs the check, keeps each failed attempt before the first valid one, and the FIRST
# program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png)
N=$1
AIDL="env PYTHONPATH=/work/wt-models-t /work/main/.venv/bin/aidl"
OUT=$($AIDL check drafts/$N.aidl 2>&1); RC=$?
echo "$OUT"
E=$(echo "$OUT" | grep -c 'error\[E'); W=$(echo "$OUT" | grep -c 'warning\[W')
echo "$(date -u +%FT%TZ) $N exit=$RC errors=$E warnings=$W" >> drafts/log.txt
if [ ! -f run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    cp drafts/$N.aidl run/$N.first_valid.aidl
    echo "$OUT" > run/$N.first_valid.check.txt
    $AIDL render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200
    echo "FIRST VALID kept"
  else
    K=$(ls drafts/$N.attempt*.aidl 2>/dev/null | wc -l); K=$((K+1))
    cp drafts/$N.aidl drafts/$N.attempt$K.aidl
    echo "$OUT" > drafts/$N.attempt$K.check.txt
  fi
fi
