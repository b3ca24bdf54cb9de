#!/bin/bash
# usage (from the run folder issue111d/): drafts/chk.sh NN_name [fix]
# checks drafts/NN_name.aidl (or run/NN_name.aidl with "fix"), logs one line per check,
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png),
# and each failed attempt before it as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
export PYTHONPATH=/work/wt-models-d
A=/work/main/.venv/bin/aidl
n=$1; mode=${2:-draft}
cd "$(dirname "$0")/.."
if [ "$mode" = fix ]; then f=run/$n.aidl; else f=drafts/$n.aidl; fi
out=$($A check "$f" 2>&1); rc=$?
echo "$out"
echo "rc=$rc"
echo "$(date -u +%FT%TZ) $n $mode rc=$rc e=$(echo "$out" | grep -c "error\[") w=$(echo "$out" | grep -c "warning\[")" >> drafts/log.txt
if [ "$mode" = fix ]; then
  $A render "$f" -o run/$n.png --png-width 1200 && echo "rendered run/$n.png"
  exit $rc
fi
if [ -e run/$n.first_valid.aidl ]; then echo "(first valid already kept)"; exit $rc; fi
if [ $rc -eq 0 ]; then
  cp "$f" run/$n.first_valid.aidl; echo "$out" > run/$n.first_valid.check.txt
  $A render run/$n.first_valid.aidl -o run/$n.first_valid.png --png-width 1200 && echo "rendered run/$n.first_valid.png"
else
  k=1; while [ -e drafts/$n.attempt$k.aidl ]; do k=$((k+1)); done
  cp "$f" drafts/$n.attempt$k.aidl; echo "$out" > drafts/$n.attempt$k.check.txt
fi
exit $rc
