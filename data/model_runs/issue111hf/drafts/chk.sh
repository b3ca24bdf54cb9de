#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts and the first valid program.
# Run from anywhere; paths are relative to this run's folder.
set -u
name="$1"
here="$(cd "$(dirname "$0")/.." && pwd)"
cd "$here"
AIDL="env PYTHONPATH=/work/wt-models-hf /work/main/.venv/bin/aidl"
src="drafts/$name.aidl"
out="$(mktemp)"
$AIDL check "$src" >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
when="$(date -u)"
if [ -e "run/$name.first_valid.aidl" ]; then
    stage="after-first-valid"
    cp "$out" "drafts/$name.fix.check.txt"
    if [ $rc -eq 0 ]; then $AIDL render "$src" -o "drafts/$name.fix.png" --png-width 1200 >/dev/null 2>&1; fi
elif [ $rc -eq 0 ]; then
    stage="FIRST-VALID"
    cp "$src" "run/$name.first_valid.aidl"
    cp "$out" "run/$name.first_valid.check.txt"
    $AIDL render "run/$name.first_valid.aidl" -o "run/$name.first_valid.png" --png-width 1200 >"drafts/$name.render.txt" 2>&1
else
    k=1
    while [ -e "drafts/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    stage="attempt$k"
    cp "$src" "drafts/$name.attempt$k.aidl"
    cp "$out" "drafts/$name.attempt$k.check.txt"
fi
echo "$when	$name	$stage	exit=$rc	errors=$ne	warnings=$nw" >> drafts/log.txt
cat "$out"
echo "--- $stage exit=$rc errors=$ne warnings=$nw"
rm -f "$out"
