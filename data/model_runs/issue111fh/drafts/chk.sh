#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log, keep the first valid program (issue111fh)
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
N="$1"
F="$HERE/$N.aidl"
export PYTHONPATH=/work/wt-models-fh
AIDL=/work/main/.venv/bin/aidl
TMP="$(mktemp)"
"$AIDL" check "$F" >"$TMP" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$TMP")
NW=$(grep -c 'warning\[W' "$TMP")
if [ -e "$RUN/$N.first_valid.aidl" ]; then
  K=1; while [ -e "$HERE/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$F" "$HERE/$N.fix$K.aidl"; cp "$TMP" "$HERE/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then "$AIDL" render "$F" -o "$HERE/$N.fix$K.png" --png-width 1200 >"$HERE/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$F" "$RUN/$N.first_valid.aidl"; cp "$TMP" "$RUN/$N.first_valid.check.txt"
  "$AIDL" render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 >"$RUN/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$F" "$HERE/$N.attempt$K.aidl"; cp "$TMP" "$HERE/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $N kind=\"$KIND\" exit=$RC errors=$NE warnings=$NW" >> "$HERE/log.txt"
cat "$TMP"
echo "--- $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$TMP"
