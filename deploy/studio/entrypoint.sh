#!/bin/sh
# The studio image's entry point (deploy/studio/Containerfile; docs/studio.md, "An image to
# deploy"): one `aidl studio` process on one port, its settings from the environment:
#   PORT                    the port (default 8780), on every interface of the container
#   AIDL_STUDIO_STORE       redis://HOST:PORT/DB: uploads and rate counters in Redis
#   AIDL_STUDIO_SCHEDULER   tcp://HOST:PORT: compiles on a Dask cluster
#   AIDL_STUDIO_COMPILERS   local compile workers (default 2)
# and the other AIDL_STUDIO_* variables `aidl studio` reads itself (RATE, MEMORY_MB, WAIT,
# QUEUE, MODEL_URL, ...).  Arguments are passed on to `aidl studio`.  One process per
# container: scale with containers behind the proxy (each one's /metrics is its own).
set -eu
PORT="${PORT:-8780}"
case "$PORT" in
    ''|*[!0-9]*) echo "aidl-studio: PORT must be a port number, got '$PORT'" >&2; exit 2 ;;
esac
COMPILERS="${AIDL_STUDIO_COMPILERS:-2}"
case "$COMPILERS" in
    ''|*[!0-9]*) echo "aidl-studio: AIDL_STUDIO_COMPILERS must be a number, got '$COMPILERS'" >&2
                 exit 2 ;;
esac
set -- --host "${AIDL_STUDIO_HOST:-0.0.0.0}" --port "$PORT" --compilers "$COMPILERS" "$@"
if [ -n "${AIDL_STUDIO_STORE:-}" ]; then set -- "$@" --store "$AIDL_STUDIO_STORE"; fi
if [ -n "${AIDL_STUDIO_SCHEDULER:-}" ]; then set -- "$@" --scheduler "$AIDL_STUDIO_SCHEDULER"; fi
exec aidl studio "$@"
