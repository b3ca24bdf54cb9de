#!/usr/bin/env bash
# chk.sh NN_name        check drafts/NN_name.aidl, log it, keep attempts / the first valid program
# chk.sh NN_name begin  log a BEGIN line for the part (before its docs are read)
set -u
cd "$(dirname "$0")/.."
export PYTHONPATH=/work/wt-models-ci
AIDL=/work/main/.venv/bin/aidl
name=$1
log=drafts/log.txt
now=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ "${2:-}" = begin ]; then
    echo "$now BEGIN $name" >> "$log"; exit 0
fi
src=drafts/$name.aidl
out=$(mktemp)
$AIDL check "$src" > "$out" 2>&1
rc=$?
errs=$(grep -c 'error\[E' "$out")
warns=$(grep -c 'warning\[W' "$out")
first=run/$name.first_valid.aidl
if [ -e "$first" ]; then
    kind=after_first_valid
elif [ $rc -eq 0 ]; then
    kind=FIRST_VALID
    cp "$src" "$first"; cp "$out" "run/$name.first_valid.check.txt"
    $AIDL render "$first" -o "run/$name.first_valid.png" --png-width 1200 > "run/$name.first_valid.render.txt" 2>&1
else
    k=1; while [ -e "drafts/$name.attempt$k.aidl" ]; do k=$((k+1)); done
    kind=attempt$k
    cp "$src" "drafts/$name.attempt$k.aidl"; cp "$out" "drafts/$name.attempt$k.check.txt"
fi
echo "$now $name exit=$rc errors=$errs warnings=$warns $kind" >> "$log"
cat "$out"; rm -f "$out"
echo "== exit=$rc errors=$errs warnings=$warns $kind"
