#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl once and log it (issue111gc).
# Before the first valid check: a failure is kept as drafts/NN_name.attemptK.aidl + .check.txt;
# the first exit-0 check is kept as run/NN_name.first_valid.aidl + .check.txt and rendered.
# After it: each check is kept as drafts/NN_name.fixK.aidl + .fixK.check.txt (rendered when it passes).
set -u
N="$1"
HERE="$(cd "$(dirname "$0")/.." && pwd)"
D="$HERE/drafts"; R="$HERE/run"
export PYTHONPATH=/work/wt-models-gc
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
if [ -f "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
printf '%s  %-28s %-12s exit=%d  errors=%d  warnings=%d\n' "$NOW" "$N" "$KIND" $RC $NE $NW >> "$D/log.txt"
tail -1 "$D/log.txt"
cat "$OUT"
rm -f "$OUT"
