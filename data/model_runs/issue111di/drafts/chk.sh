#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111di)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of error[E / warning[W lines
# to drafts/log.txt; keeps the first program that checks with exit 0 as
# run/NN_name.first_valid.aidl (+ .check.txt, + .png); failed checks before it are kept as
# drafts/NN_name.attemptK.aidl (+ .check.txt); checks after it as drafts/NN_name.fixK.check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-di
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
T=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -f "run/$N.first_valid.aidl" ]; then
  K=1; while [ -f "drafts/$N.fix$K.check.txt" ]; do K=$((K+1)); done
  cp "$OUT" "drafts/$N.fix$K.check.txt"; cp "$SRC" "drafts/$N.fix$K.aidl"
  STAGE="after first valid: fix$K"
elif [ $RC -eq 0 ]; then
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  STAGE="FIRST VALID"
else
  K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  STAGE="before first valid: attempt$K"
fi
echo "$T  $N  exit=$RC  errors=$NE  warnings=$NW  [$STAGE]" >> drafts/log.txt
cat "$OUT"
echo "--- $T exit=$RC errors=$NE warnings=$NW [$STAGE]"
rm -f "$OUT"
