#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111hm)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt, keeps the first valid program in run/,
# keeps failed checks before it as drafts/NN_name.attemptK.*, and checks after it as fixes.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-hm
AIDL=/work/main/.venv/bin/aidl
SRC=drafts/$N.aidl
OUT=$(mktemp)
when=$(date -u)
$AIDL check "$SRC" > "$OUT" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$OUT")
warns=$(grep -c 'warning\[W' "$OUT")
if [ -e run/$N.first_valid.aidl ]; then
    phase=after-first-valid
    k=$(ls drafts/$N.fix*.check.txt 2>/dev/null | wc -l); k=$((k + 1))
    cp "$SRC" drafts/$N.fix$k.aidl
    cp "$OUT" drafts/$N.fix$k.check.txt
    if [ $rc -eq 0 ]; then
        $AIDL render "$SRC" -o drafts/$N.fix$k.png --png-width 1200 >/dev/null 2>&1
        if grep -q '^assembly' "$SRC"; then
            $AIDL render "$SRC" -o drafts/${N}.fix${k}_sheet.png --png-width 1200 --layout sheet >/dev/null 2>&1
        fi
    fi
elif [ $rc -eq 0 ]; then
    phase=first-valid
    cp "$SRC" run/$N.first_valid.aidl
    cp "$OUT" run/$N.first_valid.check.txt
    $AIDL render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 > /dev/null 2>&1
    if grep -q '^assembly' "$SRC"; then
        $AIDL render run/$N.first_valid.aidl -o drafts/${N}_sheet.png --png-width 1200 --layout sheet >/dev/null 2>&1
    fi
else
    k=$(ls drafts/$N.attempt*.check.txt 2>/dev/null | wc -l); k=$((k + 1))
    phase=attempt$k
    cp "$SRC" drafts/$N.attempt$k.aidl
    cp "$OUT" drafts/$N.attempt$k.check.txt
fi
echo "$when | $N | $phase | exit $rc | errors $errs | warnings $warns" >> drafts/log.txt
cat "$OUT"
echo "== $phase exit $rc errors $errs warnings $warns"
rm -f "$OUT"
