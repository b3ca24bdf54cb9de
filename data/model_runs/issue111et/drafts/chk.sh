#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111et)
# Checks drafts/NN_name.aidl and logs time, kind, exit status and counts of
# error[E / warning[W lines to drafts/log.txt.
# Before the first valid program: a failed check is kept as drafts/NN_name.attemptK.aidl
# (+ .check.txt); the first check with exit 0 becomes run/NN_name.first_valid.aidl
# (+ .check.txt, rendered to .png, messages in .render.txt).
# After it: each check is kept as drafts/NN_name.fixK.aidl (+ .check.txt), rendered.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-et
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
TS="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$($AIDL check "$SRC" 2>&1)"; RC=$?
NE=$(printf '%s\n' "$OUT" | grep -c 'error\[E')
NW=$(printf '%s\n' "$OUT" | grep -c 'warning\[W')
if [ ! -f "run/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "run/$N.first_valid.aidl"
    printf '%s\n' "$OUT" > "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
  else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"
    printf '%s\n' "$OUT" > "drafts/$N.attempt$K.check.txt"
  fi
else
  K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "drafts/$N.fix$K.aidl"
  printf '%s\n' "$OUT" > "drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    $AIDL render "drafts/$N.fix$K.aidl" -o "drafts/$N.fix$K.png" --png-width 1200 > "drafts/$N.fix$K.render.txt" 2>&1
  fi
fi
echo "$TS | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> drafts/log.txt
printf '%s\n' "$OUT"
echo "--- $KIND: exit $RC, errors $NE, warnings $NW"
