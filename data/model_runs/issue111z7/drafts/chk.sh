#!/bin/bash
# usage (from data/model_runs/issue111z7): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs it; keeps the FIRST program that checks with exit 0 in run/
n="$1"; f="drafts/$n.aidl"
A="env PYTHONPATH=/work/wt-models-z7 /work/main/.venv/bin/aidl"
out=$($A check "$f" 2>&1); rc=$?
ne=$(grep -c 'error\[E' <<<"$out"); nw=$(grep -c 'warning\[W' <<<"$out")
echo "$(date -u) $n exit=$rc errors=$ne warnings=$nw" >> drafts/log.txt
echo "$out"
if [ ! -f "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"; echo "$out" > "run/$n.first_valid.check.txt"
    $A render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
    echo "FIRST VALID kept"
  else
    k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"; echo "$out" > "drafts/$n.attempt$k.check.txt"
    echo "kept as attempt$k"
  fi
else
  $A render "$f" -o "drafts/$n.png" --png-width 1200
fi
exit $rc
