#!/bin/bash
# usage (from data/model_runs/issue111z5): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs it, keeps the first program that checks with exit 0.
set -u
n="$1"
AIDL="env PYTHONPATH=/work/wt-models-z5 /work/main/.venv/bin/aidl"
f="drafts/$n.aidl"
out=$(mktemp)
$AIDL check "$f" > "$out" 2>&1
rc=$?
e=$(grep -c 'error\[E' "$out"); w=$(grep -c 'warning\[W' "$out")
echo "$(date -u) $n exit=$rc errors=$e warnings=$w" >> drafts/log.txt
cat "$out"
if [ ! -e "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"; cp "$out" "run/$n.first_valid.check.txt"
    $AIDL render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
    echo "== kept as run/$n.first_valid.aidl"
  else
    k=1; while [ -e "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"; cp "$out" "drafts/$n.attempt$k.check.txt"
    echo "== failed: kept as drafts/$n.attempt$k.aidl"
  fi
fi
rm -f "$out"
