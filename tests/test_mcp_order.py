"""Issue 91: the MCP server writes files in the order the calls were made, and a cancelled call
writes nothing.  Through the official SDK's stdio client (a real server subprocess), as an
agent would: render A (a panel of 20,000 holes) to race.gcode, cancel it, render B (a 10 mm
disc) to the same file; the file is B's G-code, read back by gcodeparser, and stays so; and
three edits of one program sent together all land."""
import asyncio
import contextlib
import itertools
import re

import pytest

mcp = pytest.importorskip("mcp")
from mcp.client.session import ClientSession  # noqa: E402
from mcp.client.stdio import stdio_client  # noqa: E402

from test_mcp import _server, _text  # noqa: E402

# 20,000 holes: about 10 s of CPU to render in full on a quiet machine (cancelled at once)
PANEL = ("units mm\nsolid panel {\n    body = Rectangle(center=(0, 0), width=1010, height=410)\n"
         "    for i in range(100) { for j in range(N) {\n"
         "        hole h { c = Circle(center=(i * 10 - 495, j * 10 - 195), radius=3) }\n"
         "    } }\n}\n")
DISC = "units mm\nsolid disc { c = Circle(center=(0, 0), radius=5) }\n"


def _arcs(path) -> int:
    """The cutting arcs (G2/G3) of a G-code file, read by gcodeparser: the disc is cut as
    arcs, a hole each at least."""
    from gcodeparser import parse_gcode_lines
    lines = parse_gcode_lines(path.read_text())
    return sum(1 for ln in lines if ln.command in (("G", 2), ("G", 3)))


@contextlib.asynccontextmanager
async def _session(root, log):
    async with stdio_client(_server(root), errlog=log) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            yield session


async def _logged(log_path, pattern: str, polls: int = 2400) -> str:
    """The server's log once a line matches ``pattern`` (polled every 50 ms: a hang guard,
    not a timing bound)."""
    for _ in range(polls):
        text = log_path.read_text()
        if re.search(pattern, text):
            return text
        await asyncio.sleep(0.05)
    raise AssertionError(f"the server never logged {pattern!r}:\n{log_path.read_text()}")


@pytest.mark.asyncio
async def test_a_cancelled_render_never_writes_and_the_last_call_made_wins(tmp_path):
    log_path = tmp_path / "server.log"
    (tmp_path / "panel.aidl").write_text(PANEL.replace("N", "200"))
    (tmp_path / "small.aidl").write_text(PANEL.replace("N", "6"))
    (tmp_path / "disc.aidl").write_text(DISC)
    (tmp_path / "p.aidl").write_text(
        "units mm\nparam w = 40 mm\nparam h = 20 mm\nparam r = 4 mm\n"
        "solid plate {\n    body = Rectangle(center=(0, 0), width=w, height=h)\n"
        "    hole bore { c = Circle(center=(0, 0), radius=r) }\n}\n")
    with open(log_path, "w") as log:
        async with _session(tmp_path, log) as session:
            # the disc alone: its arcs, the count the file must have at the end
            r = await session.call_tool("render", {"path": "disc.aidl", "output": "disc.gcode"})
            assert not r.is_error, _text(r)
            disc = _arcs(tmp_path / "disc.gcode")
            assert disc >= 1
            # A: the panel, cancelled (the SDK sends notifications/cancelled) while it runs
            a = asyncio.create_task(session.call_tool(
                "render", {"path": "panel.aidl", "output": "race.gcode"}))
            await asyncio.sleep(0)
            r = await session.call_tool("check", {"path": "disc.aidl"})   # A is in flight
            assert not r.is_error and not a.done()
            a.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await a
            said = await _logged(log_path, r"#2 render cancelled")
            assert "#2 render cancelled: its worker process was stopped; it writes nothing" \
                in said, said
            # B: the disc to the same file, called after A
            r = await session.call_tool("render", {"path": "disc.aidl", "output": "race.gcode"})
            assert not r.is_error and "wrote race.gcode" in _text(r), _text(r)
            # two renders to one file, neither cancelled: the one made last wins whatever
            # finishes last (the small panel, 600 holes, made first, finishes after the disc)
            first = asyncio.create_task(session.call_tool(
                "render", {"path": "small.aidl", "output": "race2.gcode"}))
            await asyncio.sleep(0)
            last = await session.call_tool("render", {"path": "disc.aidl",
                                                      "output": "race2.gcode"})
            first = await first
            assert not last.is_error and not first.is_error, (_text(last), _text(first))
            if "superseded" in first.structured_content:    # it finished after the disc
                assert "written" not in first.structured_content
                assert re.search(r"race2\.gcode not written: call #\d+, made after this one",
                                 _text(first)), _text(first)
            # three edits of one program made together (set_params) take turns in call
            # order: all three params end up set (before, they ran side by side and one was
            # lost: `h` stayed 20 mm)
            got = await asyncio.gather(*(session.call_tool("set_params", {
                "path": "p.aidl", "values": {k: v}})
                for k, v in (("w", "50 mm"), ("h", "30 mm"), ("r", "5 mm"))))
            assert all(not r.is_error and r.structured_content["ok"] for r in got), \
                [_text(r) for r in got]
            # a call made after them all: A's worker is gone, nothing of it is left to write
            r = await session.call_tool("check", {"path": "disc.aidl"})
            assert not r.is_error
    text = (tmp_path / "p.aidl").read_text()
    assert "param w = 50 mm" in text and "param h = 30 mm" in text and "param r = 5 mm" in text
    said = log_path.read_text()
    edits = [int(n) for n in re.findall(r"#(\d+) set_params wrote p\.aidl", said)]
    assert len(edits) == 3 and edits == sorted(edits), said
    assert not re.search(r"#2 render wrote", said), said
    assert _arcs(tmp_path / "race.gcode") == disc
    assert _arcs(tmp_path / "race2.gcode") == disc


def test_the_file_is_the_last_calls_whatever_order_they_finish_in(tmp_path):
    """The law under :meth:`Calls.write`: for every order in which 4 calls to one file finish
    (24 orders, each with none or one of them cancelled: 120 cases), the file holds the
    last-made call's bytes among those not cancelled, and each call not written names a later
    one."""
    from aidl_lang.mcp.order import Calls
    target = tmp_path / "f.gcode"
    cases = 0
    for finish in itertools.permutations(range(4)):
        for cancelled in (None, 0, 1, 2, 3):
            disk: dict = {}
            calls = Calls(lambda t, data, program, shown: disk.__setitem__(t, data))
            made = [calls.arrive("render") for _ in range(4)]
            if cancelled is not None:
                calls.cancel(made[cancelled])
            for k in finish:
                kept = calls.write(made[k], [(target, f"call {k}".encode(), None, "f.gcode")])
                for _, _, later in kept:
                    assert later == 0 if k == cancelled else later > made[k].seq
            live = [k for k in range(4) if k != cancelled]
            assert disk[target] == f"call {max(live)}".encode()
            cases += 1
    assert cases == 120
