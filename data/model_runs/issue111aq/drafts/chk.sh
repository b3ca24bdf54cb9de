#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111aq)
# Checks drafts/NN_name.aidl; logs date, exit status, error/warning counts and codes to drafts/log.txt.
# The FIRST program that checks with exit 0 is kept as run/NN_name.first_valid.aidl (+ .check.txt)
# and rendered to run/NN_name.first_valid.png; a failed check before it is kept as
# drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
cd "$(dirname "$0")/.."
N="$1"
F="drafts/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-aq
OUT=$(mktemp)
"$AIDL" check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
CODES=$(grep -oE '(error|warning|note)\[[EW][0-9]+\]' "$OUT" | sort | uniq -c | awk '{printf "%s x%s ", $2, $1}')
if [ -e "run/$N.first_valid.aidl" ]; then
  STAGE="recheck after first valid"
elif [ $RC -eq 0 ]; then
  STAGE="FIRST VALID"
  cp "$F" "run/$N.first_valid.aidl"
  cp "$OUT" "run/$N.first_valid.check.txt"
  "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >"run/$N.first_valid.render.txt" 2>&1
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  STAGE="failed attempt$K"
  cp "$F" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$(date -u '+%Y-%m-%dT%H:%M:%SZ') $N exit=$RC errors=$NE warnings=$NW [$CODES] $STAGE" >> drafts/log.txt
cat "$OUT"
echo "--- logged: $(tail -1 drafts/log.txt)"
rm -f "$OUT"
