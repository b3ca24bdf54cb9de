#!/bin/bash
# usage (from data/model_runs/issue111v): drafts/chk.sh NN_name
n="$1"; A="env PYTHONPATH=/work/wt-models-v /work/main/.venv/bin/aidl"
out=$($A check "drafts/$n.aidl" 2>&1); rc=$?
e=$(grep -c 'error\[E' <<<"$out"); w=$(grep -c 'warning\[W' <<<"$out")
echo "$(date -u) $n exit=$rc errors=$e warnings=$w" >> drafts/log.txt
echo "$out"
if [ ! -f "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "drafts/$n.aidl" "run/$n.first_valid.aidl"; echo "$out" > "run/$n.first_valid.check.txt"
    $A render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
  else
    k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "drafts/$n.aidl" "drafts/$n.attempt$k.aidl"
  fi
fi
echo "rc=$rc"
