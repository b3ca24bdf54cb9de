#!/bin/bash
# usage: drafts/chk.sh NN_name  (run from data/model_runs/issue111c)
# checks drafts/NN_name.aidl; logs; keeps the FIRST program that checks with exit 0
# as run/NN_name.first_valid.aidl (+ .check.txt, .png); failed checks before it as attemptK.
export PYTHONPATH=/work/wt-modelsc
A=/work/main/.venv/bin/aidl
n=$1; f=drafts/$n.aidl
out=$($A check "$f" 2>&1); rc=$?
echo "$(date -u +%H:%M:%S) $n rc=$rc" >> drafts/log.txt
echo "$out"
if [ ! -f run/$n.first_valid.aidl ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" run/$n.first_valid.aidl
    echo "$out" > run/$n.first_valid.check.txt
    $A render run/$n.first_valid.aidl -o run/$n.first_valid.png --png-width 1200 2>&1 | tail -3
  else
    k=1; while [ -f drafts/$n.attempt$k.aidl ]; do k=$((k+1)); done
    cp "$f" drafts/$n.attempt$k.aidl; echo "$out" > drafts/$n.attempt$k.check.txt
  fi
fi
echo "rc=$rc"
