#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gx)
# Checks drafts/NN_name.aidl; logs date, exit status and counts of error/warning lines
# to drafts/log.txt. Keeps the FIRST program that checks with exit 0 as
# run/NN_name.first_valid.aidl + .check.txt and renders run/NN_name.first_valid.png;
# each failed check before it is kept as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-gx
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u)
if [ -e "run/$N.first_valid.aidl" ]; then
    PHASE="after-first-valid"
elif [ "$RC" -eq 0 ]; then
    PHASE="FIRST-VALID"
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
else
    K=1
    while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    PHASE="attempt$K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
cp "$OUT" "drafts/$N.last.check.txt"
echo "$STAMP | $N | exit $RC | errors $NE | warnings $NW | $PHASE" >> drafts/log.txt
cat "$OUT"
echo "== exit $RC, errors $NE, warnings $NW, $PHASE"
rm -f "$OUT"
