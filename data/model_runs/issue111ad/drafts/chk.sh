#!/bin/bash
# drafts/chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program.
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
AIDL="env PYTHONPATH=/work/wt-models-ad /work/main/.venv/bin/aidl"
F="$D/$N.aidl"
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
    STAGE="after first valid"
elif [ $RC -eq 0 ]; then
    STAGE="FIRST VALID"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >>"$R/$N.first_valid.render.txt" 2>&1
    echo "render exit $?" >>"$R/$N.first_valid.render.txt"
else
    K=1
    while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    STAGE="attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$NE warnings=$NW stage=$STAGE" >>"$D/log.txt"
cat "$OUT"
echo "== exit $RC, errors $NE, warnings $NW, $STAGE"
rm -f "$OUT"
