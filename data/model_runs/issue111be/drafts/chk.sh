#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111be)
# checks drafts/NN_name.aidl, logs date, exit status, error/warning counts to drafts/log.txt;
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl + .check.txt
# and renders run/NN_name.first_valid.png; a failed check before the first valid is kept as
# drafts/NN_name.attemptK.aidl + .check.txt
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-be
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOTE=""
if [ ! -f "run/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    NOTE="FIRST VALID"
  else
    K=1
    while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    NOTE="attempt$K failed"
  fi
else
  NOTE="after first valid"
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $NOTE" >> drafts/log.txt
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$NE warnings=$NW $NOTE"
rm -f "$OUT"
