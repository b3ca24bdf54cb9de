#!/bin/bash
# usage: drafts/chk.sh NN_name   (from anywhere)
# Checks drafts/NN_name.aidl, logs the check to drafts/log.txt, keeps the first valid program
# (exit 0) as run/NN_name.first_valid.aidl + .check.txt and renders its PNG; a failed check
# before the first valid one is kept as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
D="$HERE/drafts"; R="$HERE/run"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-ac
AIDL=/work/main/.venv/bin/aidl
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  STAGE="recheck after first valid"
elif [ $RC -eq 0 ]; then
  STAGE="FIRST VALID"
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
  echo "render exit $?" >>"$R/$N.first_valid.render.txt"
else
  K=1
  while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="failed attempt$K"
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$NE warnings=$NW stage=$STAGE" >>"$D/log.txt"
cat "$OUT"
echo "--- exit=$RC errors=$NE warnings=$NW stage=$STAGE"
rm -f "$OUT"
