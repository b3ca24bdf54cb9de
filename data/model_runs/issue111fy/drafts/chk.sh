#!/bin/bash
# Check one part of run issue111fy and log it.
# usage: drafts/chk.sh NN_name
#  - logs `date -u`, the kind of check, exit status, counts of `error[E` / `warning[W` lines to log.txt
#  - before the first valid: a failed check is kept as NN_name.attemptK.aidl + .attemptK.check.txt
#  - the first check with exit 0 is kept as ../run/NN_name.first_valid.aidl + .check.txt and
#    rendered to ../run/NN_name.first_valid.png (--png-width 1200; messages in .render.txt)
#  - after the first valid: every check is kept as NN_name.fixK.aidl + .fixK.check.txt (rendered when it passes)
set -u
cd "$(dirname "$0")"
N=$1
export PYTHONPATH=/work/wt-models-fy
A=/work/main/.venv/bin/aidl
RUN=../run
F=$N.aidl
TS=$(date -u +"%Y-%m-%d %H:%M:%S UTC")
OUT=$(mktemp)
$A check "$F" > "$OUT" 2>&1; RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -f "$RUN/$N.first_valid.aidl" ]; then
    k=1; while [ -f "$N.fix$k.aidl" ]; do k=$((k+1)); done
    KIND="fix$k"
    cp "$F" "$N.fix$k.aidl"; cp "$OUT" "$N.fix$k.check.txt"
    if [ $RC -eq 0 ]; then
        $A render "$N.fix$k.aidl" -o "$N.fix$k.png" --png-width 1200 > "$N.fix$k.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST_VALID"
    cp "$F" "$RUN/$N.first_valid.aidl"; cp "$OUT" "$RUN/$N.first_valid.check.txt"
    $A render "$RUN/$N.first_valid.aidl" -o "$RUN/$N.first_valid.png" --png-width 1200 > "$RUN/$N.first_valid.render.txt" 2>&1
else
    k=1; while [ -f "$N.attempt$k.aidl" ]; do k=$((k+1)); done
    KIND="attempt$k"
    cp "$F" "$N.attempt$k.aidl"; cp "$OUT" "$N.attempt$k.check.txt"
fi
echo "$TS $N $KIND exit=$RC errors=$E warnings=$W" >> log.txt
cat "$OUT"
rm -f "$OUT"
echo "== $N $KIND exit=$RC errors=$E warnings=$W"
