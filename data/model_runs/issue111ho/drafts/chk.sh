#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid program.
# Written anew for run issue111ho.
set -u
cd "$(dirname "$0")/.."            # -> data/model_runs/issue111ho
N="$1"
export PYTHONPATH=/work/wt-models-ho
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
TMP="$(mktemp)"
$A check "$SRC" >"$TMP" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$TMP")
W=$(grep -c 'warning\[W' "$TMP")
NOW="$(date -u)"
if [ -f "run/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
    cp "$TMP" "drafts/$N.fix.check.txt"
    $A render "$SRC" -o "drafts/$N.fix.png" --png-width 1200 >/dev/null 2>&1
elif [ $RC -eq 0 ]; then
    STAGE="first-valid"
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$TMP" "run/$N.first_valid.check.txt"
    $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
else
    K=1
    while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$TMP" "drafts/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $STAGE | exit $RC | errors $E | warnings $W" >> drafts/log.txt
cat "$TMP"
echo "--- $STAGE exit $RC errors $E warnings $W"
rm -f "$TMP"
