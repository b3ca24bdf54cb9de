#!/bin/bash
# chk.sh NN_name        check drafts/NN_name.aidl, log it, keep attempts / the first valid program
# chk.sh NN_name begin  log that work on this part begins (before its docs are read)
set -u
D=$(cd "$(dirname "$0")" && pwd)
R="$D/../run"
N="$1"
LOG="$D/log.txt"
export PYTHONPATH=/work/wt-models-cj
AIDL=/work/main/.venv/bin/aidl
if [ "${2:-}" = "begin" ]; then
  echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N BEGIN" >> "$LOG"
  exit 0
fi
F="$D/$N.aidl"
OUT=$(mktemp)
"$AIDL" check "$F" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 > "$R/$N.first_valid.render.txt" 2>&1
  echo "render exit $?" >> "$R/$N.first_valid.render.txt"
else
  K=1
  while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N exit=$RC errors=$NE warnings=$NW $KIND" >> "$LOG"
cp "$OUT" "$D/$N.last_check.txt"
cat "$OUT"
echo "== exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
