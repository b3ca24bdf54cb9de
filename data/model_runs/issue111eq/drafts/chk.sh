#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program
# (run/NN_name.first_valid.*), a failed check before it (drafts/NN_name.attemptK.*),
# a check after it (drafts/NN_name.fixK.*).
set -u
cd "$(dirname "$0")"
name="$1"
export PYTHONPATH=/work/wt-models-eq
A=/work/main/.venv/bin/aidl
src="$name.aidl"
out=$(mktemp)
now=$(date -u '+%Y-%m-%d %H:%M:%S')
$A check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
fv="../run/$name.first_valid.aidl"
if [ -e "$fv" ]; then
  k=1; while [ -e "$name.fix$k.aidl" ]; do k=$((k+1)); done
  kind="fix $k"
  cp "$src" "$name.fix$k.aidl"; cp "$out" "$name.fix$k.check.txt"
  $A render "$name.fix$k.aidl" -o "$name.fix$k.png" --png-width 1200 >"$name.fix$k.render.txt" 2>&1
elif [ $rc -eq 0 ]; then
  kind="FIRST VALID"
  cp "$src" "$fv"; cp "$out" "../run/$name.first_valid.check.txt"
  $A render "$fv" -o "../run/$name.first_valid.png" --png-width 1200 >"../run/$name.first_valid.render.txt" 2>&1
else
  k=1; while [ -e "$name.attempt$k.aidl" ]; do k=$((k+1)); done
  kind="attempt $k"
  cp "$src" "$name.attempt$k.aidl"; cp "$out" "$name.attempt$k.check.txt"
fi
echo "$now  $name  $kind  exit=$rc  errors=$ne  warnings=$nw" >> log.txt
tail -1 log.txt
cat "$out"
rm -f "$out"
