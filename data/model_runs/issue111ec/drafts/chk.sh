#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
# Run from anywhere; paths are relative to this run's folder.
set -u
RUN="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
A="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-ec
SRC="$RUN/drafts/$N.aidl"
TMP="$(mktemp)"
"$A" check "$SRC" >"$TMP" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$TMP")
NW=$(grep -c 'warning\[W' "$TMP")
if [ -e "$RUN/run/$N.first_valid.aidl" ]; then
    K=1; while [ -e "$RUN/drafts/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix$K"
    cp "$SRC" "$RUN/drafts/$N.fix$K.aidl"; cp "$TMP" "$RUN/drafts/$N.fix$K.check.txt"
elif [ "$RC" -eq 0 ]; then
    KIND="first_valid"
    cp "$SRC" "$RUN/run/$N.first_valid.aidl"; cp "$TMP" "$RUN/run/$N.first_valid.check.txt"
    "$A" render "$RUN/run/$N.first_valid.aidl" -o "$RUN/run/$N.first_valid.png" --png-width 1200 \
        >"$RUN/run/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -e "$RUN/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$SRC" "$RUN/drafts/$N.attempt$K.aidl"; cp "$TMP" "$RUN/drafts/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $N $KIND exit=$RC errors=$NE warnings=$NW" >>"$RUN/drafts/log.txt"
cat "$TMP"
echo "== $N $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$TMP"
