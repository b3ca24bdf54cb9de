#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"        # drafts/
RUN="$HERE/../run"
N="$1"
export PYTHONPATH=/work/wt-models-ef
AIDL=/work/main/.venv/bin/aidl
SRC="$HERE/$N.aidl"
OUT="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
mkdir -p "$RUN"
if [ -e "$RUN/$N.first_valid.aidl" ]; then
    K=1; while [ -e "$HERE/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix$K"
    cp "$SRC" "$HERE/$N.fix$K.aidl"; cp "$OUT" "$HERE/$N.fix$K.check.txt"
elif [ "$RC" -eq 0 ]; then
    KIND="first_valid"
    cp "$SRC" "$RUN/$N.first_valid.aidl"; cp "$OUT" "$RUN/$N.first_valid.check.txt"
    "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 \
        >"$RUN/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$SRC" "$HERE/$N.attempt$K.aidl"; cp "$OUT" "$HERE/$N.attempt$K.check.txt"
fi
echo "$NOW  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >>"$HERE/log.txt"
cat "$OUT"
echo "--- $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
