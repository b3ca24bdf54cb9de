#!/bin/bash
# chk.sh NN_name: check drafts/NN_name.aidl, log it, keep the first valid program
# (run/NN_name.first_valid.*), the failed attempts before it (drafts/NN_name.attemptK.*)
# and the checks after it (drafts/NN_name.fixK.*).
set -u
name="$1"
here="$(cd "$(dirname "$0")" && pwd)"
top="$(dirname "$here")"
export PYTHONPATH=/work/wt-models-gt
AIDL=/work/main/.venv/bin/aidl
src="$here/$name.aidl"
out="$(mktemp)"
when="$(date -u '+%Y-%m-%d %H:%M:%S')"
$AIDL check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
mkdir -p "$top/run"
first="$top/run/$name.first_valid.aidl"
if [ -f "$first" ]; then
    k=1; while [ -f "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        $AIDL render "$src" -o "$here/$name.fix$k.png" --png-width 1200 >"$here/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$first"; cp "$out" "$top/run/$name.first_valid.check.txt"
    $AIDL render "$first" -o "$top/run/$name.first_valid.png" --png-width 1200 >"$top/run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -f "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
echo "$when  $name  $kind  exit=$rc  errors=$ne  warnings=$nw" >>"$here/log.txt"
echo "== $kind  exit=$rc  errors=$ne  warnings=$nw"
cat "$out"
rm -f "$out"
