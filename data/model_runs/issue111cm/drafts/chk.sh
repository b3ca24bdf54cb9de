#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts and the first valid program.
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-cm
F="$D/$N.aidl"
OUT="$(mktemp)"
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
    K=$(ls "$D/$N".fix*.check.txt 2>/dev/null | wc -l); K=$((K + 1))
    cp "$OUT" "$D/$N.fix$K.check.txt"
elif [ "$RC" -eq 0 ]; then
    STAGE="FIRST-VALID"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >>"$R/$N.first_valid.render.txt" 2>&1
else
    K=$(ls "$D/$N".attempt*.aidl 2>/dev/null | wc -l); K=$((K + 1))
    STAGE="attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T  $N  exit=$RC  errors=$E  warnings=$W  $STAGE" >>"$D/log.txt"
cat "$OUT"
echo "--- exit=$RC errors=$E warnings=$W $STAGE"
rm -f "$OUT"
