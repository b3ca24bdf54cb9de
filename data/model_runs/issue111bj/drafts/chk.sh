#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# and each failed check before it as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
A="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-bj
mkdir -p "$R"
cd "$D"
T="$(date -u)"
OUT="$("$A" check "$N.aidl" 2>&1)"
RC=$?
E=$(printf '%s\n' "$OUT" | grep -c 'error\[E')
W=$(printf '%s\n' "$OUT" | grep -c 'warning\[W')
if [ -f "$R/$N.first_valid.aidl" ]; then
  STATE="after-first-valid"
elif [ $RC -eq 0 ]; then
  cp "$N.aidl" "$R/$N.first_valid.aidl"
  printf '%s\n' "$OUT" > "$R/$N.first_valid.check.txt"
  "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 > "$R/$N.first_valid.render.txt" 2>&1
  STATE="FIRST-VALID"
else
  K=1
  while [ -f "$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$N.aidl" "$N.attempt$K.aidl"
  printf '%s\n' "$OUT" > "$N.attempt$K.check.txt"
  STATE="attempt$K"
fi
echo "$T | $N | exit=$RC | errors=$E | warnings=$W | $STATE" >> "$D/log.txt"
printf '%s\n' "$OUT"
echo "--- exit=$RC errors=$E warnings=$W $STATE"
