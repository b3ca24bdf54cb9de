#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
set -u
cd "$(dirname "$0")"
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-ge /work/main/.venv/bin/aidl"
RUN=../run
mkdir -p "$RUN"
F="$N.aidl"
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -e "$RUN/$N.first_valid.aidl" ]; then
    K=1; while [ -e "$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$F" "$N.fix$K.aidl"; cp "$OUT" "$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        $AIDL render "$N.fix$K.aidl" -o "$N.fix$K.png" --png-width 1200 >"$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$F" "$RUN/$N.first_valid.aidl"; cp "$OUT" "$RUN/$N.first_valid.check.txt"
    $AIDL render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 >"$RUN/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -e "$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$F" "$N.attempt$K.aidl"; cp "$OUT" "$N.attempt$K.check.txt"
fi
echo "$NOW  $N  $KIND  exit=$RC  errors=$E  warnings=$W" >> log.txt
echo "== $NOW $N $KIND exit=$RC errors=$E warnings=$W"
cat "$OUT"
rm -f "$OUT"
