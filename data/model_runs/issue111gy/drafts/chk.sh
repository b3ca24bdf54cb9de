#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt, keeps the first valid program in run/,
# keeps failed checks before it as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-gy
AIDL=/work/main/.venv/bin/aidl
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  STAGE="after-first-valid"
else
  K=$(ls "$D/$N".attempt*.aidl 2>/dev/null | wc -l)
  K=$((K + 1))
  if [ $RC -eq 0 ]; then
    STAGE="first-valid (check $K)"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 \
      || echo "render failed" >> "$R/$N.first_valid.check.txt"
  else
    STAGE="attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
  fi
fi
echo "$T $N rc=$RC errors=$NE warnings=$NW $STAGE" >> "$D/log.txt"
cat "$OUT"
echo "--- $T $N rc=$RC errors=$NE warnings=$NW $STAGE"
rm -f "$OUT"
