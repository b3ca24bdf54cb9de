#!/bin/bash
PYTHONPATH=/work/wt-models-du exec /work/main/.venv/bin/aidl "$@"
