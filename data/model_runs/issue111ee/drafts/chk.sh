#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ee)
# Checks drafts/NN_name.aidl; logs time, exit status and counts of error/warning lines.
# Keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before it as drafts/NN_name.attemptK.aidl (+ .check.txt);
# a check after it as drafts/NN_name.fixK.aidl (+ .fixK.check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-ee
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -f "run/$N.first_valid.aidl" ]; then
  K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  KIND="fix$K after first valid"
elif [ $RC -eq 0 ]; then
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  KIND="FIRST VALID"
else
  K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  KIND="attempt$K failed"
fi
echo "$NOW  $N  exit=$RC  errors=$NE  warnings=$NW  $KIND" >> drafts/log.txt
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
