#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program and
# every failed attempt before it; after the first valid, log it as a fix check.
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-hq /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
TMP=$(mktemp)
$AIDL check "$SRC" >"$TMP" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$TMP")
W=$(grep -c 'warning\[W' "$TMP")
NOW=$(date -u)
if [ -f "run/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
    cp "$TMP" "drafts/$N.fix.check.txt"
    if [ $RC -eq 0 ]; then
        $AIDL render "$SRC" -o "drafts/$N.fix.png" --png-width 1200 >/dev/null 2>&1
        if grep -q '^assembly' "$SRC"; then
            $AIDL render "$SRC" -o "drafts/${N}_fix_sheet.png" --png-width 1200 --layout sheet ${SHEET:-} 2>&1 | grep -i error
        fi
    fi
elif [ $RC -eq 0 ]; then
    STAGE="first-valid"
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$TMP" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    if grep -q '^assembly' "$SRC"; then
        $AIDL render "run/$N.first_valid.aidl" -o "drafts/${N}_sheet.png" --png-width 1200 --layout sheet ${SHEET:-} 2>&1 | grep -i error
    fi
else
    K=1
    while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$TMP" "drafts/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $STAGE | exit $RC | errors $E | warnings $W" >> drafts/log.txt
echo "$NOW | $N | $STAGE | exit $RC | errors $E | warnings $W"
cat "$TMP"
rm -f "$TMP"
