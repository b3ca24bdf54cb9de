#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111do)
# Checks drafts/NN_name.aidl; logs time, exit status and counts of error[E / warning[W lines
# to drafts/log.txt. The first program that checks with exit 0 is kept as
# run/NN_name.first_valid.aidl (+ .check.txt, rendered to .png, render messages in .render.txt).
# A failed check before it: drafts/NN_name.attemptK.aidl (+ .check.txt).
# A check after it: drafts/NN_name.fixK.aidl (+ .fixK.check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-do
A=/work/main/.venv/bin/aidl
SRC=drafts/$N.aidl
OUT=$(mktemp)
T=$(date -u '+%Y-%m-%d %H:%M:%S')
$A check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -f run/$N.first_valid.aidl ]; then
  K=1; while [ -f drafts/$N.fix$K.aidl ]; do K=$((K+1)); done
  cp "$SRC" drafts/$N.fix$K.aidl; cp "$OUT" drafts/$N.fix$K.check.txt
  KIND="fix$K (after first valid)"
elif [ $RC -eq 0 ]; then
  cp "$SRC" run/$N.first_valid.aidl; cp "$OUT" run/$N.first_valid.check.txt
  $A render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 >run/$N.first_valid.render.txt 2>&1
  KIND="FIRST VALID"
else
  K=1; while [ -f drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
  cp "$SRC" drafts/$N.attempt$K.aidl; cp "$OUT" drafts/$N.attempt$K.check.txt
  KIND="attempt$K (failed)"
fi
echo "$T $N exit=$RC errors=$E warnings=$W $KIND" >>drafts/log.txt
cat "$OUT"
echo "== $T $N exit=$RC errors=$E warnings=$W $KIND"
rm -f "$OUT"
