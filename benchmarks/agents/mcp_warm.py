"""CPU seconds of `aidl mcp`'s cold start and of its first and second `render` (issue 73), and
the wall seconds an agent waits (issue 86's warm start):

    python benchmarks/agents/mcp_warm.py [--cold]     # --cold: the server without its warm-up
    python benchmarks/agents/mcp_warm.py --wall [N]   # N runs of: spawn -> initialize, then a first render

``--wall`` starts the installed ``aidl`` command (the console script beside this Python, else
``python -m aidl_lang.cli``) as a client would, times the ``initialize`` answer from the spawn
and the first ``render`` right after it (no waiting for the warm-up), and prints each run and
the worst.  Wall time: run it on the machine you mean (it says the load average).

Starts the server with the SDK's stdio client, initialises it (the server process's CPU
seconds then: the cold start), waits until the warm-up is done (the workers' CPU settles),
then renders the switch plate of benchmarks/agents/mcp_tokens.py twice, each call's CPU seconds
summed over the server and its worker processes (psutil).  CPU, not wall time: the machine
may be loaded."""
import asyncio
import os
import sys
import tempfile
import time
from pathlib import Path

import psutil

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mcp_tokens as M  # noqa: E402


def cpu(tree: psutil.Process) -> float:
    total = 0.0
    for p in [tree, *tree.children(recursive=True)]:
        try:
            t = p.cpu_times()
            total += t.user + t.system
        except psutil.Error:
            pass
    return total


async def main(cold: bool) -> None:
    from mcp.client.session import ClientSession
    from mcp.client.stdio import stdio_client
    root = tempfile.mkdtemp()
    Path(root, "plate.aidl").write_text(M.PLATE)
    params = M.server_params(root)
    if cold:
        params.env = {**(params.env or os.environ), "AIDL_MCP_COLD": "1"}
    me = psutil.Process()
    async with stdio_client(params) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            server = next(p for p in me.children(recursive=True) if "mcp" in " ".join(p.cmdline()))
            print(f"cold start (server process, to initialize): {cpu(psutil.Process(server.pid)) - 0:.2f} CPU s")
            time.sleep(0 if cold else 1)
            last = -1.0
            while not cold:                       # the warm-up in the background: until idle
                now = cpu(server)
                if abs(now - last) < 0.02:
                    break
                last = now
                await asyncio.sleep(1.0)
            for k in (1, 2):
                before = cpu(server)
                r = await session.call_tool("render", {"path": "plate.aidl", "width": 200})
                assert not r.is_error
                print(f"render {k}: {cpu(server) - before:.2f} CPU s")


async def wall_once() -> tuple[float, float]:
    """``(initialize, first render)`` in wall seconds for one fresh server."""
    from mcp.client.session import ClientSession
    from mcp.client.stdio import stdio_client
    root = tempfile.mkdtemp()
    Path(root, "plate.aidl").write_text(M.PLATE)
    params = M.server_params(root)
    script = Path(sys.executable).with_name("aidl")
    if script.exists():
        params.command, params.args = str(script), ["mcp", "--root", root]
    start = time.perf_counter()
    async with stdio_client(params) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            ready = time.perf_counter()
            r = await session.call_tool("render", {"path": "plate.aidl", "output": "plate.svg"})
            assert not r.is_error, r
            return ready - start, time.perf_counter() - ready


def wall(runs: int) -> None:
    times = [asyncio.run(wall_once()) for _ in range(runs)]
    for k, (init, first) in enumerate(times, 1):
        print(f"run {k}: initialize {init:.2f} s, first render {first:.2f} s (wall)")
    print(f"worst: initialize {max(t[0] for t in times):.2f} s, first render "
          f"{max(t[1] for t in times):.2f} s; load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if "--wall" in args:
        rest = [a for a in args if a.isdigit()]
        wall(int(rest[0]) if rest else 5)
    else:
        asyncio.run(main("--cold" in args))
