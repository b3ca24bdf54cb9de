#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs one line to drafts/log.txt; keeps the FIRST program that
# checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, + .png by aidl render);
# a failed check before the first valid one is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
NAME="$1"
SRC="$HERE/$NAME.aidl"
export PYTHONPATH=/work/wt-models-ai
AIDL=/work/main/.venv/bin/aidl
OUT="$(mktemp)"
WHEN="$(date -u)"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
MORE=$(grep -o 'and [0-9]* more[^)]*' "$OUT" | tr '\n' ';')
CODES=$(grep -o '\(error\|warning\)\[[EW][0-9]*\]' "$OUT" | sort | uniq -c | tr -s ' ' | tr '\n' ';')
LAST=$(tail -n 1 "$OUT")
if [ -f "$RUN/$NAME.first_valid.aidl" ]; then
  KIND="recheck after first valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "$RUN/$NAME.first_valid.aidl"
  cp "$OUT" "$RUN/$NAME.first_valid.check.txt"
  $AIDL render "$RUN/$NAME.first_valid.aidl" -o "$RUN/$NAME.first_valid.png" --png-width 1200 \
      >"$RUN/$NAME.first_valid.render.txt" 2>&1
else
  K=1
  while [ -f "$HERE/$NAME.attempt$K.aidl" ]; do K=$((K + 1)); done
  KIND="failed attempt$K"
  cp "$SRC" "$HERE/$NAME.attempt$K.aidl"
  cp "$OUT" "$HERE/$NAME.attempt$K.check.txt"
fi
echo "$WHEN | $NAME | exit $RC | errors $NE | warnings $NW | more: ${MORE:-none} | codes: ${CODES:-none} | $KIND | last: $LAST" >>"$HERE/log.txt"
cat "$OUT"
echo "--- exit $RC ($KIND)"
rm -f "$OUT"
