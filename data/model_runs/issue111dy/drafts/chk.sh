#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program
# (run/NN_name.first_valid.*), failed attempts before it (drafts/NN_name.attemptK.*)
# and checks after it (drafts/NN_name.fixK.*).
set -u
name="$1"
D="$(cd "$(dirname "$0")" && pwd)"
R="$D/../run"
export PYTHONPATH=/work/wt-models-dy
AIDL=/work/main/.venv/bin/aidl
src="$D/$name.aidl"
out="$(mktemp)"
when="$(date -u '+%Y-%m-%d %H:%M:%S')"
"$AIDL" check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
cat "$out"
if [ -e "$R/$name.first_valid.aidl" ]; then
    k=1; while [ -e "$D/$name.fix$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "$D/$name.fix$k.aidl"; cp "$out" "$D/$name.fix$k.check.txt"
    what="fix$k (after the first valid)"
elif [ "$rc" -eq 0 ]; then
    cp "$src" "$R/$name.first_valid.aidl"; cp "$out" "$R/$name.first_valid.check.txt"
    "$AIDL" render "$R/$name.first_valid.aidl" -o "$R/$name.first_valid.png" --png-width 1200 \
        >"$R/$name.first_valid.render.txt" 2>&1
    what="FIRST VALID"
else
    k=1; while [ -e "$D/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    cp "$src" "$D/$name.attempt$k.aidl"; cp "$out" "$D/$name.attempt$k.check.txt"
    what="attempt$k (failed)"
fi
echo "$when  $name  exit=$rc  errors=$ne  warnings=$nw  $what" | tee -a "$D/log.txt"
rm -f "$out"
