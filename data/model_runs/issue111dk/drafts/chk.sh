#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid program.
# Run from data/model_runs/issue111dk (or anywhere: it cds there).
cd "$(dirname "$0")/.." || exit 2
N="$1"
SRC="drafts/$N.aidl"
AIDL="env PYTHONPATH=/work/wt-models-dk /work/main/.venv/bin/aidl"
[ -f "$SRC" ] || { echo "no $SRC"; exit 2; }
OUT=$(mktemp)
$AIDL check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
T=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -f "run/$N.first_valid.aidl" ]; then
    K=1; while [ -f "drafts/$N.fix$K.check.txt" ]; do K=$((K+1)); done
    cp "$OUT" "drafts/$N.fix$K.check.txt"; cp "$SRC" "drafts/$N.fix$K.aidl"
    PHASE="after-first-valid fix$K"
elif [ $RC -eq 0 ]; then
    cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
    PHASE="FIRST VALID (render rc=$?)"
else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    PHASE="attempt$K failed"
fi
echo "$T  $N  exit=$RC  errors=$NE  warnings=$NW  $PHASE" >> drafts/log.txt
cat "$OUT"
echo "--- $T $N exit=$RC errors=$NE warnings=$NW $PHASE"
rm -f "$OUT"
