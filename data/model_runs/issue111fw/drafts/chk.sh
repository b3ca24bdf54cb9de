#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
set -u
N="$1"
HERE="$(cd "$(dirname "$0")" && pwd)"          # .../issue111fw/drafts
RUN="$HERE/../run"
mkdir -p "$RUN"
export PYTHONPATH=/work/wt-models-fw
A=/work/main/.venv/bin/aidl
SRC="$HERE/$N.aidl"
OUT="$(mktemp)"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
ERR=$(grep -c 'error\[E' "$OUT")
WARN=$(grep -c 'warning\[W' "$OUT")
if [ ! -f "$RUN/$N.first_valid.aidl" ]; then
    if [ "$RC" -eq 0 ]; then
        KIND="FIRST VALID"
        cp "$SRC" "$RUN/$N.first_valid.aidl"
        cp "$OUT" "$RUN/$N.first_valid.check.txt"
        "$A" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 \
            >"$RUN/$N.first_valid.render.txt" 2>&1
    else
        K=1
        while [ -f "$HERE/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
        KIND="attempt $K"
        cp "$SRC" "$HERE/$N.attempt$K.aidl"
        cp "$OUT" "$HERE/$N.attempt$K.check.txt"
    fi
else
    K=1
    while [ -f "$HERE/$N.fix$K.aidl" ]; do K=$((K + 1)); done
    KIND="fix $K"
    cp "$SRC" "$HERE/$N.fix$K.aidl"
    cp "$OUT" "$HERE/$N.fix$K.check.txt"
    if [ "$RC" -eq 0 ]; then
        "$A" render "$SRC" -o "$RUN/$N.fix$K.png" --png-width 1200 >"$HERE/$N.fix$K.render.txt" 2>&1
    fi
fi
echo "$NOW | $N | $KIND | exit $RC | errors $ERR | warnings $WARN" >>"$HERE/log.txt"
echo "== $NOW | $N | $KIND | exit $RC | errors $ERR | warnings $WARN"
cat "$OUT"
rm -f "$OUT"
