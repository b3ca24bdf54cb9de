#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program
# (and the failed attempts before it, and the fixes after it).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
export PYTHONPATH=/work/wt-models-fq
A=/work/main/.venv/bin/aidl
mkdir -p "$R"
F="$D/$N.aidl"
OUT="$(mktemp)"
"$A" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u)"
if [ ! -f "$R/$N.first_valid.aidl" ]; then
    if [ "$RC" -eq 0 ]; then
        KIND="FIRST VALID"
        cp "$F" "$R/$N.first_valid.aidl"
        cp "$OUT" "$R/$N.first_valid.check.txt"
        "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 \
            >"$R/$N.first_valid.render.txt" 2>&1
    else
        K=1
        while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
        KIND="attempt $K"
        cp "$F" "$D/$N.attempt$K.aidl"
        cp "$OUT" "$D/$N.attempt$K.check.txt"
    fi
else
    K=1
    while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K + 1)); done
    KIND="fix $K"
    cp "$F" "$D/$N.fix$K.aidl"
    cp "$OUT" "$D/$N.fix$K.check.txt"
    if [ "$RC" -eq 0 ]; then
        "$A" render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 \
            >"$D/$N.fix$K.render.txt" 2>&1
    fi
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >>"$D/log.txt"
echo "== $NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW"
cat "$OUT"
rm -f "$OUT"
