#!/bin/bash
# usage (from data/model_runs/issue111l): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs it, keeps the FIRST program that checks with exit 0 in run/
set -u
n="$1"; A="env PYTHONPATH=/work/wt-models-l /work/main/.venv/bin/aidl"
f="drafts/$n.aidl"; out=$(mktemp)
$A check "$f" >"$out" 2>&1; rc=$?
ne=$(grep -c 'error\[E' "$out"); nw=$(grep -c 'warning\[W' "$out")
echo "$(date -u +%H:%M:%S) $n rc=$rc errors=$ne warnings=$nw" >> drafts/log.txt
cat "$out"
if [ ! -e "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"; cp "$out" "run/$n.first_valid.check.txt"
    $A render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
  else
    k=1; while [ -e "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"; cp "$out" "drafts/$n.attempt$k.check.txt"
  fi
fi
rm -f "$out"; exit $rc
