#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl; logs time, exit status and counts of error/warning lines to
# drafts/log.txt; keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.*
# (and renders its PNG); keeps each failed check before it as drafts/NN_name.attemptK.*;
# a check after the first valid is logged as after-first-valid (drafts/NN_name.fix.*).
set -u
N="$1"
R="$(cd "$(dirname "$0")/.." && pwd)"
D="$R/drafts"; RUN="$R/run"
export PYTHONPATH=/work/wt-models-hh
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
OUT="$(mktemp)"
T="$(date -u '+%Y-%m-%d %H:%M:%S UTC')"
"$AIDL" check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$RUN/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
  cp "$OUT" "$D/$N.fix.check.txt"
  if [ $RC -eq 0 ]; then "$AIDL" render "$SRC" -o "$D/$N.fix.png" --png-width 1200 >/dev/null 2>&1; fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$RUN/$N.first_valid.aidl"
  cp "$OUT" "$RUN/$N.first_valid.check.txt"
  "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed"
else
  K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >> "$D/log.txt"
cat "$OUT"
echo "--- $T $N $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
