#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep attempts / first valid / fixes.
set -u
cd "$(dirname "$0")/.." || exit 2
export PYTHONPATH=/work/wt-models-fc
AIDL=/work/main/.venv/bin/aidl
n="$1"
src="drafts/$n.aidl"
[ -f "$src" ] || { echo "no $src"; exit 2; }
tmp=$(mktemp)
now=$(date -u '+%Y-%m-%d %H:%M:%S')
$AIDL check "$src" >"$tmp" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$tmp")
nw=$(grep -c 'warning\[W' "$tmp")
if [ -f "run/$n.first_valid.aidl" ]; then
  k=1; while [ -f "drafts/$n.fix$k.aidl" ]; do k=$((k+1)); done
  kind="fix $k"
  cp "$src" "drafts/$n.fix$k.aidl"; cp "$tmp" "drafts/$n.fix$k.check.txt"
  if [ $rc -eq 0 ]; then
    $AIDL render "drafts/$n.fix$k.aidl" -o "drafts/$n.fix$k.png" --png-width 1200 >"drafts/$n.fix$k.render.txt" 2>&1
  fi
elif [ $rc -eq 0 ]; then
  kind="FIRST VALID"
  cp "$src" "run/$n.first_valid.aidl"; cp "$tmp" "run/$n.first_valid.check.txt"
  $AIDL render "run/$n.first_valid.aidl" -o "run/$n.first_valid.png" --png-width 1200 >"run/$n.first_valid.render.txt" 2>&1
else
  k=1; while [ -f "drafts/$n.attempt$k.aidl" ]; do k=$((k+1)); done
  kind="attempt $k"
  cp "$src" "drafts/$n.attempt$k.aidl"; cp "$tmp" "drafts/$n.attempt$k.check.txt"
fi
echo "$now  $n  $kind  exit=$rc  errors=$ne  warnings=$nw" >> drafts/log.txt
cat "$tmp"
echo "== $now $n $kind exit=$rc errors=$ne warnings=$nw"
rm -f "$tmp"
