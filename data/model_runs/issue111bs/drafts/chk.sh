#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# and each failed check before it as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
N="$1"
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-bs
SRC="$HERE/$N.aidl"
OUT="$(mktemp)"
"$AIDL" check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP="$(date -u)"
if [ -f "$RUN/$N.first_valid.aidl" ]; then
  PHASE="after first valid"
elif [ $RC -eq 0 ]; then
  PHASE="FIRST VALID"
  cp "$SRC" "$RUN/$N.first_valid.aidl"
  cp "$OUT" "$RUN/$N.first_valid.check.txt"
  "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 > "$RUN/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -f "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  PHASE="attempt$K failed"
  cp "$SRC" "$HERE/$N.attempt$K.aidl"
  cp "$OUT" "$HERE/$N.attempt$K.check.txt"
fi
echo "$STAMP | $N | exit $RC | errors $NE | warnings $NW | $PHASE" >> "$HERE/log.txt"
cat "$OUT"
echo "--- $STAMP | $N | exit $RC | errors $NE | warnings $NW | $PHASE"
rm -f "$OUT"
