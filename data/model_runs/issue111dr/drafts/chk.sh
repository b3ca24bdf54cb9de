#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
# Written anew for run issue111dr.
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"     # drafts/
R="$D/../run"
A="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-dr
SRC="$D/$N.aidl"
OUT="$(mktemp)"
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u)"
if [ -e "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -e "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
    KIND="fix$K (after first valid)"
elif [ "$RC" -eq 0 ]; then
    cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
    "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 \
        >"$R/$N.first_valid.render.txt" 2>&1
    KIND="FIRST VALID (render exit $?)"
else
    K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
    KIND="attempt$K failed"
fi
echo "$NOW | $N | exit $RC | errors $NE | warnings $NW | $KIND" >>"$D/log.txt"
cat "$OUT"
echo "--- $NOW | $N | exit $RC | errors $NE | warnings $NW | $KIND"
rm -f "$OUT"
