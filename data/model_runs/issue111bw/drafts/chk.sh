#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error/warning lines;
# keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid one is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
AIDL="env PYTHONPATH=/work/wt-models-bw /work/main/.venv/bin/aidl"
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP="$(date -u)"
if [ -e "$R/$N.first_valid.aidl" ]; then PHASE="after-first-valid"; else PHASE="before-first-valid"; fi
echo "$STAMP | $N | exit=$RC | errors=$NE | warnings=$NW | $PHASE" >>"$D/log.txt"
cat "$OUT"
if [ "$PHASE" = "before-first-valid" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
    echo "FIRST VALID kept: run/$N.first_valid.aidl (render exit $?)"
  else
    K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
    echo "failed check kept as drafts/$N.attempt$K.aidl"
  fi
fi
rm -f "$OUT"
exit $RC
