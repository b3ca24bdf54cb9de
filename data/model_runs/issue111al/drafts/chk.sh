#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl with this tree's aidl, logs one line to drafts/log.txt.
# First check with exit 0 -> run/NN_name.first_valid.aidl (+ .check.txt, .png, .render.txt).
# A failing check before that -> drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
WT=/work/wt-models-al
AIDL="env PYTHONPATH=$WT /work/main/.venv/bin/aidl"
N="$1"
SRC="$HERE/drafts/$N.aidl"
OUT="$(mktemp)"
cd "$HERE/drafts"
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
MORE=$(grep -o 'and [0-9]* more of [^ ]*' "$OUT" | tr '\n' ';')
CODES=$(grep -o '\(error\|warning\)\[[EW][0-9]*\]' "$OUT" | sort | uniq -c | awk '{printf "%s x%s ", $2, $1}')
FV="$HERE/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
  KIND="recheck-after-first-valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "$FV"; cp "$OUT" "$HERE/run/$N.first_valid.check.txt"
  $AIDL render "$FV" -o "$HERE/run/$N.first_valid.png" --png-width 1200 >"$HERE/run/$N.first_valid.render.txt" 2>&1
else
  K=1; while [ -e "$HERE/drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "$HERE/drafts/$N.attempt$K.aidl"; cp "$OUT" "$HERE/drafts/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$E warnings=$W more=[$MORE] codes=[$CODES] $KIND" >> "$HERE/drafts/log.txt"
cat "$OUT"
echo "--- exit=$RC errors=$E warnings=$W $KIND"
rm -f "$OUT"
