#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program
# (run/NN_name.first_valid.*) or a failed attempt before it (drafts/NN_name.attemptK.*).
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(dirname "$HERE")"
WT=/work/wt-models-ct
AIDL="env PYTHONPATH=$WT /work/main/.venv/bin/aidl"
N="$1"
SRC="$HERE/$N.aidl"
OUT="$(mktemp)"
WHEN="$(date -u)"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
# a long list of warnings ends "aidl: and N more of WXXXX": count those too
MORE=$(grep -oE 'and [0-9]+ more of W' "$OUT" | grep -oE '[0-9]+' | paste -sd+ | bc 2>/dev/null)
[ -n "$MORE" ] && NW=$((NW + MORE))
FV="$ROOT/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$FV"
  cp "$OUT" "$ROOT/run/$N.first_valid.check.txt"
  $AIDL render "$FV" -o "$ROOT/run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >>"$ROOT/run/$N.first_valid.check.txt"
else
  K=1
  while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$HERE/$N.attempt$K.aidl"
  cp "$OUT" "$HERE/$N.attempt$K.check.txt"
fi
echo "$WHEN | $N | $KIND | exit $RC | errors $NE | warnings $NW" >>"$HERE/log.txt"
cat "$OUT"
echo "--- $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
