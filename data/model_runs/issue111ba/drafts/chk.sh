#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ba or anywhere)
# Checks drafts/NN_name.aidl; logs date, exit status, error/warning counts to drafts/log.txt.
# Before the first valid check: a failing program is kept as drafts/NN_name.attemptK.aidl + .check.txt.
# The FIRST program that checks with exit 0 is kept as run/NN_name.first_valid.aidl + .check.txt
# and rendered to run/NN_name.first_valid.png.
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
export PYTHONPATH=/work/wt-models-ba
AIDL=/work/main/.venv/bin/aidl
SRC="$HERE/drafts/$N.aidl"
OUT="$(mktemp)"
STAMP="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$HERE/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$FV"
  cp "$OUT" "$HERE/run/$N.first_valid.check.txt"
  "$AIDL" render "$FV" -o "$HERE/run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >&2
else
  K=1
  while [ -e "$HERE/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$HERE/drafts/$N.attempt$K.aidl"
  cp "$OUT" "$HERE/drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $KIND" >>"$HERE/drafts/log.txt"
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
