#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gp)
# Checks drafts/NN_name.aidl, logs time, kind, exit status and counts of error[E / warning[W lines.
# Before the first valid: keeps drafts/NN_name.attemptK.aidl + .check.txt on failure.
# The first exit-0 check: run/NN_name.first_valid.aidl + .check.txt, rendered to .png (1200 px).
# After it: drafts/NN_name.fixK.aidl + .fixK.check.txt, rendered when it passes.
set -u
cd "$(dirname "$0")/.."
N="$1"
SRC="drafts/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-gp
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "run/$N.first_valid.aidl" ]; then
  K=1; while [ -e "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    "$AIDL" render "drafts/$N.fix$K.aidl" -o "drafts/$N.fix$K.png" --png-width 1200 >"drafts/$N.fix$K.render.txt" 2>&1
  fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >> drafts/log.txt
echo "== $T $N $KIND exit=$RC errors=$NE warnings=$NW"
cat "$OUT"
rm -f "$OUT"
