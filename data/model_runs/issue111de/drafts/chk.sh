#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first program that checks with
# exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png, .render.txt); a failed check
# before it is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-de
mkdir -p "$R"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
  PHASE="after first valid"
elif [ $RC -eq 0 ]; then
  PHASE="FIRST VALID"
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  PHASE="attempt$K (failed)"
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S UTC') $N exit=$RC errors=$NE warnings=$NW $PHASE" >>"$D/log.txt"
cat "$OUT"
echo "--- exit=$RC errors=$NE warnings=$NW $PHASE"
rm -f "$OUT"
