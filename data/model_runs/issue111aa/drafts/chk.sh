#!/bin/bash
# usage: drafts/chk.sh NN_name   (from data/model_runs/issue111aa, or anywhere)
# Checks drafts/NN_name.aidl, logs the check to drafts/log.txt, keeps the first program
# that checks with exit status 0 as run/NN_name.first_valid.aidl (+ .check.txt, + .png),
# and keeps every failed check before it as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
here="$(cd "$(dirname "$0")/.." && pwd)"
cd "$here"
name="$1"
export PYTHONPATH=/work/wt-models-aa
AIDL=/work/main/.venv/bin/aidl
src="drafts/$name.aidl"
out="$(mktemp)"
when="$(date -u)"
$AIDL check "$src" >"$out" 2>&1
rc=$?
nerr=$(grep -c 'error\[E' "$out")
nwarn=$(grep -c 'warning\[W' "$out")
if [ -e "run/$name.first_valid.aidl" ]; then
    stage="after first valid"
elif [ $rc -eq 0 ]; then
    stage="FIRST VALID"
    cp "$src" "run/$name.first_valid.aidl"
    cp "$out" "run/$name.first_valid.check.txt"
    $AIDL render "run/$name.first_valid.aidl" -o "run/$name.first_valid.png" --png-width 1200
else
    k=1
    while [ -e "drafts/$name.attempt$k.aidl" ]; do k=$((k + 1)); done
    stage="failed attempt$k"
    cp "$src" "drafts/$name.attempt$k.aidl"
    cp "$out" "drafts/$name.attempt$k.check.txt"
fi
echo "$when | $name | exit $rc | errors $nerr | warnings $nwarn | $stage" >>drafts/log.txt
cat "$out"
echo "== exit $rc, error[E lines: $nerr, warning[W lines: $nwarn ($stage)"
rm -f "$out"
