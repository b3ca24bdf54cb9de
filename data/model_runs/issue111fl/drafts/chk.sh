#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep first valid / attempts / fixes.
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"        # drafts/
R="$D/../run"
AIDL="env PYTHONPATH=/work/wt-models-fl /work/main/.venv/bin/aidl"
SRC="$D/$N.aidl"
OUT="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -e "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then $AIDL render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> "$D/log.txt"
cat "$OUT"
echo "--- $KIND: exit $RC, errors $NE, warnings $NW"
rm -f "$OUT"
