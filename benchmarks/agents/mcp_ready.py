"""Seconds from spawning `aidl mcp` to its first `tools/list` answer, and the server's CPU
seconds by then (issue 95: at most 0.5 s on a quiet machine):

    python benchmarks/agents/mcp_ready.py [N] [--aidl PATH]

Each of N runs (default 7) starts the ``aidl`` command beside this Python (or ``--aidl``) with
``mcp --root`` an empty folder, writes ``initialize``, ``notifications/initialized`` and
``tools/list`` to its stdin at once, as a client does, and reads its stdout until the
``tools/list`` answer: the wall seconds from the spawn to each answer, and the server
process's user + system CPU seconds at that moment (``/proc/PID/stat``, its threads
included).  Plain JSON-RPC lines, no client SDK: the figure is the server's, not a client's
start-up (``mcp_warm.py --wall`` times ``initialize`` through the SDK's client).  The first
run after a change of the sources or of another tree's server (the first answers are kept in
one cache file per user, :mod:`aidl_lang.mcp.fast`) answers from the SDK itself, slower:
runs are printed one by one, with the median and the load average.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

MESSAGES = [
    {"jsonrpc": "2.0", "id": 1, "method": "initialize",
     "params": {"protocolVersion": "2025-06-18", "capabilities": {},
                "clientInfo": {"name": "mcp_ready", "version": "0"}}},
    {"jsonrpc": "2.0", "method": "notifications/initialized"},
    {"jsonrpc": "2.0", "id": 2, "method": "tools/list"},
]


def cpu_seconds(pid: int) -> float:
    """User + system CPU seconds of process ``pid`` so far (all its threads)."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def once(aidl: str, root: str) -> tuple[float, float, float, int]:
    """``(initialize s, tools/list s, server CPU s, tools)`` for one fresh server."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    start = time.perf_counter()
    p = subprocess.Popen([aidl, "mcp", "--root", root], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env, cwd=root)
    try:
        p.stdin.write("".join(json.dumps(m) + "\n" for m in MESSAGES).encode())
        p.stdin.flush()
        init = None
        while True:
            line = p.stdout.readline()
            if not line:
                raise RuntimeError("the server ended before answering tools/list")
            answer = json.loads(line)
            if answer.get("id") == 1:
                init = time.perf_counter() - start
            elif answer.get("id") == 2:
                listed = time.perf_counter() - start
                return init, listed, cpu_seconds(p.pid), len(answer["result"]["tools"])
    finally:
        p.stdin.close()
        p.kill()
        p.wait()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="?", type=int, default=7)
    here = Path(sys.executable).with_name("aidl")
    ap.add_argument("--aidl", default=str(here), help="the aidl command (default: beside python)")
    args = ap.parse_args()
    root = tempfile.mkdtemp()
    got = [once(args.aidl, root) for _ in range(args.runs)]
    for k, (init, listed, cpu, tools) in enumerate(got, 1):
        print(f"run {k}: initialize {init:.3f} s, tools/list {listed:.3f} s (wall), "
              f"server CPU {cpu:.2f} s, {tools} tools")
    print(f"median: tools/list {statistics.median(g[1] for g in got):.3f} s wall, "
          f"server CPU {statistics.median(g[2] for g in got):.2f} s; "
          f"load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
