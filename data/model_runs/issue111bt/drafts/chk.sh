#!/bin/bash
# usage: drafts/chk.sh NN_name   (written anew for run issue111bt)
# Checks drafts/NN_name.aidl, logs date, exit status and the counts of error/warning lines to
# drafts/log.txt. The FIRST program that checks with exit 0 is kept as run/NN_name.first_valid.aidl
# (+ .check.txt) and rendered to run/NN_name.first_valid.png; a failed check before it is kept as
# drafts/NN_name.attemptK.aidl (+ .check.txt). Checks after the first valid are logged as "after".
set -u
D=$(cd "$(dirname "$0")" && pwd)
R=$D/../run
N=$1
F=$D/$N.aidl
export PYTHONPATH=/work/wt-models-bt
A=/work/main/.venv/bin/aidl
T=$(date -u +%Y-%m-%dT%H:%M:%SZ)
OUT=$(cd "$D" && $A check "$N.aidl" 2>&1)
RC=$?
E=$(grep -c 'error\[E' <<<"$OUT")
W=$(grep -c 'warning\[W' <<<"$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
    STAGE=after_first_valid
    echo "$OUT" > "$D/$N.latest.check.txt"
elif [ $RC -eq 0 ]; then
    STAGE=first_valid
    cp "$F" "$R/$N.first_valid.aidl"
    echo "$OUT" > "$R/$N.first_valid.check.txt"
    (cd "$R" && $A render "$N.first_valid.aidl" -o "$N.first_valid.png" --png-width 1200 > "$N.first_valid.render.txt" 2>&1)
else
    K=1
    while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K + 1)); done
    STAGE=attempt$K
    cp "$F" "$D/$N.attempt$K.aidl"
    echo "$OUT" > "$D/$N.attempt$K.check.txt"
fi
echo "$T $N exit=$RC errors=$E warnings=$W $STAGE" >> "$D/log.txt"
echo "$OUT"
echo "--- $STAGE (exit $RC, $E errors, $W warnings)"
