#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program.
# Run from anywhere; paths are relative to this run's folder.
set -u
D="$(cd "$(dirname "$0")" && pwd)"      # drafts/
R="$(dirname "$D")/run"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-hl
A=/work/main/.venv/bin/aidl
T="$(date -u)"
OUT="$(mktemp)"
"$A" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
IS_ASM=0
grep -qE '^\s*assembly\s' "$F" && IS_ASM=1
if [ -e "$R/$N.first_valid.aidl" ]; then
    KIND="after-first-valid"
    cp "$OUT" "$D/$N.fix.check.txt"
    if [ $RC -eq 0 ]; then
        "$A" render "$F" -o "$D/$N.fix.png" --png-width 1200 >/dev/null 2>&1
        if [ $IS_ASM -eq 1 ]; then
            "$A" render "$F" -o "$D/${N}_fix_sheet.png" --layout sheet --png-width 1200 >/dev/null 2>&1
        fi
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST-VALID"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    if [ $IS_ASM -eq 1 ]; then
        "$A" render "$R/$N.first_valid.aidl" -o "$D/${N}_sheet.png" --layout sheet --png-width 1200 >/dev/null 2>&1
    fi
else
    K=1
    while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> "$D/log.txt"
cat "$OUT"
echo "--- $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
