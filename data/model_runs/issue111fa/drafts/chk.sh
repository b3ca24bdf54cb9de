#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program and the attempts before it
# (issue111fa; written anew for this run)
set -u
name="$1"
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
run="$root/run"
mkdir -p "$run"
export PYTHONPATH=/work/wt-models-fa
AIDL=/work/main/.venv/bin/aidl
src="$here/$name.aidl"
out="$(mktemp)"
$AIDL check "$src" >"$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
if [ -e "$run/$name.first_valid.aidl" ]; then
    k=1; while [ -e "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix$k"
    cp "$src" "$here/$name.fix$k.aidl"
    cp "$out" "$here/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        $AIDL render "$src" -o "$here/$name.fix$k.png" --png-width 1200 >"$here/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$run/$name.first_valid.aidl"
    cp "$out" "$run/$name.first_valid.check.txt"
    $AIDL render "$run/$name.first_valid.aidl" -o "$run/$name.first_valid.png" --png-width 1200 >"$run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt$k"
    cp "$src" "$here/$name.attempt$k.aidl"
    cp "$out" "$here/$name.attempt$k.check.txt"
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $name $kind exit=$rc errors=$errs warnings=$warns" >> "$here/log.txt"
cat "$out"
echo "== $kind exit=$rc errors=$errs warnings=$warns"
rm -f "$out"
