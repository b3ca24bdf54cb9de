"""Issue 61 ("what models and makers reach for, round three"): each finding as the real
program a model or a maker wrote, through the real parser, solver and outputs."""
from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest
import numpy as np

from aidl_lang.api import compile as aidl_compile
from aidl_lang.cli.main import main


def run_cli(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()


def checked(src: str, path: str = "/tmp/aidl-issue61.aidl"):
    r = aidl_compile(src, path=path)
    r.find_redundant(seconds=None, max_rows=None)
    return r


# ------------------------------------------------------------ the docs' own examples warn
def test_a_point_shape_in_a_constraint_is_seen_from_the_constraints_structure():
    """`Coincident(teeth_ring.axis, hub.center)` (a `Point` of a child beside a point of the
    structure itself) tied the child's frame to nothing: the Point was seen from the model
    frame, the other point from the structure's, so moving the gear and its teeth ring
    oppositely changed no row (W0404 on `spur_gear`'s own teeth_ring).  The row now reads
    the child frame alone."""
    src = """solid part {
    solid p {
        hub = Circle(center=(0, 0), radius=10)
        Fixed(hub.center)
        solid ring {
            axis = Point(0, 0)
            Fixed(axis)
            r = Circle(center=(0, 0), radius=14)
            Fixed(r)
        }
        Coincident(ring.axis, hub.center)
    }
}
"""
    r = checked(src)
    assert not r.sink.items, [d.message for d in r.sink.items]
    m = r.compiled.model
    ring = next(t for t in m.structures if t.path == "part.p.ring")
    p = next(t for t in m.structures if t.path == "part.p")
    rows = [e for c in m.constraints if c.describe().startswith("Coincident")
            for e in c.equations]
    terms = set().union(*(e.expr.terms for e in rows))
    assert ring.fx in terms and ring.fy in terms
    assert p.fx not in terms and p.fy not in terms and 0 not in terms     # no outer frames
    # and the solve keeps the ring on the hub when the gear is moved
    r2 = checked(src.replace("Fixed(hub.center)", "hub.center == (30, 7)"))
    v = {x.name: x.value for x in r2.values}
    assert np.allclose(v["part.p.ring.r.center"], (30, 7), atol=1e-9)


def test_stdlib_locations_read_std_not_the_install_path():
    src = 'import "std/gears.aidl"\nsolid part {\n    p = spur_gear(teeth=12, module=1 mm, bore=30 mm)\n}\n'
    rc, _, err = run_cli("check", _write(src, "bore"))
    assert rc == 1
    # at the call (issue 86), the template's line a note that reads std/
    # at the arguments the assert reads (issue 95: checked before the body runs)
    assert "bore.aidl:3:25: error[E0405]: arguments `teeth`, `module`, `bore`" in err, err
    line = _stdlib_line("gears.aidl", "assert root_r > bore / 2")
    assert f"  --> std/gears.aidl:{line}:5\n" in err and \
        f"inside `spur_gear`, at std/gears.aidl:{line}:5" in err
    assert "/stdlib/" not in err and "site-packages" not in err


def _stdlib_line(name: str, text: str, after: str = "") -> int:
    """The 1-based line of the standard library file ``name`` that holds ``text`` (the first
    after the line holding ``after``): the tests follow the file's edits."""
    from aidl_lang.library.sources import STDLIB
    lines = (Path(STDLIB) / name).read_text().splitlines()
    start = next((i for i, ln in enumerate(lines) if after in ln), 0) if after else 0
    return next(i + 1 for i in range(start, len(lines)) if text in lines[i])


_MADE: list[str] = []


@pytest.fixture(scope="module", autouse=True)
def _remove_written():
    """The folders `_write` made are removed when the module's tests end (they were left in
    /tmp)."""
    yield
    import shutil
    while _MADE:
        shutil.rmtree(_MADE.pop(), ignore_errors=True)


def _write(src: str, name: str) -> str:
    import tempfile
    import os
    d = tempfile.mkdtemp(prefix="aidl-issue61-")
    _MADE.append(d)
    p = os.path.join(d, f"{name}.aidl")
    with open(p, "w", encoding="utf-8") as f:
        f.write(src)
    return p


def test_a_placement_beside_a_templates_own_hold_is_not_redundant():
    """`CenterInside(h, body)` beside `cross_halving`'s own `Fixed(self)` (issue 61 made its
    W0401 blame the user's line only, "drop `CenterInside(h, body)`: the template holds it
    already").  The hold is where the instance starts, which the parent's constraints
    override (the solver moves the instance; the freedom count does not count the hold):
    dropped as told, the slot went back 10 mm (9.5 until issue 111 left the 1 mm overrun out
    of the box; issue 109, law 4).  Nothing placing an instance is redundant with its
    template's hold, made where the centring puts it (`cy=10 mm`) or not; a restatement of
    the template's own geometry still is."""
    src = """import "std/joints.aidl"

solid plate {
    body = Rectangle(center=(0, 0), width=120, height=120)
    h = cross_halving()
    Fixed(body)
    CenterInside(h, body)
}
"""
    for text in (src, src.replace("cross_halving()", "cross_halving(cy=10 mm)")):
        r = checked(text)
        assert r.ok and not [d for d in r.sink.items if d.code == "W0401"], \
            [d.message for d in r.sink.items]
        assert max(map(abs, r.value("plate.h.cut.center").mm)) < 1e-9
    r = checked(src.replace("    CenterInside(h, body)\n", "    CenterInside(h, body)\n"
                            "    VerticalDistance(h.cut.bottom.midpoint, h.cut.top.midpoint, "
                            "20 mm)\n"))
    (w,) = [d for d in r.sink.items if d.code == "W0401"]
    assert w.span.line == 8 and "follows from the shape of `h.cut`" in w.message


def test_a_part_placed_by_a_template_names_the_file_that_places_it():
    src = """import "std/gears.aidl"
thickness 3 mm
assembly kit {
    t = gear_train(teeth=[12, 24])
    Place(t.gear[0], position=(0, 0, 10))
}
"""
    r = aidl_compile(src, path="/tmp/aidl-issue61-place.aidl")
    e = next(d for d in r.sink.items if d.code == "E0108")
    assert "already placed, in std/gears.aidl line" in e.message, e.message


# ------------------------------------------------------------ Mirrored of a list
def test_mirrored_of_a_list_is_the_list_of_the_mirror_images():
    """`Mirrored(legs, axis)` (a list a loop made, or written) was E0108 "got list"; now each
    item is mirrored, and the result is their images in order (`m[1]` is item 1's)."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    axis = Line((0, -20), (0, 20), construction=true)
    Fixed(body)
    hole h {
        a = Circle(center=(-30, 10), radius=2)
        b = Circle(center=(-20, -10), radius=3)
        Fixed(a)
        Fixed(b)
    }
    Fixed(h)
    for i in range(2) {
        hole k { c = Circle(center=(-10 + 3 * i, 0), radius=1) }
        Fixed(k)
    }
    m = Mirrored([h.a, h.b], axis)
    n = Mirrored(k, axis)
    assert m[1].center == (20, -10) and m[0].radius == 2
    assert n[1].c.center == (7, 0)
}
"""
    r = checked(src)
    assert r.ok and not r.sink.items, [d.message for d in r.sink.items]
    got = sorted((o["center"][0], o["center"][1], o["d"])
                 for o in r.description["parts"][0]["openings"])
    assert got == sorted([(-30, 10, 4), (30, 10, 4), (-20, -10, 6), (20, -10, 6),
                          (-10, 0, 2), (10, 0, 2), (-7, 0, 2), (7, 0, 2)])
    bad = aidl_compile(src.replace("Mirrored(k, axis)", "Mirrored([h, 3], axis)"),
                       path="/tmp/aidl-issue61-m.aidl")
    (e,) = [d for d in bad.sink.items if d.is_error][:1]
    assert e.code == "E0108" and "list holds a number" in e.message, e.message


# ------------------------------------------------------------ a point on an ellipse
def _on_ellipse(p, c, rx, ry, rot) -> float:
    """The implicit ellipse law (u / rx)^2 + (v / ry)^2 - 1 of point ``p`` (an independent
    statement of what `Coincident(point, ellipse)` must make true)."""
    import math
    dx, dy = p[0] - c[0], p[1] - c[1]
    u = dx * math.cos(rot) + dy * math.sin(rot)
    v = -dx * math.sin(rot) + dy * math.cos(rot)
    return (u / rx) ** 2 + (v / ry) ** 2 - 1


ELLIPSES = """solid egg {
    body = Rectangle(center=(0, 0), width=260, height=200)
    Fixed(body)
    drawing d {
        e = Ellipse(center=(10, 5), rx=20, ry=10, rotation=30 deg)
        a = Ellipse(center=(-40, 0), rx=15, ry=6, rotation=-20 deg, start_angle=0 deg,
                    end_angle=180 deg)
        Fixed(e)
        Fixed(a)
        axis = Line((50, -50), (60, 50), construction=true)
        Fixed(axis.start)
        axis.end.x == 70
        m = Mirrored(e, axis)
    }
    Fixed(d)
    hole h { c = Circle(center=(15, 10), radius=2) }
    hole k { c = Circle(center=(-40, 6), radius=1) }
    hole q { c = Circle(center=(100, 10), radius=1) }
    Coincident(h.c.center, d.e)
    h.c.center.x == 5
    Coincident(d.a, k.c.center)
    k.c.center.x == -35
    Coincident(q.c.center, d.m)
    q.c.center.y == -5
}
"""


def test_a_point_on_an_ellipse_an_elliptic_arc_and_a_mirrored_ellipse():
    """`Coincident(point, Ellipse)` was E0108; now the point lies on the ellipse exactly
    (1e-9 of the implicit law), on a whole ellipse, an elliptic arc's ellipse and a copy
    mirrored about a line the solve turns (its axes follow the line as solved)."""
    import math
    r = aidl_compile(ELLIPSES, path="/tmp/aidl-issue61-ellipse.aidl")
    assert r.ok, [d.message for d in r.sink.items]
    v = {x.name: x.value for x in r.values}
    h, k, q = v["egg.h.c.center"], v["egg.k.c.center"], v["egg.q.c.center"]
    assert abs(h[0] - 5) < 1e-9 and abs(k[0] + 35) < 1e-9 and abs(q[1] + 5) < 1e-9
    assert abs(_on_ellipse(h, v["egg.d.e.center"], 20, 10, math.radians(30))) < 1e-9
    assert abs(_on_ellipse(k, v["egg.d.a.center"], 15, 6, math.radians(-20))) < 1e-9
    s, e = v["egg.d.axis.start"], v["egg.d.axis.end"]
    phi = math.atan2(e[1] - s[1], e[0] - s[0])
    assert abs(phi - math.atan2(100, 10)) > 0.05          # the solve turned the line
    assert abs(_on_ellipse(q, v["egg.d.m.center"], 20, 10, 2 * phi - math.radians(30))) < 1e-9
    # the mirrored copy as drawn: its center is the image of the original's
    c0, cm = v["egg.d.e.center"], v["egg.d.m.center"]
    assert abs((cm[0] - s[0]) * math.sin(phi) - (cm[1] - s[1]) * math.cos(phi)
               + (c0[0] - s[0]) * math.sin(phi) - (c0[1] - s[1]) * math.cos(phi)) < 1e-9


def test_the_ellipse_residual_law():
    """For any ellipse (semi-axes, rotation) and any height through it, the solved point
    satisfies the implicit law; for rx == ry the constraint is the circle's."""
    from hypothesis import given, settings, strategies as st
    import math

    @settings(max_examples=25, deadline=None)
    @given(rx=st.floats(2, 60), ry=st.floats(2, 60), rot=st.floats(-180, 180),
           frac=st.floats(-0.9, 0.9))
    def law(rx, ry, rot, frac):
        # a height inside the ellipse's vertical extent: the horizontal line meets it twice
        half = math.sqrt((rx * math.sin(math.radians(rot))) ** 2
                         + (ry * math.cos(math.radians(rot))) ** 2)
        y = frac * half
        src = (f"solid s {{\n    e = Ellipse(center=(0, 0), rx={rx!r}, ry={ry!r}, "
               f"rotation={rot!r} deg)\n    Fixed(e)\n    p = Point({rx + ry!r}, {y!r})\n"
               f"    Coincident(p, e)\n    p.y == {y!r}\n}}\n")
        r = aidl_compile(src, path="/tmp/aidl-issue61-law.aidl")
        assert r.ok, [d.message for d in r.sink.items]
        p = {x.name: x.value for x in r.values}["s.p.p"]
        assert abs(p[1] - y) < 1e-9 * max(1.0, half)
        assert abs(_on_ellipse(p, (0, 0), rx, ry, math.radians(rot))) < 1e-9
    law()


# ------------------------------------------------------------ settings written as constants
def _apply(src: str, fix: dict) -> str:
    sp = fix["span"]
    return src[:sp["start"]] + fix["replacement"] + src[sp["end"]:]


STAND = """import "std/gears.aidl"

thickness = 4 mm
kerf = 0.2 mm
param module = 1.5 mm

assembly stand {
    solid back { r = Rectangle(center=(0, 0), width=120, height=90) }
    solid foot { r = Rectangle(center=(0, -80), width=120, height=50) }
    Below(foot, back, gap=5)
    AlignCenterX(foot, back)
    Fixed(back)
    g = spur_gear(teeth=20)
    RightOf(g, back, gap=5)
    AlignCenterY(g, back)
}
"""


def test_thickness_and_kerf_written_with_equals_are_named_and_fixed():
    """The maker's tablet stand wrote `thickness = 4 mm` and `kerf = 0.2 mm` as constants:
    3 mm parts and no kerf, silently.  Now W0108 on each, whose --json fix is the statement;
    applied, the parts are 4 mm thick and the cuts get the kerf.  `module`, which the gear's
    call leaves at its default, gets a fix that passes it."""
    r = checked(STAND)
    ws = [d for d in r.diagnostics_json() if d["code"] == "W0108"]
    assert [w["fix"]["replacement"] for w in ws] == [
        "thickness 4 mm", "kerf 0.2 mm", "spur_gear(teeth=20, module=module)"]
    assert all(w["severity"] == "warning" for w in ws)
    assert {p.thickness for p in r.output.parts} == {None}       # the constant did nothing (3 mm)
    assert r.output.drawing.kerf in (None, 0, 0.0, {})
    fixed = STAND
    for w in sorted(ws, key=lambda w: -w["fix"]["span"]["start"]):
        fixed = _apply(fixed, w["fix"])
    r2 = checked(fixed)
    assert r2.ok and not [d for d in r2.sink.items if d.code == "W0108"], \
        [d.message for d in r2.sink.items]
    assert {p.thickness for p in r2.output.parts} == {4.0}
    k = r2.output.drawing.kerf
    assert (k == 0.2) if isinstance(k, float) else set(k.values()) == {0.2}
    teeth = r2.value("stand.g.pitch.radius").mm
    assert abs(teeth - 1.5 * 20 / 2) < 1e-9                     # module 1.5 reached the gear


def test_a_param_thickness_gets_the_statement_below_it_and_read_names_are_quiet():
    src = "param thickness = 4 mm\nsolid a { r = Rectangle(center=(0, 0), width=40, height=20) }\n"
    (w,) = [d for d in checked(src).diagnostics_json() if d["code"] == "W0108"]
    fixed = _apply(src, w["fix"])
    assert fixed.startswith("param thickness = 4 mm\nthickness thickness\n")
    r = checked(fixed)
    assert not r.sink.items and {p.thickness for p in r.output.parts} == {4.0}
    # a name that something reads is an ordinary constant: no warning
    quiet = ("thickness = 4 mm\nsolid a { r = Rectangle(center=(0, 0), width=40, "
             "height=thickness * 5) }\n")
    assert not checked(quiet).sink.items


# ------------------------------------------------------------ no cascades; suggestions in meaning
def test_a_failed_definition_is_reported_once_not_again_through_a_member():
    """`t = Text("HELLO", size=5)` (no position) is one error; `label.t.center`,
    `label.t.bb.width` and `label.t` in a list index were each a second error, "a object has no
    member `center`"."""
    src = """solid tag {
    body = Rectangle(center=(0, 0), width=60, height=20)
    drawing label {
        t = Text("HELLO", size=5)
        for i in range(2) { u = Text("X", size=3) }
    }
    Coincident(label.t.center, body.center)
    x = label.t.bb.width
    label.t.center == (0, 0)
    y = label.u[1].center
}
"""
    r = aidl_compile(src, path="/tmp/aidl-issue61-text.aidl")
    errs = [(d.code, d.span.line) for d in r.sink.items if d.is_error]
    assert errs == [("E0108", 4), ("E0108", 5)], [d.message for d in r.sink.items]
    assert not any("a object" in d.message for d in r.sink.items)


def test_a_typeface_argument_says_font_is_the_argument_not_did_you_mean_on():
    """`typeface=` (a name models guess) says that the font is `font=` (issue 112: a family
    with its style, or a font file), not a did-you-mean on the spelling."""
    src = ('solid tag {\n    body = Rectangle(center=(0, 0), width=60, height=20)\n'
           '    drawing label {\n        t = Text("HI", position=(0, 0), size=5, typeface="Arial")\n'
           '    }\n}\n')
    r = aidl_compile(src, path="/tmp/aidl-issue61-font.aidl")
    (e,) = [d for d in r.sink.items if d.is_error]
    assert e.code == "E0105" and "`typeface`" in e.message
    assert "`font=`" in e.hint and "single-stroke" in e.hint and "did you mean" not in e.hint
    assert e.suggestions == [] and e.fix is None
    # a real misspelling still gets its suggestion
    r = aidl_compile(src.replace('typeface="Arial"', 'valgin="middle"'), path="/tmp/aidl-issue61-f2.aidl")
    (e,) = [d for d in r.sink.items if d.is_error]
    assert e.suggestions[:1] == ["valign"]


# ------------------------------------------------------------ half outlines, centroids, corners
def test_a_polygon_and_a_polyline_written_by_one_half():
    """`Polygon(half, mirror="y")`: the half, then its mirror images (an end on the axis not
    repeated), exact; the outline is symmetric and the shape stays rigid (literal points)."""
    src = """solid leaf {
    p = Polygon([(0, -20), (12, -15), (15, 5), (6, 18), (0, 30)], mirror="y")
    drawing vein { v = Polyline([(-10, 0), (0, 8)], mirror="y") }
    vein.bb.center == p.bb.center
    p.bb.left == 100
}
"""
    r = checked(src)
    assert r.ok and not r.sink.items, [d.message for d in r.sink.items]
    v = {x.name: x.value for x in r.values}
    pts = [v[f"leaf.p.p{i}"] for i in range(8)]
    assert f"leaf.p.p8" not in v
    want = [(0, -20), (12, -15), (15, 5), (6, 18), (0, 30), (-6, 18), (-15, 5), (-12, -15)]
    assert abs(pts[0][0] - 115) < 1e-9                  # moved whole by `p.bb.left == 100`
    assert np.allclose([(q[0] - pts[0][0], q[1] - pts[0][1]) for q in pts],
                       [(w[0], w[1] + 20) for w in want], atol=1e-12), pts
    vein = [v[f"leaf.vein.v.p{i}"] for i in range(3)]
    assert np.allclose([(q[0] - vein[1][0], q[1] - vein[1][1]) for q in vein],
                       [(-10, -8), (0, 0), (10, -8)], atol=1e-12)


def test_centroid_of_a_triangle_and_a_polygon():
    src = """solid plate {
    t = Triangle(center=(0, 0), base=30, height=20)
    Fixed(t)
    p = Polygon([(40, 0), (70, 0), (70, 10), (50, 30)])
    hole a { c = Circle(center=(1, 1), radius=1) }
    hole b { c = Circle(center=(50, 10), radius=1) }
    Coincident(a.c.center, t.centroid)
    Coincident(b.c.center, p.centroid)
}
"""
    r = aidl_compile(src, path="/tmp/aidl-issue61-centroid.aidl")
    assert r.ok, [d.message for d in r.sink.items]
    v = {x.name: x.value for x in r.values}
    P = [v[f"plate.p.p{i}"] for i in range(4)]
    # the area centroid by the shoelace formula on the solved vertices (numpy, independent)
    x, y = np.array([q[0] for q in P]), np.array([q[1] for q in P])
    x2, y2 = np.roll(x, -1), np.roll(y, -1)
    cr = x * y2 - x2 * y
    A = cr.sum() / 2
    cx, cy = ((x + x2) * cr).sum() / (6 * A), ((y + y2) * cr).sum() / (6 * A)
    assert np.allclose(v["plate.b.c.center"], (cx, cy), atol=1e-9)
    T = [v[f"plate.t.{n}"] for n in "abc"]
    assert np.allclose(v["plate.a.c.center"], np.mean(T, axis=0), atol=1e-12)
    assert abs(v["plate.a.c.center"][1] - (-10 / 3)) < 1e-12     # not the box's center (0)


def test_the_prompt_says_what_corner_pattern_keeps_and_how_an_ellipse_is_offset():
    from aidl_lang.llm.prompt import system_prompt
    text = system_prompt(examples=False)
    corner = next(ln for ln in text.splitlines() if ln.startswith("- CornerPattern("))
    assert "bottom-left" in corner and "Fixed stays put" in corner
    ellipse = next(ln for ln in text.splitlines() if ln.startswith("- Ellipse("))
    assert "Offset, Shell or kerf of it: within 1e-4 mm" in ellipse      # issue 73: taken, bound said
    assert 'mirror="y"' in next(ln for ln in text.splitlines() if ln.startswith("- Polygon("))
    members = [ln for ln in text.splitlines() if ln.startswith("- ") and " | points:" in ln]
    assert "centroid" in next(ln for ln in members if "Triangle" in ln.split("|")[0])
    assert "centroid" in next(ln for ln in members if "Polygon" in ln.split("|")[0])


# ------------------------------------------------------------ a hole that cuts nothing; CutInto
LID_HOLE = """import "std/joints.aidl"

thickness 3 mm

assembly kit {
    box = finger_box(length=80 mm, depth=80 mm, height=50 mm, thickness=3 mm)
    hole lid_hole { c = Circle(center=(0, 0), diameter=20) }
    lid_hole.c.center == box.lid.bb.center
}
"""


def _3mf_volumes(data: bytes) -> dict:
    """Each object's mesh volume (mm^3) of a 3MF, read with the standard library (zip + XML)."""
    import xml.etree.ElementTree as ET
    import zipfile
    ns = {"m": "http://schemas.microsoft.com/3dmanufacturing/core/2015/02"}
    with zipfile.ZipFile(io.BytesIO(data)) as z:
        root = ET.fromstring(z.read("3D/3dmodel.model"))
    out = {}
    for obj in root.iter(f"{{{ns['m']}}}object"):
        mesh = obj.find("m:mesh", ns)
        if mesh is None:
            continue
        V = np.array([[float(v.get(k)) for k in "xyz"] for v in mesh.find("m:vertices", ns)])
        T = np.array([[int(t.get(k)) for k in ("v1", "v2", "v3")]
                      for t in mesh.find("m:triangles", ns)])
        a, b, c = V[T[:, 0]], V[T[:, 1]], V[T[:, 2]]
        out[obj.get("name")] = abs(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6)
    return out


def test_a_hole_in_an_assembly_is_named_and_its_fix_cuts_it_into_the_lid():
    """The maker's closed box with a 20 mm hole in the lid, written the way holes are taught:
    the hole beside the `finger_box` instance cut nothing (the lid came out whole, the hole a
    part of its own).  Now W0109 names it and the part under it; its --json fix writes
    `CutInto(lid_hole, box.lid)`, and then the lid has the hole in the flat sheet (DXF), the
    3MF (volume) and the fit check (no collision), and the hole is no part (before the fix
    it is none either: it cuts nothing, and no output cuts it)."""
    r = checked(LID_HOLE)
    (w,) = [d for d in r.diagnostics_json() if d["code"] == "W0109"]
    assert "`kit.lid_hole`" in w["message"] and "`kit.box.lid`" in w["message"]
    assert w["fix"]["replacement"].strip() == "CutInto(lid_hole, box.lid)"
    assert "kit.lid_hole" not in [p.name for p in r.parts]     # it cuts nothing: no part
    assert [p.name for p in r.output.stray] == ["kit.lid_hole"]  # (the preview draws it)
    lid0 = next(p for p in r.parts if p.name == "kit.box.lid")
    fixed = _apply(LID_HOLE, w["fix"])
    r2 = checked(fixed)
    assert r2.ok and not r2.sink.items, [d.message for d in r2.sink.items]
    names = [p.name for p in r2.parts]
    assert "kit.lid_hole" not in names and len(names) == 6
    lid = next(p for p in r2.parts if p.name == "kit.box.lid")
    assert lid.holes == lid0.holes + 1
    assert abs((lid0.area - lid.area) - np.pi * 100) < 1e-6          # a 20 mm circle out
    # the flat sheet, read back by ezdxf: one circle of radius 10 among the cuts
    import ezdxf
    dxf = r2.layout(sheet=(600, 400)).encode("dxf")[0]
    doc = ezdxf.read(io.StringIO(dxf.decode()))
    circles = [e for e in doc.modelspace() if e.dxftype() == "CIRCLE"]
    assert [round(e.dxf.radius, 6) for e in circles] == [10.0]
    # the 3MF, assembled: the lid's volume is its plate less the hole, 3 mm thick (the mesh
    # holds the circle as chords: within 2 mm^3 of 16,818; the uncut lid's is 942 more)
    vol = _3mf_volumes(r2.encode("3mf", assembled=True))
    assert abs(vol["kit.box.lid"] - lid.area * 3) < 2
    assert vol["kit.box.lid"] < lid0.area * 3 - 900


def test_cut_into_keeps_the_rules():
    base = LID_HOLE.replace("    lid_hole.c.center == box.lid.bb.center\n",
                            "    lid_hole.c.center == box.lid.bb.center\n    LINE\n")

    def err(line):
        r = aidl_compile(base.replace("LINE", line), path="/tmp/aidl-issue61-cut.aidl")
        return [d for d in r.sink.items if d.is_error]
    (e,) = err("CutInto(box.lid, lid_hole)")                # the arguments swapped
    assert e.code == "E0108" and "cuts with a hole or a cut structure" in e.message
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    solid boss { c = Circle(center=(0, 0), radius=5) }\n"
           "    hole h { c = Circle(center=(0, 0), radius=2) }\n    CutInto(h, boss)\n}\n")
    (e,) = [d for d in aidl_compile(src, path="/tmp/aidl-issue61-c2.aidl").sink.items
            if d.is_error]
    assert "already cuts `plate`" in e.message
    # written in a structure beside them it cannot reach the hole (scope, E0101; a path
    # outside its subtree would be E0202): it belongs where both are
    inner = LID_HOLE.replace("    box = finger_box(", "    solid other {\n"
                             "        r = Rectangle(center=(300, 0), width=10, height=10)\n"
                             "        CutInto(lid_hole, self)\n    }\n    box = finger_box(")
    codes = [d.code for d in aidl_compile(inner, path="/tmp/aidl-issue61-c3.aidl").sink.items
             if d.is_error]
    assert codes and set(codes) <= {"E0101", "E0202"}, codes


def test_gear_train_lift_raises_the_gears_and_the_placed_message_names_the_file():
    src = """import "std/gears.aidl"
thickness 3 mm
assembly kit {
    t = gear_train(teeth=[12, 24], lift=10 mm)
}
"""
    r = aidl_compile(src, path="/tmp/aidl-issue61-lift.aidl")
    assert r.ok, [d.message for d in r.sink.items]
    z = {name: m[2, 3] for name, m in r.output.drawing.placement.items()}
    assert z["kit.t.plate"] == 0 and z["kit.t.gear[0]"] == 13 and z["kit.t.gear[1]"] == 13
    bad = aidl_compile(src.replace("lift=10 mm)", "lift=10 mm)\n    Place(t.gear[0], "
                                   "position=(0, 0, 10))"), path="/tmp/aidl-issue61-l2.aidl")
    (e,) = [d for d in bad.sink.items if d.is_error]
    assert "in std/gears.aidl line" in e.message and "lift=" in e.hint


def test_a_filled_shape_that_swallows_the_design_is_named_with_the_likely_intent():
    """The spider-web model's `frame = Circle(...)` (meant as a ring) covered the threads and
    the spider; W0506 said only that the spider "lies wholly inside the rest".  Now it names
    the covering shape, counts the shapes it hides too, and offers a ring or construction."""
    src = """solid web {
    frame = Circle(center=(0, 0), radius=50)
    for i in range(4) {
        thread = Rectangle(center=(0, 0), width=96, height=1, rotation=i * 45 deg)
    }
    solid spider { body = Circle(center=(10, 10), radius=6) }
    Fixed(spider)
}
"""
    r = aidl_compile(src, path="/tmp/aidl-issue61-web.aidl")
    (w,) = [d for d in r.sink.items if d.code == "W0506"]
    assert "the filled shape `web.frame` covers it whole" in w.message
    assert "4 other shapes of `web` (`web.thread`)" in w.message
    assert "`Shell(frame, 3)`" in w.hint and "construction=true" in w.hint
    # the spider's eyes, holes of `web`, take a little of it: the frame is still the cause
    eyes = aidl_compile(src.replace("    Fixed(spider)\n", "    Fixed(spider)\n    hole eyes { "
                                    "e = Circle(center=(8, 13), radius=1) }\n"),
                        path="/tmp/aidl-issue61-w3.aidl")
    (w,) = [d for d in eyes.sink.items if d.code == "W0506"]
    assert "(the filled shape `web.frame` covers it whole)" in w.message, w.message
    assert "`Shell(frame, 3)`" in w.hint
    # the ring the hint offers: the spider and the threads show, no W0506
    ring = aidl_compile(src.replace("frame = Circle(center=(0, 0), radius=50)",
                                    "rim = Circle(center=(0, 0), radius=47, construction=true)\n"
                                    "    frame = Shell(rim, 3)"), path="/tmp/aidl-issue61-w2.aidl")
    assert not [d for d in ring.sink.items if d.code == "W0506"], \
        [d.message for d in ring.sink.items]


def test_units_written_with_equals_says_the_statement():
    r = aidl_compile('units = in\nsolid a { r = Rectangle(center=(0, 0), width=4, height=2) }\n',
                     path="/tmp/aidl-issue61-units.aidl")
    (e,) = [d for d in r.sink.items if d.is_error]
    assert e.code == "E0001" and "`units mm`" in e.hint and "==" not in e.hint


# ------------------------------------------------------------------ W0518: contact within a fit
def _w0518(src):
    from aidl_lang.api import compile as aidl_compile
    return [d for d in aidl_compile(src).sink.items if d.code == "W0518"]


WALL_ABOVE = """thickness 3 mm
assembly kit {{
    solid base {{ r = Rectangle(center=(0, 0), width=40, height=40) }}
    solid wall {{ r = Rectangle(center=(0, 0), width=40, height=20) }}
    Place(wall, rotation=(90 deg, 0, 0), position=(0, 0, {z}))
}}
"""


def test_w0518_counts_a_fit_clearance_as_contact_and_a_real_gap_as_floating():
    """Parts within 0.1 mm touch (meshing gears 0.047 mm apart were 'touching no other
    part'); 0.5 mm above the base is still a wall that floats."""
    assert not _w0518(WALL_ABOVE.format(z=13.05))                 # 0.05 mm: a clearance
    (w,) = _w0518(WALL_ABOVE.format(z=13.5))
    assert "0.5 mm away" in w.message


def test_a_gear_train_lifted_by_its_own_argument_is_not_a_floating_part():
    assert not _w0518("""import "std/gears.aidl"
thickness 3 mm
assembly demo {
    train = gear_train(teeth=[20, 30, 15], module=2 mm, axle=4 mm, lift=10 mm)
}
""")
