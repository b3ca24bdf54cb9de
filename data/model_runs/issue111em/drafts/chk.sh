#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program
# (run/NN_name.first_valid.*), attempts before it (drafts/NN_name.attemptK.*), and fixes
# after it (drafts/NN_name.fixK.*).
set -u
here="$(cd "$(dirname "$0")" && pwd)"
base="$(dirname "$here")"
name="$1"
src="$here/$name.aidl"
export PYTHONPATH=/work/wt-models-em
AIDL=/work/main/.venv/bin/aidl
out="$(mktemp)"
now="$(date -u '+%Y-%m-%d %H:%M:%S')"
$AIDL check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
fv="$base/run/$name.first_valid.aidl"
if [ -e "$fv" ]; then
    k=1; while [ -e "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        $AIDL render "$src" -o "$here/$name.fix$k.png" --png-width 1200 >"$here/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$fv"; cp "$out" "$base/run/$name.first_valid.check.txt"
    $AIDL render "$fv" -o "$base/run/$name.first_valid.png" --png-width 1200 >"$base/run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
echo "$now  $name  $kind  exit=$rc  errors=$ne  warnings=$nw" >>"$here/log.txt"
echo "== $now $name $kind exit=$rc errors=$ne warnings=$nw"
cat "$out"
rm -f "$out"
