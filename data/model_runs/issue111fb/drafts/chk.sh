#!/bin/bash
# usage: drafts/chk.sh NN_name   (run from data/model_runs/issue111fb or anywhere)
# Checks drafts/NN_name.aidl, logs time, kind, exit status and the counts of
# error[E / warning[W lines to drafts/log.txt; keeps attempts before the first
# valid, the first valid (rendered), and fixes after it (rendered).
set -u
HERE="$(cd "$(dirname "$0")/.." && pwd)"
N="$1"
SRC="$HERE/drafts/$N.aidl"
AIDL="/work/main/.venv/bin/aidl"
export PYTHONPATH=/work/wt-models-fb
OUT="$(mktemp)"
"$AIDL" check "$SRC" >"$OUT" 2>&1
RC=$?
NE=$(grep -c 'error\[E' "$OUT")
NW=$(grep -c 'warning\[W' "$OUT")
FV="$HERE/run/$N.first_valid.aidl"
if [ -e "$FV" ]; then
    K=$(ls "$HERE/drafts/$N".fix*.aidl 2>/dev/null | wc -l); K=$((K + 1))
    KIND="fix$K"
    cp "$SRC" "$HERE/drafts/$N.fix$K.aidl"; cp "$OUT" "$HERE/drafts/$N.fix$K.check.txt"
    if [ $RC -eq 0 ]; then
        "$AIDL" render "$HERE/drafts/$N.fix$K.aidl" -o "$HERE/drafts/$N.fix$K.png" --png-width 1200 \
            >"$HERE/drafts/$N.fix$K.render.txt" 2>&1
    fi
elif [ $RC -eq 0 ]; then
    KIND="FIRST VALID"
    cp "$SRC" "$FV"; cp "$OUT" "$HERE/run/$N.first_valid.check.txt"
    "$AIDL" render "$FV" -o "$HERE/run/$N.first_valid.png" --png-width 1200 \
        >"$HERE/run/$N.first_valid.render.txt" 2>&1
else
    K=$(ls "$HERE/drafts/$N".attempt*.aidl 2>/dev/null | wc -l); K=$((K + 1))
    KIND="attempt$K"
    cp "$SRC" "$HERE/drafts/$N.attempt$K.aidl"; cp "$OUT" "$HERE/drafts/$N.attempt$K.check.txt"
fi
printf '%s\t%s\t%s\texit=%s\terrors=%s\twarnings=%s\n' "$(date -u '+%Y-%m-%d %H:%M:%S')" "$N" "$KIND" "$RC" "$NE" "$NW" >>"$HERE/drafts/log.txt"
echo "== $N $KIND exit=$RC errors=$NE warnings=$NW"
cat "$OUT"
rm -f "$OUT"
