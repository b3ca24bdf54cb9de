#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program.
# Written anew for issue111hn.
set -u
N="$1"
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
export PYTHONPATH=/work/wt-models-hn
A=/work/main/.venv/bin/aidl
F="$HERE/$N.aidl"
T="$(date -u)"
OUT="$(mktemp)"
"$A" check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -e "$RUN/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
    cp "$OUT" "$HERE/$N.fix.check.txt"
    if [ $RC -eq 0 ]; then
        "$A" render "$F" -o "$HERE/$N.fix.png" --png-width 1200 >/dev/null 2>&1
        if grep -q '^assembly' "$F"; then
            "$A" render "$F" -o "$HERE/${N}_fix_sheet.png" --layout sheet --png-width 1200 >/dev/null 2>&1
        fi
    fi
elif [ $RC -eq 0 ]; then
    STAGE="FIRST-VALID"
    cp "$F" "$RUN/$N.first_valid.aidl"
    cp "$OUT" "$RUN/$N.first_valid.check.txt"
    "$A" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    if grep -q '^assembly' "$F"; then
        "$A" render "$RUN/$N.first_valid.aidl" -o "$HERE/${N}_sheet.png" --layout sheet --png-width 1200 >/dev/null 2>&1
    fi
else
    K=1
    while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K"
    cp "$F" "$HERE/$N.attempt$K.aidl"
    cp "$OUT" "$HERE/$N.attempt$K.check.txt"
fi
echo "$T | $N | $STAGE | exit $RC | errors $E | warnings $W" >> "$HERE/log.txt"
cat "$OUT"
echo "== $STAGE exit $RC errors $E warnings $W"
rm -f "$OUT"
