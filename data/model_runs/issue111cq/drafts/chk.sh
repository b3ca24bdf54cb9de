#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts and the first valid program.
# Run from anywhere; paths are relative to this run's folder.
set -u
RUN="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
export PYTHONPATH=/work/wt-models-cq
AIDL=/work/main/.venv/bin/aidl
SRC="$RUN/drafts/$N.aidl"
OUT="$(mktemp)"
(cd "$RUN/drafts" && $AIDL check "$N.aidl") >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$RUN/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then STAGE="after-first-valid"; else STAGE="before-first-valid"; fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$NE warnings=$NW ($STAGE)" >> "$RUN/drafts/log.txt"
cat "$OUT"
if [ ! -e "$FV" ]; then
  if [ $RC -eq 0 ]; then
    cp "$SRC" "$FV"; cp "$OUT" "$RUN/run/$N.first_valid.check.txt"
    (cd "$RUN/run" && $AIDL render "$N.first_valid.aidl" -o "$N.first_valid.png" --png-width 1200) && echo "FIRST VALID kept and rendered"
  else
    K=1; while [ -e "$RUN/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$SRC" "$RUN/drafts/$N.attempt$K.aidl"; cp "$OUT" "$RUN/drafts/$N.attempt$K.check.txt"
    echo "FAILED: kept as attempt$K"
  fi
else
  cp "$OUT" "$RUN/drafts/$N.latest.check.txt"
fi
echo "exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
exit $RC
