#!/bin/bash
# usage (from data/model_runs/issue111z6): drafts/chk.sh NN_name
# Checks drafts/NN_name.aidl with this tree's CLI, logs one line to drafts/log.txt,
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, + .png at 1200 px); a failed check before that is kept as
# drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
name="$1"
tree=/work/wt-models-z6
aidl() { PYTHONPATH=$tree /work/main/.venv/bin/aidl "$@"; }
src="drafts/$name.aidl"
out=$(mktemp)
aidl check "$src" >"$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
echo "$(date -u) $name exit=$rc errors=$errs warnings=$warns" >> drafts/log.txt
cat "$out"
if [ ! -e "run/$name.first_valid.aidl" ]; then
  if [ $rc -eq 0 ]; then
    cp "$src" "run/$name.first_valid.aidl"
    cp "$out" "run/$name.first_valid.check.txt"
    aidl render "run/$name.first_valid.aidl" -o "run/$name.first_valid.png" --png-width 1200
    echo "FIRST VALID kept"
  else
    k=1; while [ -e "drafts/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "drafts/$name.attempt$k.aidl"
    cp "$out" "drafts/$name.attempt$k.check.txt"
    echo "kept failed attempt $k"
  fi
fi
rm -f "$out"
echo "exit=$rc"
