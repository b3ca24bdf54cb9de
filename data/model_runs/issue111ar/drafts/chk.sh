#!/bin/bash
# chk.sh NN_name: check drafts/NN_name.aidl, log it, keep the first valid program.
# Run from anywhere; paths are relative to this script's folder.
set -u
NAME="$1"
D="$(cd "$(dirname "$0")" && pwd)"
RUN="$D/../run"
mkdir -p "$RUN"
export PYTHONPATH=/work/wt-models-ar
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$NAME.aidl"
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
CODES=$(grep -o '\(error\|warning\|note\)\[[EW][0-9]*\]' "$OUT" | sort | uniq -c | tr -s ' ' | tr '\n' ';')
STAMP=$(date -u +%FT%TZ)
if [ -e "$RUN/$NAME.first_valid.aidl" ]; then
    KIND="recheck after first valid"
elif [ "$RC" -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$RUN/$NAME.first_valid.aidl"
    cp "$OUT" "$RUN/$NAME.first_valid.check.txt"
    "$AIDL" render "$RUN/$NAME.first_valid.aidl" -o "$RUN/$NAME.first_valid.png" --png-width 1200 \
        >"$RUN/$NAME.first_valid.render.txt" 2>&1
else
    K=1
    while [ -e "$D/$NAME.attempt$K.aidl" ]; do K=$((K + 1)); done
    KIND="failed attempt $K"
    cp "$SRC" "$D/$NAME.attempt$K.aidl"
    cp "$OUT" "$D/$NAME.attempt$K.check.txt"
fi
echo "$STAMP $NAME exit=$RC errors=$NE warnings=$NW codes=[$CODES] $KIND" >>"$D/log.txt"
cat "$OUT"
echo "--- $STAMP exit=$RC errors=$NE warnings=$NW ($KIND)"
rm -f "$OUT"
