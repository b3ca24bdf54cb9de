#!/bin/bash
# usage (from data/model_runs/issue111o): drafts/chk.sh NN_name
# Checks drafts/NN_name.aidl with this tree's CLI, logs one line to drafts/log.txt,
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt,
# + .png rendered at 1200 px); a failed check before it is kept as drafts/NN_name.attemptK.aidl.
set -u
N="$1"
export PYTHONPATH=/work/wt-models-o
A=/work/main/.venv/bin/aidl
F="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="run/$N.first_valid.aidl"
if [ -e "$FV" ]; then STAGE="after-first-valid"; else STAGE="before-first-valid"; fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N rc=$RC errors=$NE warnings=$NW $STAGE" >> drafts/log.txt
if [ ! -e "$FV" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "$FV"; cp "$OUT" "run/$N.first_valid.check.txt"
    $A render "$FV" -o "run/$N.first_valid.png" --png-width 1200
  else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  fi
fi
cat "$OUT"; rm -f "$OUT"
echo "rc=$RC"
