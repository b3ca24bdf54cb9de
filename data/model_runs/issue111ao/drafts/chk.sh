#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ao)
# checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first exit-0 program
# as run/NN_name.first_valid.aidl (+ .check.txt, .png); failures before it as
# drafts/NN_name.attemptK.aidl (+ .check.txt)
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-ao
A=/work/main/.venv/bin/aidl
F="drafts/$N.aidl"
OUT=$(mktemp)
$A check "$F" > "$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
CODES=$(grep -o '\(error\|warning\)\[[EW][0-9]*\]' "$OUT" | sed 's/.*\[\(.*\)\]/\1/' | sort | uniq -c | awk '{printf "%s%s ", $2, ($1>1?"x"$1:"")}')
STAMP=$(date -u)
if [ -e "run/$N.first_valid.aidl" ]; then
  KIND="recheck after first valid"
elif [ $RC -eq 0 ]; then
  KIND="FIRST VALID"
  cp "$F" "run/$N.first_valid.aidl"
  cp "$OUT" "run/$N.first_valid.check.txt"
  $A render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 > "run/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="failed attempt $K"
  cp "$F" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP | $N | exit $RC | errors $NE | warnings $NW | $CODES| $KIND" >> drafts/log.txt
cat "$OUT"
echo "--- $STAMP exit $RC errors $NE warnings $NW [$KIND]"
rm -f "$OUT"
