#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bp)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# failed checks before it as drafts/NN_name.attemptK.aidl + .check.txt.
cd "$(dirname "$0")/.." || exit 2
N="$1"
F="drafts/$N.aidl"
export PYTHONPATH=/work/wt-models-bp
A=/work/main/.venv/bin/aidl
T=$(date -u +%Y-%m-%dT%H:%M:%SZ)
OUT=$(mktemp)
$A check "$F" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "run/$N.first_valid.aidl" ]; then STAGE="after-first-valid"; else STAGE="before-first-valid"; fi
echo "$T $N exit=$RC errors=$NE warnings=$NW stage=$STAGE" >> drafts/log.txt
if [ "$STAGE" = "before-first-valid" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
    echo "FIRST VALID -> run/$N.first_valid.*"
  else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    echo "FAILED -> drafts/$N.attempt$K.*"
  fi
fi
cat "$OUT"
tail -1 drafts/log.txt
rm -f "$OUT"
