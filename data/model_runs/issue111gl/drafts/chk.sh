#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gl or anywhere)
# Checks drafts/NN_name.aidl, logs the result to drafts/log.txt, keeps the first valid
# program as run/NN_name.first_valid.aidl (+ .check.txt, rendered .png), a failed check
# before it as drafts/NN_name.attemptK.aidl (+ .check.txt), a check after it as
# drafts/NN_name.fixK.aidl (+ .check.txt, rendered when it passes).
set -u
cd "$(dirname "$0")/.."
N="$1"
A="env PYTHONPATH=/work/wt-models-gl /work/main/.venv/bin/aidl"
SRC="drafts/$N.aidl"
TMP="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
$A check "$SRC" > "$TMP" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$TMP")
NW=$(grep -c 'warning\[W' "$TMP")
if [ -f "run/$N.first_valid.aidl" ]; then
    K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$TMP" "drafts/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        $A render "drafts/$N.fix$K.aidl" -o "drafts/$N.fix$K.png" --png-width 1200 > "drafts/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "run/$N.first_valid.aidl"; cp "$TMP" "run/$N.first_valid.check.txt"
    $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$TMP" "drafts/$N.attempt$K.check.txt"
fi
echo "$NOW  $N  $KIND  exit=$RC  error[E=$NE  warning[W=$NW" >> drafts/log.txt
echo "== $NOW $N $KIND exit=$RC errors=$NE warnings=$NW"
cat "$TMP"
rm -f "$TMP"
