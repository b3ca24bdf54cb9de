#!/bin/bash
# usage (from data/model_runs/issue111z4): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl with this tree's CLI, logs the check, keeps the FIRST program that
# checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png); a failed check before
# it is kept as drafts/NN_name.attemptK.aidl
set -u
N="$1"
WT=/work/wt-models-z4
AIDL="env PYTHONPATH=$WT /work/main/.venv/bin/aidl"
F="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$E warnings=$W" >> drafts/log.txt
cat "$OUT"
if [ ! -e "run/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200
    echo "KEPT run/$N.first_valid.aidl"
  else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    echo "FAILED: kept drafts/$N.attempt$K.aidl"
  fi
fi
rm -f "$OUT"
exit $RC
