#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
# Written anew for run issue111ew.
set -u
name="$1"
here="$(cd "$(dirname "$0")" && pwd)"
run="$here/../run"
mkdir -p "$run"
export PYTHONPATH=/work/wt-models-ew
AIDL=/work/main/.venv/bin/aidl
src="$here/$name.aidl"
out="$(mktemp)"
"$AIDL" check "$src" >"$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
now="$(date -u '+%Y-%m-%d %H:%M:%S')"
if [ -f "$run/$name.first_valid.aidl" ]; then
    k=1; while [ -f "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k after the first valid"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then "$AIDL" render "$src" -o "$here/$name.fix$k.png" --png-width 1200 >"$here/$name.fix$k.render.txt" 2>&1; fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$run/$name.first_valid.aidl"; cp "$out" "$run/$name.first_valid.check.txt"
    "$AIDL" render "$run/$name.first_valid.aidl" -o "$run/$name.first_valid.png" --png-width 1200 >"$run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -f "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
echo "$now  $name  $kind  exit=$rc  errors=$errs  warnings=$warns" >>"$here/log.txt"
echo "== $now $name: $kind exit=$rc errors=$errs warnings=$warns"
cat "$out"
rm -f "$out"
