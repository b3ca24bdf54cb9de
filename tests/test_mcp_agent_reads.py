"""What an agent through `aidl mcp` could not read (issue 111), through the official SDK's
stdio client as in tests/test_mcp.py and through the public API the tools share:

* `values` of a pattern of template instances lists each instance's params as its call
  gives them and its members, not the template's own locals (`i`, `d`) nor the params again on every copy
  (59 lines before for the plate below, 37 after); a local asked for by name is still given.
* `measure`'s `center_distance` between the parts of an imported sheet is between the parts'
  real centres (0 mm before for parts of lines 89 mm apart: both fell back to the origin).
* `render` says in `overlaps` which parts lie over each other flat, by their true outlines
  (as drawn, or on each sheet of a layout), where `fit` is the 3D assembled product's.
Every figure is checked against an independent reading: the DXF by ezdxf, the outlines'
areas by shapely."""
import math

import pytest

mcp = pytest.importorskip("mcp")
ezdxf = pytest.importorskip("ezdxf")
shapely = pytest.importorskip("shapely")

import aidl_lang  # noqa: E402
from test_mcp import _text, shared  # noqa: E402,F401

HOLES = """units mm
import "std/fasteners.aidl"
solid plate {
    body = Rectangle(center=(0, 0), width=120, height=60)
    h = clearance_hole(size=3, cx=-50, cy=-20)
    holes = LinearPattern(h, 4, (30, 0))
}
"""


async def _values(session, names=(), **where):
    r = await session.call_tool("values", {**where, "names": list(names), "detail": True})
    assert not r.is_error and r.structured_content["ok"], _text(r)
    return {v["name"]: v["value"] for v in r.structured_content["values"]}


@pytest.mark.asyncio(loop_scope="module")
async def test_values_give_a_templates_params_and_members_not_its_locals(shared):
    """clearance_hole(size=3, cx=-50, cy=-20) copied 4 times: the original lists the params
    its call gives (size, cx, cy) and its circle; each copy its origin, box and circle,
    moved 30 mm each, and neither `i` nor `d` (the template's index into its table and the
    diameter it read there) nor the params again.  `plate.h.d` asked by name is 3.4 mm, the
    ISO 273 medium clearance of M3 (nothing lost).  The API lists what the tool does."""
    session, root = shared
    (root / "holes.aidl").write_text(HOLES)
    got = await _values(session, path="holes.aidl")
    assert len(got) == 37, sorted(got)               # 59 before: 22 lines of locals and params
    assert not [n for n in got if n.rsplit(".", 1)[-1] in ("i", "d", "found")]
    assert got["plate.h.size"] == 3 and got["plate.h.cx"] == -50 and got["plate.h.cy"] == -20
    for k in range(4):
        own = sorted(n[len(f"plate.holes[{k}]."):] for n in got
                     if n.startswith(f"plate.holes[{k}]."))
        assert own == ["bbox", "c.center", "c.diameter", "c.radius", "origin"], (k, own)
        assert got[f"plate.holes[{k}].c.center"] == pytest.approx([-50 + 30 * k, -20])
        assert got[f"plate.holes[{k}].c.diameter"] == pytest.approx(3.4)
    assert (await _values(session, ["plate.h.d"], path="holes.aidl")) == {
        "plate.h.d": pytest.approx(3.4)}
    r = aidl_lang.compile(source=HOLES, path=str(root / "holes.aidl"))
    assert sorted(v.name for v in r.sizes()) == sorted(got)
    assert r.value("plate.holes[2].i").value == 2     # a local, by its name


def test_values_keep_the_members_a_template_documents_or_the_program_reads():
    """gear_pair's `center_distance` (its Members: sentence) is listed, and the params the
    call gives, not the defaults it leaves (`pressure_angle`: asked by name, 20 deg);
    spur_gear's local
    `pitch_r` is listed only where the program reads it (`pair.gear1.pitch_r`), for every
    spur_gear, and its other locals (`base_r`, `half`, the loop's `ta`) are not."""
    src = ('units mm\nimport "std/gears.aidl"\n'
           "pair = gear_pair(teeth1=12, teeth2=24, module=2 mm)\n")
    names = {v.name: v.value for v in aidl_lang.compile(source=src).sizes()}
    assert names["pair.center_distance"] == pytest.approx(36)
    assert names["pair.teeth1"] == 12 and names["pair.gear2.mate"] == 12
    assert "pair.pressure_angle" not in names and "pair.gear1.pressure_angle" in names
    assert aidl_lang.compile(source=src).value("pair.pressure_angle").value == pytest.approx(20)
    assert not any(n.endswith((".pitch_r", ".base_r", ".half", ".ta")) for n in names)
    read = {v.name: v.value for v in aidl_lang.compile(
        source=src + "assert pair.gear1.pitch_r == 12 mm\n").sizes()}
    assert read["pair.gear1.pitch_r"] == pytest.approx(12)
    assert read["pair.gear2.pitch_r"] == pytest.approx(24)
    assert not any(n.endswith((".base_r", ".half")) for n in read)


SHEET = """units mm
solid lpart {
    body = Polygon(points=[(0, 0), (40, 0), (40, 10), (10, 10), (10, 30), (0, 30)])
}
solid tri {
    body = Polygon(points=[(89, 0), (129, 0), (109, 30)])
}
"""


def _parts_of(dxf_path):
    """name -> shapely polygon of each CUT layer's closed polylines and circles (ezdxf)."""
    from shapely.geometry import Point, Polygon
    out = {}
    for e in ezdxf.readfile(dxf_path).modelspace():
        if e.dxftype() == "LWPOLYLINE":
            shape = Polygon([(p[0], p[1]) for p in e.get_points("xy")])
        elif e.dxftype() == "CIRCLE":
            shape = Point(e.dxf.center.x, e.dxf.center.y).buffer(e.dxf.radius, 256)
        else:
            continue
        name = e.dxf.layer.removeprefix("CUT-")
        out[name] = out[name].union(shape) if name in out else shape
    return out


@pytest.mark.asyncio(loop_scope="module")
async def test_center_distance_between_the_parts_of_an_imported_sheet(shared):
    """Two parts of lines written by the project's DXF writer, imported as a sheet
    (`import_drawing` with parts): their centre distance is between the centres of their
    outlines' boxes (20, 15) and (109, 15), 89 mm as ezdxf reads the sheet (0 before), and
    the answer gives the two centres."""
    session, root = shared
    (root / "sheet_src.aidl").write_text(SHEET)
    r = await session.call_tool("render", {"path": "sheet_src.aidl", "output": "sheet.dxf"})
    assert not r.is_error and r.structured_content["ok"], _text(r)
    boxes = {n: p.bounds for n, p in _parts_of(root / "sheet.dxf").items()}
    centres = {n: ((b[0] + b[2]) / 2, (b[1] + b[3]) / 2) for n, b in boxes.items()}
    want = math.dist(centres["model.lpart"], centres["model.tri"])
    assert want == pytest.approx(89, abs=1e-6)
    for infer in (False, True):
        r = await session.call_tool("import_drawing", {"path": "sheet.dxf", "parts": True,
                                                       "infer": infer,
                                                       "output": f"sheet_{infer}.aidl"})
        assert not r.is_error and r.structured_content["check"]["ok"], _text(r)
        text = (root / f"sheet_{infer}.aidl").read_text()
        a, b = (n for n in ("cut_model_lpart1", "cut_model_tri1") if f"solid {n} " in text)
        r = await session.call_tool("measure", {"path": f"sheet_{infer}.aidl", "a": a, "b": b})
        assert not r.is_error, _text(r)
        m = r.structured_content["measure"]
        assert m["center_distance"] == pytest.approx(want, abs=1e-6), m
        assert m["centers"] == [pytest.approx(list(centres["model.lpart"]), abs=1e-6),
                                pytest.approx(list(centres["model.tri"]), abs=1e-6)]
        assert m["a"]["kind"] == "part" and m["distance"] == \
            pytest.approx(49, abs=1e-6)                 # (40, 0) to (89, 0)
        assert "center_distance 89 mm" in _text(r) and "centres (20, 15) and (109, 15)" in _text(r)


OVERLAP = """units mm
assembly sheet {
    solid a { body = Polygon(points=[(0, 0), (40, 0), (40, 10), (10, 10), (10, 30), (0, 30)]) }
    solid b { body = Rectangle(center=(30, 25), width=30, height=20) }
    solid c { body = Circle(center=(35, 0), radius=4) }
}
"""


@pytest.mark.asyncio(loop_scope="module")
async def test_render_says_which_parts_overlap_flat_by_their_true_outlines(shared):
    """An L-shaped part `a`, a rectangle `b` in its crook (their boxes cross, their outlines
    do not) and a circle `c` half over its foot: `overlaps` names a / c alone, with the half
    disc they share (8 pi mm², chords within 0.005 mm) as shapely measures it on the DXF
    written; `fit` (3D, nothing placed) is unchecked.  Laid out on a sheet, the same parts
    overlap nowhere, on the sheet's own DXF as on the answer."""
    session, root = shared
    (root / "overlap.aidl").write_text(OVERLAP)
    r = await session.call_tool("render", {"path": "overlap.aidl", "output": "overlap.dxf"})
    assert not r.is_error, _text(r)
    doc = r.structured_content
    assert not doc.get("fit", {}).get("checked")           # nothing placed: no 3D check
    [o] = doc["overlaps"]
    assert (o["a"], o["b"]) == ("sheet.a", "sheet.c") and "sheet" not in o
    parts = _parts_of(root / "overlap.dxf")
    a, b, c = (parts[f"sheet.{n}"] for n in "abc")
    assert a.intersection(b).area == 0
    assert a.bounds[2] > b.bounds[0] and a.bounds[3] > b.bounds[1]    # their boxes do cross
    shared_area = a.intersection(c).area
    assert shared_area == pytest.approx(8 * math.pi, abs=0.1)
    assert o["area"] == pytest.approx(shared_area, abs=0.1)
    assert o["box"] == pytest.approx([31, 0, 39, 4], abs=0.01)
    assert "2D: 1 pair of parts overlap" in _text(r) and "overlap sheet.a / sheet.c" in _text(r)
    assert aidl_lang.compile(source=OVERLAP).overlaps() == doc["overlaps"]

    r = await session.call_tool("render", {"path": "overlap.aidl", "layout": "sheet",
                                           "sheet": "200x100mm", "output": "laid.dxf"})
    assert not r.is_error, _text(r)
    assert r.structured_content["overlaps"] == [] and "2D: no parts overlap" in _text(r)
    laid = _parts_of(root / "laid.dxf")
    assert sorted(laid) == ["sheet.a", "sheet.b", "sheet.c"]
    for x in laid:
        for y in laid:
            assert x == y or laid[x].intersection(laid[y]).area < 1e-6, (x, y)
