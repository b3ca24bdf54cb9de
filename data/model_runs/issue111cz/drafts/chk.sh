#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cz)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the FIRST program that checks
# with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png, .render.txt); a failed
# check before that is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
SRC="drafts/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-cz
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
WCODES=$(grep -o 'warning\[W[0-9]*\]' "$OUT" | sort | uniq -c | tr -s ' ' | tr '\n' ';')
ECODES=$(grep -o 'error\[E[0-9]*\]' "$OUT" | sort | uniq -c | tr -s ' ' | tr '\n' ';')
STAMP=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -f "run/$N.first_valid.aidl" ]; then
    KIND="after-first-valid"
    K=$(ls drafts/$N.fix*.check.txt 2>/dev/null | wc -l); K=$((K + 1))
    cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
    KIND="$KIND (kept as drafts/$N.fix$K)"
elif [ "$RC" -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 \
        >"run/$N.first_valid.render.txt" 2>&1
else
    K=$(ls drafts/$N.attempt*.check.txt 2>/dev/null | wc -l); K=$((K + 1))
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    KIND="failed (kept as drafts/$N.attempt$K)"
fi
echo "$STAMP | $N | exit $RC | errors $NE [$ECODES] | warnings $NW [$WCODES] | $KIND" >> drafts/log.txt
cat "$OUT"
echo "--- exit $RC, errors $NE, warnings $NW, $KIND"
rm -f "$OUT"
