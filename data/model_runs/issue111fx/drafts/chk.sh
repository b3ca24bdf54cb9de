#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
# Run from anywhere; paths are relative to this run's folder.
set -u
RUN="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
export PYTHONPATH=/work/wt-models-fx
AIDL=/work/main/.venv/bin/aidl
SRC="$RUN/drafts/$N.aidl"
LOG="$RUN/drafts/log.txt"
FV="$RUN/run/$N.first_valid.aidl"
TMP="$(mktemp)"
WHEN="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$SRC" > "$TMP" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$TMP")
NW=$(grep -c 'warning\[W' "$TMP")
if [ ! -f "$FV" ]; then
  if [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$FV"; cp "$TMP" "$RUN/run/$N.first_valid.check.txt"
    "$AIDL" render "$FV" -o "$RUN/run/$N.first_valid.png" --png-width 1200 > "$RUN/run/$N.first_valid.render.txt" 2>&1
  else
    K=1; while [ -f "$RUN/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "$RUN/drafts/$N.attempt$K.aidl"; cp "$TMP" "$RUN/drafts/$N.attempt$K.check.txt"
  fi
else
  K=1; while [ -f "$RUN/drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "$RUN/drafts/$N.fix$K.aidl"; cp "$TMP" "$RUN/drafts/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    "$AIDL" render "$SRC" -o "$RUN/drafts/$N.fix$K.png" --png-width 1200 > "$RUN/drafts/$N.fix$K.render.txt" 2>&1
  fi
fi
printf '%s UTC | %-22s | %-11s | exit %d | error[E %d | warning[W %d\n' "$WHEN" "$N" "$KIND" "$RC" "$NE" "$NW" >> "$LOG"
cat "$TMP"
echo "--- logged: $KIND exit $RC, $NE errors, $NW warnings"
rm -f "$TMP"
