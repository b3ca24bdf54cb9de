"""Issue 95, what an agent reads: every result whole in its text (a host may show the model
the text only), paths as the agent names them (relative to the root, `std/...`, `<source>`),
an unknown tool a JSON-RPC -32602 error, a `values` name that matches nothing said; and
issue 91's `measure` of the root assembly.  Through the official SDK's stdio client; the
start-up test runs the server with a probe that reports, at the first tools/list, which
heavy modules it has loaded."""
import contextlib
import json
import os
import sys

import pytest

mcp = pytest.importorskip("mcp")
from mcp.client.session import ClientSession  # noqa: E402
from mcp.client.stdio import StdioServerParameters, stdio_client  # noqa: E402
from mcp.shared.exceptions import MCPError  # noqa: E402

from conftest import ROOT  # noqa: E402
from test_mcp import GOOD, _server, _text  # noqa: E402

KIT = """units mm
assembly kit {
    solid a { c = Circle(center=(0, 0), radius=10) }
    solid b { c = Circle(center=(15, 0), radius=10) }
}
"""
# the template's assert refuses the argument at the call; its line in the library is a note
WRONG_GEAR = ('units mm\nimport "std/gears.aidl"\nsolid s {\n'
              '    g = spur_gear(teeth=12, module=0 mm)\n}\n')


@contextlib.asynccontextmanager
async def _session(params, log=None):
    async with stdio_client(params, **({"errlog": log} if log else {})) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            yield session


def _no_server_paths(result, root) -> None:
    """Neither the root's absolute path, the install folder nor `untitled.aidl` anywhere."""
    said = _text(result) + json.dumps(result.structured_content)
    for bad in (str(root), str(ROOT / "aidl_lang"), "untitled.aidl"):
        assert bad not in said, (bad, said[:2000])


@pytest.mark.asyncio
async def test_every_answer_is_whole_in_its_text_with_the_agents_paths(tmp_path):
    (tmp_path / "plate.aidl").write_text(GOOD)
    (tmp_path / "kit.aidl").write_text(KIT)
    async with _session(_server(tmp_path)) as session:
        # a broken program given as source: located at <source>, with its hint and fix
        r = await session.call_tool("check", {"source": "units mm\nsolid s { c = Circel("
                                                        "center=(0, 0), radius=4) }\n"})
        text = _text(r)
        assert text.splitlines()[0] == "not ok: 1 error; no warnings", text
        assert "error E0103 at <source>:2:15: unknown function `Circel`" in text
        assert "did you mean `Circle`?" in text and "with `Circle`" in text
        assert r.structured_content["diagnostics"][0]["span"]["file"] == "<source>"
        _no_server_paths(r, tmp_path)
        # inside the standard library: std/gears.aidl, never the install folder
        r = await session.call_tool("check", {"source": WRONG_GEAR})
        assert "std/gears.aidl:" in _text(r)
        _no_server_paths(r, tmp_path)
        # a file of the root: its name relative to the root
        (tmp_path / "sub").mkdir()
        (tmp_path / "sub" / "bad.aidl").write_text("solid s {\n")
        r = await session.call_tool("check", {"path": "sub/bad.aidl"})
        assert "error E0001 at sub/bad.aidl:1:9" in _text(r), _text(r)
        _no_server_paths(r, tmp_path)
        # values: every value a line of text; a name that matches nothing said
        r = await session.call_tool("values", {"path": "plate.aidl",
                                               "names": ["bore.c", "screws"]})
        lines = _text(r).splitlines()
        assert "no value matches `screws`" in lines[0], lines
        assert lines[1:] == ["plate.bore.c.center = (10, 0) mm", "plate.bore.c.radius = 4 mm",
                             "plate.bore.c.diameter = 8 mm"]
        assert r.structured_content["unmatched"] == ["no value matches `screws`"]
        # describe: the description itself, line by line
        r = await session.call_tool("describe", {"path": "plate.aidl"})
        assert "outline: rectangle 40 x 20" in _text(r) and "circle d=8 at (10, 0)" in _text(r)
        # check with dof: the freedom per structure
        r = await session.call_tool("check", {"path": "plate.aidl", "dof": True})
        assert "plate: " in _text(r) and "free" in _text(r)
        # measure, the root assembly too (issue 91: an internal error)
        r = await session.call_tool("measure", {"path": "kit.aidl", "a": "a", "b": "b"})
        assert not r.is_error
        assert "clearance -5 mm (overlapping), overlap_area 45.331175 mm²" in _text(r)
        assert r.structured_content["measure"]["overlap_area"] == pytest.approx(
            45.331175398, abs=1e-9)
        r = await session.call_tool("measure", {"path": "kit.aidl", "a": "kit", "b": "b"})
        assert not r.is_error, _text(r)
        m = r.structured_content["measure"]
        assert m["a"]["kind"] == "assembly" and m["contact"] == "overlapping"
        assert "kit (assembly) to b (part)" in _text(r) and "overlap_area 314" in _text(r)
        for r in (await session.call_tool("render", {"path": "plate.aidl",
                                                     "output": "plate.dxf"}),):
            assert "wrote plate.dxf" in _text(r)
            assert "structured content" not in _text(r)
        # an unknown tool: JSON-RPC invalid params (the MCP spec), not an isError result
        with pytest.raises(MCPError) as e:
            await session.call_tool("chek", {"path": "plate.aidl"})
        assert e.value.error.code == -32602
        assert "Unknown tool: `chek`; did you mean `check`?" in e.value.error.message


PROBE = """import runpy, sys
import aidl_lang.mcp.server as S
listed = S._Server.list_tools
async def list_tools(self):
    heavy = [m for m in ("numpy", "scipy", "manifold3d", "lark", "shapely", "ezdxf", "PIL")
             if m in sys.modules]
    print("HEAVY", heavy, len(sys.modules), file=sys.stderr, flush=True)
    return await listed(self)
S._Server.list_tools = list_tools
sys.argv = ["aidl", "mcp", "--root", sys.argv[1]]
runpy.run_module("aidl_lang.cli", run_name="__main__")
"""


@pytest.mark.asyncio
async def test_no_heavy_module_is_loaded_before_the_first_tools_list(tmp_path):
    """Issue 95: the server is ready for tools/list without numpy, SciPy, Manifold, lark,
    shapely, ezdxf or Pillow in its process (they load in the workers, or when a call needs
    them); 795 modules with numpy and Manifold before, about 660 after."""
    env = {k: v for k, v in os.environ.items() if k != "AIDL_DEBUG"}
    env["XDG_CACHE_HOME"] = str(tmp_path / "cache")     # the SDK's own tools/list, no cache
    params = StdioServerParameters(command=sys.executable,
                                   args=["-c", PROBE, str(tmp_path)], env=env, cwd=str(ROOT))
    log = tmp_path / "server.log"
    with open(log, "w") as f:
        async with _session(params, f) as session:
            tools = (await session.list_tools()).tools
            assert len(tools) == 10
    said = [ln for ln in log.read_text().splitlines() if ln.startswith("HEAVY")]
    assert said and said[0].startswith("HEAVY [] "), log.read_text()[-2000:]
    assert int(said[0].split()[-1]) < 750, said


def test_the_listed_output_formats_are_the_writers():
    """`render`'s description names the writers' formats without importing them."""
    from aidl_lang.mcp.server import OUTPUT_FORMATS
    from aidl_lang.output.writers import FORMATS
    assert list(OUTPUT_FORMATS) == [k for k in FORMATS if k != ".stp"]


@pytest.mark.asyncio
async def test_the_second_start_answers_initialize_and_tools_list_before_the_sdk_loads(
        tmp_path):
    """Issue 95: the SDK's answers to `initialize` and `tools/list` are kept (the user's cache
    folder, keyed by the versions and every source file); the next server answers them from
    there while the SDK loads (0.3 s to tools/list beside load 13 on 2 cores, was 4-6 s), the
    same answers to the SDK's client, and the session goes on as usual: a call after them is
    answered by the SDK's server, which read the replayed `initialize`."""
    env = {k: v for k, v in os.environ.items() if k != "AIDL_DEBUG"}
    env["XDG_CACHE_HOME"] = str(tmp_path / "cache")
    params = StdioServerParameters(command=sys.executable, env=env, cwd=str(ROOT), args=[
        "-m", "aidl_lang.cli", "mcp", "--root", str(tmp_path)])
    said = []
    for k in range(2):
        log = tmp_path / f"server{k}.log"
        with open(log, "w") as f:
            async with stdio_client(params, errlog=f) as (read, write):
                async with ClientSession(read, write) as session:
                    init = await session.initialize()
                    tools = await session.list_tools()
                    r = await session.call_tool("check", {"source": GOOD})
                    assert not r.is_error and r.structured_content["ok"], _text(r)
        said.append((init.model_dump(), tools.model_dump(), log.read_text()))
    assert (tmp_path / "cache" / "aidl" / "mcp-first-answers.json").is_file()
    assert said[0][:2] == said[1][:2]
    assert "answered from the cache" not in said[0][2]
    assert "initialize and tools/list answered from the cache" in said[1][2], said[1][2]
