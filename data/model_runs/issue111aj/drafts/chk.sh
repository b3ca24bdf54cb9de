#!/bin/bash
# drafts/chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program
# (run/NN_name.first_valid.aidl + .check.txt + .png) or, before it, the failed attempt
# (drafts/NN_name.attemptK.aidl + .check.txt).
set -u
here="$(cd "$(dirname "$0")" && pwd)"
top="$(dirname "$here")"
name="$1"
src="$here/$name.aidl"
export PYTHONPATH=/work/wt-models-aj
AIDL=/work/main/.venv/bin/aidl
out="$(mktemp)"
when="$(date -u)"
"$AIDL" check "$src" >"$out" 2>&1
rc=$?
nerr=$(grep -c 'error\[E' "$out")
nwarn=$(grep -c 'warning\[W' "$out")
more=$(grep -o 'and [0-9]* more of [A-Z0-9]*' "$out" | tr '\n' ';')
codes=$(grep -o '\(error\|warning\)\[[EW][0-9]*\]' "$out" | sort | uniq -c | awk '{printf "%s x%s ", $2, $1}')
first="$top/run/$name.first_valid.aidl"
if [ -e "$first" ]; then
  kind="after first valid"
elif [ $rc -eq 0 ]; then
  kind="FIRST VALID"
  cp "$src" "$first"
  cp "$out" "$top/run/$name.first_valid.check.txt"
  "$AIDL" render "$first" -o "$top/run/$name.first_valid.png" --png-width 1200 \
     >"$top/run/$name.first_valid.render.txt" 2>&1
else
  k=1
  while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
  kind="attempt$k (failed, before first valid)"
  cp "$src" "$here/$name.attempt$k.aidl"
  cp "$out" "$here/$name.attempt$k.check.txt"
fi
echo "$when | $name | exit $rc | errors $nerr | warnings $nwarn | ${more:-} | $codes| $kind" >>"$here/log.txt"
cat "$out"
echo "--- exit $rc; $kind"
rm -f "$out"
