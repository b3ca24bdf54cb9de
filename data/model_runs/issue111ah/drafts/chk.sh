#!/bin/bash
# Usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs one line to drafts/log.txt, keeps the FIRST program that
# checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt) and renders its PNG;
# a failed check before that is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
export PYTHONPATH=/work/wt-models-ah
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
OUT="$(mktemp)"
WHEN="$(date -u)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
# "aidl: and N more of WXXXX" lines: add N to the warning (or error) count
MW=$(grep -oE 'and [0-9]+ more of W[0-9]+' "$OUT" | awk '{s+=$2} END {print s+0}')
ME=$(grep -oE 'and [0-9]+ more of E[0-9]+' "$OUT" | awk '{s+=$2} END {print s+0}')
NW=$((NW + MW)); NE=$((NE + ME))
if [ -e "$R/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
elif [ $RC -eq 0 ]; then
    STAGE="FIRST-VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 \
        >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    STAGE="attempt$K"
    cp "$SRC" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
CODES=$(grep -oE '(error|warning)\[[EW][0-9]+\]' "$OUT" | sort | uniq -c | awk '{printf "%s%sx%s", sep, $2, $1; sep=","}')
echo "$WHEN | $N | exit $RC | errors $NE | warnings $NW | $STAGE | ${CODES:-none}" >>"$D/log.txt"
cat "$OUT"
echo "--- logged: exit $RC, errors $NE, warnings $NW, $STAGE"
rm -f "$OUT"
