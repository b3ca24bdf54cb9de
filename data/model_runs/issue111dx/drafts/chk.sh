#!/bin/bash
# drafts/chk.sh NN_name [note]: check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
set -u
cd "$(dirname "$0")/.." || exit 2
N="$1"; NOTE="${2:-}"
export PYTHONPATH=/work/wt-models-dx
A=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
T=$(date -u +"%Y-%m-%d %H:%M:%S")
$A check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "run/$N.first_valid.aidl" ]; then
    K=1; while [ -f "drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix$K"
    cp "$SRC" "drafts/$N.fix$K.aidl"; cp "$OUT" "drafts/$N.fix$K.check.txt"
elif [ $RC -eq 0 ]; then
    KIND="first_valid"
    cp "$SRC" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$SRC" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$T UTC  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW  $NOTE" >> drafts/log.txt
tail -1 drafts/log.txt
cat "$OUT"
rm -f "$OUT"
