#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / the first valid / fixes.
# Written anew for run issue111fm.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
run="$here/../run"
name="$1"
src="$here/$name.aidl"
AIDL="env PYTHONPATH=/work/wt-models-fm /work/main/.venv/bin/aidl"
mkdir -p "$run"
now="$(date -u '+%Y-%m-%d %H:%M:%S')"
out="$(mktemp)"
$AIDL check "$src" >"$out" 2>&1
rc=$?
nerr=$(grep -c 'error\[E' "$out")
nwarn=$(grep -c 'warning\[W' "$out")
first="$run/$name.first_valid.aidl"
if [ -e "$first" ]; then
    k=1; while [ -e "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        $AIDL render "$src" -o "$here/$name.fix$k.png" --png-width 1200 >"$here/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$first"; cp "$out" "$run/$name.first_valid.check.txt"
    $AIDL render "$first" -o "$run/$name.first_valid.png" --png-width 1200 >"$run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
printf '%s\t%s\t%s\texit=%s\terrors=%s\twarnings=%s\n' "$now" "$name" "$kind" "$rc" "$nerr" "$nwarn" >>"$here/log.txt"
echo "== $now $name $kind exit=$rc errors=$nerr warnings=$nwarn"
cat "$out"
rm -f "$out"
