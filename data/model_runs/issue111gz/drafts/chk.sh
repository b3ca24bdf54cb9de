#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gz or anywhere)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of error/warning lines to drafts/log.txt.
# Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl + .check.txt (+ .png);
# every failed check before it is kept as drafts/NN_name.attemptK.aidl + .check.txt.
# After the first valid program, checks are logged as "after-first-valid" and rendered to drafts/NN_name.fix.png.
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
D="$HERE/drafts"; R="$HERE/run"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-gz
AIDL=/work/main/.venv/bin/aidl
TS="$(date -u)"
OUT="$(mktemp)"
"$AIDL" check "$F" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
  STAGE="after-first-valid"
  cp "$OUT" "$D/$N.fix.check.txt"
  if [ $RC -eq 0 ]; then "$AIDL" render "$F" -o "$D/$N.fix.png" --png-width 1200 >/dev/null 2>&1; fi
elif [ $RC -eq 0 ]; then
  STAGE="FIRST-VALID"
  cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 \
    || echo "render failed" >> "$R/$N.first_valid.check.txt"
else
  K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="attempt$K-failed"
  cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$TS | $N | exit=$RC | errors=$NE | warnings=$NW | $STAGE" >> "$D/log.txt"
cat "$OUT"
echo "--- $STAGE exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
