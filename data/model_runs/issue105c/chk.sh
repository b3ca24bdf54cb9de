#!/bin/bash
# usage: chk.sh NN_name   (checks work/NN_name.aidl; keeps the first valid one)
cd /work/wt20-models2/data/model_runs/issue105c
n=$1; f=work/$n.aidl
att=$(ls work/$n.attempt*.txt 2>/dev/null | wc -l); att=$((att+1))
/work/wt20-models2/.venv/bin/aidl check $f > work/$n.attempt$att.txt 2>&1; rc=$?
cp $f work/$n.attempt$att.aidl
cat work/$n.attempt$att.txt; echo "rc=$rc attempt=$att"
if [ $rc -eq 0 ] && [ ! -f run/$n.first_valid.aidl ]; then
  cp $f run/$n.first_valid.aidl; cp work/$n.attempt$att.txt run/$n.first_valid.check.txt
  echo "attempt $att" > run/$n.first_valid.attempt
  /work/wt20-models2/.venv/bin/aidl render run/$n.first_valid.aidl -o run/$n.first_valid.png --png-width 1200 >/dev/null 2>&1 && echo RENDERED
fi
