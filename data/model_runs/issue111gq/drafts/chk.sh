#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
# Run from anywhere; paths are relative to this script's folder.
set -u
cd "$(dirname "$0")"
N="$1"
export PYTHONPATH=/work/wt-models-gq
A=/work/main/.venv/bin/aidl
SRC="$N.aidl"
RUN=../run
OUT=$(mktemp)
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$RUN/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K after the first valid"
    cp "$SRC" "$N.fix$K.aidl"; cp "$OUT" "$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then "$A" render "$N.fix$K.aidl" -o "$N.fix$K.png" --png-width 1200 >"$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$RUN/$N.first_valid.aidl"; cp "$OUT" "$RUN/$N.first_valid.check.txt"
    "$A" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 >"$RUN/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "$N.attempt$K.aidl"; cp "$OUT" "$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $N | $KIND | exit $RC | errors $NE | warnings $NW" >> log.txt
tail -1 log.txt
cat "$OUT"
rm -f "$OUT"
