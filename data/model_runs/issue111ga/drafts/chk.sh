#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
set -u
D=/work/wt-models-ga/data/model_runs/issue111ga
export PYTHONPATH=/work/wt-models-ga
A=/work/main/.venv/bin/aidl
N="$1"
SRC="$D/drafts/$N.aidl"
FV="$D/run/$N.first_valid.aidl"
mkdir -p "$D/run"
OUT=$(mktemp)
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$FV" ]; then
  K=1; while [ -f "$D/drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "$D/drafts/$N.fix$K.aidl"; cp "$OUT" "$D/drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    "$A" render "$D/drafts/$N.fix$K.aidl" -o "$D/drafts/$N.fix$K.png" --png-width 1200 >"$D/drafts/$N.fix$K.render.txt" 2>&1
  fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "$FV"; cp "$OUT" "$D/run/$N.first_valid.check.txt"
  "$A" render "$FV" -o "$D/run/$N.first_valid.png" --png-width 1200 >"$D/run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "$D/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$SRC" "$D/drafts/$N.attempt$K.aidl"; cp "$OUT" "$D/drafts/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> "$D/drafts/log.txt"
echo "== $NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW"
cat "$OUT"
rm -f "$OUT"
