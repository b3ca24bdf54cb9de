#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl once and log it (issue111gr)
# - logs date -u, kind, exit status, counts of `error[E` and `warning[W` lines to drafts/log.txt
# - before the first valid program: a failed check is kept as drafts/NN_name.attemptK.aidl + .check.txt
# - the first program that checks with exit 0: run/NN_name.first_valid.aidl + .check.txt,
#   rendered to run/NN_name.first_valid.png (1200 px), messages in .render.txt
# - after it: drafts/NN_name.fixK.aidl + .check.txt, rendered to drafts/NN_name.fixK.png when it passes
set -u
name="$1"
here="$(cd "$(dirname "$0")/.." && pwd)"
d="$here/drafts"; r="$here/run"
src="$d/$name.aidl"
AIDL="env PYTHONPATH=/work/wt-models-gr /work/main/.venv/bin/aidl"
out="$(mktemp)"
$AIDL check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
now="$(date -u '+%Y-%m-%d %H:%M:%S')"
if [ -f "$r/$name.first_valid.aidl" ]; then
    k=1; while [ -f "$d/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$d/$name.fix$k.aidl"; cp "$out" "$d/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        $AIDL render "$d/$name.fix$k.aidl" -o "$d/$name.fix$k.png" --png-width 1200 >"$d/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$r/$name.first_valid.aidl"; cp "$out" "$r/$name.first_valid.check.txt"
    $AIDL render "$r/$name.first_valid.aidl" -o "$r/$name.first_valid.png" --png-width 1200 >"$r/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -f "$d/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$d/$name.attempt$k.aidl"; cp "$out" "$d/$name.attempt$k.check.txt"
fi
echo "$now  $name  $kind  exit=$rc  errors=$ne  warnings=$nw" >> "$d/log.txt"
cat "$out"
echo "--- $now $name $kind exit=$rc errors=$ne warnings=$nw"
rm -f "$out"
