#!/bin/bash
# drafts/chk.sh NN_name -- check drafts/NN_name.aidl once and log it (issue111ey).
# Logs: date -u, part, kind, exit status, counts of `error[E` and `warning[W` lines.
# Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, rendered to run/NN_name.first_valid.png at 1200 px);
# a failed check before it: drafts/NN_name.attemptK.aidl + .check.txt;
# a check after it: drafts/NN_name.fixK.aidl + .fixK.check.txt (rendered too).
set -u
name="$1"
here="$(cd "$(dirname "$0")" && pwd)"
run="$here/../run"
export PYTHONPATH=/work/wt-models-ey
AIDL=/work/main/.venv/bin/aidl
src="$here/$name.aidl"
[ -f "$src" ] || { echo "no $src" >&2; exit 2; }
out="$(mktemp)"
when="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$src" >"$out" 2>&1
rc=$?
nerr=$(grep -c 'error\[E' "$out")
nwarn=$(grep -c 'warning\[W' "$out")
if [ -f "$run/$name.first_valid.aidl" ]; then
    k=1; while [ -f "$here/$name.fix$k.aidl" ]; do k=$((k+1)); done
    kind="fix $k"
    cp "$src" "$here/$name.fix$k.aidl"; cp "$out" "$here/$name.fix$k.check.txt"
    if [ $rc -eq 0 ]; then
        "$AIDL" render "$here/$name.fix$k.aidl" -o "$here/$name.fix$k.png" --png-width 1200 \
            >"$here/$name.fix$k.render.txt" 2>&1
    fi
elif [ $rc -eq 0 ]; then
    kind="FIRST VALID"
    cp "$src" "$run/$name.first_valid.aidl"; cp "$out" "$run/$name.first_valid.check.txt"
    "$AIDL" render "$run/$name.first_valid.aidl" -o "$run/$name.first_valid.png" --png-width 1200 \
        >"$run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -f "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind="attempt $k"
    cp "$src" "$here/$name.attempt$k.aidl"; cp "$out" "$here/$name.attempt$k.check.txt"
fi
printf '%s  %-28s %-12s exit=%d  errors=%d  warnings=%d\n' "$when" "$name" "$kind" "$rc" "$nerr" "$nwarn" >>"$here/log.txt"
echo "== $when $name $kind exit=$rc errors=$nerr warnings=$nwarn"
cat "$out"
rm -f "$out"
