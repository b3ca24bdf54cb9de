#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111du)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of error/warning lines to
# drafts/log.txt; keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.*
# (and renders its PNG); a failed check before it is kept as drafts/NN_name.attemptK.*;
# a check after it (a fix) is kept as drafts/NN_name.fixK.*.
set -u
cd "$(dirname "$0")/.."
N="$1"
SRC="drafts/$N.aidl"
AIDL() { PYTHONPATH=/work/wt-models-du /work/main/.venv/bin/aidl "$@"; }
OUT=$(mktemp)
AIDL check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -f "run/$N.first_valid.aidl" ]; then
    K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
    KIND="fix$K (after first valid)"
elif [ $RC -eq 0 ]; then
    cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 \
        > "run/$N.first_valid.render.txt" 2>&1
    KIND="FIRST VALID"
else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    KIND="attempt$K (failed)"
fi
echo "$NOW  $N  exit=$RC  errors=$NE  warnings=$NW  $KIND" >> drafts/log.txt
echo "$NOW  $N  exit=$RC  errors=$NE  warnings=$NW  $KIND"
cat "$OUT"
rm -f "$OUT"
