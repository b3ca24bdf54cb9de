#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111dw)
# Checks drafts/NN_name.aidl, logs the time, exit status and the counts of
# error[E / warning[W lines to drafts/log.txt, and keeps:
#  - before the first valid: drafts/NN_name.attemptK.aidl + .check.txt
#  - the first valid: run/NN_name.first_valid.aidl + .check.txt + .png (+ .render.txt)
#  - after it: drafts/NN_name.fixK.aidl + .fixK.check.txt
set -u
cd "$(dirname "$0")/.."
name="$1"
src="drafts/$name.aidl"
export PYTHONPATH=/work/wt-models-dw
AIDL=/work/main/.venv/bin/aidl
out=$(mktemp)
$AIDL check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
now=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ -e "run/$name.first_valid.aidl" ]; then
    k=1; while [ -e "drafts/$name.fix$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "drafts/$name.fix$k.aidl"; cp "$out" "drafts/$name.fix$k.check.txt"
    kind="fix$k (after the first valid)"
elif [ "$rc" -eq 0 ]; then
    cp "$src" "run/$name.first_valid.aidl"; cp "$out" "run/$name.first_valid.check.txt"
    $AIDL render "run/$name.first_valid.aidl" -o "run/$name.first_valid.png" --png-width 1200 \
        >"run/$name.first_valid.render.txt" 2>&1
    kind="FIRST VALID"
else
    k=1; while [ -e "drafts/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "drafts/$name.attempt$k.aidl"; cp "$out" "drafts/$name.attempt$k.check.txt"
    kind="attempt$k (failed)"
fi
echo "$now  $name  exit=$rc  errors=$ne  warnings=$nw  $kind" >> drafts/log.txt
cat "$out"
echo "--- $now exit=$rc errors=$ne warnings=$nw $kind"
rm -f "$out"
