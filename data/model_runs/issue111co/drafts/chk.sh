#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111co)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/
# and every failed check before it as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-co
AIDL=/work/main/.venv/bin/aidl
F=drafts/$N.aidl
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
T=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -e run/$N.first_valid.aidl ]; then PHASE=after_first_valid; else PHASE=before_first_valid; fi
echo "$T $N exit=$RC errors=$NE warnings=$NW $PHASE" >> drafts/log.txt
cat "$OUT"
if [ ! -e run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" run/$N.first_valid.aidl
    cp "$OUT" run/$N.first_valid.check.txt
    $AIDL render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200
    echo "FIRST VALID kept: run/$N.first_valid.aidl"
  else
    K=1; while [ -e drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp "$F" drafts/$N.attempt$K.aidl
    cp "$OUT" drafts/$N.attempt$K.check.txt
    echo "failed check kept as drafts/$N.attempt$K"
  fi
else
  cp "$OUT" drafts/$N.latest.check.txt
fi
rm -f "$OUT"
exit $RC
