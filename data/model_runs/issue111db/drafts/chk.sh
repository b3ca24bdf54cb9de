#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111db)
# logs date, exit status and counts of error[E / warning[W lines to drafts/log.txt;
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl (+ .check.txt,
# + .png rendered at 1200 px); a failed check before it is kept as drafts/NN_name.attemptK.aidl.
set -u
cd "$(dirname "$0")/.."
name="$1"
src="drafts/$name.aidl"
A="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-db
out=$(mktemp)
"$A" check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
if [ -e "run/$name.first_valid.aidl" ]; then phase="after-first-valid"; else phase="before-first-valid"; fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $name exit=$rc errors=$ne warnings=$nw phase=$phase" >> drafts/log.txt
if [ "$phase" = "before-first-valid" ]; then
  if [ $rc -eq 0 ]; then
    cp "$src" "run/$name.first_valid.aidl"
    cp "$out" "run/$name.first_valid.check.txt"
    "$A" render "run/$name.first_valid.aidl" -o "run/$name.first_valid.png" --png-width 1200 > "run/$name.first_valid.render.txt" 2>&1
    echo "FIRST VALID kept: run/$name.first_valid.aidl"
  else
    k=1; while [ -e "drafts/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "drafts/$name.attempt$k.aidl"
    cp "$out" "drafts/$name.attempt$k.check.txt"
    echo "failed check kept as drafts/$name.attempt$k.aidl"
  fi
fi
cat "$out"
echo "exit=$rc errors=$ne warnings=$nw"
rm -f "$out"
