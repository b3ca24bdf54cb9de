"""Countersinks and counterbores (issue 102): `Countersink(hole, diameter, angle)` and
`Counterbore(hole, diameter, depth)` on a hole or a pattern of holes, through the real parser,
solver, booleans and writers, each output re-read by an independent reader: the laser SVG by
svgelements (the heads on their own layer), the DXF by ezdxf, the router G-code by
gcodeparser (a tool change, then the V-bit's plunges or the pocket's rings), the STL by
trimesh (the cone or the step cut: the volume it removes, watertight); `aidl parts`,
`check --describe` and `measure` list them; W0528 / W0529 and the call's errors located."""
from __future__ import annotations

import io
import json
import math

import pytest

import aidl_lang
from aidl_lang.cli.main import main

gcodeparser = pytest.importorskip("gcodeparser")

from test_gcode import replay  # noqa: E402

PLATE = """units mm
thickness 6 mm
solid plate {
    body = Rectangle(center=(0, 0), width=80, height=50)
    hole holes { c = Circle(center=(-30, -15), diameter=4.5 mm) }
    corners = CornerPattern(holes, body, inset=10)
    Countersink(corners, diameter=9 mm)
}
"""
CENTRES = sorted([(-30.0, -15.0), (30.0, -15.0), (30.0, 15.0), (-30.0, 15.0)])

BORED = """units mm
thickness 6 mm
solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole h { c = Circle(center=(-15, 0), diameter=4.5) }
    hole g { c = Circle(center=(15, 0), diameter=4.5) }
    Counterbore([h, g.c], diameter=8, depth=2.5)
}
"""


def _run(tmp_path, src: str, *args) -> tuple[int, str, str]:
    f = tmp_path / "p.aidl"
    f.write_text(src)
    import contextlib
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([args[0], str(f), *args[1:]])
    return rc, out.getvalue(), err.getvalue()


def _frustum(R: float, r: float, h: float) -> float:
    return math.pi * h / 3 * (R * R + R * r + r * r)


def test_plate_of_four_countersunk_holes_laser_svg_router_gcode_and_parts(tmp_path):
    """The issue's done-when: four 4.5 mm holes, 9 mm heads: the laser SVG has the four 9 mm
    circles on the `countersink` layer (and the holes cut through), the router's G-code sinks
    them after the through-cuts, `aidl parts` lists them."""
    rc, out, err = _run(tmp_path, PLATE, "render", "-o", str(tmp_path / "p.svg"),
                        "--svg-style", "laser")
    assert rc == 0, err
    assert "note: 4 countersink heads (9 mm) drawn as circles on the engrave layer " \
        "`countersink`" in out
    import svgelements
    svg = svgelements.SVG.parse(str(tmp_path / "p.svg"))
    layer = next(e for e in svg.elements() if isinstance(e, svgelements.Group)
                 and e.id == "countersink")
    heads = [e for e in layer if isinstance(e, svgelements.Circle)]
    # the file's own numbers (svgelements' values as written: mm of the viewBox, y down)
    assert sorted((float(c.values["cx"]), -float(c.values["cy"])) for c in heads) == CENTRES
    assert all(float(c.values["r"]) == 4.5 for c in heads)
    cut = next(e for e in svg.elements() if isinstance(e, svgelements.Group) and e.id == "cut")
    holes = [e for e in cut.select() if isinstance(e, svgelements.Circle)]
    assert len(holes) == 4 and all(float(c.values["r"]) == 2.25 for c in holes)
    assert sorted((float(c.values["cx"]), -float(c.values["cy"])) for c in holes) == CENTRES

    # the router: every through-cut, then a tool change (M0) and a 90 deg V-bit plunged at
    # each hole to 9 / 2 / tan(45 deg) = 4.5 mm, the cone's top 9 mm across
    rc, out, err = _run(tmp_path, PLATE, "render", "-o", str(tmp_path / "p.nc"),
                        "--machine", "router")
    assert rc == 0, err
    assert "note: 4 countersinks sunk after the through-cuts with a 90 deg V-bit" in out
    text = (tmp_path / "p.nc").read_text()
    head, tail = text.split("\nM0\n")
    assert "; tool change: a 90 deg V-bit for the 4 countersinks" in head
    moves = replay(text, "router")
    n_before = len(replay(head + "\n", "router"))
    after = moves[n_before:]
    plunges = [(mv.p, mv.z) for mv in after if mv.g == 1 and mv.p == mv.q]
    assert sorted(p for p, _ in plunges) == CENTRES
    assert all(z == pytest.approx(-4.5, abs=1e-9) for _, z in plunges)
    assert not [mv for mv in after if mv.g in (1, 2, 3) and mv.p != mv.q]   # no XY cutting
    # every hole's through-cut comes before: the bit's circles at radius 2.25 - 1.5875
    assert sum(1 for mv in moves[:n_before] if mv.on and mv.g == 2) >= 4 * 2 * 4

    rc, out, err = _run(tmp_path, PLATE, "parts")
    assert rc == 0, err
    assert "countersinks and counterbores:\n  plate: 4 countersinks, 4.5 mm holes, 9 mm " \
        "heads at 90 deg, 2.25 mm deep" in out
    rc, out, err = _run(tmp_path, PLATE, "parts", "--json")
    sinks = json.loads(out)["parts"][0]["sinks"]
    assert sorted(tuple(s["center"]) for s in sinks) == CENTRES
    assert {(s["kind"], s["hole_d"], s["diameter"], s["angle"]) for s in sinks} == \
        {("countersink", 4.5, 9.0, 90.0)}
    assert all(s["depth"] == pytest.approx(2.25, abs=1e-12) for s in sinks)


def test_laid_out_the_heads_move_with_their_holes(tmp_path):
    """`--layout sheet` moves (and may turn) the plate: the V-bit still plunges at the centre
    of each hole the router cut (the centres of its G2 circles)."""
    rc, _, err = _run(tmp_path, PLATE, "render", "--layout", "sheet", "-o",
                      str(tmp_path / "l.nc"), "--machine", "router")
    assert rc == 0, err
    text = (tmp_path / "l.nc").read_text()
    head, _ = text.split("\nM0\n")
    moves = replay(text, "router")
    n = len(replay(head + "\n", "router"))
    holes = sorted({(round(mv.center[0], 6), round(mv.center[1], 6)) for mv in moves[:n]
                    if mv.on and mv.g == 2 and abs(mv.radius - (2.25 - 1.5875)) < 1e-9})
    plunges = sorted((round(mv.p[0], 6), round(mv.p[1], 6)) for mv in moves[n:]
                     if mv.g == 1 and mv.p == mv.q)
    assert len(holes) == 4 and plunges == holes


def test_countersinks_dxf_layer_stl_cone_describe_and_measure(tmp_path):
    res = aidl_lang.compile(PLATE)
    assert res.ok and not res.diagnostics, res.diagnostics
    import ezdxf
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    circles = [(e.dxf.layer, round(e.dxf.radius, 9)) for e in doc.modelspace()
               if e.dxftype() == "CIRCLE"]
    assert sorted(circles) == [("COUNTERSINK", 4.5)] * 4 + [("CUT", 2.25)] * 4
    # the STL: the part with the cones cut, against the same part without them
    import trimesh
    (tmp_path / "a.aidl").write_text(PLATE)
    (tmp_path / "b.aidl").write_text(PLATE.replace("    Countersink(corners, diameter=9 mm)\n",
                                                   ""))
    vols = []
    for name in ("a", "b"):
        assert main(["render", str(tmp_path / f"{name}.aidl"), "-o",
                     str(tmp_path / f"{name}.stl")]) == 0
        m = trimesh.load(tmp_path / f"{name}.stl")
        assert m.is_watertight
        vols.append(m.volume)
    cone = _frustum(4.5, 2.25, 2.25) - math.pi * 2.25 ** 2 * 2.25     # less the hole's share
    assert vols[1] - vols[0] == pytest.approx(4 * cone, rel=5e-3)
    assert vols[1] - vols[0] > 4 * cone * 0.99
    # the GLB (the studio's 3D view) cuts the same cones
    assert main(["render", str(tmp_path / "a.aidl"), "-o", str(tmp_path / "a.glb")]) == 0
    glb = trimesh.load(tmp_path / "a.glb").to_geometry()
    assert glb.volume == pytest.approx(vols[0], abs=1e-6)
    # describe and measure
    d = res.description
    part = d["parts"][0]
    assert len(part["sinks"]) == 4 and {s["diameter"] for s in part["sinks"]} == {9.0}
    m = res.measure("plate.holes.c", "plate.body")
    assert m["sinks"] == [{"kind": "countersink", "hole": "plate.holes.c",
                           "center": [-30.0, -15.0], "hole_d": 4.5, "diameter": 9.0,
                           "depth": pytest.approx(2.25, abs=1e-12), "angle": 90.0}]
    rc, out, _ = _run(tmp_path, PLATE, "check", "--describe")
    assert "  countersink: d=9 head, 90 deg cone, 2.25 mm deep, on the d=4.5 hole " \
        "`plate.holes.c` at (-30, -15)" in out


@pytest.mark.step
def test_step_cuts_the_exact_cone_and_step(tmp_path):
    """STEP (the `step` extra): the cones a `CONICAL_SURFACE` each and the counterbores'
    steps exact; the file read back (OCP's STEP reader) has the volume of the plate less the
    holes and the heads to 1e-6 mm^3."""
    pytest.importorskip("OCP")
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps
    from OCP.STEPControl import STEPControl_Reader

    def volume(src: str, name: str) -> tuple[float, str]:
        f = tmp_path / f"{name}.aidl"
        f.write_text(src)
        assert main(["render", str(f), "-o", str(tmp_path / f"{name}.step")]) == 0
        r = STEPControl_Reader()
        r.ReadFile(str(tmp_path / f"{name}.step"))
        r.TransferRoots()
        g = GProp_GProps()
        BRepGProp.VolumeProperties_s(r.OneShape(), g)
        return g.Mass(), (tmp_path / f"{name}.step").read_text()
    v, text = volume(PLATE, "csk")
    assert text.count("CONICAL_SURFACE") == 4
    cone = _frustum(4.5, 2.25, 2.25) - math.pi * 2.25 ** 2 * 2.25
    assert v == pytest.approx(80 * 50 * 6 - 4 * math.pi * 2.25 ** 2 * 6 - 4 * cone, abs=1e-6)
    v, _ = volume(BORED, "cb")
    step = math.pi * (4 ** 2 - 2.25 ** 2) * 2.5
    assert v == pytest.approx(60 * 40 * 6 - 2 * math.pi * 2.25 ** 2 * 6 - 2 * step, abs=1e-6)


def test_counterbores_are_pocketed_by_the_router_and_stepped_in_the_stl(tmp_path):
    """Two 8 mm counterbores 2.5 mm deep: the router pockets each with its 3.175 mm end mill
    in rings out to 4 - 1.5875 mm, in two depths of 1.25 mm; the STL loses two 8 mm x 2.5 mm
    steps less the holes' share; the laser SVG has the circles on the `counterbore` layer."""
    rc, out, err = _run(tmp_path, BORED, "render", "-o", str(tmp_path / "b.nc"), "--machine",
                        "router", "-o", str(tmp_path / "b.svg"), "-o", str(tmp_path / "b.stl"))
    assert rc == 0, err
    text = (tmp_path / "b.nc").read_text()
    head, _ = text.split("\nM0\n")
    assert "; tool change: a 3.175 mm end mill for the 2 counterbores" in head
    moves = replay(text, "router")
    after = moves[len(replay(head + "\n", "router")):]
    R = 4 - 3.175 / 2
    for cx in (-15.0, 15.0):
        rings = [mv for mv in after if mv.g == 3 and mv.center == pytest.approx((cx, 0.0))]
        radii = sorted({round(mv.radius, 9) for mv in rings})
        assert radii[-1] == pytest.approx(R, abs=1e-9)
        # neighbouring rings (and the first from the centre) no further apart than the
        # tool's diameter: nothing is left standing between them
        assert all(b - a <= 3.175 - 1e-9 for a, b in zip([0.0] + radii, radii))
        assert sorted({round(mv.z, 9) for mv in rings}) == [-2.5, -1.25]
    import trimesh
    (tmp_path / "c.aidl").write_text(BORED.replace(
        "    Counterbore([h, g.c], diameter=8, depth=2.5)\n", ""))
    assert main(["render", str(tmp_path / "c.aidl"), "-o", str(tmp_path / "c.stl")]) == 0
    a, b = trimesh.load(tmp_path / "b.stl"), trimesh.load(tmp_path / "c.stl")
    assert a.is_watertight
    step = math.pi * (4 ** 2 - 2.25 ** 2) * 2.5
    assert b.volume - a.volume == pytest.approx(2 * step, rel=5e-3)
    assert 'id="counterbore"' in (tmp_path / "b.svg").read_text()


def test_warnings_at_the_call(tmp_path):
    src = """units mm
thickness 3 mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole h { c = Circle(center=(17, 0), diameter=4.5 mm) }
    Countersink(h, diameter=9 mm)
    hole g { c = Circle(center=(0, 0), diameter=4 mm) }
    Counterbore(g, diameter=8 mm, depth=4 mm)
    hole k { c = Circle(center=(-10, 0), diameter=4 mm) }
    Countersink(k, diameter=3 mm)
    hole m { c = Circle(center=(-10, 6), diameter=3 mm) }
    Countersink(m, diameter=12 mm, angle=60 deg)
}
"""
    res = aidl_lang.compile(src)
    got = [(d.code, d.span.line, d.message) for d in res.diagnostics]
    codes = [(c, line) for c, line, _ in got]
    assert ("W0528", 6) in codes and ("W0529", 8) in codes and ("W0528", 10) in codes
    assert ("W0529", 12) in codes and ("W0528", 12) in codes
    msg = dict(((c, line), m) for c, line, m in got)
    assert "the 9 mm head of the countersink of `plate.h.c` at (17, 0) reaches past the " \
        "material around it" in msg[("W0528", 6)]
    assert "it is 4 mm deep, past the part's thickness (3 mm)" in msg[("W0529", 8)]
    assert "is not larger than the hole (4 mm)" in msg[("W0528", 10)]
    # (12 - 3) / 2 / tan(30 deg) = 7.79 mm of cone in 3 mm
    assert "its 60 deg cone is 7.79 mm deep" in msg[("W0529", 12)]
    assert len([c for c in codes if c[0] in ("W0528", "W0529")]) == 5


@pytest.mark.parametrize("call, code, said", [
    ("Countersink(body, diameter=9)", "E0108", "`Countersink` sinks a round hole"),
    ("Countersink(s, diameter=9)", "E0108", "hole `plate.s` has no Circle"),
    ("Countersink(h, diameter=9, angle=170 deg)", "E0108", "from 30 to 150 deg"),
    ("Counterbore(h, diameter=9, depth=0)", "E0108", "more than 0 deep"),
    ("Counterbore(h, diameter=9)", "E0106", "missing"),
    ("Countersink(h, diameter=0)", "E0108", "the head's diameter is above 0"),
])
def test_errors_are_located_at_the_call(call, code, said):
    src = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    hole h { c = Circle(center=(0, 0), diameter=4) }\n"
           "    hole s { r = Rectangle(center=(10, 0), width=3, height=3) }\n"
           f"    {call}\n}}\n")
    res = aidl_lang.compile(src)
    errs = [d for d in res.diagnostics if d.severity == "error"]
    assert errs and errs[0].code == code and said in errs[0].message, errs
    assert errs[0].span.line == 6


def _sunk(src: str) -> list:
    res = aidl_lang.compile(src)
    assert res.ok, res.diagnostics
    return [(s.kind, s.hole, s.diameter, s.angle, s.depth) for s in res.compiled.drawing.sinks]


@pytest.mark.parametrize("syn", ["CounterSink", "Csink"])
def test_countersink_synonyms_are_the_same_call(syn):
    """`CounterSink(holes=..., d=..., included_angle=...)` is Countersink's call."""
    want = _sunk(PLATE.replace("Countersink(corners, diameter=9 mm)",
                               "Countersink(corners, diameter=9 mm, angle=82 deg)"))
    assert len(want) == 4 and want[0][3] == pytest.approx(math.radians(82))
    assert _sunk(PLATE.replace("Countersink(corners, diameter=9 mm)",
                               f"{syn}(holes=corners, d=9 mm, included_angle=82 deg)")) == want


@pytest.mark.parametrize("syn", ["CounterBore", "Cbore"])
def test_counterbore_synonyms_and_a_list_of_a_hole_and_a_circle(syn):
    want = _sunk(BORED)
    assert want == [("counterbore", "plate.h.c", 8.0, None, 2.5),
                    ("counterbore", "plate.g.c", 8.0, None, 2.5)]
    assert _sunk(BORED.replace("Counterbore([h, g.c], diameter=8, depth=2.5)",
                               f"{syn}(of=[h, g.c], head=8, deep=2.5)")) == want


def test_heads_that_leave_nothing_of_the_part_are_E0503_at_the_call():
    """A 30 mm counterbore 4 mm deep on a 20 x 10 tag 3 mm thick: the recess goes through and
    covers the whole tag (the STL would be empty beside an SVG of the tag): "E0503" at the
    call, the compile stops (issue 109; tests/test_law_outputs.py has the countersinks)."""
    src = ("units mm\nthickness 3 mm\nsolid tag {\n"
           "    body = Rectangle(center=(0, 0), width=20, height=10)\n"
           "    hole h { c = Circle(center=(0, 0), diameter=4) }\n"
           "    Counterbore(h, diameter=30 mm, depth=4 mm)\n}\n")
    r = aidl_lang.compile(source=src)
    (d,) = [d for d in r.diagnostics if d.severity == "error"]
    assert d.code == "E0503" and (d.span.line, d.span.col) == (6, 5)
    assert d.message.startswith("the counterbores of part `tag` leave nothing of it: the 30 mm "
                                "head on `tag.h.c` (4 mm hole) goes through the 3 mm part, its "
                                "4 mm recess 30 mm wide at its bottom face")
    assert "give a `depth` under 3 mm" in d.hint
