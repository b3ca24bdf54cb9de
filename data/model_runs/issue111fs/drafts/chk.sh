#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl once and log it (issue111fs).
# Before the first valid: a failing check is kept as drafts/NN_name.attemptK.aidl + .check.txt;
# the first check with exit 0 is kept as run/NN_name.first_valid.aidl + .check.txt and rendered
# to run/NN_name.first_valid.png (1200 px; messages in .render.txt).
# After the first valid: each check is kept as drafts/NN_name.fixK.aidl + .fixK.check.txt and
# rendered to drafts/NN_name.fixK.png when it passes.
set -u
name="$1"
here="$(cd "$(dirname "$0")/.." && pwd)"
d="$here/drafts"; r="$here/run"
export PYTHONPATH=/work/wt-models-fs
A=/work/main/.venv/bin/aidl
src="$d/$name.aidl"
out="$(mktemp)"
when="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$A" check "$src" >"$out" 2>&1
rc=$?
nerr=$(grep -c 'error\[E' "$out")
nwarn=$(grep -c 'warning\[W' "$out")
if [ -f "$r/$name.first_valid.aidl" ]; then
    k=1; while [ -f "$d/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$d/$name.fix$k.aidl"; cp "$out" "$d/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        "$A" render "$d/$name.fix$k.aidl" -o "$d/$name.fix$k.png" --png-width 1200 >"$d/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$r/$name.first_valid.aidl"; cp "$out" "$r/$name.first_valid.check.txt"
    "$A" render "$r/$name.first_valid.aidl" -o "$r/$name.first_valid.png" --png-width 1200 >"$r/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -f "$d/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$d/$name.attempt$k.aidl"; cp "$out" "$d/$name.attempt$k.check.txt"
fi
printf '%s UTC\t%s\t%s\texit=%s\terrors=%s\twarnings=%s\n' "$when" "$name" "$kind" "$rc" "$nerr" "$nwarn" >>"$d/log.txt"
tail -n 1 "$d/log.txt"
cat "$out"
rm -f "$out"
