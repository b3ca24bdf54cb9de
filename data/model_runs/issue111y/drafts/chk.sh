#!/bin/bash
# usage (from data/model_runs/issue111y): drafts/chk.sh NN_name
# Checks drafts/NN_name.aidl with this tree's CLI, logs one line to drafts/log.txt,
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt, .png);
# a failed check before the first valid one is kept as drafts/NN_name.attemptK.aidl (+ .check.txt).
n="$1"
export PYTHONPATH=/work/wt-models-y
AIDL=/work/main/.venv/bin/aidl
f="drafts/$n.aidl"
out=$(mktemp)
$AIDL check "$f" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $n exit=$rc errors=$ne warnings=$nw" >> drafts/log.txt
if [ ! -f "run/$n.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$f" "run/$n.first_valid.aidl"
    cp "$out" "run/$n.first_valid.check.txt"
    $AIDL render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200
  else
    k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$f" "drafts/$n.attempt$k.aidl"; cp "$out" "drafts/$n.attempt$k.check.txt"
  fi
fi
cat "$out"; rm -f "$out"
echo "exit=$rc"
