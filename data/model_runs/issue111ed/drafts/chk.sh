#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes
# (issue111ed; written anew for this run)
set -u
cd "$(dirname "$0")/.."          # data/model_runs/issue111ed
N="$1"
SRC="drafts/$N.aidl"
export PYTHONPATH=/work/wt-models-ed
AIDL=/work/main/.venv/bin/aidl
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="run/$N.first_valid.aidl"
if [ -f "$FV" ]; then
  K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix$K (after first valid)"
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
elif [ "$RC" -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
  "$AIDL" render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K (failed)"
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$NOW  $N  exit=$RC  errors=$NE  warnings=$NW  $KIND" >> drafts/log.txt
cat "$OUT"
echo "---- $NOW $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
