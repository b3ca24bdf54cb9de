#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bl or anywhere)
# Checks drafts/NN_name.aidl, logs date, exit status and message counts to drafts/log.txt,
# keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt,
# rendered to .png), and each failed check before it as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
SRC="$HERE/drafts/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-bl
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
ERRS=$(grep -c 'error\[E' "$OUT")
WARNS=$(grep -c 'warning\[W' "$OUT")
STAMP="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
FV="$HERE/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  KIND="after first valid"
elif [ $RC -eq 0 ]; then
  cp "$SRC" "$FV"; cp "$OUT" "$HERE/run/$N.first_valid.check.txt"
  "$AIDL" render "$FV" -o "$HERE/run/$N.first_valid.png" --png-width 1200 >"$HERE/run/$N.first_valid.render.txt" 2>&1
  KIND="FIRST VALID (render exit $?)"
else
  K=1; while [ -e "$HERE/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "$HERE/drafts/$N.attempt$K.aidl"; cp "$OUT" "$HERE/drafts/$N.attempt$K.check.txt"
  KIND="failed attempt $K"
fi
echo "$STAMP $N exit=$RC errors=$ERRS warnings=$WARNS $KIND" >>"$HERE/drafts/log.txt"
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$ERRS warnings=$WARNS $KIND"
rm -f "$OUT"
