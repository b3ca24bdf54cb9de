#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111ca or anywhere)
# Checks drafts/NN_name.aidl, logs date, exit status and counts of error[E / warning[W lines
# to drafts/log.txt. Keeps the FIRST program that checks with exit 0 as run/NN_name.first_valid.aidl
# (+ .check.txt, + rendered .png); failed checks before it as drafts/NN_name.attemptK.aidl (+ .check.txt).
set -u
HERE="$(cd "$(dirname "$0")" && pwd)"
BASE="$(dirname "$HERE")"
N="$1"
F="$HERE/$N.aidl"
export PYTHONPATH=/work/wt-models-ca
AIDL=/work/main/.venv/bin/aidl
OUT="$(mktemp)"
STAMP="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$BASE/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then PHASE="after-first-valid"; else PHASE="before-first-valid"; fi
echo "$STAMP $N exit=$RC errors=$NE warnings=$NW $PHASE" >> "$HERE/log.txt"
cat "$OUT"
if [ ! -e "$FV" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" "$FV"; cp "$OUT" "$BASE/run/$N.first_valid.check.txt"
    $AIDL render "$FV" -o "$BASE/run/$N.first_valid.png" --png-width 1200 > "$BASE/run/$N.first_valid.render.txt" 2>&1
    echo "== FIRST VALID kept: run/$N.first_valid.aidl (render exit $?)"
  else
    K=1; while [ -e "$HERE/$N.attempt$K.aidl" ]; do K=$((K+1)); done
    cp "$F" "$HERE/$N.attempt$K.aidl"; cp "$OUT" "$HERE/$N.attempt$K.check.txt"
    echo "== failed attempt kept: drafts/$N.attempt$K.aidl"
  fi
fi
rm -f "$OUT"
exit $RC
