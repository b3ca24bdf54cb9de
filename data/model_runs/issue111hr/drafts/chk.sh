#!/bin/bash
# chk.sh NN_name [sheet]: check drafts/NN_name.aidl, log it, keep attempts and the first valid program.
# Written anew for run issue111hr.
#   - logs `date -u`, the stage, the exit status and the counts of `error[E` and `warning[W`
#     lines to drafts/log.txt (note[...] lines are not counted);
#   - before the first valid program: a failed check is kept as drafts/NN_name.attemptK.aidl
#     + .check.txt; the first check with exit 0 is kept as run/NN_name.first_valid.aidl +
#     .check.txt and rendered to run/NN_name.first_valid.png (--png-width 1200);
#   - after the first valid program: the check is logged as after-first-valid, its messages
#     go to drafts/NN_name.fix.check.txt and it is rendered to drafts/NN_name.fix.png;
#   - with a second argument `sheet` (an assembly) the PNG is also rendered --layout sheet
#     (drafts/NN_name_sheet.png, or drafts/NN_name_fix_sheet.png after the first valid).
set -u
N="$1"; SHEET="${2:-}"
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
mkdir -p "$R"
export PYTHONPATH=/work/wt-models-hr
A="/work/main/.venv/bin/aidl"
SRC="$D/$N.aidl"
OUT="$(mktemp)"
"$A" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
NOW="$(date -u)"
if [ -f "$R/$N.first_valid.aidl" ]; then
    STAGE="after-first-valid"
    cp "$OUT" "$D/$N.fix.check.txt"
    if [ $RC -eq 0 ]; then
        "$A" render "$SRC" -o "$D/$N.fix.png" --png-width 1200 >/dev/null 2>&1
        [ "$SHEET" = sheet ] && "$A" render "$SRC" -o "$D/${N}_fix_sheet.png" --png-width 1200 --layout sheet >/dev/null 2>&1
    fi
elif [ $RC -eq 0 ]; then
    STAGE="first-valid"
    cp "$SRC" "$R/$N.first_valid.aidl"
    cp "$OUT" "$R/$N.first_valid.check.txt"
    "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    [ "$SHEET" = sheet ] && "$A" render "$R/$N.first_valid.aidl" -o "$D/${N}_sheet.png" --png-width 1200 --layout sheet >/dev/null 2>&1
else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    STAGE="attempt$K"
    cp "$SRC" "$D/$N.attempt$K.aidl"
    cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$NOW | $N | $STAGE | exit $RC | errors $NE | warnings $NW" >>"$D/log.txt"
echo "== $STAGE exit $RC errors $NE warnings $NW"
cat "$OUT"
rm -f "$OUT"
