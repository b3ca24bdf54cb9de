#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ex or anywhere)
# Checks drafts/NN_name.aidl; logs time, kind, exit status and counts of error[E / warning[W lines
# to drafts/log.txt; keeps the first valid program in run/, failed attempts before it as
# drafts/NN_name.attemptK.*, checks after it as drafts/NN_name.fixK.* (rendered too).
set -u
D=$(cd "$(dirname "$0")" && pwd)
R=$(dirname "$D")/run
N=$1
export PYTHONPATH=/work/wt-models-ex
A=/work/main/.venv/bin/aidl
SRC=$D/$N.aidl
TS=$(date -u '+%Y-%m-%d %H:%M:%S')
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then $A render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  $A render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$TS  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >>"$D/log.txt"
echo "== $TS $N $KIND exit=$RC errors=$NE warnings=$NW"
cat "$OUT"
rm -f "$OUT"
