#!/bin/bash
# usage (from issue111u/): drafts/chk.sh NN_name   -- checks drafts/NN_name.aidl, logs, keeps first valid
n="$1"; f="drafts/$n.aidl"
A="env PYTHONPATH=/work/wt-models-u /work/main/.venv/bin/aidl"
out=$($A check "$f" 2>&1); rc=$?
ne=$(grep -c 'error\[E' <<<"$out"); nw=$(grep -c 'warning\[W' <<<"$out")
echo "$(date -u) $n rc=$rc errors=$ne warnings=$nw" >> drafts/log.txt
echo "$out"
if [ ! -f "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"; echo "$out" > "run/$n.first_valid.check.txt"
    $A render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
    echo "FIRST VALID kept"
  else
    k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"; echo "$out" > "drafts/$n.attempt$k.check.txt"
  fi
fi
exit $rc
