#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cs or anywhere)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error[E / warning[W lines
# to drafts/log.txt. Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, + .png rendered at 1200 px); a failed check before it is kept as
# drafts/NN_name.attemptK.aidl + .check.txt.
set -u
D="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
SRC="$D/drafts/$N.aidl"
AIDL="env PYTHONPATH=/work/wt-models-cs /work/main/.venv/bin/aidl"
OUT="$(mktemp)"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
FV="$D/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  KIND="after-first-valid"
elif [ "$RC" -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$FV"; cp "$OUT" "$D/run/$N.first_valid.check.txt"
  $AIDL render "$FV" -o "$D/run/$N.first_valid.png" --png-width 1200 >/dev/null 2>"$D/run/$N.render.err" || echo "render failed" >>"$D/run/$N.render.err"
else
  K=1; while [ -e "$D/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$D/drafts/$N.attempt$K.aidl"; cp "$OUT" "$D/drafts/$N.attempt$K.check.txt"
fi
echo "$NOW  $N  exit=$RC  errors=$NE  warnings=$NW  $KIND" >>"$D/drafts/log.txt"
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
