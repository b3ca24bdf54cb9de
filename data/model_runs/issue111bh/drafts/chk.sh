#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program (issue111bh)
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
N="$1"
export PYTHONPATH=/work/wt-models-bh
AIDL=/work/main/.venv/bin/aidl
F="$HERE/$N.aidl"
OUT="$(mktemp)"
STAMP="$(date -u)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$RUN/$N.first_valid.aidl" ]; then PHASE="after-first-valid"; else PHASE="before-first-valid"; fi
echo "$STAMP | $N | exit $RC | errors $NE | warnings $NW | $PHASE" >> "$HERE/log.txt"
if [ "$PHASE" = "before-first-valid" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "$RUN/$N.first_valid.aidl"
    cp "$OUT" "$RUN/$N.first_valid.check.txt"
    "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 > "$RUN/$N.first_valid.render.txt" 2>&1
    echo "FIRST VALID kept: run/$N.first_valid.aidl"
  else
    K=1
    while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$HERE/$N.attempt$K.aidl"
    cp "$OUT" "$HERE/$N.attempt$K.check.txt"
    echo "failed: kept as drafts/$N.attempt$K.aidl"
  fi
fi
cat "$OUT"
rm -f "$OUT"
exit $RC
