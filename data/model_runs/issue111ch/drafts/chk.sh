#!/bin/bash
# chk.sh NN_name  -- check drafts/NN_name.aidl, log it, keep attempts and the first valid program.
# chk.sh NN_name begin -- log the start of a part (before its program is written).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
RUN="$D/../run"
mkdir -p "$RUN"
N="$1"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-ch
LOG="$D/log.txt"
if [ "${2:-}" = "begin" ]; then
  echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) BEGIN $N" >> "$LOG"
  exit 0
fi
SRC="$D/$N.aidl"
OUT="$(mktemp)"
"$AIDL" check "$SRC" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
if [ -f "$RUN/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$RUN/$N.first_valid.aidl"
  cp "$OUT" "$RUN/$N.first_valid.check.txt"
  "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 > "$RUN/$N.first_valid.render.txt" 2>&1
  echo "render exit $?" >> "$RUN/$N.first_valid.render.txt"
else
  K=1
  while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $KIND" >> "$LOG"
cat "$OUT"
echo "--- $STAMP exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
