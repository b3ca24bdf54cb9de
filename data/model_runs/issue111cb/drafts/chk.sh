#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111cb)
# checks drafts/NN_name.aidl, logs to drafts/log.txt; keeps the first valid program in run/,
# failed attempts before it as drafts/NN_name.attemptK.aidl + .check.txt
set -u
cd "$(dirname "$0")/.."
N="$1"
export PYTHONPATH=/work/wt-models-cb
AIDL=/work/main/.venv/bin/aidl
F=drafts/$N.aidl
OUT=$(mktemp)
$AIDL check "$F" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
if [ -e run/$N.first_valid.aidl ]; then STATE="after-first-valid"; else STATE="before-first-valid"; fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) $N exit=$RC errors=$E warnings=$W ($STATE)" >> drafts/log.txt
cat "$OUT"
if [ "$STATE" = "before-first-valid" ]; then
  if [ $RC -eq 0 ]; then
    cp "$F" run/$N.first_valid.aidl
    cp "$OUT" run/$N.first_valid.check.txt
    $AIDL render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 > run/$N.first_valid.render.txt 2>&1
    echo "render exit=$? (run/$N.first_valid.png)"
    echo "   kept as run/$N.first_valid.aidl" >> drafts/log.txt
  else
    K=1; while [ -e drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    cp "$F" drafts/$N.attempt$K.aidl
    cp "$OUT" drafts/$N.attempt$K.check.txt
    echo "   kept as drafts/$N.attempt$K.aidl" >> drafts/log.txt
  fi
fi
rm -f "$OUT"
exit $RC
