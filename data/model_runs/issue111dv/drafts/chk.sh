#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep first valid / attempts / fixes.
set -u
cd "$(dirname "$0")/.."            # the run folder issue111dv/
N="$1"
export PYTHONPATH=/work/wt-models-dv
AIDL=/work/main/.venv/bin/aidl
SRC=drafts/$N.aidl
OUT=$(mktemp)
$AIDL check "$SRC" >"$OUT" 2>&1
RC=$?
E=$(grep -c 'error\[E' "$OUT")
W=$(grep -c 'warning\[W' "$OUT")
NOW=$(date -u '+%Y-%m-%d %H:%M:%S')
if [ ! -e run/$N.first_valid.aidl ]; then
  if [ $RC -eq 0 ]; then
    KIND=first_valid
    cp "$SRC" run/$N.first_valid.aidl
    cp "$OUT" run/$N.first_valid.check.txt
    $AIDL render run/$N.first_valid.aidl -o run/$N.first_valid.png --png-width 1200 \
      >run/$N.first_valid.render.txt 2>&1
  else
    K=1; while [ -e drafts/$N.attempt$K.aidl ]; do K=$((K+1)); done
    KIND=attempt$K
    cp "$SRC" drafts/$N.attempt$K.aidl
    cp "$OUT" drafts/$N.attempt$K.check.txt
  fi
else
  K=1; while [ -e drafts/$N.fix$K.aidl ]; do K=$((K+1)); done
  KIND=fix$K
  cp "$SRC" drafts/$N.fix$K.aidl
  cp "$OUT" drafts/$N.fix$K.check.txt
fi
echo "$NOW $N exit=$RC errors=$E warnings=$W $KIND" >>drafts/log.txt
cat "$OUT"
echo "== $NOW $N exit=$RC errors=$E warnings=$W $KIND"
rm -f "$OUT"
