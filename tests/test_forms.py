"""Issue 23, "Say it directly": the language-level forms -- GridPattern, CornerPattern,
CircularPattern(start_angle=), copies that vary with the index (a `for` loop), the polar and
segment forms (Line/Slot by length and angle, a Rectangle along a segment, At), a template's
kind chosen at the call site, AllowOverlap and rigid structures.

Real `.aidl` text through the parser, solver, Manifold and the DXF writer; the DXF re-read
with ezdxf (tests/exact_geometry.py)."""
from __future__ import annotations

import math

import pytest

from exact_geometry import DXF_TOL, C, read_dxf


def compile_ok(src: str, tmp_path, warnings_ok: bool = False):
    from aidl_lang.pipeline import compile_source
    c = compile_source(src, str(tmp_path / "t.aidl"))
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    if not warnings_ok:
        assert not [d for d in c.sink.items if d.severity == "warning"], \
            [(d.code, d.message) for d in c.sink.items]
    return c


def dxf(src: str, tmp_path):
    """Compile ``src``, write it through the real DXF writer, read it back with ezdxf."""
    from aidl_lang.output import Options, build, encode
    c = compile_ok(src, tmp_path)
    out = build(c.drawing, c.model.root.name)
    path = tmp_path / "t.dxf"
    path.write_bytes(encode(out, ".dxf", Options()))
    return c, read_dxf(path)


def circles(ents) -> list[tuple[float, float, float]]:
    """(x, y, r) of every CIRCLE, sorted."""
    return sorted((s.center[0], s.center[1], s.radius) for e in ents for s in e.segments
                  if isinstance(s, C))


def same(got, want, tol=DXF_TOL) -> bool:
    """Two lists of points (or tuples) equal within ``tol``, in any order."""
    def key(p):
        return tuple(round(v, 6) + 0.0 for v in p)
    got, want = sorted(got, key=key), sorted(want, key=key)
    return len(got) == len(want) and all(
        len(g) == len(w) and all(abs(a - b) <= tol for a, b in zip(g, w))
        for g, w in zip(got, want))


def errors(c):
    return [d for d in c.sink.items if d.severity == "error"]


# ---------------------------------------------------------------- 1 GridPattern, CornerPattern
def test_mounting_plate_with_four_corner_holes_in_three_lines(tmp_path):
    c, ents = dxf("solid plate {\n"
                  "    body = Rectangle(center=(0, 0), width=80, height=50)\n"
                  "    hole h { c = Circle(center=(0, 0), diameter=5) }\n"
                  "    CornerPattern(h, body, inset=6)\n"
                  "}\n", tmp_path)
    (outline,) = [e for e in ents if not isinstance(e.segments[0], C)]
    xs = [p for s in outline.segments for p in (s.start[0], s.end[0])]
    ys = [p for s in outline.segments for p in (s.start[1], s.end[1])]
    x0, y0 = min(xs), min(ys)
    assert (max(xs) - x0, max(ys) - y0) == pytest.approx((80, 50), abs=DXF_TOL)
    got = circles(ents)
    want = sorted((x0 + dx, y0 + dy, 2.5) for dx in (6, 74) for dy in (6, 44))
    assert same(got, want)


def test_corner_pattern_follows_a_rotated_rectangle_and_takes_at_points(tmp_path):
    c, ents = dxf("solid plate {\n"
                  "    body = Rectangle(center=(0, 0), width=40, height=20, rotation=30 deg)\n"
                  "    Fixed(body)\n"
                  "    hole g { c = Circle(center=(1, 1), radius=1) }\n"
                  "    hole h { k = Circle(center=(0, 0), radius=0.5) }\n"
                  "    CornerPattern(g, body, inset=3)\n"
                  "    CornerPattern(h, at=[(5, 0), (-5, 0)])\n"
                  "}\n", tmp_path)
    th = math.radians(30)
    u, v = (math.cos(th), math.sin(th)), (-math.sin(th), math.cos(th))
    want = []
    for su, sv in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
        a, b = -su * (20 - 3), -sv * (10 - 3)       # corner, inset 3 along both sides
        want.append((a * u[0] + b * v[0], a * u[1] + b * v[1]))
    got = circles(ents)
    small = [(x, y) for x, y, r in got if abs(r - 1) < 1e-9]
    assert same(sorted(small), sorted(want))
    holes = [(x, y) for x, y, r in got if abs(r - 0.5) < 1e-9]
    assert same(sorted(holes), [(-5, 0), (5, 0)])


def test_grid_pattern_places_rows_and_columns(tmp_path):
    c, ents = dxf("solid plate {\n"
                  "    body = Rectangle(bottom_left=(0, 0), width=100, height=60)\n"
                  "    Fixed(body)\n"
                  "    hole h { c = Circle(center=(10, 10), radius=2) }\n"
                  "    holes = GridPattern(h, rows=3, cols=4, spacing=(20, 15))\n"
                  "    hole small {\n"
                  "        dot = Circle(center=(90, 50), radius=1)\n"
                  "        dots = GridPattern(dot, nrows=2, columns=2, dx=-5, dy=-6)\n"
                  "        sq = GridPattern(Circle(center=(50, 3), radius=0.5), 1, 3, 2)\n"
                  "    }\n"
                  "}\n", tmp_path)
    got = circles(ents)
    big = sorted((x, y) for x, y, r in got if r == pytest.approx(2, abs=1e-12))
    assert same(big, sorted((10 + 20 * i, 10 + 15 * j) for i in range(4)
                                       for j in range(3)))
    small = sorted((x, y) for x, y, r in got if r == pytest.approx(1, abs=1e-12))
    assert same(small, [(85, 44), (85, 50), (90, 44), (90, 50)])
    tiny = sorted((x, y) for x, y, r in got if r == pytest.approx(0.5, abs=1e-12))
    assert same(tiny, [(50, 3), (52, 3), (54, 3)])
    # row-major: holes[r * cols + c]
    names = [s.name for s in c.model.root.children.values()]
    assert names[:2] == ["h", "holes[1]"] and "holes[11]" in names


@pytest.mark.parametrize("line, msg", [
    ("CornerPattern(h, c)", "needs a Rectangle"),
    ('GridPattern(h, 2, 2, spacing="wide")', "spacing is a length"),
    ("GridPattern(h, 0, 2, spacing=3)", "whole number"),
    ("GridPattern(h, 200, 200, spacing=3)", "more than 10000"),
])
def test_pattern_errors_are_located(compile_text, line, msg):
    c = compile_text("solid s {\n    b = Rectangle(center=(0, 0), width=9, height=9)\n"
                     "    c = Circle(center=(0, 0), radius=9)\n"
                     "    hole h { k = Circle(center=(0, 0), radius=1) }\n"
                     f"    {line}\n}}\n")
    (d,) = errors(c)
    assert msg in d.message and d.span.line == 5 and d.code == "E0108", d.message


# ---------------------------------------------------------------- 2 start_angle, varying copies
def test_circular_pattern_start_angle_turns_every_instance(tmp_path):
    c, ents = dxf("solid flange {\n"
                  "    disc = Circle(center=(0, 0), radius=30)\n"
                  "    Fixed(disc)\n"
                  "    hole h { c = Circle(center=(20, 0), radius=2) }\n"
                  "    holes = CircularPattern(h, 6, center=disc.center, start_angle=30 deg)\n"
                  "}\n", tmp_path)
    got = [(x, y) for x, y, r in circles(ents) if r < 3]
    want = [(20 * math.cos(math.radians(30 + 60 * k)), 20 * math.sin(math.radians(30 + 60 * k)))
            for k in range(6)]
    assert same(sorted(got), sorted(want))
    names = [s.name for s in c.model.root.children.values()]
    assert "holes[0]" in names and "holes[5]" in names


def test_drill_gauge_copies_vary_with_the_index(tmp_path):
    """Copies that differ (2 ... 9 mm) are a `for` loop over the index: docs/language.md 2.8."""
    c, ents = dxf("solid gauge {\n"
                  "    body = Rectangle(bottom_left=(0, 0), width=110, height=25)\n"
                  "    Fixed(body)\n"
                  "    for i in range(8) {\n"
                  "        d = 2 + i\n"
                  "        hole drill { c = Circle(center=(8 + 13 * i, 12), diameter=d) }\n"
                  "    }\n"
                  "}\n", tmp_path)
    got = circles(ents)
    assert same(got, [(8 + 13 * i, 12, (2 + i) / 2) for i in range(8)])


# ---------------------------------------------------------------- 3 polar and segment forms
def test_line_and_slot_by_length_and_angle(tmp_path):
    c, ents = dxf("solid s {\n"
                  "    base = Rectangle(bottom_left=(0, 0), width=60, height=40)\n"
                  "    Fixed(base)\n"
                  "    hole slot { sl = Slot(start=(10, 30), length=20, angle=-20 deg, width=4) }\n"
                  "    drawing d { l = Line(start=(5, 5), length=20, angle=30 deg) }\n"
                  "}\n", tmp_path)
    from exact_geometry import A as Arc, L as Seg
    t = math.radians(-20)
    end = (10 + 16 * math.cos(t), 30 + 16 * math.sin(t))      # length is end to end: 20 - 4
    arcs = [s for e in ents for s in e.segments if isinstance(s, Arc)]
    assert same([a.center for a in arcs], [(10, 30), end])
    assert all(abs(a.radius - 2) < DXF_TOL and abs(abs(a.sweep) - math.pi) < 1e-9 for a in arcs)
    lines = [s for e in ents for s in e.segments if isinstance(s, Seg)
             ]
    eng = [s for s in lines if math.dist(s.start, (5, 5)) < 1e-9]
    (ln,) = eng
    assert same([ln.end], [(5 + 20 * math.cos(math.radians(30)), 5 + 10)])


def test_rectangle_along_a_segment_follows_its_moving_ends(tmp_path):
    c, ents = dxf("solid s {\n"
                  "    base = Rectangle(bottom_left=(0, 0), width=60, height=40)\n"
                  "    Fixed(base)\n"
                  "    hole bar {\n"
                  "        b = Rectangle(start=(0, 0), end=(10, 10), width=3)\n"
                  "    }\n"
                  "    At(bar.b.start, base.bottom_left, dx=10, dy=10)\n"
                  "    At(bar.b.end, base.top_right, dx=-10, dy=-6)\n"
                  "}\n", tmp_path)
    # the bar's center line runs (10, 10) -> (50, 34); its corners 1.5 mm either side
    d = (40, 24)
    L = math.hypot(*d)
    n = (-d[1] / L * 1.5, d[0] / L * 1.5)
    want = [(10 + n[0], 10 + n[1]), (10 - n[0], 10 - n[1]), (50 + n[0], 34 + n[1]),
            (50 - n[0], 34 - n[1])]
    loops = [e for e in ents if e.layer.lower() == "cut"]
    pts = [s.start for e in loops for s in e.segments
           if not (abs(s.start[0]) < 1e-9 or abs(s.start[0] - 60) < 1e-9)]
    assert same(pts, want)
    v = _values(c)
    assert v["s.bar.b.height"] == pytest.approx(L, abs=1e-9)
    assert v["s.bar.b.width"] == pytest.approx(3, abs=1e-12)


def _values(c):
    """Solved scalar values by path (``aidl check --values``), in mm."""
    from aidl_lang.api import _values
    return {v.name: v.mm for v in _values(c.model, 1.0, "mm")}


def test_at_places_a_point_at_an_offset(compile_text):
    c = compile_text("solid s {\n"
                     "    base = Rectangle(bottom_left=(0, 0), width=60, height=40)\n"
                     "    Fixed(base)\n"
                     "    p = Point(1, 1)\n"
                     "    q = Point(2, 2)\n"
                     "    At(p, base.top_right, dx=-6, dy=-4)\n"
                     "    PlaceAt(point=q, of=p, x=2)\n"
                     "}\n")
    assert c.ok
    x = c.model.xs()
    g = {g.name: g for g in c.model.root.geometry}
    pp, qq = g["p"].points["p"], g["q"].points["p"]
    assert (x[pp.ix], x[pp.iy]) == (pytest.approx(54, abs=1e-9), pytest.approx(36, abs=1e-9))
    assert (x[qq.ix], x[qq.iy]) == (pytest.approx(56, abs=1e-9), pytest.approx(36, abs=1e-9))


@pytest.mark.parametrize("src, msg", [
    ("Slot(start=(0, 0), length=3, angle=10 deg, width=4)", "at least its width"),
    ("Rectangle(start=(1, 1), end=(1, 1), width=2)", "start and end apart"),
    ("Line(start=(0, 0), length=0, angle=10 deg)", "positive length"),
])
def test_polar_form_errors_are_located(compile_text, src, msg):
    c = compile_text("solid s {\n    g = " + src + "\n}\n")
    (d,) = errors(c)
    assert msg in d.message and d.span.line == 2, d.message


# ---------------------------------------------------------------- 4 a template's kind at the call
TAB = "def tab(w = 10) -> solid {\n    r = Rectangle(center=(0, 0), width=w, height=4)\n}\n"


def test_a_solid_template_used_as_a_hole_and_as_a_drawing(tmp_path):
    c, ents = dxf(TAB + "solid plate {\n"
                  "    body = Rectangle(center=(0, 0), width=80, height=40)\n"
                  "    Fixed(body)\n"
                  "    hole slot = tab(w=20)\n"
                  "    drawing mark = tab(w=6)\n"
                  "    lug = tab()\n"
                  "    CenterInside(slot, body)\n"
                  "    mark.r.center == (0, 12)\n"
                  "    Above(lug, body, gap=-2)\n"
                  "}\n", tmp_path)
    kinds = {n: s.kind for n, s in c.model.root.children.items()}
    assert kinds == {"slot": "hole", "mark": "drawing", "lug": "solid"}
    cut = [e for e in ents if e.layer.lower() == "cut"]
    pts = sorted({(round(s.start[0], 9) + 0, round(s.start[1], 9) + 0)
                  for e in cut for s in e.segments})
    # the 20 x 4 slot cut through the middle; the lug (10 x 4) overlaps the top by 2 mm
    for p in [(-10, -2), (10, -2), (10, 2), (-10, 2), (-5, 22), (5, 22)]:
        assert p in pts, (p, pts)
    eng = [s for e in ents if e.layer.lower() != "cut" for s in e.segments]
    assert same(sorted({(round(s.start[0], 9) + 0, round(s.start[1], 9) + 0) for s in eng}),
                [(-3, 10), (-3, 14), (3, 10), (3, 14)])


@pytest.mark.parametrize("line, msg, col", [
    ("hole c = Circle(center=(0, 0), radius=2)", "not a template call", 5),
    ("hoel c = tab()", "unknown structure kind `hoel`", 5),
])
def test_a_kind_at_the_call_site_needs_a_template_and_a_kind(compile_text, line, msg, col):
    c = compile_text(TAB + "solid s {\n    b = Circle(center=(0, 0), radius=9)\n"
                     f"    {line}\n}}\n")
    (d,) = errors(c)
    assert msg in d.message and (d.span.line, d.span.col) == (6, col), d.message


# ---------------------------------------------------------------- 5 an intended overlap
LOCK = """solid lock {
    solid body {
        b = Rectangle(center=(0, 0), width=40, height=30)
        hole key { k = Circle(center=(0, 8), radius=3) }
        hole vent { v = Circle(center=(-12, 11), radius=2) }
    }
    solid shackle { s = Rectangle(center=(0, 14), width=30, height=8) }
    %s
}
"""


def test_allow_overlap_silences_w0501_for_that_pair_only(compile_text):
    import re
    c = compile_text(LOCK % "")
    w = {d.message.split("`")[1]: d for d in c.sink.items if d.code == "W0501"}
    assert set(w) == {"lock.body.key", "lock.body.vent"}
    # the hint's own fix, pasted in, silences exactly that hole
    fix = re.search(r"write `(AllowOverlap\(body\.key, shackle\))` in `lock`",
                    w["lock.body.key"].hint).group(1)
    c = compile_text(LOCK % fix)
    assert [d.message.split("`")[1] for d in c.sink.items if d.code == "W0501"] == \
        ["lock.body.vent"]
    # by synonym, with the shape instead of its structure, in either order
    c = compile_text(LOCK % "IntendedOverlap(shackle.s, body.key)\n"
                            "    AllowOverlap(body.vent.v, shackle)")
    assert not [d for d in c.sink.items if d.code == "W0501"]


def test_allow_overlap_needs_a_hole(compile_text):
    c = compile_text(LOCK % "AllowOverlap(body, shackle)")
    (d,) = errors(c)
    assert "names a hole" in d.message and d.span.line == 8 and d.code == "E0108"


# ---------------------------------------------------------------- 6 rigid
WINDMILL = """solid windmill {
    tower = Rectangle(bottom_left=(-5, 0), width=10, height=60)
    Fixed(tower)
    %s
}
"""


def _pt(c, path):
    return _values(c)[path]


def test_rigid_shapes_move_together(compile_text):
    body = ("spar = Rectangle(center=(0, 90), width=4, height=50)\n"
            "    sail = Rectangle(center=(9, 100), width=14, height=30)\n"
            "    %s\n"
            "    Coincident(spar.bottom.midpoint, tower.top.midpoint)")
    free = compile_text(WINDMILL % (body % ""))
    assert free.ok
    # without Rigid the spar moves down 5 mm and the sail stays: left behind
    assert _pt(free, "windmill.spar.center") == pytest.approx((0, 85), abs=1e-9)
    assert _pt(free, "windmill.sail.center") == pytest.approx((9, 100), abs=1e-9)
    c = compile_text(WINDMILL % (body % "Rigid(spar, sail)"))
    assert c.ok and not [d for d in c.sink.items if d.severity == "warning"]
    assert _pt(c, "windmill.spar.center") == pytest.approx((0, 85), abs=1e-9)
    assert _pt(c, "windmill.sail.center") == pytest.approx((9, 95), abs=1e-9)
    # one placing point per held shape: no redundant rows (W0401 under --dof)
    from aidl_lang.solver.diagnosis.redundancy import redundancies
    assert not [r for r in redundancies(c.solve.solver) if r.constraint.kind == "Rigid"]


def test_a_rigid_structure_is_moved_never_bent(compile_text):
    body = ("solid blades {\n"
            "        spar = Rectangle(center=(0, 90), width=4, height=50)\n"
            "        sail = Rectangle(center=(9, 100), width=14, height=30)\n"
            "    }\n"
            "    %s\n"
            "    Coincident(blades.spar.bottom.midpoint, tower.top.midpoint)\n"
            "    %s")
    # translation suffices: both kinds move the whole structure
    for rigid in ("", "Rigid(blades)"):
        c = compile_text(WINDMILL % (body % (rigid, "")))
        assert c.ok
        assert _pt(c, "windmill.blades.sail.center") == pytest.approx((9, 95), abs=1e-9)
    # a constraint translation cannot meet: the solver bends a plain structure (the sail
    # torn off the spar) but reports a conflict for a rigid one
    extra = "blades.sail.top_right.y == 120"
    bent = compile_text(WINDMILL % (body % ("", extra)))
    assert bent.ok
    spar, sail = (_pt(bent, f"windmill.blades.{n}.center") for n in ("spar", "sail"))
    assert sail[1] - spar[1] == pytest.approx(20, abs=1e-9)      # 10 at the start
    c = compile_text(WINDMILL % (body % ("Rigid(blades)", extra)))
    (d,) = errors(c)
    assert d.code == "E0401" and d.span.line == 10
    assert "`windmill.blades` is rigid" in d.hint


def test_rigid_self_in_a_template_makes_every_instance_rigid(compile_text):
    src = ("def blade() -> solid {\n"
           "    spar = Rectangle(center=(0, 0), width=4, height=50)\n"
           "    sail = Rectangle(center=(9, 10), width=14, height=30)\n"
           "    Rigid(self)\n"
           "}\n"
           "solid s {\n"
           "    base = Rectangle(center=(0, 0), width=10, height=10)\n"
           "    Fixed(base)\n"
           "    b = blade()\n"
           "    b.spar.center == (0, 0)\n"
           "    b.sail.center == (0, 0)\n"
           "}\n")
    c = compile_text(src)
    assert [d.code for d in errors(c)] == ["E0401"]
    c = compile_text(src.replace("    Rigid(self)\n", ""))
    assert c.ok


def test_rigid_takes_structures_and_shapes(compile_text):
    c = compile_text("solid s {\n    a = Circle(center=(0, 0), radius=2)\n    Rigid(a, 3)\n}\n")
    (d,) = errors(c)
    assert d.span.line == 3 and d.code == "E0108", d.message


FIVE_HOLES = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=60)
    Fixed(body)
    hole a { c = Circle(center=(10, 0), radius=3) }
    hole b { c = Circle(center=(-10, 0), radius=3) }
    hole c { c = Circle(center=(0, 10), radius=3) }
    hole d { c = Circle(center=(0, -10), radius=3) }
    hole e { c = Circle(center=(20, 20), radius=3) }
    %s
    a.c.center == (15, 5)
}
"""
_STARTS = {"a": (10, 0), "b": (-10, 0), "c": (0, 10), "d": (0, -10), "e": (20, 20)}


def test_rigid_takes_any_number_of_arguments_and_moves_them_as_one_body(compile_text):
    """Issue 35 §3: `Rigid(a, b, c, d, e)` was E0104 "takes at most 3 arguments"; five
    holes now move as one body: hole a pinned 5 mm right and 5 mm up carries the other four by
    the same offset (without Rigid they stay where they started)."""
    free = compile_text(FIVE_HOLES % "")
    assert free.ok
    assert _pt(free, "plate.b.c.center") == pytest.approx((-10, 0), abs=1e-9)
    c = compile_text(FIVE_HOLES % "Rigid(a, b, c, d, e)")
    assert c.ok, [d.message for d in c.sink.items]
    for k, (x, y) in _STARTS.items():
        assert _pt(c, f"plate.{k}.c.center") == pytest.approx((x + 5, y + 5), abs=1e-9), k
    # the program says it too, in its own asserts (E0405 if one were false)
    asserts = "Rigid(a, b, c, d, e)\n" + "".join(
        f"    assert {k}.c.center.x == {x + 5} and {k}.c.center.y == {y + 5}\n"
        for k, (x, y) in _STARTS.items())
    c = compile_text(FIVE_HOLES % asserts)
    assert c.ok and not errors(c)
    wrong = compile_text(FIVE_HOLES % (asserts + "    assert e.c.center.x == 20\n"))
    assert [d.code for d in errors(wrong)] == ["E0405"]


def test_rigid_of_four_checks_and_mixes_structures_lists_shapes_and_a_drawing(compile_text):
    """`Rigid(a, b, c, d)` binds in the checker and the interpreter (no E0104); a drawing, a
    list and a shape are arguments like any other: the engraved text moves with the holes."""
    from aidl_lang.pipeline import compile_source
    c = compile_source(FIVE_HOLES % "Rigid(a, b, c, d)", "t.aidl", do_solve=False)
    assert not errors(c), [d.message for d in c.sink.items]
    src = FIVE_HOLES.replace("    %s", "    drawing t { m = Text(\"X\", (30, 0), size=5) }\n"
                             "    mark = Circle(center=(-30, 20), radius=1)\n"
                             "    Rigid(a, [b, c], t, d, mark, e)")
    c = compile_text(src)
    assert c.ok, [d.message for d in c.sink.items]
    assert _pt(c, "plate.e.c.center") == pytest.approx((25, 25), abs=1e-9)
    assert _pt(c, "plate.mark.center") == pytest.approx((-25, 25), abs=1e-9)
    assert _pt(c, "plate.t.m.position") == pytest.approx((35, 5), abs=1e-9)


def test_rigid_keyword_mistakes_are_located(compile_text):
    """Extra positional arguments do not hide a wrong keyword: E0105 points at it; a name
    given both ways is E0104 at the call."""
    c = compile_text(FIVE_HOLES % "Rigid(a, b, c, d, bodyy=e)")
    (d,) = errors(c)
    assert d.code == "E0105" and "`Rigid` has no argument `bodyy`" in d.message
    assert (d.span.line, d.span.col) == (9, 23)
    assert "Rigid(a: any, b: any = none, ...)" in d.hint
    c = compile_text(FIVE_HOLES % "Rigid(a, b, c, b=d)")
    (d,) = errors(c)
    assert d.code == "E0104" and "argument `b` given twice" in d.message
    assert d.span.line == 9


# ---------------------------------------------------------------- a law: the grid is a lattice
from hypothesis import given, settings, strategies as st  # noqa: E402


@settings(max_examples=12, deadline=None)
@given(rows=st.integers(1, 4), cols=st.integers(1, 4),
       # a spacing of 0 with two rows or columns is E0108 (the copies land on one another,
       # tests/test_operations.py), not a lattice: a drawn dy of 0 failed this law in a full
       # run (rows=2, dy=0; about 1 run in 7 at 12 examples)
       dx=st.integers(-30, 30).filter(lambda v: v != 0),
       dy=st.integers(-30, 30).filter(lambda v: v != 0),
       x0=st.integers(-50, 50), y0=st.integers(-50, 50))
def test_grid_copy_r_c_sits_at_the_lattice_point(tmp_path_factory, rows, cols, dx, dy, x0, y0):
    from aidl_lang.pipeline import compile_source
    src = (f"solid s {{\n    c = Circle(center=({x0}, {y0}), radius=0.5)\n"
           f"    g = GridPattern(c, {rows}, {cols}, col_spacing={dx}, row_spacing={dy})\n}}\n")
    c = compile_source(src, str(tmp_path_factory.mktemp("g") / "t.aidl"), do_solve=True)
    assert not errors(c), [d.message for d in c.sink.items]
    v = _values(c)
    for r in range(rows):
        for k in range(cols):
            i = r * cols + k
            name = "s.c.center" if i == 0 else f"s.g[{i}].center"
            assert v[name] == pytest.approx((x0 + k * dx, y0 + r * dy), abs=1e-9), name


def test_corner_pattern_on_a_bar_follows_its_direction(tmp_path):
    c, ents = dxf("solid s {\n"
                  "    base = Rectangle(bottom_left=(-10, -10), width=80, height=60)\n"
                  "    Fixed(base)\n"
                  "    drawing link { b = Rectangle(start=(0, 0), end=(10, 0), width=8) }\n"
                  "    hole h { c = Circle(center=(0, 0), radius=1) }\n"
                  "    CornerPattern(h, link.b, inset=2)\n"
                  "    At(link.b.start, (0, 0))\n"
                  "    At(link.b.end, (30, 40))\n"
                  "}\n", tmp_path)
    # the bar runs (0, 0) -> (30, 40): along d = (0.6, 0.8), across n = (0.8, -0.6), 4 wide
    d, n = (0.6, 0.8), (0.8, -0.6)
    want = []
    for end, inward in ((0.0, 1), (50.0, -1)):
        for side in (1, -1):
            along = end + inward * 2
            across = side * (4 - 2)
            want.append((along * d[0] + across * n[0], along * d[1] + across * n[1]))
    got = [(x, y) for x, y, r in circles(ents) if abs(r - 1) < 1e-9]
    assert same(got, want)


@pytest.mark.parametrize("corner,opposite", [((0, 0), (10, 6)), ((10, 6), (0, 0)),
                                             ((10, 0), (0, 6)), ((0, 6), (10, 0))],
                         ids=["bl-tr", "tr-bl", "br-tl", "tl-br"])
def test_rectangle_by_two_opposite_corners_in_any_order(corner, opposite):
    """`Rectangle(corner=, opposite=)` with the corner at any of the four corners: the same
    10 x 6 rectangle, its corners named by where they are (bottom-right/top-left used to be an
    internal error, KeyError 'bottom_left', found by the nasty-program fuzzer)."""
    import aidl_lang
    r = aidl_lang.compile(source=f"solid s {{\n    r = Rectangle(corner={corner}, "
                                 f"opposite={opposite})\n}}\n")
    assert r.ok, [d.message for d in r.diagnostics]
    want = {"bottom_left": (0, 0), "bottom_right": (10, 0), "top_right": (10, 6),
            "top_left": (0, 6), "center": (5, 3)}
    for name, xy in want.items():
        assert r.value(f"s.r.{name}").value == pytest.approx(xy, abs=1e-12), name
    assert r.value("s.r.width").value == pytest.approx(10) and \
        r.value("s.r.height").value == pytest.approx(6)
