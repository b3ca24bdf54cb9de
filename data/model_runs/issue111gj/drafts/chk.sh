#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs time, kind, exit status and counts of error[E / warning[W lines
# to drafts/log.txt. Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, rendered to .png); a failed check before it as drafts/NN_name.attemptK.aidl
# (+ .check.txt); a check after it as drafts/NN_name.fixK.aidl (+ .fixK.check.txt, rendered when it passes).
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
mkdir -p "$R"
export PYTHONPATH=/work/wt-models-gj
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
OUT="$(mktemp)"
NOW="$(date -u)"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
    K=$(ls "$D/$N".fix*.aidl 2>/dev/null | grep -c 'fix[0-9]*\.aidl$')
    K=$((K + 1))
    KIND="fix $K"
    cp "$SRC" "$D/$N.fix$K.aidl"
    cp "$OUT" "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        $AIDL render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=$(ls "$D/$N".attempt*.aidl 2>/dev/null | grep -c 'attempt[0-9]*\.aidl$')
    K=$((K + 1))
    KIND="attempt $K"
    cp "$SRC" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $KIND | exit $RC | error[E lines $NE | warning[W lines $NW" >>"$D/log.txt"
cat "$OUT"
echo "== $KIND, exit $RC, errors $NE, warnings $NW"
rm -f "$OUT"
