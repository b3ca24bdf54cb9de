#!/bin/bash
# usage: drafts/chk.sh NN_name  (run from issue111an/)
cd "$(dirname "$0")/.." || exit 1
N=$1; export PYTHONPATH=/work/wt-models-an; A=/work/main/.venv/bin/aidl
out=$($A check drafts/$N.aidl 2>&1); rc=$?
e=$(grep -c 'error\[E' <<<"$out"); w=$(grep -c 'warning\[W' <<<"$out")
codes=$(grep -o '\(error\|warning\)\[[EW][0-9]*\]' <<<"$out" | sort | uniq -c | tr '\n' ' ')
if [ -f run/$N.first_valid.aidl ]; then kind=after_first_valid
elif [ $rc -eq 0 ]; then kind=first_valid
  cp drafts/$N.aidl run/$N.first_valid.aidl; echo "$out" > run/$N.first_valid.check.txt
  $A render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 > run/$N.first_valid.render.txt 2>&1
else k=1; while [ -f drafts/$N.attempt$k.aidl ]; do k=$((k+1)); done; kind=attempt$k
  cp drafts/$N.aidl drafts/$N.attempt$k.aidl; echo "$out" > drafts/$N.attempt$k.check.txt
fi
echo "$(date -u) $N rc=$rc errors=$e warnings=$w $kind codes: $codes" >> drafts/log.txt
echo "$out"; echo "== $kind rc=$rc"
