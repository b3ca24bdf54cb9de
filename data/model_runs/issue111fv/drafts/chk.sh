#!/bin/bash
# chk.sh NN_name: check drafts/NN_name.aidl once and log it (issue111fv).
# Before the first valid program: a failed check is kept as drafts/NN_name.attemptK.aidl
# (+ .check.txt); the first check with exit 0 is kept as run/NN_name.first_valid.aidl
# (+ .check.txt) and rendered to run/NN_name.first_valid.png (1200 px wide).
# After it: every check is kept as drafts/NN_name.fixK.aidl (+ .fixK.check.txt), rendered when it passes.
set -u
N="$1"
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
mkdir -p "$R"
export PYTHONPATH=/work/wt-models-fv
A=/work/main/.venv/bin/aidl
SRC="$D/$N.aidl"
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(cd "$D" && $A check "$SRC" 2>&1)"
RC=$?
NE=$(printf '%s\n' "$OUT" | grep -c 'error\[E')
NW=$(printf '%s\n' "$OUT" | grep -c 'warning\[W')
if [ -e "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -e "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$SRC" "$D/$N.fix$K.aidl"; printf '%s\n' "$OUT" > "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        (cd "$D" && $A render "$N.fix$K.aidl" -o "$N.fix$K.png" --png-width 1200 > "$N.fix$K.render.txt" 2>&1)
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$R/$N.first_valid.aidl"; printf '%s\n' "$OUT" > "$R/$N.first_valid.check.txt"
    (cd "$R" && $A render "$N.first_valid.aidl" -o "$N.first_valid.png" --png-width 1200 > "$N.first_valid.render.txt" 2>&1)
else
    K=1; while [ -e "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$SRC" "$D/$N.attempt$K.aidl"; printf '%s\n' "$OUT" > "$D/$N.attempt$K.check.txt"
fi
echo "$T  $N  $KIND  exit=$RC  errors=$NE  warnings=$NW" >> "$D/log.txt"
printf '%s\n' "$OUT"
echo "--- $T $N $KIND exit=$RC errors=$NE warnings=$NW"
