#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cg)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error[E / warning[W lines
# to drafts/log.txt; keeps the first program that checks with exit 0 as run/NN_name.first_valid.*
# and renders its PNG; a failed check before the first valid is kept as drafts/NN_name.attemptK.*
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-cg /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ -e "run/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
elif [ "$RC" -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "run/$N.first_valid.aidl"
  cp "$OUT" "run/$N.first_valid.check.txt"
  $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$E warnings=$W $KIND" >> drafts/log.txt
cat "$OUT"
echo "== $STAMP $N exit=$RC errors=$E warnings=$W $KIND"
rm -f "$OUT"
