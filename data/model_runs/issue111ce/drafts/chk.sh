#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error[E / warning[W lines
# to drafts/log.txt; keeps the first program that checks with exit 0 as
# run/NN_name.first_valid.aidl + .check.txt (+ .png render); a failed check before the first
# valid one is kept as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
export PYTHONPATH=/work/wt-models-ce
AIDL=/work/main/.venv/bin/aidl
F="$D/$N.aidl"
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
TS="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
if [ -e "$R/$N.first_valid.aidl" ]; then
  STATE="after-first-valid"
elif [ $RC -eq 0 ]; then
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
  STATE="FIRST-VALID"
else
  K=1
  while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
  STATE="attempt$K"
fi
echo "$TS $N exit=$RC errors=$E warnings=$W $STATE" >>"$D/log.txt"
cat "$OUT"
echo "== $TS $N exit=$RC errors=$E warnings=$W $STATE"
rm -f "$OUT"
