#!/bin/bash
# chk.sh NN_name: check drafts/NN_name.aidl, log it, keep the first valid program (issue111gu).
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
mkdir -p "$R"
export PYTHONPATH=/work/wt-models-gu
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
TMP="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$SRC" > "$TMP" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$TMP")
W=$(grep -c 'warning\[W' "$TMP")
if [ ! -f "$R/$N.first_valid.aidl" ]; then
    if [ $RC -eq 0 ]; then
        KIND="FIRST VALID"
        cp "$SRC" "$R/$N.first_valid.aidl"
        cp "$TMP" "$R/$N.first_valid.check.txt"
        "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 > "$R/$N.first_valid.render.txt" 2>&1
    else
        K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
        KIND="attempt $K"
        cp "$SRC" "$D/$N.attempt$K.aidl"
        cp "$TMP" "$D/$N.attempt$K.check.txt"
    fi
else
    K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "$D/$N.fix$K.aidl"
    cp "$TMP" "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "$D/$N.fix$K.aidl" -o "$R/$N.fix$K.png" --png-width 1200 > "$D/$N.fix$K.render.txt" 2>&1
    fi
fi
echo "$NOW | $N | $KIND | exit $RC | errors $E | warnings $W" >> "$D/log.txt"
cat "$TMP"
echo "--- $KIND: exit $RC, errors $E, warnings $W"
rm -f "$TMP"
