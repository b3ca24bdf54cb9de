#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program (issue111ag)
set -u
D="$(cd "$(dirname "$0")" && pwd)"      # drafts/
R="$D/../run"
mkdir -p "$R"
N="$1"
F="$D/$N.aidl"
AIDL="env PYTHONPATH=/work/wt-models-ag /work/main/.venv/bin/aidl"
T="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
# the check prints at most 10 of one code and then "aidl: and N more of Wxxxx"
MORE=$(grep -oE 'and [0-9]+ more of W[0-9]+' "$OUT" | awk '{s+=$2} END {print s+0}')
NW=$((NW + MORE))
if [ -e "$R/$N.first_valid.aidl" ]; then
    STAGE="after first valid"
elif [ $RC -eq 0 ]; then
    STAGE="FIRST VALID"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 \
        >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    STAGE="failed (attempt$K)"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T $N exit=$RC errors=$NE warnings=$NW $STAGE" >>"$D/log.txt"
cat "$OUT"
echo "== $T $N exit=$RC errors=$NE warnings=$NW $STAGE"
rm -f "$OUT"
