#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111am)
set -u
N=$1; D=drafts; R=run
A="env PYTHONPATH=/work/wt-models-am /work/main/.venv/bin/aidl"
OUT=$($A check $D/$N.aidl 2>&1); RC=$?
E=$(echo "$OUT" | grep -c 'error\[E'); W=$(echo "$OUT" | grep -c 'warning\[W')
CODES=$(echo "$OUT" | grep -o '\(error\|warning\)\[[EW][0-9]*\]' | sort | uniq -c | tr '\n' ' ')
if [ -f $R/$N.first_valid.aidl ]; then KIND=after_first_valid
elif [ $RC -eq 0 ]; then KIND=first_valid
  cp $D/$N.aidl $R/$N.first_valid.aidl; echo "$OUT" > $R/$N.first_valid.check.txt
  $A render $R/$N.first_valid.aidl -o $R/$N.first_valid.png --png-width 1200 > $R/$N.first_valid.render.txt 2>&1
else K=1; while [ -f $D/$N.attempt$K.aidl ]; do K=$((K+1)); done; KIND=attempt$K
  cp $D/$N.aidl $D/$N.attempt$K.aidl; echo "$OUT" > $D/$N.attempt$K.check.txt
fi
echo "$(date -u) $N rc=$RC errors=$E warnings=$W codes=[$CODES] $KIND" | tee -a $D/log.txt
echo "$OUT" | tail -40
