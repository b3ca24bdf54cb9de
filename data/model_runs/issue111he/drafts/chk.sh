#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from anywhere)
# Checks drafts/NN_name.aidl, logs to drafts/log.txt. Keeps the FIRST program that checks
# with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png); each failed check before it
# as drafts/NN_name.attemptK.aidl (+ .check.txt). Checks after the first valid are logged as
# after-first-valid.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$(dirname "$D")/run"
mkdir -p "$R"
N="$1"
F="$D/$N.aidl"
export PYTHONPATH=/work/wt-models-he
A=/work/main/.venv/bin/aidl
T="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
OUT="$(mktemp)"
"$A" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  STAGE=after-first-valid
elif [ $RC -eq 0 ]; then
  STAGE=first-valid
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  "$A" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >>"$R/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE=attempt$K
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T $N exit=$RC errors=$NE warnings=$NW $STAGE" >>"$D/log.txt"
cat "$OUT"
echo "== $T $N exit=$RC errors=$NE warnings=$NW $STAGE"
rm -f "$OUT"
