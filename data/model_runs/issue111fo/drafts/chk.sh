#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs time, kind, exit status, counts of error[E / warning[W lines.
# Before the first valid: a failed check is kept as drafts/NN_name.attemptK.aidl + .check.txt.
# The first exit-0 check: run/NN_name.first_valid.aidl + .check.txt, rendered to .png (1200 px).
# After it: drafts/NN_name.fixK.aidl + .fixK.check.txt, rendered to drafts/NN_name.fixK.png.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-fo
AIDL=/work/main/.venv/bin/aidl
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
  K=1; while [ -e "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$F" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then "$AIDL" render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >> "$D/log.txt"
cat "$OUT"
echo "--- $T $N $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
