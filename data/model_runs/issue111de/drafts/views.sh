#!/bin/bash
# usage: drafts/views.sh NN_name [first_valid|fix]  -- sheet and assembled PNGs of a program
D="$(cd "$(dirname "$0")" && pwd)"
N="$1"; K="${2:-first_valid}"
export PYTHONPATH=/work/wt-models-de
A=/work/main/.venv/bin/aidl
if [ "$K" = first_valid ]; then F="$D/../run/$N.first_valid.aidl"; O="$D/../run/$N.first_valid"; else F="$D/$N.aidl"; O="$D/$N.fix"; fi
[ "$K" = first_valid ] || "$A" render "$F" -o "$O.png" --png-width 1200 2>&1 | grep -v '^wrote' | tail -5
"$A" render "$F" -o "$O.sheet.png" --layout sheet --png-width 1200 2>&1 | grep -v '^wrote' | tail -5
"$A" render "$F" -o "$O.assembled.png" --assembled --png-width 1200 2>&1 | grep -v '^wrote' | tail -5
ls "$O"*.png
