#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs the result to drafts/log.txt; keeps the first program that
# checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, rendered .png); a failed
# check before the first valid is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
N="$1"
F="$HERE/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-bm
mkdir -p "$RUN"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
STAMP="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
KEPT=""
if [ ! -e "$RUN/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "$RUN/$N.first_valid.aidl"
    cp "$OUT" "$RUN/$N.first_valid.check.txt"
    "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 \
      >"$RUN/$N.first_valid.render.txt" 2>&1
    KEPT="first_valid"
  else
    K=1
    while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$HERE/$N.attempt$K.aidl"
    cp "$OUT" "$HERE/$N.attempt$K.check.txt"
    KEPT="attempt$K"
  fi
else
  KEPT="after_first_valid"
fi
echo "$STAMP $N exit=$RC errors=$E warnings=$W kept=$KEPT" >> "$HERE/log.txt"
cat "$OUT"
echo "--- $STAMP $N exit=$RC errors=$E warnings=$W kept=$KEPT"
rm -f "$OUT"
