#!/bin/bash
# usage: drafts/chk.sh NN_name [tag]   (run from data/model_runs/issue111hd)
# logs date, exit status and counts of error[E / warning[W lines to drafts/log.txt;
# keeps the FIRST program that checks with exit 0 as run/NAME.first_valid.aidl + .check.txt
# and renders run/NAME.first_valid.png; failed checks before it are kept as drafts/NAME.attemptK.aidl + .check.txt
set -u
cd "$(dirname "$0")/.."
N="$1"; TAG="${2:-}"
export PYTHONPATH=/work/wt-models-hd
A=/work/main/.venv/bin/aidl
SRC=drafts/$N.aidl
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e run/$N.first_valid.aidl ]; then STAGE=after-first-valid; else STAGE=before-first-valid; fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N exit=$RC errors=$NE warnings=$NW stage=$STAGE $TAG" >> drafts/log.txt
cat "$OUT"
echo "--- exit=$RC errors=$NE warnings=$NW stage=$STAGE"
if [ "$STAGE" = before-first-valid ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" run/$N.first_valid.aidl
    cp "$OUT" run/$N.first_valid.check.txt
    $A render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 && echo "rendered run/$N.first_valid.png"
  else
    K=1; while [ -e drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp "$SRC" drafts/$N.attempt$K.aidl
    cp "$OUT" drafts/$N.attempt$K.check.txt
    echo "kept drafts/$N.attempt$K.aidl"
  fi
else
  cp "$OUT" drafts/$N.latest.check.txt
fi
rm -f "$OUT"
exit $RC
