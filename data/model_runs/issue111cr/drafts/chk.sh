#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cr)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error/warning lines to
# drafts/log.txt; keeps the first program that checks with exit 0 as run/NN_name.first_valid.*
# (and renders its PNG); a failure before that is kept as drafts/NN_name.attemptK.*
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-cr /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -e "run/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "run/$N.first_valid.aidl"
  cp "$OUT" "run/$N.first_valid.check.txt"
  $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >>"run/$N.first_valid.check.txt"
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$NOW $N exit=$RC errors=$NE warnings=$NW $KIND" >>drafts/log.txt
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
