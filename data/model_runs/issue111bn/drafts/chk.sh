#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bn)
# Logs date, exit status, error/warning counts to drafts/log.txt; keeps the first valid program
# in run/, renders it; keeps failed checks before the first valid one as drafts/NN.attemptK.
set -u
N="$1"
D=$(cd "$(dirname "$0")" && pwd)
R="$D/../run"
mkdir -p "$R"
AIDL="env PYTHONPATH=/work/wt-models-bn /work/main/.venv/bin/aidl"
F="$D/$N.aidl"
OUT=$(mktemp)
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
(cd "$D" && $AIDL check "$N.aidl") >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
KIND="after-first-valid"
if [ ! -f "$R/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    (cd "$R" && $AIDL render "$N.first_valid.aidl" -o "$N.first_valid.png" --png-width 1200) >"$R/$N.first_valid.render.txt" 2>&1
    KIND="FIRST-VALID"
  else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
    KIND="attempt$K"
  fi
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $KIND" >> "$D/log.txt"
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
