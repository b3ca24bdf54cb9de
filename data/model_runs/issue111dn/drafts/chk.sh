#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111dn)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt, keeps the first valid program
# (run/NN_name.first_valid.aidl + .check.txt + .png), failed attempts before it
# (drafts/NN_name.attemptK.*) and checks after it (drafts/NN_name.fixK.*).
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-dn
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
T=$(date -u +%Y-%m-%dT%H:%M:%SZ)
OUT=$(mktemp)
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "run/$N.first_valid.aidl" ]; then
    K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
    KIND="fix$K (after first valid)"
elif [ $RC -eq 0 ]; then
    cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 \
        >"run/$N.first_valid.render.txt" 2>&1
    KIND="FIRST VALID (render rc=$?)"
else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    KIND="attempt$K (failed)"
fi
echo "$T $N rc=$RC errors=$NE warnings=$NW $KIND" >> drafts/log.txt
cat "$OUT"
echo "== $T $N rc=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
