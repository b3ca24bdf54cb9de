#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111eh)
# Checks drafts/NN_name.aidl and logs: date -u, exit status, counts of error[E / warning[W lines.
# Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt)
# and renders run/NN_name.first_valid.png; a failed check before it is kept as
# drafts/NN_name.attemptK.aidl (+ .check.txt); a check after it as drafts/NN_name.fixK.aidl.
set -u
cd "$(dirname "$0")/.."
N="$1"
F="drafts/$N.aidl"
export PYTHONPATH=/work/wt-models-eh
AIDL=/work/main/.venv/bin/aidl
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
D=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -e "run/$N.first_valid.aidl" ]; then
    K=1; while [ -e "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
    KIND="fix $K after the first valid"
elif [ "$RC" -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 \
        >"run/$N.first_valid.render.txt" 2>&1
    KIND="FIRST VALID"
else
    K=1; while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    KIND="attempt $K"
fi
echo "$D  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >>drafts/log.txt
tail -n 1 drafts/log.txt
cat "$OUT"
rm -f "$OUT"
