#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Logs date -u, exit status and counts of error[E / warning[W lines to drafts/log.txt.
# Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl + .check.txt
# and renders run/NN_name.first_valid.png; a failed check before it is kept as
# drafts/NN_name.attemptK.aidl + .check.txt.
set -u
D=$(cd "$(dirname "$0")" && pwd)
R="$D/../run"
N="$1"
export PYTHONPATH=/work/wt-models-bv
A=/work/main/.venv/bin/aidl
F="$D/$N.aidl"
OUT=$(mktemp)
"$A" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ -e "$R/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
  echo "render exit $?" >>"$R/$N.first_valid.render.txt"
else
  K=1
  while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $KIND" >>"$D/log.txt"
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
