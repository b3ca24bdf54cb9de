#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# failed checks before it as drafts/NN_name.attemptK.aidl + .check.txt
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
export PYTHONPATH=/work/wt-models-cy
A=/work/main/.venv/bin/aidl
F="$D/$N.aidl"
OUT=$(mktemp)
$A check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
STATE=""
if [ -e "$R/$N.first_valid.aidl" ]; then
  STATE="after first valid"
elif [ $RC -eq 0 ]; then
  cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  $A render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
  STATE="FIRST VALID (rendered rc=$?)"
else
  K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
  STATE="failed: kept as attempt$K"
fi
echo "$NOW  $N  exit=$RC  errors=$E  warnings=$W  $STATE" >> "$D/log.txt"
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$E warnings=$W $STATE"
rm -f "$OUT"
