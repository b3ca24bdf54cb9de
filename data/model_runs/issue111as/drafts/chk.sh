#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program (issue111as)
set -u
here="$(cd "$(dirname "$0")" && pwd)"
base="$(dirname "$here")"
name="$1"
src="$here/$name.aidl"
export PYTHONPATH=/work/wt-models-as
AIDL=/work/main/.venv/bin/aidl
stamp="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
out="$(cd "$here" && $AIDL check "$name.aidl" 2>&1)"
rc=$?
ne=$(printf '%s\n' "$out" | grep -c 'error\[E')
nw=$(printf '%s\n' "$out" | grep -c 'warning\[W')
codes=$(printf '%s\n' "$out" | grep -o '\(error\|warning\|note\)\[[EW][0-9]*\]' | sort | uniq -c | awk '{printf "%s%s", sep, $2"x"$1; sep=","}')
first="$base/run/$name.first_valid.aidl"
if [ -f "$first" ]; then phase="recheck"; else phase="before-first-valid"; fi
echo "$stamp $name rc=$rc errors=$ne warnings=$nw codes=[$codes] phase=$phase" >> "$here/log.txt"
printf '%s\n' "$out"
if [ ! -f "$first" ]; then
  if [ $rc -eq 0 ]; then
    cp "$src" "$first"
    printf '%s\n' "$out" > "$base/run/$name.first_valid.check.txt"
    (cd "$base/run" && $AIDL render "$name.first_valid.aidl" -o "$name.first_valid.png" --png-width 1200 > "$name.first_valid.render.txt" 2>&1)
    echo "FIRST VALID kept: run/$name.first_valid.aidl (+ .check.txt, .png)"
  else
    k=1
    while [ -f "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "$here/$name.attempt$k.aidl"
    printf '%s\n' "$out" > "$here/$name.attempt$k.check.txt"
    echo "FAILED: kept as drafts/$name.attempt$k.aidl"
  fi
fi
exit $rc
