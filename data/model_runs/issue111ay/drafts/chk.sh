#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ay)
# Checks drafts/NN_name.aidl; logs date, exit status and counts of error/warning lines to
# drafts/log.txt; keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, + .png rendered at 1200 px); keeps each failed check before it as
# drafts/NN_name.attemptK.aidl + .check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-ay
AIDL=/work/main/.venv/bin/aidl
SRC=drafts/$N.aidl
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ -f run/$N.first_valid.aidl ]; then PHASE=after_first_valid; else PHASE=before_first_valid; fi
echo "$STAMP $N exit=$RC errors=$E warnings=$W $PHASE" >> drafts/log.txt
if [ ! -f run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" run/$N.first_valid.aidl
    cp "$OUT" run/$N.first_valid.check.txt
    $AIDL render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200
    echo "FIRST VALID kept: run/$N.first_valid.aidl"
  else
    K=1; while [ -f drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp "$SRC" drafts/$N.attempt$K.aidl
    cp "$OUT" drafts/$N.attempt$K.check.txt
    echo "failed attempt kept: drafts/$N.attempt$K.aidl"
  fi
fi
cat "$OUT"
echo "exit=$RC errors=$E warnings=$W"
rm -f "$OUT"
