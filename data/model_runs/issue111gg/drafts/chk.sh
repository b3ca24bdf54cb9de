#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs the result to drafts/log.txt, keeps the
# first program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, + .png rendered at 1200 px); a failed check before the
# first valid is kept as drafts/NN_name.attemptK.aidl (+ .check.txt); a
# check after the first valid as drafts/NN_name.fixK.aidl (+ .fixK.check.txt).
set -u
D=$(cd "$(dirname "$0")" && pwd)
R="$D/../run"
mkdir -p "$R"
N="$1"
SRC="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-gg
AIDL=/work/main/.venv/bin/aidl
NOW=$(date -u)
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
  K=1; while [ -e "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
  KIND="fix $K"
  cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
  if [ $RC -eq 0 ]; then
    "$AIDL" render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1
  fi
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt $K"
  cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $KIND | exit $RC | errors $NE | warnings $NW" >> "$D/log.txt"
echo "== $KIND: exit $RC, errors $NE, warnings $NW"
cat "$OUT"
rm -f "$OUT"
