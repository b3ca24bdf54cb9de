#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid program
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-dg /work/main/.venv/bin/aidl"
F="$D/$N.aidl"
OUT="$(mktemp)"
(cd "$D" && $AIDL check "$F") >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
if [ -f "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$D/$N.fix$K.check.txt" ]; do K=$((K+1)); done
    cp "$OUT" "$D/$N.fix$K.check.txt"
    STAGE="after first valid (fix$K)"
elif [ $RC -eq 0 ]; then
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    (cd "$R" && $AIDL render "$N.first_valid.aidl" -o "$N.first_valid.png" --png-width 1200) >"$R/$N.first_valid.render.txt" 2>&1
    STAGE="FIRST VALID"
else
    K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
    STAGE="attempt$K failed"
fi
echo "$NOW  $N  exit=$RC  errors=$E  warnings=$W  $STAGE" >> "$D/log.txt"
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$E warnings=$W $STAGE"
rm -f "$OUT"
