#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs the time, exit status and the counts of
# error/warning lines to drafts/log.txt. Keeps the FIRST program that checks
# with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, + rendered .png);
# a failing check before the first valid is kept as drafts/NN_name.attemptK.aidl
# (+ .check.txt). Checks after the first valid (fixes) are kept as
# drafts/NN_name.afterK.aidl (+ .check.txt).
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-au /work/main/.venv/bin/aidl"
mkdir -p "$R"
F="$D/$N.aidl"
T="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
OUT="$(mktemp)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  K=1; while [ -f "$D/$N.after$K.aidl" ]; do K=$((K+1)); done
  cp "$F" "$D/$N.after$K.aidl"; cp "$OUT" "$D/$N.after$K.check.txt"
  KIND="after-first-valid $K"
elif [ $RC -eq 0 ]; then
  cp "$F" "$R/$N.first_valid.aidl"; cp "$OUT" "$R/$N.first_valid.check.txt"
  $AIDL render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
  KIND="FIRST VALID"
else
  K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  cp "$F" "$D/$N.attempt$K.aidl"; cp "$OUT" "$D/$N.attempt$K.check.txt"
  KIND="attempt $K (failed)"
fi
echo "$T $N exit=$RC errors=$E warnings=$W $KIND" >> "$D/log.txt"
cat "$OUT"
echo "--- $T $N exit=$RC errors=$E warnings=$W $KIND"
rm -f "$OUT"
