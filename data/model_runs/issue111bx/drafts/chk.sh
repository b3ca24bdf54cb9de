#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bx)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# and each failed check before it as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-bx /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
FV="run/$N.first_valid.aidl"
if [ -e "$FV" ]; then PHASE="after-first-valid"; else PHASE="before-first-valid"; fi
if [ ! -e "$FV" ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
    PHASE="FIRST-VALID"
  else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    PHASE="attempt$K"
  fi
fi
echo "$STAMP $N exit=$RC errors=$E warnings=$W $PHASE" >> drafts/log.txt
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$E warnings=$W $PHASE"
rm -f "$OUT"
