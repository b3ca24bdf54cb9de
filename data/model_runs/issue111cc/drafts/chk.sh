#!/bin/bash
# chk.sh NN_name        : check drafts/NN_name.aidl, log it, keep the first valid / the failed attempts
# chk.sh NN_name begin  : log that writing part NN_name begins
set -u
D="$(cd "$(dirname "$0")" && pwd)"      # .../issue111cc/drafts
R="$(dirname "$D")/run"
mkdir -p "$R"
export PYTHONPATH=/work/wt-models-cc
AIDL=/work/main/.venv/bin/aidl
N="$1"
LOG="$D/log.txt"
if [ "${2:-}" = "begin" ]; then
  echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) BEGIN $N" >> "$LOG"; exit 0
fi
F="$D/$N.aidl"
OUT="$(mktemp)"
"$AIDL" check "$F" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  STAGE="after-first-valid"
elif [ $RC -eq 0 ]; then
  STAGE="FIRST-VALID"
  cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 > "$R/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="attempt$K"
  cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N exit=$RC errors=$NE warnings=$NW $STAGE" >> "$LOG"
cat "$OUT"; echo "--- exit=$RC errors=$NE warnings=$NW $STAGE"
rm -f "$OUT"
