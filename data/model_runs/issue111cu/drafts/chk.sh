#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cu)
# Checks drafts/NN_name.aidl; logs date -u, exit status, error/warning counts to drafts/log.txt;
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-cu
A=/work/main/.venv/bin/aidl
OUT="$(mktemp)"
T="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
"$A" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
MORE=$(grep -o 'and [0-9]* more of W[0-9]*' "$OUT" | tr '\n' ' ')
STATE=""
if [ -e "$R/$N.first_valid.aidl" ]; then
  STATE="after-first-valid"
elif [ "$RC" -eq 0 ]; then
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
  STATE="FIRST-VALID"
else
  K=1
  while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
  STATE="attempt$K"
fi
echo "$T $N exit=$RC errors=$NE warnings=$NW ${MORE:+($MORE)} $STATE" >>"$D/log.txt"
cat "$OUT"
echo "--- $T $N exit=$RC errors=$NE warnings=$NW $STATE"
rm -f "$OUT"
