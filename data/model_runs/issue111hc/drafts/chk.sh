#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl with `aidl check`; logs date -u, exit status and the
# counts of `error[E` / `warning[W` lines to drafts/log.txt. Keeps the FIRST program
# that checks with exit 0 as run/NN_name.first_valid.aidl + .check.txt and renders
# run/NN_name.first_valid.png. A failed check before the first valid one is kept as
# drafts/NN_name.attemptK.aidl + .check.txt. Later checks are logged as after-first-valid.
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
RUN="$HERE/../run"
NAME="$1"
SRC="$HERE/$NAME.aidl"
export PYTHONPATH=/work/wt-models-hc
AIDL=/work/main/.venv/bin/aidl
mkdir -p "$RUN"
NOW="$(date -u '+%Y-%m-%dT%H:%M:%SZ')"
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$RUN/$NAME.first_valid.aidl" ]; then
    PHASE="after-first-valid"
elif [ $RC -eq 0 ]; then
    PHASE="first-valid"
    cp "$SRC" "$RUN/$NAME.first_valid.aidl"
    cp "$OUT" "$RUN/$NAME.first_valid.check.txt"
    "$AIDL" render "$RUN/$NAME.first_valid.aidl" -o "$RUN/$NAME.first_valid.png" --png-width 1200 >/dev/null 2>"$OUT.render" \
        || { echo "render failed:"; cat "$OUT.render"; }
else
    K=1
    while [ -e "$HERE/$NAME.attempt$K.aidl" ]; do K=$((K+1)); done
    PHASE="attempt$K"
    cp "$SRC" "$HERE/$NAME.attempt$K.aidl"
    cp "$OUT" "$HERE/$NAME.attempt$K.check.txt"
fi
echo "$NOW $NAME exit=$RC errors=$NE warnings=$NW $PHASE" >> "$HERE/log.txt"
cat "$OUT"
echo "--- $NOW $NAME exit=$RC errors=$NE warnings=$NW $PHASE"
rm -f "$OUT" "$OUT.render"
exit $RC
