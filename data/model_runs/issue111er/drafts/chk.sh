#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of error/warning lines
# to drafts/log.txt. Before the first valid check, a failed check is kept as
# drafts/NN_name.attemptK.aidl + .check.txt; the first check with exit 0 is kept as
# run/NN_name.first_valid.aidl + .check.txt and rendered to run/NN_name.first_valid.png;
# later checks are kept as drafts/NN_name.fixK.aidl + .fixK.check.txt (and rendered).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-er
AIDL=/work/main/.venv/bin/aidl
mkdir -p "$R"
T="$(date -u '+%Y-%m-%d %H:%M:%S')"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
    K=1; while [ -f "$D/$N.fix$K.aidl" ]; do K=$((K+1)); done
    KIND="fix $K"
    cp "$F" "$D/$N.fix$K.aidl"; cp "$OUT" "$D/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "$D/$N.fix$K.aidl" -o "$D/$N.fix$K.png" --png-width 1200 >"$D/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
    "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >"$R/$N.first_valid.render.txt" 2>&1
else
    K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    KIND="attempt $K"
    cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
printf '%s  %-24s %-12s exit=%s errors=%s warnings=%s\n' "$T" "$N" "$KIND" "$RC" "$NE" "$NW" >>"$D/log.txt"
cat "$OUT"
echo "--- $T $N $KIND exit=$RC errors=$NE warnings=$NW"
rm -f "$OUT"
