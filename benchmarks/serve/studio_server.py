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
    with launched(cmd + ["studio", "--port", "0", *args], env={**os.environ, **(env or {})},
                  timeout=timeout) as got:
        yield got
