#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bu)
# Checks drafts/NN_name.aidl, logs date, exit status and counts to drafts/log.txt.
# Keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt,
# and renders run/NN_name.first_valid.png); a failed check before that is kept as
# drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-bu
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
FV="run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  KIND="after-first-valid"
elif [ "$RC" -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$FV"
  cp "$OUT" "run/$N.first_valid.check.txt"
  "$AIDL" render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  echo "render exit $?" >>"run/$N.first_valid.render.txt"
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$E warnings=$W $KIND" >>drafts/log.txt
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$E warnings=$W $KIND"
rm -f "$OUT"
