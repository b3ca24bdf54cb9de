#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111bb)
# Checks drafts/NN_name.aidl; logs date -u, exit status, error/warning counts to drafts/log.txt.
# The first program that checks with exit 0 is kept as run/NN_name.first_valid.aidl + .check.txt
# and rendered to run/NN_name.first_valid.png; a failed check before it is kept as
# drafts/NN_name.attemptK.aidl + .check.txt.
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-bb
AIDL=/work/main/.venv/bin/aidl
SRC="drafts/$N.aidl"
OUT=$(mktemp)
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
STAMP=$(date -u +%Y-%m-%dT%H:%M:%SZ)
if [ -e "run/$N.first_valid.aidl" ]; then
  KIND="after-first-valid"
elif [ "$RC" -eq 0 ]; then
  KIND="FIRST-VALID"
  cp "$SRC" "run/$N.first_valid.aidl"
  cp "$OUT" "run/$N.first_valid.check.txt"
  "$AIDL" render "run/$N.first_valid.aidl" -o "run/$N.first_valid.png" --png-width 1200 >/dev/null 2>&1 || echo "render failed" >&2
else
  K=1
  while [ -e "drafts/$N.attempt$K.aidl" ]; do K=$((K+1)); done
  KIND="attempt$K"
  cp "$SRC" "drafts/$N.attempt$K.aidl"
  cp "$OUT" "drafts/$N.attempt$K.check.txt"
fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $KIND" >> drafts/log.txt
cat "$OUT"
echo "== $STAMP $N exit=$RC errors=$NE warnings=$NW $KIND"
rm -f "$OUT"
