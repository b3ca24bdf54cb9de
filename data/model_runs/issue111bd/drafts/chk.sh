#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bd)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error/warning lines to drafts/log.txt.
# Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-bd /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
TS=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ -f "run/$N.first_valid.aidl" ]; then
  STAGE="after-first-valid"
elif [ $RC -eq 0 ]; then
  STAGE="FIRST-VALID"
  cp "$SRC" "run/$N.first_valid.aidl"
  cp "$OUT" "run/$N.first_valid.check.txt"
  $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >&2
else
  K=1
  while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$TS $N exit=$RC errors=$NE warnings=$NW $STAGE" >> drafts/log.txt
cat "$OUT"
echo "== $TS $N exit=$RC errors=$NE warnings=$NW $STAGE"
rm -f "$OUT"
