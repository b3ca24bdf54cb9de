#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl; logs time, exit status and message counts to drafts/log.txt.
# Before the first valid check: a failed program is kept as drafts/NN_name.attemptK.aidl
# (+ .check.txt); the first program that checks with exit 0 is kept as
# run/NN_name.first_valid.aidl (+ .check.txt) and rendered to run/NN_name.first_valid.png.
# After it: the check is logged as after-first-valid, its messages go to
# drafts/NN_name.fix.check.txt and it renders to drafts/NN_name.fix.png.
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"
R="$(dirname "$D")/run"
mkdir -p "$R"
export PYTHONPATH=/work/wt-models-hi
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u)
if [ -f "$R/$N.first_valid.aidl" ]; then
    KIND=after-first-valid
    cp "$OUT" "$D/$N.fix.check.txt"
    if [ $RC -eq 0 ]; then "$AIDL" render "$SRC" -o "$D/$N.fix.png" --png-width 1200 >/dev/null 2>&1; fi
elif [ $RC -eq 0 ]; then
    KIND=first-valid
    cp "$SRC" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    KIND="attempt$K"
    cp "$SRC" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >>"$D/log.txt"
cat "$OUT"
echo "--- $NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW"
rm -f "$OUT"
