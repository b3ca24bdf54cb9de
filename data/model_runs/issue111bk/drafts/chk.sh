#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bk)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error/warning lines to
# drafts/log.txt; keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.*
# (and renders it); failed checks before the first valid are kept as drafts/NN_name.attemptK.*
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-bk /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ -e "run/$N.first_valid.aidl" ]; then PHASE="after-first-valid"; else PHASE="before-first-valid"; fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $PHASE" >> drafts/log.txt
cat "$OUT"
if [ "$PHASE" = "before-first-valid" ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
    echo "FIRST VALID kept: run/$N.first_valid.aidl (render exit $?)"
  else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    echo "failed attempt kept: drafts/$N.attempt$K.aidl"
  fi
else
  cp "$OUT" "drafts/$N.latest.check.txt"
fi
rm -f "$OUT"
exit $RC
