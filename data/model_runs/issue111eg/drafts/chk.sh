#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
export PYTHONPATH=/work/wt-models-eg
A="/work/main/.venv/bin/aidl"
SRC="$D/$N.aidl"
OUT="$(mktemp)"
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u)"
if [ -f "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
    KIND="fix$K (after the first valid)"
elif [ $RC -eq 0 ]; then
    cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
    "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
    KIND="first valid"
else
    K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
    KIND="attempt$K (failed)"
fi
echo "$NOW | $N | exit $RC | errors $NE | warnings $NW | $KIND" >> "$D/log.txt"
cat "$OUT"
echo "== $NOW | $N | exit $RC | errors $NE | warnings $NW | $KIND"
rm -f "$OUT"
