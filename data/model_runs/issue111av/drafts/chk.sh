#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log the result, keep the first valid program
# (run/NN_name.first_valid.*) and every failed attempt before it (drafts/NN_name.attemptK.*).
set -u
here="$(cd "$(dirname "$0")" && pwd)"
base="$(dirname "$here")"
name="$1"
src="$here/$name.aidl"
AIDL() { PYTHONPATH=/work/wt-models-av /work/main/.venv/bin/aidl "$@"; }
out="$(mktemp)"
AIDL check "$src" >"$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
fv="$base/run/$name.first_valid"
if [ -e "$fv.aidl" ]; then
    phase="after-first-valid"
else
    if [ $rc -eq 0 ]; then
        phase="FIRST-VALID"
        cp "$src" "$fv.aidl"
        cp "$out" "$fv.check.txt"
        AIDL render "$fv.aidl" -o "$fv.png" --png-width 1200 >>"$fv.check.txt.render" 2>&1
        rm -f "$fv.check.txt.render"
    else
        k=1
        while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
        phase="attempt$k"
        cp "$src" "$here/$name.attempt$k.aidl"
        cp "$out" "$here/$name.attempt$k.check.txt"
    fi
fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $name exit=$rc errors=$errs warnings=$warns $phase" >>"$here/log.txt"
cat "$out"
echo "--- $name exit=$rc errors=$errs warnings=$warns $phase"
# a picture of the current draft, to look at
AIDL render "$src" -o "$here/$name.png" --png-width 1200 >/dev/null 2>&1 || true
rm -f "$out"
exit $rc
