#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111af)
# Checks drafts/NN_name.aidl, logs the check to drafts/log.txt, keeps the FIRST program that
# checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png), and each failed
# check before it as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-af
A=/work/main/.venv/bin/aidl
F=drafts/$N.aidl
OUT=$(mktemp)
$A check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
# the check prints at most 10 of one code and then "aidl: and N more of WXXXX": add those
MORE=$(grep -o 'and [0-9]* more of W' "$OUT" | grep -o '[0-9]*' | paste -sd+ | bc 2>/dev/null)
NW=$((NW + ${MORE:-0}))
if [ -e run/$N.first_valid.aidl ]; then
  STAGE="recheck after first valid"
elif [ $RC -eq 0 ]; then
  STAGE="FIRST VALID"
  cp "$F" run/$N.first_valid.aidl
  cp "$OUT" run/$N.first_valid.check.txt
  $A render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 >run/$N.first_valid.render.txt 2>&1
else
  K=1
  while [ -e drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
  STAGE="failed attempt$K"
  cp "$F" drafts/$N.attempt$K.aidl
  cp "$OUT" drafts/$N.attempt$K.check.txt
fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$NE warnings=$NW stage=$STAGE" >> drafts/log.txt
cat "$OUT"
echo "== exit=$RC errors=$NE warnings=$NW stage=$STAGE"
rm -f "$OUT"
