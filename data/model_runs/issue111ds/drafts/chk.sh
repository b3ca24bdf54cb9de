#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ds or anywhere)
# Checks drafts/NN_name.aidl, logs date -u, exit status and the counts of error[E / warning[W
# lines to drafts/log.txt. Keeps the FIRST program that checks with exit 0 as
# run/NN_name.first_valid.aidl (+ .check.txt) and renders run/NN_name.first_valid.png;
# a failed check before it is kept as drafts/NN_name.attemptK.aidl (+ .check.txt);
# a check after it as drafts/NN_name.fixK.aidl (+ .fixK.check.txt).
set -u
D="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
F="$D/drafts/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-ds
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u '+%Y-%m-%d %H:%M:%S UTC')"
if [ ! -e "$D/run/$N.first_valid.aidl" ]; then
  if [ "$RC" -eq 0 ]; then
    cp "$F" "$D/run/$N.first_valid.aidl"
    cp "$OUT" "$D/run/$N.first_valid.check.txt"
    "$AIDL" render "$D/run/$N.first_valid.aidl" -o "$D/run/$N.first_valid.png" --png-width 1200 \
      >"$D/run/$N.first_valid.render.txt" 2>&1
    TAG="first_valid (render exit $?)"
  else
    K=1; while [ -e "$D/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$D/drafts/$N.attempt$K.aidl"
    cp "$OUT" "$D/drafts/$N.attempt$K.check.txt"
    TAG="attempt$K (failed)"
  fi
else
  K=1; while [ -e "$D/drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  cp "$F" "$D/drafts/$N.fix$K.aidl"
  cp "$OUT" "$D/drafts/$N.fix$K.check.txt"
  TAG="fix$K (after first valid)"
fi
echo "$NOW | $N | exit $RC | errors $NE | warnings $NW | $TAG" >>"$D/drafts/log.txt"
cat "$OUT"
echo "--- $NOW | $N | exit $RC | errors $NE | warnings $NW | $TAG"
rm -f "$OUT"
