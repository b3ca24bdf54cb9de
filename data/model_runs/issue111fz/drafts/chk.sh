#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
N="$1"
SRC="$HERE/$N.aidl"
export PYTHONPATH=/work/wt-models-fz
AIDL=/work/main/.venv/bin/aidl
LOG="$HERE/log.txt"
OUT="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$RUN/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$HERE/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix$K"
    cp "$SRC" "$HERE/$N.fix$K.aidl"; cp "$OUT" "$HERE/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "$HERE/$N.fix$K.aidl" -o "$HERE/$N.fix$K.png" --png-width 1200 > "$HERE/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$RUN/$N.first_valid.aidl"; cp "$OUT" "$RUN/$N.first_valid.check.txt"
    "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 > "$RUN/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$SRC" "$HERE/$N.attempt$K.aidl"; cp "$OUT" "$HERE/$N.attempt$K.check.txt"
fi
echo "$NOW  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >> "$LOG"
echo "== $NOW $N $KIND exit=$RC errors=$NE warnings=$NW"
cat "$OUT"
rm -f "$OUT"
