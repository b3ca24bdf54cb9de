#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111dm)
# Checks drafts/NN_name.aidl; logs time, exit status, error/warning line counts to drafts/log.txt.
# Keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before it as drafts/NN_name.attemptK.aidl (+ .check.txt); a check after it as
# drafts/NN_name.fixK.aidl (+ .fixK.check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-dm /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
T=$(date -u '+%Y-%m-%d %H:%M:%S')
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "run/$N.first_valid.aidl" ]; then
  K=1; while [ -e "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
  KIND="fix$K (after first valid)"
elif [ "$RC" -eq 0 ]; then
  cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
  $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
  KIND="FIRST VALID"
else
  K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
  KIND="attempt$K (failed)"
fi
echo "$T  $N  exit=$RC  errors=$NE  warnings=$NW  $KIND" >> drafts/log.txt
cat "$OUT"
echo "== $T $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
