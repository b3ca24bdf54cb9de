#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
# Written anew for issue111gm.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-gm
mkdir -p "$R"
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$F" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    "$AIDL" render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1
  fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> "$D/log.txt"
cat "$OUT"
echo "--- $NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW"
rm -f "$OUT"
