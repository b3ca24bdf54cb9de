#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ae)
# Checks drafts/NN_name.aidl, logs one line to drafts/log.txt, keeps the first program
# that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png), and each
# failed check before it as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-ae /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
WHEN=$(date -u)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "run/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
elif [ $RC -eq 0 ]; then
    STAGE="FIRST-VALID"
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 \
        >"run/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    STAGE="attempt$K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$WHEN | $N | exit $RC | errors $NE | warnings $NW | $STAGE" >>drafts/log.txt
cat "$OUT"
echo "--- exit $RC, errors $NE, warnings $NW, $STAGE"
rm -f "$OUT"
