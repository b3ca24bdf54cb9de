"""Start ``aidl studio --port 0`` in a subprocess and yield its URL (the browser test and the
load test, benchmarks/serve/studio_load.py, share it)."""
from __future__ import annotations

import contextlib
import os
import sys
from pathlib import Path

from benchmarks.serve.serve_latency import launched


@contextlib.contextmanager
def studio(*args: str, env: dict | None = None, timeout: float = 60.0):
    """Run ``aidl studio --port 0 ARGS`` (this environment's ``aidl``); yield ``(url, proc)``;
    stop it after."""
    exe = Path(sys.executable).with_name("aidl")
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "aidl_lang.cli"]
    # the gallery is not swept ahead of time (issue 113: minutes of CPU beside a test) unless
    # asked: AIDL_STUDIO_AHEAD in ``env``
    with launched(cmd + ["studio", "--port", "0", *args],
                  env={**os.environ, "AIDL_STUDIO_AHEAD": "none", **(env or {})},
                  timeout=timeout) as got:
        yield got
