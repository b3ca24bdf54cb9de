#!/bin/bash
# usage: drafts/chk.sh NN_name   -- checks drafts/NN_name.aidl, logs, keeps attempts / first valid
set -u
D="$(cd "$(dirname "$0")" && pwd)"; R="$D/../run"; mkdir -p "$R"
N="$1"; F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-ck
A=/work/main/.venv/bin/aidl
T="$(date -u)"
OUT="$($A check "$F" 2>&1)"; RC=$?
NE=$(printf '%s\n' "$OUT" | grep -c 'error\[E')
NW=$(printf '%s\n' "$OUT" | grep -c 'warning\[W')
if [ -f "$R/$N.first_valid.aidl" ]; then STAGE="after-first-valid"
else
  if [ $RC -eq 0 ]; then
    STAGE="FIRST-VALID"
    cp "$F" "$R/$N.first_valid.aidl"; printf '%s\n' "$OUT" > "$R/$N.first_valid.check.txt"
    $A render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >&2
  else
    K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"; printf '%s\n' "$OUT" > "$D/$N.attempt$K.check.txt"
  fi
fi
if [ "$STAGE" = "after-first-valid" ] && [ $RC -eq 0 ]; then
  $A render "$F" -o "$D/$N.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >&2
fi
echo "$T  $N  $STAGE  exit=$RC  errors=$NE  warnings=$NW" >> "$D/log.txt"
printf '%s\n' "$OUT"
echo "== $STAGE exit=$RC errors=$NE warnings=$NW"
