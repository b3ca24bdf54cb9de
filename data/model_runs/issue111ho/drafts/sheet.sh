#!/bin/bash
# sheet.sh FILE.aidl OUT.png : render an assembly as --layout sheet (for looking only)
export PYTHONPATH=/work/wt-models-ho
/work/main/.venv/bin/aidl render "$1" -o "$2" --png-width 1200 --layout sheet
