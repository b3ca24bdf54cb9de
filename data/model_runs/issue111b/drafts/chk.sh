#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111b)
# Checks drafts/NN_name.aidl, logs one line per check (date -u) in drafts/log.txt,
# keeps every failed check before the first valid one as drafts/NN_name.attemptK.aidl (+ .check.txt),
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt)
# and renders run/NN_name.first_valid.png at 1200 px.
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models /work/main/.venv/bin/aidl"
F="drafts/$N.aidl"
OUT=$($AIDL check "$F" 2>&1); RC=$?
echo "$OUT"
K=$(ls drafts/$N.attempt*.aidl 2>/dev/null | wc -l)
echo "$(date -u +%FT%TZ) $N exit=$RC" >> drafts/log.txt
if [ ! -e "run/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"
    echo "$OUT" > "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200
    echo "FIRST VALID -> run/$N.first_valid.aidl (+png)"
  else
    K=$((K+1))
    cp "$F" "drafts/$N.attempt$K.aidl"
    echo "$OUT" > "drafts/$N.attempt$K.check.txt"
    echo "kept as drafts/$N.attempt$K.aidl"
  fi
fi
exit $RC
