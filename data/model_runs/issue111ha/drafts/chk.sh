#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ha or anywhere)
# Checks drafts/NN_name.aidl; logs date -u, exit status and counts of error/warning lines
# to drafts/log.txt. Keeps the FIRST program that checks with exit 0 as
# run/NN_name.first_valid.aidl + .check.txt and renders run/NN_name.first_valid.png.
# A failed check before the first valid is kept as drafts/NN_name.attemptK.aidl + .check.txt.
# Checks after the first valid are logged as "after-first-valid" and rendered to drafts/NN_name.fix.png.
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-ha
SRC="$HERE/drafts/$N.aidl"
LOG="$HERE/drafts/log.txt"
OUT="$(mktemp)"
NOW="$(date -u '+%Y-%m-%dT%H:%M:%SZ')"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$HERE/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
    STAGE="after-first-valid"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "$SRC" -o "$HERE/drafts/$N.fix.png" --png-width 1200 >/dev/null 2>&1
    fi
    cp "$OUT" "$HERE/drafts/$N.latest.check.txt"
elif [ $RC -eq 0 ]; then
    STAGE="FIRST-VALID"
    cp "$SRC" "$FV"
    cp "$OUT" "$HERE/run/$N.first_valid.check.txt"
    "$AIDL" render "$FV" -o "$HERE/run/$N.first_valid.png" --png-width 1200 >>"$HERE/run/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -e "$HERE/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K-failed"
    cp "$SRC" "$HERE/drafts/$N.attempt$K.aidl"
    cp "$OUT" "$HERE/drafts/$N.attempt$K.check.txt"
fi
echo "$NOW $N exit=$RC errors=$NE warnings=$NW stage=$STAGE" >>"$LOG"
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$NE warnings=$NW stage=$STAGE"
rm -f "$OUT"
