#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
# Run from anywhere; paths are relative to this script's run folder.
set -u
name="$1"
here="$(cd "$(dirname "$0")" && pwd)"
run="$(dirname "$here")/run"
src="$here/$name.aidl"
export PYTHONPATH=/work/wt-models-fe
AIDL=/work/main/.venv/bin/aidl
now="$(date -u '+%Y-%m-%d %H:%M:%S')"
out="$(mktemp)"
$AIDL check "$src" >"$out" 2>&1
rc=$?
nerr=$(grep -c 'error\[E' "$out")
nwarn=$(grep -c 'warning\[W' "$out")
if [ -e "$run/$name.first_valid.aidl" ]; then
    k=1; while [ -e "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    $AIDL render "$here/$name.fix$k.aidl" -o "$here/$name.fix$k.png" --png-width 1200 >"$here/$name.fix$k.render.txt" 2>&1
elif [ "$rc" -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$run/$name.first_valid.aidl"; cp "$out" "$run/$name.first_valid.check.txt"
    $AIDL render "$run/$name.first_valid.aidl" -o "$run/$name.first_valid.png" --png-width 1200 >"$run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
printf '%s  %-28s %-12s exit=%s errors=%s warnings=%s\n' "$now" "$name" "$kind" "$rc" "$nerr" "$nwarn" >>"$here/log.txt"
cat "$out"
echo "== $kind: exit=$rc errors=$nerr warnings=$nwarn"
rm -f "$out"
