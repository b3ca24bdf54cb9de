#!/bin/bash
# usage (from data/model_runs/issue111ab): drafts/chk.sh NN_name
# Checks drafts/NN_name.aidl, logs the check, keeps the first valid program (and any failed
# attempt before it), renders the first valid program.
set -u
N="$1"
HERE="$(cd "$(dirname "$0")/.." && pwd)"
D="$HERE/drafts"; R="$HERE/run"
export PYTHONPATH=/work/wt-models-ab
AIDL=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -e "$R/$N.first_valid.aidl" ]; then
    KIND="after-first-valid"
elif [ $RC -eq 0 ]; then
    KIND="first-valid"
    cp "$SRC" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 \
        || echo "render failed" >&2
else
    K=1
    while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    KIND="attempt$K"
    cp "$SRC" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$NE warnings=$NW $KIND" >>"$D/log.txt"
cat "$OUT"
echo "--- exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
