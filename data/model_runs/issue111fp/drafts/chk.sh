#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
# Written anew for issue111fp.
set -u
cd "$(dirname "$0")/.." || exit 2
N="$1"
SRC="drafts/$N.aidl"
export PYTHONPATH=/work/wt-models-fp
AIDL=/work/main/.venv/bin/aidl
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="run/$N.first_valid.aidl"
if [ ! -f "$FV" ]; then
  if [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  fi
else
  K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    $AIDL render "drafts/$N.fix$K.aidl" -o "drafts/$N.fix$K.png" --png-width 1200 >"drafts/$N.fix$K.render.txt" 2>&1
  fi
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> drafts/log.txt
cat "$OUT"
echo "--- $KIND: exit $RC, errors $NE, warnings $NW"
rm -f "$OUT"
