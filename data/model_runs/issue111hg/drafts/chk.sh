#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111hg)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt, keeps the first valid program in run/.
set -u
N="$1"
D=drafts
R=run
AIDL="env PYTHONPATH=/work/wt-models-hg /work/main/.venv/bin/aidl"
SRC="$D/$N.aidl"
OUT=$(mktemp)
NOW=$(date -u)
$AIDL check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
    KIND="after-first-valid"
    cp "$OUT" "$D/$N.fix.check.txt"
    $AIDL render "$SRC" -o "$D/$N.fix.png" --png-width 1200 >/dev/null 2>&1 || echo "render of fix failed"
elif [ $RC -eq 0 ]; then
    KIND="FIRST-VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed"
else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$SRC" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> "$D/log.txt"
cat "$OUT"
echo "== $KIND exit $RC errors $NE warnings $NW"
rm -f "$OUT"
