#!/bin/bash
# usage (from data/model_runs/issue111e): drafts/chk.sh NN_name [fix]
# Checks drafts/NN_name.aidl with this tree's CLI and logs one line per check in drafts/log.txt.
# Until the part has a first valid program: a failed check is kept as drafts/NN_name.attemptK.aidl
# (+ .check.txt); the FIRST check with exit 0 is kept as run/NN_name.first_valid.aidl (+ .check.txt)
# and rendered to run/NN_name.first_valid.png. With "fix": the program is the part's final one,
# kept as run/NN_name.aidl (+ .check.txt) and rendered to run/NN_name.png.
set -u
n=$1; mode=${2:-first}
W=/work/wt-models-e
A="env PYTHONPATH=$W /work/main/.venv/bin/aidl"
src=drafts/$n.aidl
out=$(mktemp)
$A check "$src" >"$out" 2>&1; rc=$?
if [ "$mode" = fix ]; then
  echo "$(date -u +%FT%TZ) $n fix exit=$rc" >> drafts/log.txt
  cp "$src" run/$n.aidl; cp "$out" run/$n.check.txt
  [ $rc = 0 ] && $A render run/$n.aidl -o run/$n.png --png-width 1200 >/dev/null 2>&1
elif [ -e run/$n.first_valid.aidl ]; then
  echo "already has a first valid program; use: chk.sh $n fix"; rm -f "$out"; exit 2
else
  k=$(( $(ls drafts/$n.attempt*.aidl 2>/dev/null | wc -l) + 1 ))
  echo "$(date -u +%FT%TZ) $n check $k exit=$rc" >> drafts/log.txt
  if [ $rc = 0 ]; then
    cp "$src" run/$n.first_valid.aidl; cp "$out" run/$n.first_valid.check.txt
    $A render run/$n.first_valid.aidl -o run/$n.first_valid.png --png-width 1200 >/dev/null 2>&1
  else
    cp "$src" drafts/$n.attempt$k.aidl; cp "$out" drafts/$n.attempt$k.check.txt
  fi
fi
cat "$out"; rm -f "$out"; exit $rc
