#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bf or anywhere)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error/warning lines to
# drafts/log.txt; keeps the first program that checks with exit 0 as run/NN_name.first_valid.*
# (and renders its PNG); a failed check before the first valid is kept as drafts/NN_name.attemptK.*
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
WT=/work/wt-models-bf
AIDL="env PYTHONPATH=$WT /work/main/.venv/bin/aidl"
N="$1"
SRC="$HERE/drafts/$N.aidl"
OUT="$(mktemp)"
STAMP="$(date -u)"
( cd "$HERE/drafts" && $AIDL check "$SRC" ) >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
FV="$HERE/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  KIND="after-first-valid"
elif [ "$RC" -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$FV"
  cp "$OUT" "$HERE/run/$N.first_valid.check.txt"
  ( cd "$HERE/run" && $AIDL render "$FV" -o "$HERE/run/$N.first_valid.png" --png-width 1200 ) >>"$HERE/run/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -e "$HERE/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$HERE/drafts/$N.attempt$K.aidl"
  cp "$OUT" "$HERE/drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP | $N | exit=$RC | errors=$E | warnings=$W | $KIND" >> "$HERE/drafts/log.txt"
cat "$OUT"
echo "--- $STAMP | $N | exit=$RC | errors=$E | warnings=$W | $KIND"
rm -f "$OUT"
