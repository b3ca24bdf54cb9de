#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111dj)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of error[E / warning[W lines.
# Before the first valid: a failing check is kept as drafts/NN_name.attemptK.aidl + .check.txt;
# the first check with exit 0 is kept as run/NN_name.first_valid.aidl + .check.txt and rendered.
# After the first valid: each check is kept as drafts/NN_name.fixK.aidl + .check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-dj
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -f "run/$N.first_valid.aidl" ]; then
  K=1; while [ -f "drafts/$N.fix$K.check.txt" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  STAGE="fix$K (after first valid)"
elif [ $RC -eq 0 ]; then
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  STAGE="FIRST VALID"
else
  K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  STAGE="attempt$K (failed)"
fi
echo "$NOW  $N  exit=$RC  errors=$E  warnings=$W  $STAGE" >> drafts/log.txt
tail -1 drafts/log.txt
cat "$OUT"
rm -f "$OUT"
