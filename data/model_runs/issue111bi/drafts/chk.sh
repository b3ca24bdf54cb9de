#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Logs date, exit status and the counts of error[E / warning[W lines to drafts/log.txt.
# Keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid one is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
D=/work/wt-models-bi/data/model_runs/issue111bi
AIDL="env PYTHONPATH=/work/wt-models-bi /work/main/.venv/bin/aidl"
N=$1
F=$D/drafts/$N.aidl
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV=$D/run/$N.first_valid.aidl
if [ -e "$FV" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$F" "$FV"; cp "$OUT" "$D/run/$N.first_valid.check.txt"
  $AIDL render "$FV" -o "$D/run/$N.first_valid.png" --png-width 1200 >"$D/run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -e "$D/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$F" "$D/drafts/$N.attempt$K.aidl"; cp "$OUT" "$D/drafts/$N.attempt$K.check.txt"
fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N exit=$RC errors=$NE warnings=$NW $KIND" >> $D/drafts/log.txt
cat "$OUT"
echo "--- exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
