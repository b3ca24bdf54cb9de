#!/bin/bash
# usage (from issue111w/): drafts/chk.sh NN_name
# checks drafts/NN_name.aidl, logs one line, keeps the FIRST exit-0 program as run/NN_name.first_valid.*
set -u
n="$1"; f="drafts/$n.aidl"
AIDL="env PYTHONPATH=/work/wt-models-w /work/main/.venv/bin/aidl"
out=$($AIDL check "$f" 2>&1); rc=$?
ne=$(grep -c 'error\[E' <<<"$out"); nw=$(grep -c 'warning\[W' <<<"$out")
echo "$(date -u +%FT%TZ) $n exit=$rc errors=$ne warnings=$nw" >> drafts/log.txt
echo "$out"
echo "== exit $rc"
if [ ! -e "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"; echo "$out" > "run/$n.first_valid.check.txt"
    $AIDL render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
  else
    k=1; while [ -e "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"; echo "$out" > "drafts/$n.attempt$k.check.txt"
  fi
fi
