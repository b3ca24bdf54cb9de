#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl once and log it (issue111gi).
# Before the first valid check: a failure is kept as drafts/NN_name.attemptK.aidl + .check.txt;
# the first exit-0 check is kept as run/NN_name.first_valid.aidl + .check.txt and rendered
# to run/NN_name.first_valid.png (render messages in .render.txt).
# After it: each check is kept as drafts/NN_name.fixK.aidl + .fixK.check.txt (rendered if it passes).
set -u
N="$1"
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
SRC="$HERE/$N.aidl"
LOG="$HERE/log.txt"
export PYTHONPATH=/work/wt-models-gi
AIDL=/work/main/.venv/bin/aidl
mkdir -p "$RUN"
TMP="$(mktemp)"
(cd "$HERE" && "$AIDL" check "$N.aidl") > "$TMP" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$TMP")
NW=$(grep -c 'warning\[W' "$TMP")
NOW="$(date -u '+%Y-%m-%d %H:%M:%S')"
if [ -f "$RUN/$N.first_valid.aidl" ]; then
  K=1; while [ -f "$HERE/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "$HERE/$N.fix$K.aidl"; cp "$TMP" "$HERE/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    (cd "$HERE" && "$AIDL" render "$N.fix$K.aidl" -o "$N.fix$K.png" --png-width 1200) > "$HERE/$N.fix$K.render.txt" 2>&1
  fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "$RUN/$N.first_valid.aidl"; cp "$TMP" "$RUN/$N.first_valid.check.txt"
  (cd "$RUN" && "$AIDL" render "$N.first_valid.aidl" -o "$N.first_valid.png" --png-width 1200) > "$RUN/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -f "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$SRC" "$HERE/$N.attempt$K.aidl"; cp "$TMP" "$HERE/$N.attempt$K.check.txt"
fi
printf '%s  %-22s %-12s exit=%s  error[E=%s  warning[W=%s\n' "$NOW" "$N" "$KIND" "$RC" "$NE" "$NW" >> "$LOG"
tail -1 "$LOG"
cat "$TMP"
rm -f "$TMP"
