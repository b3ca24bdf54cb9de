#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid program.
# Run from anywhere; paths are relative to this run's folder.
set -u
RUN="$(cd "$(dirname "$0")/.." && pwd)"
WT=/work/wt-models-hj
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=$WT
N="$1"
SRC="$RUN/drafts/$N.aidl"
LOG="$RUN/drafts/log.txt"
OUT="$(mktemp)"
NOW="$(date -u)"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$RUN/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
    STAGE="after-first-valid"
    cp "$OUT" "$RUN/drafts/$N.fix.check.txt"
    if [ $RC -eq 0 ]; then
        $AIDL render "$SRC" -o "$RUN/drafts/$N.fix.png" --png-width 1200 >/dev/null 2>&1
        if grep -q '^ *assembly ' "$SRC"; then
            $AIDL render "$SRC" --layout sheet -o "$RUN/drafts/${N}_fix_sheet.png" --png-width 1200 >/dev/null 2>&1
        fi
    fi
elif [ $RC -eq 0 ]; then
    STAGE="FIRST-VALID"
    cp "$SRC" "$FV"
    cp "$OUT" "$RUN/run/$N.first_valid.check.txt"
    $AIDL render "$FV" -o "$FV.png" --png-width 1200 >/dev/null 2>&1
    # the brief names it run/NN_name.first_valid.png
    mv "$FV.png" "$RUN/run/$N.first_valid.png" 2>/dev/null
    if grep -q '^ *assembly ' "$SRC"; then
        $AIDL render "$FV" --layout sheet -o "$RUN/drafts/${N}_sheet.png" --png-width 1200 >/dev/null 2>&1
    fi
else
    K=1
    while [ -e "$RUN/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K"
    cp "$SRC" "$RUN/drafts/$N.attempt$K.aidl"
    cp "$OUT" "$RUN/drafts/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $STAGE | exit $RC | errors $NE | warnings $NW" >>"$LOG"
echo "== $N $STAGE exit $RC errors $NE warnings $NW"
cat "$OUT"
rm -f "$OUT"
