#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111dq or anywhere)
# Checks drafts/NN_name.aidl; logs date -u, exit status, counts of error[E / warning[W lines
# to drafts/log.txt. Keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, rendered to .png); a failed check before it as drafts/NN_name.attemptK.aidl
# (+ .check.txt); a check after it as drafts/NN_name.fixK.aidl (+ .fixK.check.txt).
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
D="$HERE/drafts"; R="$HERE/run"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-dq
SRC="$D/$N.aidl"
OUT="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
  KIND="fix$K (after first valid)"
elif [ "$RC" -eq 0 ]; then
  cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 > "$R/$N.first_valid.render.txt" 2>&1
  KIND="FIRST VALID"
else
  K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
  KIND="attempt$K (failed)"
fi
echo "$NOW  $N  exit=$RC  errors=$NE  warnings=$NW  $KIND" >> "$D/log.txt"
cat "$OUT"
echo "--- $NOW exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
