#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111df)
# checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/
# and each failed check before it as drafts/NN_name.attemptK.aidl + .check.txt
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-df
A=/work/main/.venv/bin/aidl
F="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "run/$N.first_valid.aidl" ]; then PHASE=after_first_valid; else PHASE=before_first_valid; fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $N rc=$RC errors=$NE warnings=$NW $PHASE" >> drafts/log.txt
if [ "$PHASE" = before_first_valid ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
    echo "FIRST VALID kept; render rc=$?"
  else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    echo "attempt $K kept"
  fi
else
  K=1; while [ -f "drafts/$N.fix$K.check.txt" ]; do K=$((K+1)); done
  cp "$OUT" "drafts/$N.fix$K.check.txt"
  echo "fix check $K kept"
fi
cat "$OUT"
rm -f "$OUT"
