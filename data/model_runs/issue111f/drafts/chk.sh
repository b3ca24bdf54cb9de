#!/bin/bash
# usage (from data/model_runs/issue111f): drafts/chk.sh NN_name [fix]
# Checks drafts/NN_name.aidl, logs one line to drafts/log.txt. Until the part has a first
# valid program: a failed check is kept as drafts/NN_name.attemptK.aidl + .check.txt; the
# first check with exit 0 is kept as run/NN_name.first_valid.aidl + .check.txt and rendered.
# With "fix": checks run/NN_name.aidl (the fixed program) and renders run/NN_name.png.
set -u
n=$1; mode=${2:-}
AIDL="env PYTHONPATH=/work/wt-models-f /work/main/.venv/bin/aidl"
if [ "$mode" = fix ]; then
  f=run/$n.aidl
else
  f=drafts/$n.aidl
fi
out=$($AIDL check "$f" 2>&1); rc=$?
e=$(printf '%s\n' "$out" | grep -c 'error\[E')
w=$(printf '%s\n' "$out" | grep -c 'warning\[W')
echo "$(date -u +%FT%TZ) $n ${mode:-check} rc=$rc e=$e w=$w" >> drafts/log.txt
printf '%s\n' "$out"
if [ "$mode" = fix ]; then
  [ $rc -eq 0 ] && $AIDL render "$f" -o run/$n.png --png-width 1200
  exit $rc
fi
if [ -e run/$n.first_valid.aidl ]; then echo "(first valid already kept)"; exit $rc; fi
if [ $rc -eq 0 ]; then
  cp "$f" run/$n.first_valid.aidl
  printf '%s\n' "$out" > run/$n.first_valid.check.txt
  $AIDL render run/$n.first_valid.aidl -o run/$n.first_valid.png --png-width 1200
else
  k=1; while [ -e drafts/$n.attempt$k.aidl ]; do k=$((k+1)); done
  cp "$f" drafts/$n.attempt$k.aidl
  printf '%s\n' "$out" > drafts/$n.attempt$k.check.txt
fi
exit $rc
