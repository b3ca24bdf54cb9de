#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111at)
# Checks drafts/NN_name.aidl, logs one line to drafts/log.txt, keeps the first valid program
# as run/NN_name.first_valid.aidl (+ .check.txt, .png), and failed checks before it as
# drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-at
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
STAMP=$(date -u +%H:%M:%S)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
CODES=$(grep -oE '(error|warning|note)\[[EW][0-9]+\]' "$OUT" | sort | uniq -c | awk '{printf "%s%s ", $2, ($1>1?"x"$1:"")}')
if [ -e "run/$N.first_valid.aidl" ]; then
    KIND="recheck"
elif [ "$RC" -eq 0 ]; then
    KIND="FIRST_VALID"
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 \
        >"run/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    KIND="attempt$K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $KIND codes: $CODES" >>drafts/log.txt
cat "$OUT"
echo "--- logged: $STAMP $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
