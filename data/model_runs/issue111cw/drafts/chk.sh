#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cw)
# Checks drafts/NN_name.aidl; logs date, exit status, error/warning counts to drafts/log.txt.
# Before the first valid: a failing check is kept as drafts/NN_name.attemptK.aidl + .check.txt.
# The first exit-0 program is kept as run/NN_name.first_valid.aidl + .check.txt, rendered to .png.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-cw
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
MORE=$(grep -o 'and [0-9]* more[^(]*W[0-9]*' "$OUT" | tr '\n' ' ')
STAMP=$(date -u '+%Y-%m-%d %H:%M:%S')
FV="run/$N.first_valid.aidl"
if [ -f "$FV" ]; then
  KIND="after-first-valid"
else
  if [ $RC -eq 0 ]; then
    cp "$SRC" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
    $A render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed"
    KIND="FIRST-VALID"
  else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    KIND="attempt$K"
  fi
fi
echo "$STAMP $N exit=$RC errors=$E warnings=$W ${MORE:+($MORE)} $KIND" >> drafts/log.txt
tail -1 drafts/log.txt
cat "$OUT"
rm -f "$OUT"
