#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111br)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# failed checks before it as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-br /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FIRST="run/$N.first_valid.aidl"
if [ -e "$FIRST" ]; then PHASE="after-first-valid"; else PHASE="before-first-valid"; fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $PHASE" >> drafts/log.txt
if [ ! -e "$FIRST" ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" "$FIRST"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "$FIRST" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
    echo "FIRST VALID kept: $FIRST"
  else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    echo "kept failed attempt $K"
  fi
fi
cat "$OUT"
rm -f "$OUT"
exit $RC
