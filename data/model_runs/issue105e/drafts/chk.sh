#!/bin/bash
# usage: chk.sh NN_name   (checks drafts/NN_name.aidl; first valid copy kept in run/)
cd /work/wt21-modelse/data/model_runs/issue105e
n=$1
out=$(/work/wt21-modelse/.venv/bin/aidl check drafts/$n.aidl 2>&1); rc=$?
echo "$out"
echo "$(date -u +%H:%M:%S) $n rc=$rc" >> drafts/log.txt
echo "$out" > drafts/$n.last_check.txt
if [ $rc -eq 0 ] && [ ! -f run/$n.first_valid.aidl ]; then
  cp drafts/$n.aidl run/$n.first_valid.aidl
  echo "$out" > run/$n.first_valid.check.txt
  /work/wt21-modelse/.venv/bin/aidl render run/$n.first_valid.aidl -o run/$n.first_valid.png --png-width 1200 2>&1 | tail -3
  echo "== FIRST VALID saved"
fi
echo "rc=$rc"
