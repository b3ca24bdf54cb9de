#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts and the first valid program.
set -u
name="$1"
here="$(cd "$(dirname "$0")" && pwd)"
run="$here/../run"
mkdir -p "$run"
export PYTHONPATH=/work/wt-models-cl
AIDL=/work/main/.venv/bin/aidl
src="$here/$name.aidl"
out="$(mktemp)"
(cd "$here" && "$AIDL" check "$name.aidl") >"$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
stamp="$(date -u)"
if [ -e "$run/$name.first_valid.aidl" ]; then
    phase="after-first-valid"
else
    phase="before-first-valid"
fi
echo "$stamp | $name | exit $rc | errors $errs | warnings $warns | $phase" >> "$here/log.txt"
if [ "$phase" = "before-first-valid" ]; then
    if [ $rc -eq 0 ]; then
        cp "$src" "$run/$name.first_valid.aidl"
        cp "$out" "$run/$name.first_valid.check.txt"
        (cd "$run" && "$AIDL" render "$name.first_valid.aidl" -o "$name.first_valid.png" --png-width 1200)
        echo "FIRST VALID kept: run/$name.first_valid.aidl"
    else
        k=1
        while [ -e "$here/$name.attempt$k.aidl" ]; do k=$((k+1)); done
        cp "$src" "$here/$name.attempt$k.aidl"
        cp "$out" "$here/$name.attempt$k.check.txt"
        echo "failed check kept as drafts/$name.attempt$k.aidl"
    fi
fi
cat "$out"
rm -f "$out"
exit $rc
