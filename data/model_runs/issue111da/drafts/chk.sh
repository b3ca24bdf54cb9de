#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# failed checks before it as drafts/NN_name.attemptK.aidl + .check.txt.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
AIDL="env PYTHONPATH=/work/wt-models-da /work/main/.venv/bin/aidl"
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
CODES=$(grep -oE '(error\[E[0-9]+|warning\[W[0-9]+)' "$OUT" | sed 's/.*\[//' | sort | uniq -c | awk '{printf "%s%sx%s", (NR>1?",":""), $2, $1}')
STAMP="$(date -u '+%Y-%m-%d %H:%M:%S')"
if [ -e "$R/$N.first_valid.aidl" ]; then
    KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
    KIND="FIRST-VALID"
    cp "$F" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1
    while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt$K"
    cp "$F" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$STAMP $N $KIND exit=$RC errors=$NE warnings=$NW codes=[$CODES]" >> "$D/log.txt"
cat "$OUT"
echo "--- logged: $STAMP $N $KIND exit=$RC errors=$NE warnings=$NW codes=[$CODES]"
rm -f "$OUT"
