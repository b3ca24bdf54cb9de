#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
export PYTHONPATH=/work/wt-models-gv
A=/work/main/.venv/bin/aidl
mkdir -p "$R"
SRC="$D/$N.aidl"
OUT="$(mktemp)"
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then "$A" render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1; fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
    "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$E  warnings=$W" >>"$D/log.txt"
echo "$T  $N  $KIND  exit=$RC  errors=$E  warnings=$W"
cat "$OUT"
rm -f "$OUT"
