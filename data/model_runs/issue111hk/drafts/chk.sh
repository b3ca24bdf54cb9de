#!/bin/bash
# chk.sh NN_name [sheet]: check drafts/NN_name.aidl, log it, keep the first valid program.
# Logs `date -u`, exit status, counts of `error[E` and `warning[W` lines to drafts/log.txt.
# Before the first valid: a failed check is kept as drafts/NN_name.attemptK.aidl + .check.txt.
# The first check with exit 0: run/NN_name.first_valid.aidl + .check.txt + .png (1200 px);
# with "sheet" as 2nd argument also --layout sheet PNGs in drafts/.
# After the first valid: logged as after-first-valid, drafts/NN_name.fix.check.txt + fix PNG.
set -u
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
N="$1"; SHEET="${2:-}"
export PYTHONPATH=/work/wt-models-hk
AIDL=/work/main/.venv/bin/aidl
F="$D/$N.aidl"
T="$(date -u)"
OUT="$(mktemp)"
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
if [ -f "$R/$N.first_valid.aidl" ]; then
  STAGE="after-first-valid"
  cp "$OUT" "$D/$N.fix.check.txt"
  if [ $RC -eq 0 ]; then
    "$AIDL" render "$F" -o "$D/$N.fix.png" --png-width 1200 >/dev/null 2>&1
    [ -n "$SHEET" ] && "$AIDL" render "$F" -o "$D/${N}.fix_sheet.png" --layout sheet --png-width 1200 >/dev/null 2>&1
  fi
elif [ $RC -eq 0 ]; then
  STAGE="FIRST-VALID"
  cp "$F" "$R/$N.first_valid.aidl"
  cp "$OUT" "$R/$N.first_valid.check.txt"
  "$AIDL" render "$R/$N.first_valid.aidl" -o "$R/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
  [ -n "$SHEET" ] && "$AIDL" render "$R/$N.first_valid.aidl" -o "$D/${N}_sheet.png" --layout sheet --png-width 1200 >/dev/null 2>&1
else
  K=1; while [ -f "$D/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="attempt$K"
  cp "$F" "$D/$N.attempt$K.aidl"
  cp "$OUT" "$D/$N.attempt$K.check.txt"
fi
echo "$T | $N | $STAGE | exit $RC | errors $NE | warnings $NW" >>"$D/log.txt"
cat "$OUT"
echo "--- $STAGE exit $RC errors $NE warnings $NW"
rm -f "$OUT"
