#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cf)
# Checks drafts/NN_name.aidl, logs time, exit status and counts to drafts/log.txt.
# Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, rendered to .png); a failed check before it is kept as
# drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-cf
SRC="drafts/$N.aidl"
OUT="$(mktemp)"
NOW="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="run/$N.first_valid"
if [ -e "$FV.aidl" ]; then
  STAGE="after-first-valid"
elif [ "$RC" -eq 0 ]; then
  STAGE="FIRST-VALID"
  cp "$SRC" "$FV.aidl"; cp "$OUT" "$FV.check.txt"
  "$AIDL" render "$FV.aidl" -o "$FV.png" --png-width 1200 >"$FV.render.txt" 2>&1
else
  K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$NOW $N exit=$RC errors=$NE warnings=$NW $STAGE" >> drafts/log.txt
cat "$OUT"
echo "== $NOW $N exit=$RC errors=$NE warnings=$NW $STAGE"
rm -f "$OUT"
