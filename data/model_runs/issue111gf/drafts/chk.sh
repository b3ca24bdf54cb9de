#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gf)
# Checks drafts/NN_name.aidl; logs time, kind, exit status, counts of error[E / warning[W lines.
# Before the first valid: failures kept as drafts/NN_name.attemptK.aidl + .check.txt.
# First exit-0 check: kept as run/NN_name.first_valid.aidl + .check.txt, rendered to .png.
# After it: kept as drafts/NN_name.fixK.aidl + .fixK.check.txt (rendered when it passes).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-gf
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
T=$(date -u +%Y-%m-%dT%H:%M:%SZ)
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "run/$N.first_valid.aidl" ]; then
  K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix$K"
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then $A render "drafts/$N.fix$K.aidl" -o "drafts/$N.fix$K.png" --png-width 1200 >"drafts/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST_VALID"
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$T $N $KIND exit=$RC errors=$NE warnings=$NW" >> drafts/log.txt
echo "== $T $N $KIND exit=$RC errors=$NE warnings=$NW"
cat "$OUT"
rm -f "$OUT"
