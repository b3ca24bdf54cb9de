#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bz)
# Checks drafts/NN_name.aidl, logs date, exit status, error/warning counts to drafts/log.txt.
# Keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid one is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-bz
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u)
FV="run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  STATE="after first valid"
elif [ "$RC" -eq 0 ]; then
  cp "$SRC" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
  "$A" render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  STATE="FIRST VALID"
else
  K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  STATE="attempt$K failed"
fi
echo "$STAMP | $N | exit=$RC | errors=$NE | warnings=$NW | $STATE" >>drafts/log.txt
cat "$OUT"
echo "== $STAMP | $N | exit=$RC | errors=$NE | warnings=$NW | $STATE"
rm -f "$OUT"
