#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111aw)
# Checks drafts/NN_name.aidl; logs date, exit status, error/warning counts to drafts/log.txt.
# Keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-aw /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u +%Y-%m-%dT%H:%M:%SZ)
STATE=""
if [ -e "run/$N.first_valid.aidl" ]; then
  STATE="after-first-valid"
elif [ $RC -eq 0 ]; then
  cp "$SRC" "run/$N.first_valid.aidl"
  cp "$OUT" "run/$N.first_valid.check.txt"
  $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
  STATE="FIRST-VALID"
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$SRC" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
  STATE="attempt$K"
fi
echo "$NOW $N exit=$RC errors=$E warnings=$W $STATE" >> drafts/log.txt
cat "$OUT"
echo "--- $NOW $N exit=$RC errors=$E warnings=$W $STATE"
rm -f "$OUT"
