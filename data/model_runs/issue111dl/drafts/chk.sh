#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111dl)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of error/warning lines to
# drafts/log.txt. The FIRST program that checks with exit 0 is kept as
# run/NN_name.first_valid.aidl (+ .check.txt) and rendered to run/NN_name.first_valid.png.
# A failed check before that is kept as drafts/NN_name.attemptK.aidl (+ .check.txt);
# a check after it as drafts/NN_name.fixK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-dl
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
T=$(date -u +%Y-%m-%dT%H:%M:%SZ)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "run/$N.first_valid.aidl" ]; then
  K=1; while [ -f "drafts/$N.fix$K.check.txt" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  PHASE="after-first-valid fix$K"
elif [ $RC -eq 0 ]; then
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  PHASE="FIRST-VALID (render exit $?)"
else
  K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  PHASE="before-first-valid attempt$K"
fi
echo "$T $N exit=$RC errors=$NE warnings=$NW $PHASE" >> drafts/log.txt
cat "$OUT"
echo "--- $T $N exit=$RC errors=$NE warnings=$NW $PHASE"
rm -f "$OUT"
