#!/bin/bash
# usage: ck.sh NN_name   (checks NN_name.work.aidl; first valid copied to NN_name.first_valid.aidl)
cd /work/wt-models/data/model_runs/issue105/run
f=$1.work.aidl
n=$(cat $1.checks 2>/dev/null || echo 0); n=$((n+1)); echo $n > $1.checks
out=$(/work/wt-models/.venv/bin/aidl check $f 2>&1); rc=$?
echo "$out"; echo "rc=$rc check#$n"
if [ $rc -eq 0 ] && [ ! -f $1.first_valid.aidl ]; then cp $f $1.first_valid.aidl; echo "$out" > $1.first_valid.check.txt; echo "n=$n" >> $1.first_valid.check.txt; /work/wt-models/.venv/bin/aidl render $1.first_valid.aidl -o $1.first_valid.png --png-width 1200 && echo RENDERED; fi
