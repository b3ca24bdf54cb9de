#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
# Run from anywhere; paths are relative to this run's folder.
set -u
cd "$(dirname "$0")/.." || exit 2
N="$1"
SRC="drafts/$N.aidl"
export PYTHONPATH=/work/wt-models-gs
AIDL=/work/main/.venv/bin/aidl
[ -f "$SRC" ] || { echo "no $SRC"; exit 2; }
OUT=$(mktemp)
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "run/$N.first_valid.aidl" ]; then
    K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "drafts/$N.fix$K.aidl" -o "drafts/$N.fix$K.png" --png-width 1200 >"drafts/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
printf '%s UTC | %s | %s | exit %s | error[E lines %s | warning[W lines %s\n' "$NOW" "$N" "$KIND" "$RC" "$NE" "$NW" >> drafts/log.txt
cat "$OUT"
echo "--- logged: $NOW $N $KIND exit $RC errors $NE warnings $NW"
rm -f "$OUT"
