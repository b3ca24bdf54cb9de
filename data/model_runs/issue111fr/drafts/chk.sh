#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid / attempts / fixes
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-fr
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="run/$N.first_valid.aidl"
if [ -f "$FV" ]; then
  K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then $A render "$SRC" -o "drafts/$N.fix$K.png" --png-width 1200 >"drafts/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
  $A render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $N | $KIND | exit $RC | errors $NE | warnings $NW" >> drafts/log.txt
tail -1 drafts/log.txt
cat "$OUT"
rm -f "$OUT"
