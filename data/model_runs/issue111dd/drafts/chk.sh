#!/bin/bash
# chk.sh NN_name : check drafts/NN_name.aidl, log it, keep the first valid program (issue111dd)
set -u
here="$(cd "$(dirname "$0")" && pwd)"
run="$here/../run"
name="$1"
src="$here/$name.aidl"
export PYTHONPATH=/work/wt-models-dd
AIDL=/work/main/.venv/bin/aidl
out="$(mktemp)"
stamp="$(date -u '+%Y-%m-%d %H:%M:%S')"
(cd "$here" && "$AIDL" check "$name.aidl") >"$out" 2>&1
rc=$?
ne=$(grep -c 'error\[E' "$out")
nw=$(grep -c 'warning\[W' "$out")
if [ -e "$run/$name.first_valid.aidl" ]; then
    phase="after-first-valid"
elif [ "$rc" -eq 0 ]; then
    phase="FIRST-VALID"
else
    k=$(( $(ls "$here/$name".attempt*.aidl 2>/dev/null | wc -l) + 1 ))
    phase="attempt$k"
fi
echo "$stamp  $name  exit=$rc  errors=$ne  warnings=$nw  $phase" >>"$here/log.txt"
case "$phase" in
  FIRST-VALID)
    cp "$src" "$run/$name.first_valid.aidl"
    cp "$out" "$run/$name.first_valid.check.txt"
    (cd "$run" && "$AIDL" render "$name.first_valid.aidl" -o "$name.first_valid.png" --png-width 1200) \
        >"$run/$name.first_valid.render.txt" 2>&1
    ;;
  attempt*)
    cp "$src" "$here/$name.$phase.aidl"
    cp "$out" "$here/$name.$phase.check.txt"
    ;;
esac
cat "$out"
echo "--- $stamp exit=$rc errors=$ne warnings=$nw $phase"
rm -f "$out"
