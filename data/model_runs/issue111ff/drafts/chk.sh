#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
run="$here/../run"
name="$1"
src="$here/$name.aidl"
export PYTHONPATH=/work/wt-models-ff
AIDL=/work/main/.venv/bin/aidl
out="$(mktemp)"
now="$(date -u '+%Y-%m-%d %H:%M:%S')"
(cd "$here" && "$AIDL" check "$src") >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
if [ -e "$run/$name.first_valid.aidl" ]; then
    k=1; while [ -e "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    (cd "$here" && "$AIDL" render "$src" -o "$here/$name.fix$k.png" --png-width 1200) >"$here/$name.fix$k.render.txt" 2>&1
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$run/$name.first_valid.aidl"; cp "$out" "$run/$name.first_valid.check.txt"
    (cd "$here" && "$AIDL" render "$run/$name.first_valid.aidl" -o "$run/$name.first_valid.png" --png-width 1200) >"$run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
echo "$now | $name | $kind | exit $rc | errors $ne | warnings $nw" >> "$here/log.txt"
cat "$out"
echo "== $now $name $kind exit=$rc errors=$ne warnings=$nw"
rm -f "$out"
