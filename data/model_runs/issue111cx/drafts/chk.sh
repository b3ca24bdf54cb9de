#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error[E / warning[W lines
# to drafts/log.txt. Before the first valid program: a failed check is kept as
# drafts/NN_name.attemptK.aidl + .check.txt; the first check with exit 0 is kept as
# run/NN_name.first_valid.aidl + .check.txt and rendered to run/NN_name.first_valid.png.
# After that (fixes) it only logs and saves drafts/NN_name.check.txt.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-cx
A=/work/main/.venv/bin/aidl
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
"$A" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
MORE=$(grep -o 'and [0-9]* more' "$OUT" | tr '\n' ' ')
if [ -f "$R/$N.first_valid.aidl" ]; then
    STAGE="after first valid"
    cp "$OUT" "$D/$N.check.txt"
elif [ $RC -eq 0 ]; then
    STAGE="FIRST VALID"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="failed attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T  $N  exit=$RC  errors=$NE  warnings=$NW ${MORE:+($MORE)} [$STAGE]" >> "$D/log.txt"
cat "$OUT"
echo "---- exit=$RC errors=$NE warnings=$NW [$STAGE]"
rm -f "$OUT"
