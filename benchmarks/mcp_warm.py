"""CPU seconds of `aidl mcp`'s cold start and of its first and second `render` (issue 73):

    python benchmarks/mcp_warm.py [--cold]     # --cold: the server without its warm-up

Starts the server with the SDK's stdio client, initialises it (the server process's CPU
seconds then: the cold start), waits until the warm-up is done (the workers' CPU settles),
then renders the switch plate of benchmarks/mcp_tokens.py twice, each call's CPU seconds
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


if __name__ == "__main__":
    asyncio.run(main("--cold" in sys.argv[1:]))
