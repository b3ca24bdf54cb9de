#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111hb)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the FIRST program that
# checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png); each failed
# check before it as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
N="$1"
HERE="$(cd "$(dirname "$0")/.." && pwd)"
D="$HERE/drafts"; R="$HERE/run"
SRC="$D/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-hb
OUT="$(mktemp)"
"$AIDL" check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
    PHASE="after-first-valid"
elif [ $RC -eq 0 ]; then
    PHASE="FIRST-VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 \
        || echo "render failed" >> "$R/$N.first_valid.check.txt"
else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    PHASE="attempt$K"
    cp "$SRC" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N $PHASE exit=$RC errors=$NE warnings=$NW" >> "$D/log.txt"
cat "$OUT"
echo "== $N $PHASE exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
