#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program (issue111bq)
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
N="$1"
F="$HERE/$N.aidl"
export PYTHONPATH=/work/wt-models-bq
AIDL=/work/main/.venv/bin/aidl
TS="$(date -u)"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
echo "$TS | $N | exit $RC | errors $NE | warnings $NW" >>"$HERE/log.txt"
cat "$OUT"
echo "--- exit $RC, errors $NE, warnings $NW"
if [ ! -e "$RUN/$N.first_valid.aidl" ]; then
  if [ "$RC" -eq 0 ]; then
    cp "$F" "$RUN/$N.first_valid.aidl"
    cp "$OUT" "$RUN/$N.first_valid.check.txt"
    "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 >"$RUN/$N.first_valid.render.txt" 2>&1
    echo "first valid kept; render exit $?"
    echo "$TS | $N | first valid kept" >>"$HERE/log.txt"
  else
    K=1
    while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$HERE/$N.attempt$K.aidl"
    cp "$OUT" "$HERE/$N.attempt$K.check.txt"
    echo "kept as attempt$K"
  fi
fi
rm -f "$OUT"
exit $RC
