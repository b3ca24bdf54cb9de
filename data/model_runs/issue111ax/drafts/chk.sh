#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ax)
# Checks drafts/NN_name.aidl; logs date, exit status, error/warning counts to drafts/log.txt;
# keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl + .check.txt
# and renders it; a failing check before the first valid is kept as drafts/NN_name.attemptK.*
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-ax /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
NOTE=""
if [ ! -f "run/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    NOTE="first_valid"
  else
    K=1
    while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    NOTE="attempt$K"
  fi
else
  NOTE="after_first_valid"
fi
echo "$STAMP $N exit=$RC errors=$E warnings=$W $NOTE" >> drafts/log.txt
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$E warnings=$W $NOTE"
rm -f "$OUT"
