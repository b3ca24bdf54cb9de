#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program (issue111dt)
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
N="$1"
F="$HERE/$N.aidl"
AIDL="env PYTHONPATH=/work/wt-models-dt /work/main/.venv/bin/aidl"
TS="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -f "$RUN/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$HERE/$N.fix$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$HERE/$N.fix$K.aidl"; cp "$OUT" "$HERE/$N.fix$K.check.txt"
    KIND="fix$K (after first valid)"
    $AIDL render "$F" -o "$HERE/$N.fix$K.png" --png-width 1200 >"$HERE/$N.fix$K.render.txt" 2>&1
elif [ "$RC" -eq 0 ]; then
    cp "$F" "$RUN/$N.first_valid.aidl"; cp "$OUT" "$RUN/$N.first_valid.check.txt"
    KIND="FIRST VALID"
    $AIDL render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 >"$RUN/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$HERE/$N.attempt$K.aidl"; cp "$OUT" "$HERE/$N.attempt$K.check.txt"
    KIND="attempt$K failed"
fi
echo "$TS UTC  $N  exit=$RC  errors=$E  warnings=$W  $KIND" >> "$HERE/log.txt"
cat "$OUT"
echo "--- $TS exit=$RC errors=$E warnings=$W $KIND"
rm -f "$OUT"
