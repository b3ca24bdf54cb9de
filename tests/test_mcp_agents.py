"""What an agent sees of `aidl mcp` (issue 48, finding 5), through the official SDK's stdio
client as in tests/test_mcp.py: calls run side by side, results carry structured content
matching each tool's output schema, the arguments' schema states the source/path choice and
refuses unknown names, and the messages name tools and arguments instead of command-line
flags."""
import asyncio
import json
import time

import pytest

mcp = pytest.importorskip("mcp")
from mcp.client.session import ClientSession  # noqa: E402
from mcp.client.stdio import stdio_client  # noqa: E402

from test_mcp import GOOD, _doc, _server, _session, _text, shared  # noqa: E402,F401

# seconds of work that ends in E0304: the shape checks of 3,000 overlapping holes stop at
# their shares of the budget (W0521), then the exact outlines of the stacked circles run past
# their bounded work (once an "internal error" in the MCP check: its parts list)
SLOW = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
        "    for i in range(3000) { hole h { c = Circle(center=(i * 0.001, 0), radius=1) } }\n"
        "}\n")


@pytest.mark.timing
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
        assert not r.is_error and _doc((r))["ok"], _text(r)
        # answered while the slow one still runs (not queued behind it); the seconds are a
        # hang guard only, wide for a loaded machine
        assert not slow.done()
        assert fast < 60, f"the fast check waited {fast:.1f} s"
        r = await slow
        if r.is_error:                      # a machine too busy to end it within 30 s
            assert "took longer than" in _text(r)
        else:
            doc = _doc((r))
            assert not doc["ok"] and "E0304" in [d["code"] for d in doc["diagnostics"]]


@pytest.mark.asyncio(loop_scope="module")
async def test_results_are_structured_content_matching_the_output_schemas(shared):
    """check, render, values and describe declare an output schema; a call's result carries
    structuredContent that matches it (good and broken programs alike), with the same JSON
    as a text block for older clients (render: after its image)."""
    session, root = shared
    import jsonschema
    (root / "plate.aidl").write_text(GOOD)
    tools = {t.name: t for t in (await session.list_tools()).tools}
    calls = {"check": {"dof": True}, "render": {"width": 64, "picture": True}, "values": {},
             "describe": {}}
    for name, extra in calls.items():
        # tools/list gives an outline (issue 86); the full schema is a resource
        schema = tools[name].output_schema
        assert schema and schema["type"] == "object", name
        assert schema["required"] == ["ok", "units"], name
        assert schema["description"].endswith(f"full schema: aidl://schemas/{name}.json")
        full = json.loads((await session.read_resource(
            f"aidl://schemas/{name}.json")).contents[0].text)
        assert {"ok", "units"} <= set(full["properties"]), name
        for source in (GOOD, "solid p { c = Circel(center=(0, 0), radius=1) }"):
            r = await session.call_tool(name, {"source": source, **extra})
            assert not r.is_error, _text(r)
            jsonschema.validate(r.structured_content, schema)
            jsonschema.validate(r.structured_content, full)
            assert _doc((r)) == r.structured_content
            assert r.structured_content["ok"] is (source == GOOD)
    r = await session.call_tool("values", {"path": "plate.aidl", "names": ["bore.c"]})
    assert [v["name"] for v in r.structured_content["values"]] == [
        "plate.bore.c.center", "plate.bore.c.radius", "plate.bore.c.diameter"]
    assert r.structured_content["values"][0]["value"] == [10, 0]
    r = await session.call_tool("render", {"path": "plate.aidl", "width": 64,
                                           "picture": True})
    assert [c.type for c in r.content] == ["image", "text"]
    assert r.structured_content["image"] == {"format": "png", "width": 64, "view": "flat"}
    assert r.structured_content["parts"][0]["holes"] == 1
    props = tools["check"].output_schema["properties"]
    assert {"diagnostics", "solve", "freedom", "parts", "summary"} <= set(props)
    assert props["parts"]["description"] == "[{name, kind, bbox, area, holes, loops}]"
    # render says the fields it shares with check by name, without their schema again
    assert tools["render"].output_schema["description"].startswith(
        "as `check`: ok, error, diagnostics, units")


@pytest.mark.asyncio(loop_scope="module")
async def test_the_input_schema_states_source_or_path_and_refuses_unknown_arguments(shared):
    """The choice of `source` or `path` is in each compiling tool's input schema (`oneOf`,
    each with its `required`), no tool takes arguments beyond its properties
    (`additionalProperties: false`); a call with both, neither or an unknown argument is a
    tool error saying so (the unknown one named, with the nearest and the accepted names)."""
    session, root = shared
    import jsonschema
    (root / "plate.aidl").write_text(GOOD)
    tools = {t.name: t for t in (await session.list_tools()).tools}
    for t in tools.values():
        assert t.input_schema["additionalProperties"] is False, t.name
    for name in ("check", "render", "values", "describe"):
        schema = tools[name].input_schema
        assert [b["required"] for b in schema["oneOf"]] == [["source"], ["path"]]
        jsonschema.validate({"source": GOOD}, schema)
        jsonschema.validate({"path": "plate.aidl", "source": None}, schema)
        for bad in ({}, {"source": GOOD, "path": "plate.aidl"}, {"sourse": GOOD}):
            with pytest.raises(jsonschema.ValidationError):
                jsonschema.validate(bad, schema)
        for bad in ({}, {"source": GOOD, "path": "plate.aidl"}):
            r = await session.call_tool(name, bad)
            assert r.is_error and "give exactly one of `source`" in _text(r), (name, bad)

    r = await session.call_tool("check", {"sourse": GOOD})
    assert r.is_error
    assert "unknown argument `sourse`" in _text(r) and "did you mean `source`?" in _text(r)
    assert "source, path, overrides, dof, budget" in _text(r)
    r = await session.call_tool("render", {"path": "plate.aidl", "widht": 64})
    assert r.is_error and "unknown argument `widht`" in _text(r)
    assert "did you mean `width`?" in _text(r)
    assert not (root / "plate.svg").exists()
    r = await session.call_tool("docs", {"topic": "Circle"})
    assert r.is_error and "unknown argument `topic`" in _text(r) and "name" in _text(r)
    r = await session.call_tool("check", {"path": "plate.aidl", "dof": True})
    assert not r.is_error and r.structured_content["ok"]


@pytest.mark.asyncio(loop_scope="module")
async def test_overrides_take_bare_numbers_in_the_files_units(shared):
    """`overrides` takes a bare number as its description says (in the file's units, like
    the string "3"), a string with a unit, and true/false."""
    session, root = shared
    src = ("units in\nparam width = 2\nparam slot = true\n"
           "solid plate { body = Rectangle(center=(0, 0), width=width, height=1) }\n")
    for given, inches in ((3, 3.0), (2.5, 2.5), ("3", 3.0), ("25.4 mm", 1.0)):
        r = await session.call_tool("values", {"source": src, "names": ["body.width"],
                                               "overrides": {"width": given}})
        assert not r.is_error, _text(r)
        [v] = r.structured_content["values"]
        assert v["unit"] == "in" and v["value"] == pytest.approx(inches), given
    r = await session.call_tool("check", {"source": src, "overrides": {"slot": False}})
    assert not r.is_error and r.structured_content["ok"], _text(r)
    r = await session.call_tool("check", {"source": src, "overrides": {"width": [1]}})
    assert r.is_error and "overrides" in _text(r)


@pytest.mark.asyncio(loop_scope="module")
async def test_render_never_writes_through_a_link_inside_the_root(shared):
    """An output path with a symbolic link in any component below the root is refused, also
    a link that points inside the root: to another folder of it, or to a file of it (the
    tool's description says "never through a symbolic link")."""
    session, root = shared
    import os
    (root / "sub").mkdir()
    (root / "sub" / "real.svg").write_text("keep")
    os.symlink(root / "sub", root / "alias")
    os.symlink(root / "sub" / "real.svg", root / "file.svg")
    for output in ("alias/x.svg", "alias/../x.svg", "file.svg", "alias/real.svg",
                   str(root / "alias" / "x.dxf")):
        r = await session.call_tool("render", {"source": GOOD, "output": output})
        assert r.is_error and "symbolic link" in _text(r), (output, _text(r))
    assert sorted(os.listdir(root / "sub")) == ["real.svg"]
    assert (root / "sub" / "real.svg").read_text() == "keep"
    assert not (root / "x.svg").exists()
    r = await session.call_tool("render", {"source": GOOD, "output": "sub/y.svg"})
    assert not r.is_error and r.structured_content["written"] == "sub/y.svg", _text(r)
    assert (root / "sub" / "y.svg").read_text().lstrip().startswith("<")


MIXED = """units mm
assembly kit {
    solid plate {
        thickness 3 mm
        body = Rectangle(center=(0, 0), width=60, height=40)
    }
    solid spacer {
        thickness 6 mm
        body = Rectangle(center=(80, 0), width=20, height=20)
    }
}
"""


@pytest.mark.asyncio(loop_scope="module")
async def test_render_takes_the_cli_layout_sheet_kerf_and_thickness(shared):
    """`render` has `aidl render`'s cutting-layout options (`layout: "sheet"`, `sheet`, `gap`,
    `rotate`), `kerf` and `thickness`, with the CLI's meanings (a bare number is mm), and
    makes a missing output folder inside the root: a kit of 3 mm and 6 mm stock is laid out
    on two sheets, one file and one picture each."""
    session, root = shared
    import re

    import trimesh
    r = await session.call_tool("render", {
        "source": MIXED, "layout": "sheet", "sheet": "200x150mm", "gap": 2,
        "rotate": 0, "width": 100, "picture": True, "output": "sheets/cut.svg"})
    assert not r.is_error, _text(r)
    lay = r.structured_content["layout"]
    assert lay["sheets"] == 2 and lay["size"] == [200, 150]
    assert lay["files"] == ["sheets/cut-1.svg", "sheets/cut-2.svg"]
    assert lay["text"].startswith("laid out 2 parts on 2 sheets of 200 x 150 mm, use ")
    assert r.structured_content["written"] == "sheets/cut-1.svg"
    assert [c.type for c in r.content] == ["image", "image", "text"]
    ids = [re.findall(r'id="(part-[^"]+)"', (root / f).read_text())
           for f in lay["files"]]
    assert ids == [["part-kit_plate"], ["part-kit_spacer"]]
    assert 'width="200mm"' in (root / "sheets" / "cut-1.svg").read_text()

    # kerf (mm, or a length with its unit): the bore of radius 4 is cut 0.1 mm smaller
    for kerf in (0.2, "0.2mm", "0.02 cm"):
        r = await session.call_tool("render", {"source": GOOD, "kerf": kerf,
                                               "output": "deep/er/k.dxf"})
        assert not r.is_error, _text(r)
        assert "\n 40\n3.9\n" in (root / "deep" / "er" / "k.dxf").read_text()
    # thickness: the STL extruded 6 mm instead of the default 3
    r = await session.call_tool("render", {"source": GOOD, "thickness": "6mm",
                                           "output": "t.stl"})
    assert not r.is_error, _text(r)
    assert trimesh.load(root / "t.stl").extents[2] == pytest.approx(6)

    for args, said in (({"sheet": "100x100mm"}, "layout"),
                       ({"layout": "sheet", "assembled": True}, "assembled"),
                       ({"layout": "sheet", "sheet": "big"}, "sheet"),
                       ({"kerf": "wide"}, "kerf"), ({"kerf": 11}, "kerf"),
                       ({"thickness": -1}, "thickness"),
                       ({"layout": "sheet", "rotate": "sideways"}, "rotate"),
                       ({"layout": "sheet", "sheet": "20x20mm"}, "is larger than the")):
        r = await session.call_tool("render", {"source": MIXED, "width": 64, **args})
        assert r.is_error and said in _text(r), (args, _text(r))


def _said(doc) -> list[str]:
    """Every message, hint and label of a result's diagnostics, its summary and its freedom
    text: what an agent reads (the rendered text repeats them, with source lines)."""
    out = [doc.get("summary", ""), doc.get("freedom", {}).get("text", "")]
    for d in doc.get("diagnostics", []):
        out += [d["message"], d["hint"] or "", d.get("rendered", "")]
        out += [lab["message"] for lab in d["labels"]]
    return [s for s in out if s]


@pytest.mark.asyncio(loop_scope="module")
async def test_messages_name_tools_and_arguments_not_command_line_flags(shared):
    """Through MCP, hints say which tool and argument to use (`overrides={...}`, `docs` with
    name=..., dof=true, `budget`, `sheet`) instead of `--set`, `aidl docs NAME`, `--dof`,
    `--budget`, `--sheet`; the command line's and the API's wording is unchanged."""
    session, root = shared
    import aidl_lang
    width = "param width = 4\nsolid p { body = Rectangle(center=(0, 0), width=width, height=2) }\n"
    cases = [  # (arguments, a phrase the MCP wording must hold)
        ({"source": "solid p { g = spur_gear(teeth=10) }"},
         'call `docs` with name="spur_gear" for its parameters'),
        ({"source": "solid p { g = Qzxqzx(1) }"}, "call `docs` with no name for the list of"),
        ({"source": width, "overrides": {"nope": 1}}, '`overrides={"nope": ...}`'),
        ({"source": width, "overrides": {"width": "abc"}}, 'write e.g. `overrides={"width": "4"}`'),
        ({"source": "solid p { for i in range(100000) { c = Circle(center=(0, 0), radius=1) } }"},
         "raise `budget`"),
        ({"source": width.replace("height=2)", "height=2)\n  l = Line((0, 0), (1, 1))")},
         "call `check` with dof=true"),
    ]
    for args, phrase in cases:
        r = await session.call_tool("check", {**args, "detail": True})
        assert not r.is_error, _text(r)
        said = _said(r.structured_content)
        assert any(phrase in s for s in said), (phrase, said)
        for s in said:
            assert "--" not in s and "aidl docs" not in s, s
    r = await session.call_tool("docs", {"name": "spur_gaer"})
    assert r.is_error and "Call `docs` with no name for the list of every topic" in _text(r)
    r = await session.call_tool("docs", {})
    assert _text(r).startswith('Call `docs` with name="NAME" for a topic:')
    r = await session.call_tool("render", {"source": MIXED, "layout": "sheet",
                                           "sheet": "30x30mm"})
    assert r.is_error and 'use a sheet of 46.02 x 66.02 mm or larger (sheet="47x67mm")' in \
        _text(r) and "--" not in _text(r) and "rotate" not in _text(r)
    # the command line's (and the API's) own wording
    r = aidl_lang.compile(source=width, overrides={"nope": 1})
    assert r.errors[0].message == "`--set nope=...`: the model has no param `nope`"
    from aidl_lang.library.reference import lookup_text
    assert "`aidl docs` lists every topic." in lookup_text("spur_gaer")[0]


@pytest.mark.asyncio(loop_scope="module")
async def test_values_list_every_copy_of_a_pattern_at_its_real_origin(shared):
    """examples/bracket.aidl: `holes = LinearPattern(bolt, 4, (pitch, 0))` lists holes[0]
    (the original, `bolt`) to holes[3], and the unnamed `CircularPattern(first, 8, ...)`
    first_pattern[0] to [7]; each copy's `origin` is where the original's origin went
    (moved by k x 20 mm, turned by k x 45 degrees about the plate's centre), not (0, 0); a
    shape's pattern (`dots = LinearPattern(c, 3, ...)`) lists dots[0] too."""
    session, root = shared
    import math

    from conftest import ROOT
    (root / "bracket.aidl").write_text((ROOT / "examples" / "bracket.aidl").read_text())
    async def values(*names, source=None):
        where = {"source": source} if source else {"path": "bracket.aidl"}
        r = await session.call_tool("values", {**where, "names": list(names)})
        assert not r.is_error and r.structured_content["ok"], _text(r)
        return {v["name"]: v["value"] for v in r.structured_content["values"]}

    got = await values("holes", "bolt", "first", "first_pattern", "plate.center")
    bolt = got["bracket.bolt.origin"]
    for k in range(4):
        # the plate stays at its written (0, 0) (issue 73): the row starts 0.75 pitch in
        assert got[f"bracket.holes[{k}].c.center"] == pytest.approx([-30 + 20 * k, 12])
        assert got[f"bracket.holes[{k}].origin"] == pytest.approx([bolt[0] + 20 * k, bolt[1]])
    assert got["bracket.holes[0].c.radius"] == got["bracket.bolt.c.radius"] == 3
    cx, cy = got["bracket.plate.center"]
    fx, fy = got["bracket.first.origin"]
    for k in range(8):
        a = math.radians(45 * k)
        turned = [cx + (fx - cx) * math.cos(a) - (fy - cy) * math.sin(a),
                  cy + (fx - cx) * math.sin(a) + (fy - cy) * math.cos(a)]
        assert got[f"bracket.first_pattern[{k}].origin"] == pytest.approx(turned, abs=1e-9)
    assert got["bracket.first_pattern[0].v.center"] == got["bracket.first.v.center"]

    dots = await values("holes", source=(
        "units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=80, height=20)\n"
        "    hole holes {\n        c = Circle(center=(-20, 0), radius=2)\n"
        "        dots = LinearPattern(c, 3, (10, 0))\n    }\n}\n"))
    assert [dots[f"plate.holes.dots[{k}].center"] for k in range(3)] == [
        [-20, 0], [-10, 0], [0, 0]]


@pytest.mark.asyncio(loop_scope="module")
async def test_a_path_that_is_not_an_aidl_file_is_refused_in_one_clear_error(shared):
    """`path` takes a program: a DXF is refused once, saying a program imports it with
    Drawing2D, instead of being parsed as AIDL (some 20 E0002 errors)."""
    session, root = shared
    import shutil

    from conftest import ROOT
    shutil.copyfile(ROOT / "examples" / "parts" / "pcb_board.dxf", root / "board.dxf")
    (root / "notes.txt").write_text("solid p {}\n")
    for tool in ("check", "render", "values", "describe"):
        r = await session.call_tool(tool, {"path": "board.dxf"})
        assert r.is_error, (tool, _text(r))
        assert "`board.dxf` is not an .aidl file" in _text(r)
        assert 'Drawing2D("board.dxf")' in _text(r) and "E0002" not in _text(r)
    r = await session.call_tool("check", {"path": "notes.txt"})
    assert r.is_error and "`notes.txt` is not an .aidl file" in _text(r)


@pytest.mark.asyncio
async def test_the_prompt_argument_is_described_and_a_bad_one_is_a_clean_error(tmp_path):
    """The `aidl` prompt's `request` has a description; an unknown argument is an MCP error
    (invalid params) naming it and the accepted one, with no traceback on the server's
    stderr; a good call still works after it."""
    import tempfile

    from mcp.shared.exceptions import MCPError
    with tempfile.TemporaryFile("w+") as err:
        async with stdio_client(_server(tmp_path), errlog=err) as (read, write):
            async with ClientSession(read, write) as session:
                await session.initialize()
                [prompt] = (await session.list_prompts()).prompts
                [arg] = prompt.arguments
                assert arg.name == "request" and not arg.required
                assert "part to design" in arg.description
                for bad in ({"req": "a washer"}, {"request": "a washer", "style": "x"}):
                    with pytest.raises(MCPError) as e:
                        await session.get_prompt("aidl", bad)
                    assert e.value.code == -32602, e.value
                    unknown = next(k for k in bad if k != "request")
                    assert f"unknown argument `{unknown}`" in e.value.message
                    assert "takes: request" in e.value.message
                got = await session.get_prompt("aidl", {"request": "a washer"})
                assert got.messages[0].content.text.endswith("Design this part: a washer\n")
        err.seek(0)
        logged = err.read()
    assert "Traceback" not in logged and "Error rendering prompt" not in logged, logged
