#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
# Usage from anywhere: drafts/chk.sh NN_name
set -u
NAME="$1"
HERE="$(cd "$(dirname "$0")" && pwd)"      # .../issue111eb/drafts
RUN="$HERE/../run"
export PYTHONPATH=/work/wt-models-eb
AIDL=/work/main/.venv/bin/aidl
SRC="$HERE/$NAME.aidl"
mkdir -p "$RUN"
OUT="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$RUN/$NAME.first_valid.aidl"
if [ -f "$FV" ]; then
    K=1; while [ -f "$HERE/$NAME.fix$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "$HERE/$NAME.fix$K.aidl"; cp "$OUT" "$HERE/$NAME.fix$K.check.txt"
    KIND="fix$K (after the first valid)"
elif [ $RC -eq 0 ]; then
    cp "$SRC" "$FV"; cp "$OUT" "$RUN/$NAME.first_valid.check.txt"
    "$AIDL" render "$FV" -o "$RUN/$NAME.first_valid.png" --png-width 1200 >"$RUN/$NAME.first_valid.render.txt" 2>&1
    KIND="FIRST VALID (render exit $?)"
else
    K=1; while [ -f "$HERE/$NAME.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "$HERE/$NAME.attempt$K.aidl"; cp "$OUT" "$HERE/$NAME.attempt$K.check.txt"
    KIND="attempt$K (failed)"
fi
echo "$NOW  $NAME  exit=$RC  errors=$NE  warnings=$NW  $KIND" | tee -a "$HERE/log.txt"
cat "$OUT"
rm -f "$OUT"
