#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cn)
# checks drafts/NN_name.aidl, logs date, exit status and the counts of error/warning lines;
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt,
# + .png render); a failed check before it is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-cn /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT="$(mktemp)"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  STAGE="after-first-valid"
  cp "$OUT" "drafts/$N.latest.check.txt"
elif [ "$RC" -eq 0 ]; then
  STAGE="FIRST-VALID"
  cp "$SRC" "$FV"
  cp "$OUT" "run/$N.first_valid.check.txt"
  $AIDL render "$FV" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >>"run/$N.first_valid.check.txt"
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $N exit=$RC errors=$NE warnings=$NW $STAGE" >>drafts/log.txt
cat "$OUT"
echo "--- exit=$RC errors=$NE warnings=$NW $STAGE"
rm -f "$OUT"
