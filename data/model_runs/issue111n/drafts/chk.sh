#!/bin/bash
# usage (from data/model_runs/issue111n): drafts/chk.sh NN_name
# Checks drafts/NN_name.aidl with this tree's CLI, logs one line to drafts/log.txt,
# keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, + .png rendered at 1200 px); a failed check before it is kept as
# drafts/NN_name.attemptK.aidl + .check.txt.
set -u
N="$1"
AIDL="env PYTHONPATH=/work/wt-models-n /work/main/.venv/bin/aidl"
F="drafts/$N.aidl"
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
K=$(ls drafts/$N.attempt*.aidl 2>/dev/null | wc -l)
FIRST=""
if [ ! -e "run/$N.first_valid.aidl" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "run/$N.first_valid.aidl"; cp "$OUT" "run/$N.first_valid.check.txt"
    $AIDL render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1
    FIRST=" first_valid"
  else
    K=$((K+1)); cp "$F" "drafts/$N.attempt$K.aidl"; cp "$OUT" "drafts/$N.attempt$K.check.txt"
    FIRST=" attempt$K"
  fi
fi
echo "$(date -u '+%Y-%m-%d %H:%M:%S') $N exit=$RC errors=$NE warnings=$NW$FIRST" >> drafts/log.txt
cat "$OUT"; rm -f "$OUT"
