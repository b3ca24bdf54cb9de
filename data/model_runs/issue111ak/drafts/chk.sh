#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs one line to drafts/log.txt, keeps the first
# program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt,
# rendered to .png), and each failed check before it as drafts/NN_name.attemptK.aidl.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-ak /work/main/.venv/bin/aidl"
F="$D/$N.aidl"
OUT="$(mktemp)"
WHEN="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
MORE=$(grep -o 'and [0-9]* more of [A-Z][0-9]*' "$OUT" | tr '\n' ';')
CODES=$(grep -o -E '(error|warning)\[[EW][0-9]+\]' "$OUT" | sort | uniq -c | awk '{printf "%s%s ", $2, ($1>1?"x"$1:"")}')
if [ -f "$R/$N.first_valid.aidl" ]; then
    KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
    KIND="FIRST-VALID"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$WHEN $N exit=$RC errors=$NE warnings=$NW more=[$MORE] codes=[$CODES] $KIND" >>"$D/log.txt"
cat "$OUT"
echo "--- exit=$RC $KIND"
rm -f "$OUT"
