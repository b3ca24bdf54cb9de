"""`aidl mcp` started as a subprocess and driven by the official SDK's own stdio client
(`mcp.client.stdio.stdio_client` + `ClientSession`): tools, resources, a located diagnostic,
a PNG image block, solved values, a file written inside the root and paths refused outside
it (also through a symlink)."""
import asyncio
import base64
import contextlib
import json
import os
import sys

import pytest
import pytest_asyncio

mcp = pytest.importorskip("mcp")
from mcp.client.session import ClientSession  # noqa: E402
from mcp.client.stdio import StdioServerParameters, stdio_client  # noqa: E402

from aidl_lang.mcp import tools as T  # noqa: E402
from conftest import ROOT  # noqa: E402

GOOD = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole bore { c = Circle(center=(10, 0), radius=4) }
}
"""

BROKEN = """solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    c = Circel(center=(0, 0), radius=5)
}
"""


def _server(root) -> StdioServerParameters:
    """`aidl mcp --root ROOT` as the SDK's stdio client starts it (AIDL_DEBUG unset)."""
    env = {k: v for k, v in os.environ.items() if k != "AIDL_DEBUG"}
    return StdioServerParameters(command=sys.executable,
                                 args=["-m", "aidl_lang.cli", "mcp", "--root", str(root)],
                                 env=env, cwd=str(ROOT))


@contextlib.asynccontextmanager
async def _session(root):
    async with stdio_client(_server(root)) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            yield session


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def shared(tmp_path_factory):
    """One `aidl mcp --root ROOT` for the tests of a module that need no server of their own
    (each test's files have their own names in ROOT), imported by each module that shares
    one: a server and its worker pool start once per module, not once per test.  The session
    lives in a task of its own, as the SDK's task group must be entered and left in one
    task."""
    root = tmp_path_factory.mktemp("mcp-root")
    ready = asyncio.get_running_loop().create_future()
    stop = asyncio.Event()

    async def hold():
        try:
            async with _session(root) as session:
                ready.set_result(session)
                await stop.wait()
        except BaseException as e:
            if not ready.done():
                ready.set_exception(e)
            raise
    task = asyncio.create_task(hold())
    session = await ready
    yield session, root
    stop.set()
    await task


def _text(result) -> str:
    return "\n".join(c.text for c in result.content if c.type == "text")


def _doc(result) -> dict:
    """The structured content of a result (its text is one line: issue 73)."""
    return result.structured_content


@pytest.mark.asyncio
async def test_mcp_server_over_stdio(tmp_path):
    root = tmp_path / "work"
    root.mkdir()
    (root / "plate.aidl").write_text(GOOD)
    outside = tmp_path / "secret.aidl"
    outside.write_text(GOOD)
    (root / "escape.aidl").symlink_to(outside)
    params = _server(root)
    async with stdio_client(params) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            tools = {t.name: t for t in (await session.list_tools()).tools}
            assert set(tools) == {"check", "render", "values", "describe", "explain", "docs",
                                  "import_drawing", "write_program", "set_params", "measure"}
            assert "source" in tools["check"].input_schema["properties"]
            assert tools["check"].annotations.read_only_hint
            assert not tools["render"].annotations.read_only_hint

            # a broken program: a located diagnostic with its fix
            r = await session.call_tool("check", {"source": BROKEN})
            assert not r.is_error
            doc = _doc((r))
            assert doc["ok"] is False
            [d] = doc["diagnostics"]
            assert d["code"] == "E0103" and d["span"]["line"] == 3 and d["span"]["column"] == 9
            assert d["fix"]["replacement"] == "Circle"

            # a good one by path: ok, degrees of freedom, parts
            doc = _doc((await session.call_tool("check", {"path": "plate.aidl"})))
            assert doc["ok"] and doc["freedom"]["dof"] >= 0
            assert doc["parts"][0]["holes"] == 1

            # describe: the part in words and numbers (the d=8 bore at (10, 0))
            doc = _doc((await session.call_tool("describe", {"path": "plate.aidl"})))
            assert doc["ok"] and "circle d=8 at (10, 0)" in doc["text"]
            assert doc["describe"]["parts"][0]["openings"][0]["center"] == [10, 0]
            assert tools["describe"].annotations.read_only_hint

            # render: an image block (asked: `picture`) that decodes to a PNG of the asked
            # width, and a DXF
            r = await session.call_tool("render", {"path": "plate.aidl", "width": 300,
                                                   "picture": True,
                                                   "output": "out/../plate.dxf"})
            assert not r.is_error, _text(r)
            [img] = [c for c in r.content if c.type == "image"]
            assert img.mime_type == "image/png"
            png = base64.b64decode(img.data)
            assert png[:8] == b"\x89PNG\r\n\x1a\n" and int.from_bytes(png[16:20], "big") == 300
            assert _doc((r))["written"] == "plate.dxf"
            assert (root / "plate.dxf").read_text().lstrip().startswith("0")

            # a value, in the file's units
            doc = _doc((await session.call_tool(
                "values", {"path": "plate.aidl", "names": ["bore.c"], "detail": True})))
            assert doc["text"].splitlines() == ["plate.bore.c.center = (10.000, 0.000) mm",
                                                "plate.bore.c.radius = 4.000 mm",
                                                "plate.bore.c.diameter = 8.000 mm"]

            # refused: outside the root, directly, by `..` and through a symlink
            for args in ({"path": str(outside)}, {"path": "../secret.aidl"},
                         {"path": "escape.aidl"}):
                r = await session.call_tool("check", args)
                assert r.is_error and "outside the allowed folder" in _text(r), args
            r = await session.call_tool("render", {"source": GOOD, "output": str(tmp_path / "x.svg")})
            assert r.is_error and not (tmp_path / "x.svg").exists()
            r = await session.call_tool("render", {"path": "plate.aidl", "output": "plate.aidl"})
            assert r.is_error and (root / "plate.aidl").read_text() == GOOD

            # import_drawing: the DXF just written comes back as its design, and is written
            doc = _doc((await session.call_tool(
                "import_drawing", {"path": "plate.dxf", "output": "back.aidl"})))
            assert doc["ok"] and doc["output"] == "back.aidl", doc
            # (off the centre line: from the nearer, right edge of the plate centred on 0, by a
            # param of its own for that distance, issue 114)
            assert "hole hole1 { h = Circle(center=(width / 2 - hole1_x, 0), diameter=hole1_d) }" \
                in doc["program"] and "param hole1_x = 10 mm" in doc["program"], doc["program"]
            assert (root / "back.aidl").read_text() == doc["program"]
            r = await session.call_tool("import_drawing", {"path": "plate.aidl"})
            assert r.is_error and "not a .dxf or .svg" in _text(r)

            assert (await session.call_tool("explain", {"code": "e0103"})).content[0].text \
                .startswith("E0103:")
            assert (await session.call_tool("explain", {"code": "X9"})).is_error

            uris = {str(x.uri) for x in (await session.list_resources()).resources}
            assert {"aidl://docs/language", "aidl://prompt", "aidl://stdlib/shapes.aidl",
                    "aidl://examples/mounting_plate.aidl"} <= uris
            got = await session.read_resource("aidl://stdlib/shapes.aidl")
            assert "def " in got.contents[0].text
            got = await session.read_resource("aidl://prompt")
            assert "Rectangle" in got.contents[0].text

            # docs: the tool gives what `aidl docs` prints; every topic is a resource
            from aidl_lang.library.reference import find, index_text, topics
            r = await session.call_tool("docs", {"name": "SpurGear"})
            assert not r.is_error and _text(r) == find("spur_gear").render()
            assert "bore_hole" in _text(r) and "phase = 0 deg: an angle" in _text(r)
            from aidl_lang.mcp.wording import for_agents
            assert _text(await session.call_tool("docs", {})) == for_agents(index_text())
            r = await session.call_tool("docs", {"name": "spur_gaer"})
            assert r.is_error and "did you mean `spur_gear`" in _text(r)
            assert {f"aidl://docs/topic/{n}" for n in topics()} | {"aidl://docs/topics"} <= uris
            got = await session.read_resource("aidl://docs/topic/assert")
            assert got.contents[0].text == find("assert").render()

            # the system prompt, offered as a prompt too
            from aidl_lang.llm.prompt import agent_prompt, system_prompt
            prompts = {p.name: p for p in (await session.list_prompts()).prompts}
            assert set(prompts) == {"aidl"}
            got = await session.get_prompt("aidl", {})
            [msg] = got.messages
            assert msg.role == "user" and msg.content.text == for_agents(agent_prompt())
            # the prompt an agent reads names the tools' arguments, not the CLI's flags
            for flag in ("--set", "--layout", "--assembled", "--describe", "--infer"):
                assert flag in system_prompt() and flag not in msg.content.text, flag
            assert 'layout="sheet"' in msg.content.text
            got = await session.get_prompt("aidl", {"request": "a washer 20 mm across"})
            assert got.messages[0].content.text.endswith("Design this part: a washer 20 mm "
                                                         "across\n")


def test_workspace_refuses_what_is_outside(tmp_path):
    ws = T.Workspace(tmp_path)
    with pytest.raises(T.Refused, match="exactly one"):
        T.check(ws)
    with pytest.raises(T.Refused, match="budget"):
        T.check(ws, source=GOOD, budget=100)
    with pytest.raises(T.Refused, match="outside"):
        ws.inside("/etc/passwd")
    with pytest.raises(T.Refused, match="not a file"):
        ws.inside("missing.aidl", must_exist=True)
    assert T.check(ws, source=GOOD)["ok"]
    doc = T.values(ws, source=BROKEN)
    assert doc["ok"] is False and "E0103 line 3" in doc["summary"]


REDUNDANT = """solid s {
    l1 = Line((0, 0), (10, 0))
    Fixed(l1)
    Horizontal(l1)
}
"""


def test_check_reports_redundant_constraints_as_aidl_check_does(tmp_path):
    """The MCP check tool lists W0401 (an LLM's loop sees over-constraining), like `aidl check`;
    the API adds them on request only, once."""
    import aidl_lang
    doc = T.check(T.Workspace(tmp_path), source=REDUNDANT)
    w = [d for d in doc["diagnostics"] if d["code"] == "W0401"]
    assert doc["ok"] and any("`Horizontal(l1)` is redundant" in d["message"] for d in w)
    r = aidl_lang.compile(source=REDUNDANT)
    assert [d.code for d in r.diagnostics if d.code == "W0401"] == []
    found = r.find_redundant()
    assert [d.message for d in found] == [d["message"] for d in w]
    assert r.find_redundant() == found
    assert [d.code for d in r.diagnostics].count("W0401") == len(w)


def test_render_writes_the_file_at_the_asked_width(tmp_path):
    """`width` is the written PNG's width too, not only the returned image's."""
    doc, [png] = T.render(T.Workspace(tmp_path), source=GOOD, output="x.png", width=300,
                          picture=True)
    assert doc["written"] == "x.png"
    data = (tmp_path / "x.png").read_bytes()
    assert int.from_bytes(data[16:20], "big") == 300 == int.from_bytes(png[16:20], "big")


def test_server_info_version_is_the_package_version():
    from importlib.metadata import version
    from aidl_lang.mcp.server import build_server
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        server = build_server(d, warm=False)
    assert version("aidl-lang") and server.version == version("aidl-lang")


@pytest.mark.asyncio(loop_scope="module")
async def test_tool_schemas_describe_every_argument_with_its_values_and_ranges(shared):
    """`tools/list` gives each argument a description, the allowed values (style) and ranges
    (width, budget), and the SDK refuses a call outside them before the tool runs (issue 37:
    the schemas had titles only)."""
    session, root = shared
    tools = {t.name: t for t in (await session.list_tools()).tools}
    assert set(tools) == {"check", "render", "values", "describe", "explain", "docs",
                          "import_drawing", "write_program", "set_params", "measure"}
    # an argument several tools take alike is described in full once, in the first
    # of them; the others say `as in `FIRST`` (issue 86: tools/list in few tokens)
    for t in tools.values():
        props = t.input_schema["properties"]
        assert props, t.name
        for name, prop in props.items():
            said = prop.get("description", "")
            if said.startswith("as in `"):
                first = tools[said[len("as in `"):-1]].input_schema["properties"]
                said = first[name]["description"]
                assert {k: v for k, v in first[name].items() if k != "description"} \
                    == {k: v for k, v in prop.items() if k != "description"}
            elif said.startswith("as `"):     # as an earlier argument of the tool
                like = props[said[len("as `"):-1]]
                said = like["description"]
                assert {k: v for k, v in like.items() if k != "description"} \
                    == {k: v for k, v in prop.items() if k != "description"}
            assert len(said) > 20, (t.name, name)
    render = tools["render"].input_schema["properties"]
    assert render["style"]["enum"] == ["preview", "laser"]
    assert render["style"]["default"] == "preview"
    assert (render["width"]["minimum"], render["width"]["maximum"]) == (16, 4096)
    for t in ("check", "render", "values", "describe"):
        budget = tools[t].input_schema["properties"]["budget"]
        assert budget["type"] == ["number", "null"]
        assert budget["exclusiveMinimum"] == 0 and budget["maximum"] == 4
    assert tools["explain"].input_schema["required"] == ["code"]

    # a call outside the schema is refused, naming the argument; a good one is not
    for args in ({"style": "blueprint"}, {"width": 0}, {"budget": 0},
                 {"budget": 5.0}):
        r = await session.call_tool("render", {"source": GOOD, **args})
        assert r.is_error, args
        assert next(iter(args)) in _text(r), (args, _text(r))
    r = await session.call_tool("render", {"source": GOOD, "style": "laser",
                                           "width": 64, "budget": 0.5})
    assert not r.is_error and _doc((r))["ok"], _text(r)


def test_a_program_path_that_is_not_utf8_or_has_a_bom_reads_as_aidl_check_reads_it(tmp_path):
    """MCP `check` by path decodes like `aidl check` (sources.decode_program): Latin-1 bytes are
    refused naming the first bad byte; a UTF-8 BOM is dropped."""
    (tmp_path / "latin1.aidl").write_bytes("# caf\xe9\n".encode("latin-1"))
    with pytest.raises(T.Refused, match=r"not UTF-8 text \(invalid continuation byte at byte 5\)"):
        T.Workspace(tmp_path).read("latin1.aidl")
    (tmp_path / "bom.aidl").write_bytes("\ufeffunits mm\n".encode("utf-8"))
    assert T.Workspace(tmp_path).read("bom.aidl")[1] == "units mm\n"


@pytest.mark.asyncio(loop_scope="module")
async def test_render_assembled_returns_the_product_in_3d(shared):
    """`assembled`: the image is the phone stand stood up (a collision boxed in red when the
    slot is too narrow), a written .glb has one node per part, an .svg is refused."""
    session, root = shared
    import io

    import numpy as np
    import trimesh
    from PIL import Image
    # the example's range stops at the sheet (3 mm): opened to 1 mm to show the collision
    (root / "stand.aidl").write_text((ROOT / "examples" / "phone_stand.aidl").read_text()
                                     .replace("min = 3 mm, max = 6 mm", "min = 1 mm, max = 6 mm"))
    reds = []
    for slot in ("3mm", "2.5mm"):
        r = await session.call_tool("render", {
            "path": "stand.aidl", "width": 240, "assembled": True, "picture": True,
            "overrides": {"slot": slot}, "output": "stand.glb"})
        assert not r.is_error, _text(r)
        doc = _doc((r))
        assert doc["image"]["view"] == "assembled" and doc["written"] == "stand.glb"
        [img] = [c for c in r.content if c.type == "image"]
        im = np.asarray(Image.open(io.BytesIO(base64.b64decode(img.data))).convert("RGB"))
        assert im.shape[1] == 240
        im = im.astype(int)
        reds.append(int(((im[:, :, 0] > 200) & (im[:, :, 1] < 60) & (im[:, :, 2] < 60)).sum()))
    assert reds[0] == 0 and reds[1] > 20
    sc = trimesh.load(root / "stand.glb")
    assert sorted(sc.graph.nodes_geometry) == ["stand.foot", "stand.support"]
    r = await session.call_tool("render", {"path": "stand.aidl", "assembled": True,
                                           "output": "stand.svg"})
    assert r.is_error and "not `.svg`" in _text(r)


@pytest.mark.timing
def test_a_call_past_its_time_limit_is_stopped_and_the_next_one_runs(tmp_path, monkeypatch):
    """Issue 37: the MCP server compiled in its own process with no hard time limit (Fillet
    on 2,000 stars ran 17-24 s against 15 s).  The compiling tools run in a worker process
    killed past the budget's wall guard (limits.wall_limit: 10 x its CPU seconds + 10 s), as
    `aidl batch` does; the call is refused saying so and the next call gets a fresh worker.  The
    limit is made tiny here."""
    from aidl_lang.mcp import tools as T
    from aidl_lang.mcp import worker as W
    src = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    for i in range(3000) { hole h { c = Circle(center=(i * 0.001, 0), radius=1) } }\n}\n")
    w = W.Worker(str(tmp_path))
    try:
        first = w.proc
        monkeypatch.setattr(W, "wall_limit", lambda seconds: 1e-4 * seconds)   # 1.5 ms
        with pytest.raises(T.Refused, match="took longer than 0.0015 s .* was stopped"):
            w.call("check", src, None, None, False, None)
        assert w.proc is None and w.restarts == 1
        monkeypatch.undo()
        doc = w.call("check", "solid p { body = Rectangle(center=(0, 0), width=4, height=2) }",
                     None, None, False, None)
        assert doc["ok"] and w.proc is not first and w.proc.is_alive()
        with pytest.raises(T.Refused, match="budget"):            # the tool's own refusals
            w.call("check", "solid p {}", None, None, False, 99.0, budget=99.0)
        assert w.seconds(None) == 160.0 and w.seconds(4) == 610.0 and w.seconds(-1) == 160.0
    finally:
        w.stop()


def test_check_and_render_read_a_drawing_beside_the_program_inside_the_root(tmp_path):
    """Drawing2D through the MCP tools: a DXF beside the program (given as source or path)
    is read; one reached by a link out of the root is refused with E0130, nothing read."""
    import shutil
    root = tmp_path / "root"
    (root / "parts").mkdir(parents=True)
    shutil.copyfile(ROOT / "examples" / "parts" / "pcb_board.dxf", root / "parts" / "board.dxf")
    prog = ('solid s {\n    d = Drawing2D("parts/board.dxf", layer="Edge.Cuts")\n'
            '    Fixed(d.origin)\n}\n')
    ws = T.Workspace(root)
    doc = T.check(ws, source=prog)
    assert doc["ok"] and doc["parts"][0]["bbox"] == pytest.approx([0, 0, 64, 42], abs=1e-9)
    (root / "lid.aidl").write_text(prog)
    doc, png = T.render(ws, path="lid.aidl", output="lid.dxf", picture=True)
    assert doc["ok"] and png and (root / "lid.dxf").exists()
    outside = tmp_path / "secret.dxf"
    shutil.copyfile(root / "parts" / "board.dxf", outside)
    os.symlink(outside, root / "parts" / "leak.dxf")
    doc = T.check(ws, source=prog.replace("board.dxf", "leak.dxf"))
    assert not doc["ok"] and [d["code"] for d in doc["diagnostics"]] == ["E0130"]
    assert "secret" not in json.dumps(doc)


@pytest.mark.asyncio(loop_scope="module")
async def test_every_resource_uri_of_the_docs_is_served(shared):
    """Issue 37: docs/mcp.md gave stdlib resource URIs that did not exist.  Every concrete
    `aidl://` URI written in docs/mcp.md (NAME placeholders aside) is one the server lists and
    reads."""
    session, root = shared
    import re
    text = (ROOT / "docs" / "mcp.md").read_text(encoding="utf-8")
    said = {u.rstrip(".,)") for u in re.findall(r"aidl://[\w./-]+", text) if "NAME" not in u}
    assert len(said) >= 8
    listed = {str(x.uri) for x in (await session.list_resources()).resources}
    assert sorted(said - listed) == []
    for uri in sorted(said):
        got = await session.read_resource(uri)
        assert got.contents[0].text.strip(), uri


# A line that is no JSON-RPC message, and the error JSON-RPC 2.0 answers it with (issue 83):
# the SDK dropped each of these (an object/boolean/float/null id read as a notification).
BAD_LINES = [
    ("{not json", -32700),
    ("[]", -32600),
    ('[{"jsonrpc": "2.0", "id": 1, "method": "ping"}]', -32600),    # a batch (MCP 2025-06)
    ('{"jsonrpc": "2.0", "id": {}, "method": "ping"}', -32600),
    ('{"jsonrpc": "2.0", "id": true, "method": "ping"}', -32600),
    ('{"jsonrpc": "2.0", "id": 1.5, "method": "ping"}', -32600),
    ('{"jsonrpc": "2.0", "id": null, "method": "ping"}', -32600),
    ('{"jsonrpc": "2.0", "id": 7, "method": 5}', -32600),
    ('{"jsonrpc": "1.0", "id": 8, "method": "ping"}', -32600),
    ("42", -32600),
    ('{"jsonrpc": "2.0", "id": NaN, "method": "ping"}', -32700),     # not JSON (RFC 8259)
    ("[" * 100_000 + "]" * 100_000, -32700),                          # nested too deep
]


def test_lines_that_are_no_message_get_json_rpc_errors_and_the_server_goes_on(tmp_path):
    """A real `aidl mcp`: each bad line gets one error reply with id null and the code of
    JSON-RPC 2.0 section 5; a response sent by the client (id null) gets none; a ping after
    each is answered with its own id, so nothing was dropped or left waiting."""
    import select
    import subprocess
    env = {k: v for k, v in os.environ.items() if k != "AIDL_DEBUG"}
    env["AIDL_MCP_COLD"] = "1"
    p = subprocess.Popen([sys.executable, "-m", "aidl_lang.cli", "mcp", "--root", str(tmp_path)],
                         cwd=str(ROOT), env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL)

    def send(line: str) -> None:
        p.stdin.write(line.encode() + b"\n")
        p.stdin.flush()

    def reply() -> dict:
        ready, _, _ = select.select([p.stdout], [], [], 30)
        assert ready, "no reply in 30 s"
        return json.loads(p.stdout.readline())

    try:
        send(json.dumps({"jsonrpc": "2.0", "id": 0, "method": "initialize", "params": {
            "protocolVersion": "2025-06-18", "capabilities": {},
            "clientInfo": {"name": "test", "version": "1"}}}))
        assert reply()["id"] == 0
        send('{"jsonrpc": "2.0", "method": "notifications/initialized"}')
        for n, (line, code) in enumerate(BAD_LINES, start=100):
            send(line)
            answer = reply()
            assert answer["jsonrpc"] == "2.0" and answer["id"] is None, (line, answer)
            assert answer["error"]["code"] == code, (line, answer)
            send(json.dumps({"jsonrpc": "2.0", "id": n, "method": "ping"}))
            assert reply() == {"jsonrpc": "2.0", "id": n, "result": {}}
        # a response, even one with id null, is never answered; blank lines are skipped
        send('{"jsonrpc": "2.0", "id": null, "error": {"code": -32600, "message": "no"}}')
        send("")
        send(json.dumps({"jsonrpc": "2.0", "id": "last", "method": "ping"}))
        assert reply() == {"jsonrpc": "2.0", "id": "last", "result": {}}
    finally:
        p.stdin.close()
        p.wait(30)


def test_check_with_dof_does_not_send_the_agent_to_check_with_dof(tmp_path):
    """Issue 86: with `dof: true` passed, the freedom text still said "call `check` with
    dof=true for the details"; now it points at the answer's own `structures`."""
    from aidl_lang.mcp import tools as T
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    hole h { c = Circle(center=(5, 0), radius=2) }\n}\n")
    ws = T.Workspace(str(tmp_path))
    plain = T.check(ws, source=src)["freedom"]["text"]
    asked = T.check(ws, source=src, dof=True)["freedom"]
    assert "call `check` with dof=true" in plain
    assert "dof=true" not in asked["text"] and "`structures`" in asked["text"]
    assert asked["structures"]


KERF_SLOT = """kerf 0.5 mm
solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole vent { v = Circle(center=(20, 0), diameter=6) }
    hole s {
        sl = Rectangle(center=(0, 0), width=20, height=0.4)
    }
}
"""


@pytest.mark.asyncio(loop_scope="module")
async def test_render_of_a_kerf_a_hole_cannot_take_is_a_located_E0504(shared):
    """Through the official client (issue 111 round eleven): a 0.4 mm slot under a 0.5 mm
    kerf is refused as E0504 at the slot's hole (line 5, column 5), nothing written, where
    it was the layout's bare message with no line."""
    session, root = shared
    (root / "kerf_slot.aidl").write_text(KERF_SLOT)
    r = await session.call_tool("render", {"path": "kerf_slot.aidl",
                                           "output": "kerf_slot.dxf"})
    # round twelve: the check says it (the program's own kerf), so the compile is not ok
    assert "not ok: 1 error" in _text(r) and "error E0504 at kerf_slot.aidl:5:5" in _text(r), \
        _text(r)
    assert "widen it to 0.5 mm or more" in _text(r)
    assert not (root / "kerf_slot.dxf").exists()
