"""The tools an agent reaches for (issue 86), through the official SDK's stdio client:
`set_params` (param values changed in the file, formatting kept, checked against their kind
and range), `measure` (distance, centre distance, angle, clearance between named entities),
`import_drawing` with the check of the program it wrote, and every refusal naming its
argument in `error.argument`."""
import os

import pytest

mcp = pytest.importorskip("mcp")

from test_mcp import GOOD, _text  # noqa: E402
from test_mcp import shared  # noqa: E402,F401  (one server for the module)

PLATE = """units mm
# a plate with a bore
param width = 40 mm, min=20 mm, max=80 mm   # the plate's width
param bore_r = 4    # in the file's units

solid plate {
    body = Rectangle(center=(0, 0), width=width, height=20)
    hole bore { c = Circle(center=(10, 0), radius=bore_r) }
}
"""

GEARS = """units mm
import "std/gears.aidl"
assembly kit {
    gear_a = spur_gear(teeth=12, module=2 mm, cx=0 mm, cy=0 mm)
    gear_b = spur_gear(teeth=18, module=2 mm, cx=31 mm, cy=0 mm, phase=10 deg)
    solid disks {
        hole a { c = Circle(center=(100, 0), radius=3) }
        hole b { c = Circle(center=(100, 20), radius=5) }
        l1 = Line((150, 50), (160, 50))
        l2 = Line((150, 60), (160, 70))
    }
}
"""


@pytest.mark.asyncio(loop_scope="module")
async def test_set_params_rewrites_only_the_values_and_checks(shared):
    """The value text of each named `param` line changes, nothing else (comments, options,
    spacing); the answer is the new file's check; a value of the wrong kind, outside the
    declared range or for an unknown name is refused naming `values`, the file untouched."""
    session, root = shared
    f = root / "plate.aidl"
    f.write_text(PLATE)
    tools = {t.name: t for t in (await session.list_tools()).tools}
    assert tools["set_params"].output_schema and len(tools["set_params"].description) < 400
    r = await session.call_tool("set_params", {"path": "plate.aidl",
                                               "values": {"width": "50 mm", "bore_r": 5}})
    assert not r.is_error, _text(r)
    doc = r.structured_content
    assert doc["ok"] and doc["written"] == "plate.aidl"
    assert doc["parts"][0]["bbox"] == [-25.0, -10.0, 25.0, 10.0]
    assert f.read_text() == PLATE.replace("width = 40 mm,", "width = 50 mm,").replace(
        "bore_r = 4 ", "bore_r = 5 ")
    before = f.read_text()
    for values, code, said in (({"width": "200 mm"}, "bad_argument", "outside the range"),
                               ({"width": "30 deg"}, "bad_argument", "angle"),
                               ({"widht": 45}, "no_match", "did you mean `width`")):
        r = await session.call_tool("set_params", {"path": "plate.aidl", "values": values})
        assert r.is_error, values
        err = r.structured_content["error"]
        assert (err["code"], err["argument"]) == (code, "values"), err
        assert said in err["message"], err
        assert "--set" not in err["message"]
        assert f.read_text() == before


@pytest.mark.asyncio(loop_scope="module")
async def test_measure_gives_exact_distances_angles_and_clearances(shared):
    """Circles 20 mm apart centre to centre with radii 3 and 5: clearance 12; the gears'
    centres 31 mm apart (m (12 + 18) / 2 = 30 would mesh; 31 leaves them apart); two lines
    at 45 degrees; a point to a circle."""
    session, root = shared
    (root / "kit.aidl").write_text(GEARS)
    async def m(a, b):
        r = await session.call_tool("measure", {"path": "kit.aidl", "a": a, "b": b})
        assert not r.is_error, _text(r)
        return r.structured_content["measure"]

    got = await m("disks.a.c", "disks.b.c")
    assert got["center_distance"] == pytest.approx(20, abs=1e-9)
    assert got["clearance"] == pytest.approx(12, abs=1e-9) and got["contact"] == "apart"
    assert got["distance"] == pytest.approx(12, abs=1e-9)
    got = await m("gear_a", "gear_b")
    assert got["center_distance"] == pytest.approx(31, abs=1e-9)
    assert got["contact"] == "apart" and 0 < got["clearance"] < 2
    got = await m("disks.l1", "disks.l2")
    assert got["angle"] == pytest.approx(45, abs=1e-9)
    assert got["distance"] == pytest.approx(10, abs=1e-9)
    got = await m("disks.a.c.center", "disks.b.c")
    assert got["distance"] == pytest.approx(15, abs=1e-9)
    r = await session.call_tool("measure", {"path": "kit.aidl", "a": "disks.a.c",
                                            "b": "gear_c"})
    assert r.is_error
    err = r.structured_content["error"]
    assert (err["code"], err["argument"]) == ("no_match", "b")
    assert "gear_a" in err["message"] or "gear_b" in err["message"]


@pytest.mark.asyncio(loop_scope="module")
async def test_import_drawing_returns_the_check_of_its_program(shared):
    """The program written from a DXF is checked in the same call: ok, its parts, dof."""
    session, root = shared
    ezdxf = pytest.importorskip("ezdxf")
    doc = ezdxf.new()
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (60, 0), (60, 30), (0, 30)], close=True)
    msp.add_circle((15, 15), 3)
    doc.saveas(root / "plate.dxf")
    r = await session.call_tool("import_drawing", {"path": "plate.dxf"})
    assert not r.is_error, _text(r)
    check = r.structured_content["check"]
    assert check["ok"] and len(check["parts"]) == 1
    x0, y0, x1, y1 = check["parts"][0]["bbox"]
    assert (x1 - x0, y1 - y0) == pytest.approx((60, 30), abs=1e-6)
    assert check["parts"][0]["holes"] == 1
    assert "checked ok" in _text(r)


# each refusal kind, and the argument it must name
REFUSALS = [
    ("check", {"source": GOOD, "widht": 3}, "unknown_argument", "widht"),
    ("check", {"source": GOOD, "path": "plate.aidl"}, "program_choice", "source"),
    ("render", {"source": GOOD, "width": 5000}, "bad_argument", "width"),
    ("check", {"path": "../x.aidl"}, "outside_root", "path"),
    ("check", {"path": "missing.aidl"}, "not_found", "path"),
    ("check", {"path": "board.dxf"}, "wrong_kind", "path"),
    ("values", {"source": GOOD, "names": ["plate.bor"]}, "no_match", "names"),
    ("write_program", {"path": "plate.aidl", "old": "0", "new": "1"}, "not_unique", "old"),
    ("render", {"source": GOOD, "assembled": True, "output": "a.dxf"}, "wrong_kind", "output"),
    ("render", {"source": GOOD, "output": "link/a.svg"}, "symlink", "output"),
    ("render", {"source": GOOD, "layout": "sheet", "sheet": "30x30mm"}, "bad_argument",
     "sheet"),
    ("render", {"source": GOOD, "gap": 2}, "bad_argument", "gap"),
    ("render", {"source": GOOD, "kerf": "wide"}, "bad_argument", "kerf"),
    ("render", {"source": GOOD, "layout": "sheet", "rotate": "sideways"}, "bad_argument",
     "rotate"),
    ("render", {"source": GOOD, "output": "a.gcode", "machine": "lathe"}, "not_found",
     "machine"),
    ("render", {"source": GOOD, "page": "A4"}, "bad_argument", "page"),
    ("render", {"source": GOOD, "output": "a.xyz"}, "output_failed", "output"),
    ("import_drawing", {"path": "board.dxf", "output": "b.txt"}, "wrong_kind", "output"),
    ("docs", {"name": "Circel"}, "no_match", "name"),
    ("explain", {"code": "E9999"}, "no_match", "code"),
    ("set_params", {"path": "plate.aidl", "values": {"x": 1}}, "no_match", "values"),
    ("measure", {"source": GOOD, "a": "plate.nothing", "b": "plate.bore.c"}, "no_match", "a"),
]


@pytest.mark.asyncio(loop_scope="module")
async def test_every_refusal_names_its_argument(shared):
    """docs/mcp.md: a refused call is `{ok: false, error: {code, message, argument}}`; each
    kind of refusal, driven through the real client, names the argument at fault (a refused
    `assembled` + `.dxf` render had none: issue 86)."""
    session, root = shared
    (root / "plate.aidl").write_text(PLATE)
    (root / "board.dxf").write_text("0\nEOF\n")
    (root / "real").mkdir()
    os.symlink(root / "real", root / "link")
    for tool, args, code, argument in REFUSALS:
        r = await session.call_tool(tool, args)
        assert r.is_error, (tool, args, _text(r))
        err = r.structured_content["error"]
        assert (err["code"], err.get("argument")) == (code, argument), (tool, args, err)


@pytest.mark.asyncio(loop_scope="module")
async def test_the_routers_bit_is_set_through_render_and_said_in_the_header(shared):
    """Issue 111: an agent could not set the router's bit (a profile is a .toml that
    `write_program` refuses, and `render` took no tool settings) and the built-in bit's
    diameter was said nowhere.  `machine` takes a profile's keys as an object; the G-code's
    header says the bit, and the path runs its radius beside the line (re-read)."""
    from test_gcode import replay
    session, root = shared
    (root / "bit.aidl").write_text(PLATE)
    r = await session.call_tool("render", {
        "path": "bit.aidl", "output": "bit.nc",
        "machine": {"kind": "router", "tool_diameter": 6, "relief": "none"}})
    assert not r.is_error, _text(r)
    text = (root / "bit.nc").read_text()
    assert "; tool: a 6 mm end mill (tool_diameter): every cut's path runs 3 mm beside the " \
        "line; inside corners: no relief\n" in text
    xs = [mv.q[0] for mv in replay(text, "router") if mv.on]
    # the outline's cut runs 3 mm outside the 40 mm plate (x = -23 .. 23)
    assert abs(max(xs) - 23) < 1e-9 and abs(min(xs) + 23) < 1e-9
    r = await session.call_tool("render", {"path": "bit.aidl", "output": "bit2.nc",
                                           "machine": {"kind": "router", "tool_diametr": 6}})
    assert r.is_error and r.structured_content["error"]["argument"] == "machine"
    assert "did you mean `tool_diameter`" in r.structured_content["error"]["message"]
    assert not (root / "bit2.nc").exists()


@pytest.mark.asyncio(loop_scope="module")
async def test_measure_takes_every_name_values_lists_a_patterns_original_too(shared):
    """Issue 111: `values` lists a pattern's original as `plate.corners[0]` (before its
    copies), and `measure` said "nothing is named `plate.corners[0].c`"."""
    session, root = shared
    (root / "corners.aidl").write_text("""units mm
solid plate {
    body = Rectangle(center=(0, 0), width=80, height=50)
    hole holes { c = Circle(center=(-30, -15), diameter=4.5 mm) }
    corners = CornerPattern(holes, body, inset=10)
}
""")
    r = await session.call_tool("values", {"path": "corners.aidl"})
    names = [v["name"] for v in r.structured_content["values"]]
    assert "plate.corners[0].c.center" in names
    r = await session.call_tool("measure", {"path": "corners.aidl", "a": "plate.corners[0].c",
                                            "b": "plate.corners[1].c"})
    assert not r.is_error, _text(r)
    m = r.structured_content["measure"]
    assert m["center_distance"] == 60.0 and m["distance"] == 55.5 and m["contact"] == "apart"
