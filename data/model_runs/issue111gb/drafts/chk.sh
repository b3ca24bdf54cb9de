#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gb or anywhere)
# Checks drafts/NN_name.aidl and logs the check to drafts/log.txt:
#   before the first valid program: a failed check is kept as drafts/NN_name.attemptK.aidl (+ .check.txt);
#   the first check with exit 0 is kept as run/NN_name.first_valid.aidl (+ .check.txt, .png, .render.txt);
#   after it: each check is kept as drafts/NN_name.fixK.aidl (+ .fixK.check.txt; rendered when it passes).
set -u
D="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
export PYTHONPATH=/work/wt-models-gb
AIDL=/work/main/.venv/bin/aidl
SRC="$D/drafts/$N.aidl"
[ -f "$SRC" ] || { echo "no $SRC"; exit 2; }
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$D/run/$N.first_valid.aidl"
if [ -f "$FV" ]; then
    K=1; while [ -f "$D/drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "$D/drafts/$N.fix$K.aidl"; cp "$OUT" "$D/drafts/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "$D/drafts/$N.fix$K.aidl" -o "$D/drafts/$N.fix$K.png" --png-width 1200 >"$D/drafts/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$FV"; cp "$OUT" "$D/run/$N.first_valid.check.txt"
    "$AIDL" render "$FV" -o "$D/run/$N.first_valid.png" --png-width 1200 >"$D/run/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "$D/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "$D/drafts/$N.attempt$K.aidl"; cp "$OUT" "$D/drafts/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >>"$D/drafts/log.txt"
cat "$OUT"
echo "--- logged: $T  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW"
rm -f "$OUT"
