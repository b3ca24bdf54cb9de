#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs the result, keeps attempts / the first valid / fixes.
set -u
D=$(cd "$(dirname "$0")" && pwd)
R=$(cd "$D/.." && pwd)/run
N=$1
export PYTHONPATH=/work/wt-models-go
AIDL=/work/main/.venv/bin/aidl
F=$D/$N.aidl
T=$(date -u '+%Y-%m-%d %H:%M:%S')
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
    K=$(ls "$D/$N".fix*.aidl 2>/dev/null | wc -l); K=$((K + 1))
    KIND="fix $K"
    cp "$F" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        $AIDL render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=$(ls "$D/$N".attempt*.aidl 2>/dev/null | grep -vc check); K=$((K + 1))
    KIND="attempt $K"
    cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >> "$D/log.txt"
echo "== $T $N $KIND exit=$RC errors=$NE warnings=$NW"
cat "$OUT"
rm -f "$OUT"
