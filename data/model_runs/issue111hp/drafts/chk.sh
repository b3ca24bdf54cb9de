#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111hp)
# Checks drafts/NN_name.aidl, logs the result to drafts/log.txt, keeps failed attempts
# before the first valid one, the first valid program (+ its PNG), and fix checks after it.
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-hp /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
ERR=$(grep -c 'error\[E' "$OUT")
WARN=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u)
if [ -e "run/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
    cp "$OUT" "drafts/$N.fix.check.txt"
    $AIDL render "$SRC" -o "drafts/$N.fix.png" --png-width 1200 >/dev/null 2>&1
    if grep -q '^ *assembly ' "$SRC"; then
        $AIDL render "$SRC" -o "drafts/${N}_fix_sheet.png" --png-width 1200 --layout sheet >/dev/null 2>&1
    fi
elif [ $RC -eq 0 ]; then
    STAGE="first-valid"
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    if grep -q '^ *assembly ' "$SRC"; then
        $AIDL render "run/$N.first_valid.aidl" -o "drafts/${N}_sheet.png" --png-width 1200 --layout sheet >/dev/null 2>&1
    fi
else
    K=1
    while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $STAGE | exit $RC | errors $ERR | warnings $WARN" >> drafts/log.txt
echo "== $STAGE exit=$RC errors=$ERR warnings=$WARN"
cat "$OUT"
rm -f "$OUT"
