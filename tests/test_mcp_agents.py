"""What an agent sees of `aidl mcp` (issue 48, finding 5), through the official SDK's stdio
client as in tests/test_mcp.py: calls run side by side, results carry structured content
matching each tool's output schema, the arguments' schema states the source/path choice and
refuses unknown names, and the messages name tools and arguments instead of command-line
flags."""
import asyncio
import contextlib
import json
import time

import pytest

mcp = pytest.importorskip("mcp")
from mcp.client.session import ClientSession  # noqa: E402
from mcp.client.stdio import stdio_client  # noqa: E402

from test_mcp import GOOD, _server, _text  # noqa: E402

# runs until its evaluation budget's 15 s of wall time (E0304): the shape checks of 3,000
# overlapping holes
SLOW = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
        "    for i in range(3000) { hole h { c = Circle(center=(i * 0.001, 0), radius=1) } }\n"
        "}\n")


@contextlib.asynccontextmanager
async def _session(root):
    async with stdio_client(_server(root)) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            yield session


@pytest.mark.asyncio
async def test_a_slow_call_delays_only_itself(tmp_path):
    """Calls run side by side in the pool of worker processes: a check issued while a slow
    compile runs to its budget answers within seconds, and the slow one still ends."""
    async with _session(tmp_path) as session:
        slow = asyncio.create_task(session.call_tool("check", {"source": SLOW}))
        await asyncio.sleep(1.0)
        t0 = time.monotonic()
        r = await session.call_tool("check", {"source": GOOD})
        fast = time.monotonic() - t0
        assert not r.is_error and json.loads(_text(r))["ok"], _text(r)
        assert fast < 10, f"the fast check waited {fast:.1f} s"
        assert not slow.done()
        r = await slow
        if r.is_error:                      # a machine too busy to end it within 30 s
            assert "took longer than" in _text(r)
        else:
            doc = json.loads(_text(r))
            assert not doc["ok"] and "E0304" in [d["code"] for d in doc["diagnostics"]]
