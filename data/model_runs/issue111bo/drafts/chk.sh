#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bo)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error/warning lines to
# drafts/log.txt; keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, rendered .png); a failed check before it is kept as drafts/NN_name.attemptK.aidl.
set -u
cd "$(dirname "$0")/.."
N="$1"
SRC="drafts/$N.aidl"
AIDL="env PYTHONPATH=/work/wt-models-bo /work/main/.venv/bin/aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u +%Y-%m-%dT%H:%M:%SZ)
FV="run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
    NOTE="after first valid"
elif [ "$RC" -eq 0 ]; then
    cp "$SRC" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
    NOTE="FIRST VALID -> $FV"
else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    NOTE="failed -> drafts/$N.attempt$K.aidl"
fi
echo "$NOW $N exit=$RC errors=$E warnings=$W $NOTE" >>drafts/log.txt
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$E warnings=$W $NOTE"
rm -f "$OUT"
