#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111gw)
# Checks drafts/NN_name.aidl, logs time, exit status and counts of errors and warnings to
# drafts/log.txt; keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, + .png render); each failed check before it as drafts/NN_name.attemptK.aidl.
set -u
cd "$(dirname "$0")/.."
name="$1"
export PYTHONPATH=/work/wt-models-gw
AIDL=/work/main/.venv/bin/aidl
src="drafts/$name.aidl"
out=$(mktemp)
$AIDL check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
when=$(date -u)
if [ -e "run/$name.first_valid.aidl" ]; then
  stage="after-first-valid"
else
  stage="before-first-valid"
fi
echo "$when | $name | exit=$rc | errors=$ne | warnings=$nw | $stage" >> drafts/log.txt
cat "$out"
if [ "$stage" = "before-first-valid" ]; then
  if [ $rc -eq 0 ]; then
    cp "$src" "run/$name.first_valid.aidl"
    cp "$out" "run/$name.first_valid.check.txt"
    $AIDL render "run/$name.first_valid.aidl" -o "run/$name.first_valid.png" --png-width 1200
    echo ">> kept as run/$name.first_valid.aidl"
  else
    k=1
    while [ -e "drafts/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "drafts/$name.attempt$k.aidl"
    cp "$out" "drafts/$name.attempt$k.check.txt"
    echo ">> failed; kept as drafts/$name.attempt$k.aidl"
  fi
fi
rm -f "$out"
exit $rc
