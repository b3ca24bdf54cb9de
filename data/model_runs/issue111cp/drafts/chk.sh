#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program (run/)
# or each failed attempt before it (drafts/NN_name.attemptK.*).
set -u
cd "$(dirname "$0")/.."            # issue111cp/
export PYTHONPATH=/work/wt-models-cp
AIDL=/work/main/.venv/bin/aidl
N="$1"
SRC="drafts/$N.aidl"
OUT=$(mktemp)
when=$(date -u)
$AIDL check "$SRC" >"$OUT" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$OUT")
nw=$(grep -c 'warning\[W' "$OUT")
if [ -e "run/$N.first_valid.aidl" ]; then
    kind="after-first-valid"
elif [ $rc -eq 0 ]; then
    kind="FIRST-VALID"
    cp "$SRC" "run/$N.first_valid.aidl"
    cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >>"$OUT" 2>&1 \
        || echo "(render failed)" >>"$OUT"
else
    k=1; while [ -e "drafts/$N.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt$k"
    cp "$SRC" "drafts/$N.attempt$k.aidl"
    cp "$OUT" "drafts/$N.attempt$k.check.txt"
fi
echo "$when | $N | exit=$rc | errors=$ne | warnings=$nw | $kind" >> drafts/log.txt
cat "$OUT"
echo "--- $when exit=$rc errors=$ne warnings=$nw $kind"
rm -f "$OUT"
