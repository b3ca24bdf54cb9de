#!/bin/bash
# chk.sh NN_name: check drafts/NN_name.aidl, log it, keep the first valid program and attempts.
# Run from anywhere; paths are relative to this script's run directory.
set -u
name="$1"
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
export PYTHONPATH=/work/wt-models-gk
AIDL=/work/main/.venv/bin/aidl
src="$here/$name.aidl"
out="$(mktemp)"
when="$(date -u '+%Y-%m-%d %H:%M:%S')"
$AIDL check "$src" >"$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
first="$root/run/$name.first_valid.aidl"
if [ -f "$first" ]; then
    k=1; while [ -f "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        $AIDL render "$src" -o "$here/$name.fix$k.png" --png-width 1200 >"$here/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$first"; cp "$out" "$root/run/$name.first_valid.check.txt"
    $AIDL render "$first" -o "$root/run/$name.first_valid.png" --png-width 1200 >"$root/run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -f "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
printf '%s  %-22s %-12s exit=%s  error[E=%s  warning[W=%s\n' "$when" "$name" "$kind" "$rc" "$errs" "$warns" >>"$here/log.txt"
cat "$out"
echo "== $kind exit=$rc errors=$errs warnings=$warns"
rm -f "$out"
