#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cd)
# logs date, exit status and counts of error[E / warning[W lines to drafts/log.txt;
# keeps the FIRST program that checks with exit 0 as run/NN.first_valid.*;
# a failed check before the first valid one is kept as drafts/NN.attemptK.*
set -u
N="$1"
D="$(cd "$(dirname "$0")/.." && pwd)"
export PYTHONPATH=/work/wt-models-cd
AIDL=/work/main/.venv/bin/aidl
SRC="$D/drafts/$N.aidl"
OUT="$(mktemp)"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
if [ -e "$D/run/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$D/run/$N.first_valid.aidl"
  cp "$OUT" "$D/run/$N.first_valid.check.txt"
  $AIDL render "$D/run/$N.first_valid.aidl" -o "$D/run/$N.first_valid.png" --png-width 1200 \
    >"$D/run/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -e "$D/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$D/drafts/$N.attempt$K.aidl"
  cp "$OUT" "$D/drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $KIND" >>"$D/drafts/log.txt"
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
