#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bc)
# checks drafts/NN_name.aidl; logs date, exit status, error/warning counts to drafts/log.txt;
# keeps the first program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-bc
F="drafts/$N.aidl"
OUT=$(mktemp)
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
D=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ -e "run/$N.first_valid.aidl" ]; then STATE="after-first-valid"; else STATE="before-first-valid"; fi
echo "$D $N exit=$RC errors=$E warnings=$W $STATE" >> drafts/log.txt
if [ "$STATE" = "before-first-valid" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 \
      && echo "rendered run/$N.first_valid.png" || echo "RENDER FAILED"
  else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.attempt$K.aidl"
    cp "$OUT" "drafts/$N.attempt$K.check.txt"
    echo "kept as drafts/$N.attempt$K.aidl"
  fi
else
  cp "$OUT" "drafts/$N.latest.check.txt"
fi
cat "$OUT"
echo "exit=$RC errors=$E warnings=$W"
rm -f "$OUT"
