#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111dc)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of error[E / warning[W lines
# to drafts/log.txt; keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, rendered to .png); a failed check before it is kept as drafts/NN_name.attemptK.aidl.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-dc
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
T=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -f "run/$N.first_valid.aidl" ]; then PHASE=after; else PHASE=before; fi
echo "$T $N exit=$RC errors=$E warnings=$W ($PHASE first valid)" >> drafts/log.txt
if [ "$PHASE" = before ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
    echo "$T $N first valid kept, render exit=$?" >> drafts/log.txt
  else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
  fi
else
  cp "$OUT" "drafts/$N.latest.check.txt"
fi
cat "$OUT"
echo "exit=$RC errors=$E warnings=$W"
rm -f "$OUT"
