#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gh)
# Checks drafts/NN_name.aidl; logs time, kind, exit status, error/warning counts to drafts/log.txt.
# Before the first valid check: a failing program is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
# The first program that checks with exit 0 is kept as run/NN_name.first_valid.aidl (+ .check.txt)
# and rendered to run/NN_name.first_valid.png (1200 px; messages in .render.txt).
# After it: each check is kept as drafts/NN_name.fixK.aidl (+ .fixK.check.txt), rendered when it passes.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-gh
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
T=$(date -u '+%Y-%m-%d %H:%M:%S')
$A check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -e "run/$N.first_valid.aidl" ]; then
  K=1; while [ -e "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then $A render "drafts/$N.fix$K.aidl" -o "drafts/$N.fix$K.png" --png-width 1200 >"drafts/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$E  warnings=$W" >> drafts/log.txt
echo "== $T $N $KIND exit=$RC errors=$E warnings=$W"
cat "$OUT"
rm -f "$OUT"
