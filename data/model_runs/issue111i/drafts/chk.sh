#!/bin/bash
# usage (from the run folder): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs one line, keeps the FIRST program that checks with exit 0
set -u
n=$1
export PYTHONPATH=/work/wt-models-i
A=/work/main/.venv/bin/aidl
f=drafts/$n.aidl
out=$($A check "$f" 2>&1); rc=$?
e=$(printf '%s\n' "$out" | grep -c 'error\[E')
w=$(printf '%s\n' "$out" | grep -c 'warning\[W')
echo "$(date -u +%H:%M:%S) $n rc=$rc e=$e w=$w" >> drafts/log.txt
printf '%s\n' "$out"
if [ $rc -eq 0 ]; then
  if [ ! -e run/$n.first_valid.aidl ]; then
    cp "$f" run/$n.first_valid.aidl
    printf '%s\n' "$out" > run/$n.first_valid.check.txt
    $A render run/$n.first_valid.aidl -o run/$n.first_valid.png --png-width 1200
    echo "FIRST VALID kept"
  fi
else
  k=1; while [ -e drafts/$n.attempt$k.aidl ]; do k=$((k+1)); done
  cp "$f" drafts/$n.attempt$k.aidl
  printf '%s\n' "$out" > drafts/$n.attempt$k.check.txt
  echo "failed: kept as attempt$k"
fi
