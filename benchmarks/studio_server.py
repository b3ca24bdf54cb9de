"""Start ``aidl studio --port 0`` in a subprocess and yield its URL (the browser test and the
load test, benchmarks/studio_load.py, share it)."""
from __future__ import annotations

import contextlib
import os
import re
import subprocess
import sys
import time
from pathlib import Path


@contextlib.contextmanager
def studio(*args: str, env: dict | None = None, timeout: float = 60.0):
    """Run ``aidl studio --port 0 ARGS`` (this environment's ``aidl``); yield ``(url, proc)``;
    stop it after (SIGTERM, then SIGKILL)."""
    exe = Path(sys.executable).with_name("aidl")
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "aidl_lang.cli"]
    proc = subprocess.Popen(cmd + ["studio", "--port", "0", *args], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True,
                            env={**os.environ, **(env or {})})
    try:
        deadline = time.monotonic() + timeout
        url = None
        while time.monotonic() < deadline:
            line = proc.stdout.readline()
            if not line:
                break
            m = re.search(r"(http://[^/\s]+/)", line)
            if m:
                url = m.group(1)
                break
        if url is None:
            raise RuntimeError("aidl studio did not start: "
                               + (proc.stdout.read() if proc.poll() is not None else ""))
        yield url, proc
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
