"""Offset / Inset / Shell, Hull and RoundedRectangle(corner_radii=...) (issue 23): real .aidl
text through the parser, solver, Manifold and the DXF / SVG writers, the files re-read by
ezdxf and svgelements (tests/exact_geometry.py) and the geometry compared with hand
formulas to 1e-9 mm."""
from __future__ import annotations

import math

import pytest
from hypothesis import example, given, settings, strategies as st

from exact_geometry import DXF_TOL, SVG_TOL, A, C, L, count, loop_defects, read_dxf, read_svg_loops


def render(tmp_path, src: str, suffix: str = ".dxf"):
    """Compile ``src`` (no errors, no warnings), write ``suffix`` with the real writer."""
    from aidl_lang.output import Options, build, encode
    from aidl_lang.pipeline import compile_source
    c = compile_source(src, str(tmp_path / "t.aidl"))
    assert c.ok and not c.sink.items, [(d.code, d.message) for d in c.sink.items]
    path = tmp_path / f"out{suffix}"
    path.write_bytes(encode(build(c.drawing), suffix, Options()))
    return path


def cut_loops(path):
    return [e.segments for e in read_dxf(path) if e.layer.lower() == "cut"]


def flat(points):
    """Points sorted and flattened (pytest.approx takes flat sequences)."""
    return [float(v) for p in sorted(points) for v in p]


def box(segs):
    """The bounding box (x0, y0, x1, y1) of a loop from its segments' ends and arcs' extremes."""
    xs, ys = [], []
    for s in segs:
        if isinstance(s, C):
            xs += [s.center[0] - s.radius, s.center[0] + s.radius]
            ys += [s.center[1] - s.radius, s.center[1] + s.radius]
            continue
        xs += [s.start[0], s.end[0]]
        ys += [s.start[1], s.end[1]]
        if isinstance(s, A):                  # the quadrant points the arc passes
            a0 = math.atan2(s.start[1] - s.center[1], s.start[0] - s.center[0])
            lo, sw = (a0, s.sweep) if s.sweep > 0 else (a0 + s.sweep, -s.sweep)
            for k in range(4):
                if (k * math.pi / 2 - lo) % (2 * math.pi) <= sw:
                    xs.append(s.center[0] + s.radius * math.cos(k * math.pi / 2))
                    ys.append(s.center[1] + s.radius * math.sin(k * math.pi / 2))
    return min(xs), min(ys), max(xs), max(ys)


def exact_area(c) -> float:
    """The area of the compiled part from its exact output loops (no chords)."""
    from aidl_lang.output.part.part import build
    return sum(lp.area for p in build(c.drawing).parts for lp in p.loops)


# ------------------------------------------------------------------ Offset
def test_rectangle_offset_by_3_is_46_by_26_with_four_corner_arcs_of_3(tmp_path):
    path = render(tmp_path, "solid p {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
                            "    grown = Offset(body, 3)\n}\n")
    (segs,) = cut_loops(path)
    assert count(segs) == (4, 4, 0)
    assert box(segs) == pytest.approx((-23, -13, 23, 13), abs=DXF_TOL)
    arcs = [s for s in segs if isinstance(s, A)]
    assert flat(a.center for a in arcs) == pytest.approx(
        flat([(-20, -10), (-20, 10), (20, -10), (20, 10)]), abs=DXF_TOL)
    assert all(a.radius == pytest.approx(3, abs=DXF_TOL) for a in arcs)
    assert all(a.sweep == pytest.approx(math.pi / 2, abs=1e-9) for a in arcs)
    assert loop_defects(segs, radii=[3]) == []            # the arcs meet the sides tangent


def test_inset_by_2_is_36_by_16_sharp_and_inset_synonyms_agree(tmp_path):
    for call in ("Offset(body, -2)", "Inset(body, 2)", "Shrink(shape=body, by=2 mm)",
                 "Offset(body, -2, join=\"miter\")"):
        path = render(tmp_path, "solid p {\n    body = Rectangle(center=(1, 1), width=40, "
                                f"height=20)\n    i = {call}\n}}\n")
        (segs,) = cut_loops(path)
        assert count(segs) == (4, 0, 0), call
        assert box(segs) == pytest.approx((-17, -7, 19, 9), abs=DXF_TOL), call


def test_circle_inset_by_4_is_a_circle_of_6(tmp_path):
    path = render(tmp_path, "solid p {\n    c = Circle(center=(5, -3), radius=10)\n"
                            "    s = Offset(c, -4)\n}\n")
    ((circle,),) = cut_loops(path)
    assert isinstance(circle, C)
    assert circle.center == pytest.approx((5, -3), abs=DXF_TOL)
    assert circle.radius == pytest.approx(6, abs=DXF_TOL)


def test_miter_offset_of_a_triangle_meets_at_the_extended_sides(tmp_path):
    # apex half-angle atan(15/20): the tip moves out by d / sin = 2 / 0.6
    path = render(tmp_path, "solid p {\n    t = Polygon([(0, 40), (30, 40), (15, 60)])\n"
                            "    o = Offset(t, 2, join=\"miter\")\n}\n")
    (segs,) = cut_loops(path)
    assert count(segs) == (3, 0, 0)
    top = max((s.start for s in segs), key=lambda p: p[1])
    assert top == pytest.approx((15, 60 + 2 / 0.6), abs=DXF_TOL)
    assert min(s.start[1] for s in segs) == pytest.approx(38, abs=DXF_TOL)


def test_miter_past_the_limit_is_a_round_join(tmp_path):
    # a 10 deg spike: its miter would reach 2 / sin(5 deg) = 23 mm > 4 x 2 mm
    path = render(tmp_path, "solid p {\n    t = Polygon([(0, 0), (40, 0), (0, 40 * tan(10 deg))])\n"
                            "    o = Offset(t, 2, join=\"miter\")\n}\n")
    (segs,) = cut_loops(path)
    arcs = [s for s in segs if isinstance(s, A)]
    assert len(arcs) == 1 and arcs[0].center == pytest.approx((40, 0), abs=DXF_TOL)
    assert arcs[0].radius == pytest.approx(2, abs=DXF_TOL)


def test_offset_of_an_arc_shape_keeps_the_arcs_center(tmp_path):
    """A slot grown by 1.5 is the slot of radius r + 1.5 on the same centers (DXF and SVG
    re-read; the SVG's 6 printed decimals leave a half circle's center good to ~1e-3 mm)."""
    src = "solid p {\n    s = Slot(start=(0, 0), end=(30, 10), radius=4)\n    g = Offset(s, 1.5)\n}\n"
    (segs,) = cut_loops(render(tmp_path, src))
    arcs = [s for s in segs if isinstance(s, A)]
    assert [a.radius for a in arcs] == pytest.approx([5.5, 5.5], abs=DXF_TOL)
    assert flat(a.center for a in arcs) == pytest.approx(flat([(0, 0), (30, 10)]), abs=DXF_TOL)
    assert loop_defects(segs, radii=[5.5], tangent="all") == []
    (segs,) = read_svg_loops(render(tmp_path, src, ".svg"))
    arcs = [s for s in segs if isinstance(s, A)]
    assert [a.radius for a in arcs] == pytest.approx([5.5, 5.5], abs=SVG_TOL)
    assert flat(a.center for a in arcs) == pytest.approx(flat([(0, 0), (30, 10)]), abs=2e-3)


def test_inset_of_a_concave_shape_rounds_its_reflex_corner(tmp_path):
    """An L-shape inset by 2: its convex corners stay sharp, the reflex corner becomes an arc
    of radius 2 about the original corner (the round join of an inset)."""
    path = render(tmp_path, "solid p {\n    l = Polygon([(0, 0), (30, 0), (30, 10), (10, 10), "
                            "(10, 30), (0, 30)])\n    i = Offset(l, -2)\n}\n")
    (segs,) = cut_loops(path)
    (arc,) = [s for s in segs if isinstance(s, A)]
    assert arc.center == pytest.approx((10, 10), abs=DXF_TOL) and arc.radius == pytest.approx(2)
    assert box(segs) == pytest.approx((2, 2, 28, 28), abs=DXF_TOL)


def test_outward_offset_fills_a_narrow_notch(tmp_path):
    """A U whose gap (4 mm) is narrower than twice the offset (2 x 3) closes up: the result
    has no notch left at the top, and its area is the Minkowski sum's."""
    from aidl_lang.pipeline import compile_source
    c = compile_source("solid p {\n    u = Polygon([(0, 0), (24, 0), (24, 20), (14, 20), "
                       "(14, 5), (10, 5), (10, 20), (0, 20)])\n    o = Offset(u, 3)\n}\n",
                       str(tmp_path / "t.aidl"))
    assert c.ok
    # the 30 x 26 box with its four corners rounded (r 3), less the dip left at the top of
    # the gap: between y = 23 and the round joins about (10, 20) and (14, 20), which meet
    # at x = 12; under each, the integral of sqrt(9 - t^2) from 0 to 2
    outer = 30 * 26 - (4 - math.pi) * 9
    under = math.sqrt(5) + 4.5 * math.asin(2 / 3)
    assert exact_area(c) == pytest.approx(outer - (4 * 3 - 2 * under), rel=1e-9)


@pytest.mark.parametrize("src, code, msg", [
    ("body = Rectangle(center=(0, 0), width=40, height=20)\n    i = Offset(body, -12)",
     "E0406", "leaves nothing"),
    ("c = Circle(center=(0, 0), radius=5)\n    i = Inset(c, 5)", "E0406", "leaves nothing"),
    ("l = Line((0, 0), (1, 0))\n    i = Offset(l, 2)", "E0108", "closed shapes"),
    ("c = Circle(center=(0, 0), radius=5)\n    i = Offset(c, 2, join=\"bevel\")", "E0108",
     "join"),
    ("c = Circle(center=(0, 0), radius=5)\n    i = Shell(c, 0)", "E0108", "non-zero"),
])
def test_bad_offsets_are_located_errors(compile_text, src, code, msg):
    c = compile_text("solid s {\n    " + src + "\n}\n")
    errs = [d for d in c.sink.items if d.severity == "error"]
    assert [d.code for d in errs] == [code], [d.message for d in c.sink.items]
    assert msg in errs[0].message and errs[0].span.line == 3
    assert not [d for d in c.sink.items if d.code == "W0509"]       # no second, vaguer word


@settings(max_examples=15, deadline=None)
@given(w=st.floats(5, 60), h=st.floats(5, 60), d=st.floats(0.1, 8))
def test_offset_area_law(w, h, d):
    """Steiner: a convex shape grown by d has area A + P d + pi d^2; an inset of a rectangle
    by d < half its short side is (w - 2d)(h - 2d)."""
    from aidl_lang.pipeline import compile_source
    src = (f"solid p {{\n    b = Rectangle(center=(0, 0), width={w!r}, height={h!r})\n"
           f"    o = Offset(b, {d!r})\n}}\n")
    c = compile_source(src, "t.aidl")
    assert c.ok
    assert exact_area(c) == pytest.approx(w * h + 2 * (w + h) * d + math.pi * d * d, rel=1e-9)
    if d < min(w, h) / 2 - 1e-3:
        c = compile_source(src.replace(f"Offset(b, {d!r})", f"Offset(b, {-d!r})"), "t.aidl")
        assert c.ok
        assert exact_area(c) == pytest.approx((w - 2 * d) * (h - 2 * d), rel=1e-9)


# ------------------------------------------------------------------ Shell
def test_shell_is_a_cookie_cutter_wall(tmp_path):
    """Shell(outline, 2): the outline offset by 2 outside, the outline itself as the hole."""
    path = render(tmp_path, "solid cutter {\n    heart = Polygon([(0, 0), (20, 20), (10, 30), "
                            "(0, 22), (-10, 30), (-20, 20)])\n    wall = Shell(heart, 2)\n}\n")
    loops = cut_loops(path)
    assert len(loops) == 2
    outer, inner = sorted(loops, key=lambda s: -len(s))
    assert count(inner) == (6, 0, 0)
    assert flat(s.start for s in inner) == pytest.approx(
        flat([(0, 0), (20, 20), (10, 30), (0, 22), (-10, 30), (-20, 20)]), abs=DXF_TOL)
    assert all(a.radius == pytest.approx(2, abs=DXF_TOL) for a in outer if isinstance(a, A))
    # every outer vertex is 2 mm from the heart's outline
    x0, y0, x1, y1 = box(outer)
    assert (x0, x1) == pytest.approx((-22, 22), abs=DXF_TOL)


def test_inside_shell_keeps_the_outline_and_insets_the_hole(compile_text):
    c = compile_text("solid s {\n    r = Rectangle(center=(0, 0), width=40, height=20)\n"
                     "    w = Shell(r, thickness=-3)\n}\n")
    assert c.ok
    assert exact_area(c) == pytest.approx(40 * 20 - 34 * 14, rel=1e-12)


# ------------------------------------------------------------------ Hull
def test_hull_of_two_pulleys_is_a_belt(tmp_path):
    """Circles r 10 and 5, 50 apart: two tangent lines of sqrt(50^2 - 5^2), each touching
    both circles at a right angle to the radius, and the arcs between them."""
    path = render(tmp_path, "solid belt {\n    a = Circle(center=(0, 0), radius=10)\n"
                            "    b = Circle(center=(50, 0), radius=5)\n    h = Hull(a, b)\n}\n")
    (segs,) = cut_loops(path)
    lines = [s for s in segs if isinstance(s, L)]
    arcs = [s for s in segs if isinstance(s, A)]
    assert len(lines) == 2 and len(arcs) == 2
    for ln in lines:
        assert ln.length == pytest.approx(math.sqrt(50 ** 2 - 5 ** 2), abs=1e-9)
        for c, r in (((0, 0), 10), ((50, 0), 5)):
            p = min((ln.start, ln.end), key=lambda q: abs(math.dist(q, c) - r))
            assert math.dist(p, c) == pytest.approx(r, abs=1e-9)
            u = (ln.end[0] - ln.start[0], ln.end[1] - ln.start[1])
            assert (p[0] - c[0]) * u[0] + (p[1] - c[1]) * u[1] == pytest.approx(0, abs=1e-9)
    # the hand formula: the big arc sweeps pi + 2 asin(5/50)
    big = max(arcs, key=lambda a: a.radius)
    assert big.radius == pytest.approx(10) and big.sweep == pytest.approx(
        math.pi + 2 * math.asin(5 / 50), abs=1e-9)
    assert loop_defects(segs, radii=[10, 5], tangent="all") == []


def test_hull_of_a_list_of_shapes_and_its_bounding_box(compile_text):
    from aidl_lang.geometry.relations.bbox import numeric_box
    c = compile_text("solid s {\n    r = Rectangle(center=(0, 0), width=10, height=10)\n"
                     "    c = Circle(center=(20, 0), radius=5)\n    h = ConvexHull([r, c])\n}\n")
    assert c.ok, [d.message for d in c.sink.items]
    g = {g.name: g for g in c.model.root.geometry}
    assert numeric_box(c.model.root, c.model.root, c.model.xs()) == pytest.approx(
        (-5, 25, -5, 5), abs=1e-9)
    assert numeric_box(g["h"], c.model.root, c.model.xs()) == pytest.approx((-5, 25, -5, 5))
    # the square, the 15 x 10 band to the circle's center, and its right half disc
    assert exact_area(c) == pytest.approx(100 + 150 + math.pi * 25 / 2, rel=1e-9)


def test_hull_rejects_what_has_no_inside(compile_text):
    c = compile_text("solid s {\n    l = Line((0, 0), (10, 0))\n    h = Hull(l, l)\n}\n")
    assert [d.code for d in c.sink.items if d.severity == "error"] == ["E0108"]


# ------------------------------------------------------------------ RoundedRectangle radii
def test_corner_radii_round_each_corner_on_its_own(tmp_path):
    path = render(tmp_path, "solid tag {\n    body = RoundedRectangle(center=(0, 0), width=40, "
                            "height=20, corner_radii=[8, 0, 4, 0])\n}\n")
    (segs,) = cut_loops(path)
    arcs = sorted((s for s in segs if isinstance(s, A)), key=lambda a: a.radius)
    assert [a.radius for a in arcs] == pytest.approx([4, 8], abs=DXF_TOL)
    assert arcs[0].center == pytest.approx((16, -6), abs=DXF_TOL)       # bottom right
    assert arcs[1].center == pytest.approx((-12, 2), abs=DXF_TOL)       # top left
    corners = {(round(s.start[0], 9), round(s.start[1], 9)) for s in segs}
    assert (20.0, 10.0) in corners and (-20.0, -10.0) in corners        # the sharp ones
    assert loop_defects(segs, radii=[4, 8]) == []


def test_corner_radii_that_overrun_a_side_are_a_located_error(compile_text):
    c = compile_text("solid s {\n    b = RoundedRectangle(center=(0, 0), width=40, height=20,\n"
                     "        radii=[12, 0, 0, 10])\n}\n")
    (d,) = [d for d in c.sink.items if d.severity == "error"]
    assert d.code == "E0108" and "left side" in d.message and d.span.line == 2
    c = compile_text("solid s {\n    b = RoundedRectangle(center=(0, 0), width=40, height=20, "
                     "corner_radii=[1, 2])\n}\n")
    assert "four radii" in [d for d in c.sink.items if d.severity == "error"][0].message


def test_grow_then_shrink_gives_back_the_rectangle(tmp_path):
    """Offset(Offset(r, 3), -3) of a convex shape is the shape again (a morphological
    closing): the corner arcs of radius 3 shrink to the sharp corners, exactly."""
    path = render(tmp_path, "solid p {\n    r = Rectangle(center=(2, 3), width=40, height=20)\n"
                            "    g = Offset(r, 3)\n    s = Offset(g, -3)\n}\n")
    (segs,) = cut_loops(path)
    assert count(segs) == (4, 0, 0)
    assert flat(s.start for s in segs) == pytest.approx(
        flat([(-18, -7), (22, -7), (22, 13), (-18, 13)]), abs=DXF_TOL)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(0.5, 20)),
                min_size=1, max_size=5),
       st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(1, 30), st.floats(1, 30)),
       st.none() | st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(-50, 50),
                             st.floats(-50, 50), st.floats(0.5, 10)))
@example(circles=[(-2.0, 0.0, 1.0), (-3.0, -1.0, 1.0), (-3.0, -1.0, 1.0)],
         rect=(0.0, 0.0, 1.0, 1.0), slot=None)           # one circle twice
def test_hull_law(circles, rect, slot):
    """The hull of circles, a rectangle and a slot (its end arcs are half circles) is
    convex, its lines meet its arcs tangent, every arc lies on one of the circles, and every
    circle and corner lies inside it."""
    from aidl_lang.geometry.shapes.curves import Arc, Circle, Line, Loop, turn_between
    from aidl_lang.geometry.derived.hull import hull_loop
    from aidl_lang.geometry.derived.offset import sweep_loops
    x, y, w, h = rect
    corners = [(x, y), (x + w, y), (x + w, y + h), (x, y + h)]
    loops = [Loop([Circle((cx, cy), r)]) for cx, cy, r in circles]
    loops.append(Loop([Line(corners[i], corners[(i + 1) % 4]) for i in range(4)]))
    if slot is not None:               # a stadium is the hull of its two end circles
        ax, ay, bx, by, r = slot
        loops += sweep_loops(Line((ax, ay), (bx, by)), r)
        circles = circles + [(ax, ay, r), (bx, by, r)]
    lp = hull_loop(loops)
    assert lp is not None and lp.area > 0
    segs = lp.segments
    if len(segs) == 1:
        (c,) = segs
        assert isinstance(c, Circle) and any(
            c.center == (cx, cy) and c.radius == r for cx, cy, r in circles)
        return
    scale = 1e-9 * 100
    for i, s in enumerate(segs):
        t = turn_between(segs[i - 1], s)
        assert t >= -1e-9                                     # convex: never turns right
        assert math.dist(segs[i - 1].end, s.start) <= scale
        if isinstance(s, Arc):
            assert s.sweep > 0 and any(math.dist(s.center, (cx, cy)) <= 1e-12 and
                                       abs(s.radius - r) <= 1e-12 for cx, cy, r in circles)
            for nb in (segs[i - 1], segs[(i + 1) % len(segs)]):
                if isinstance(nb, Line):
                    assert abs(turn_between(*((nb, s) if nb is segs[i - 1] else (s, nb)))) \
                        <= 1e-9                               # a tangent join
        if isinstance(s, Line) and s.length > 1e-9:
            (x0, y0), (x1, y1) = s.start, s.end
            L = s.length
            for cx, cy, r in circles:                 # left of the line by at least r
                assert ((x1 - x0) * (cy - y0) - (y1 - y0) * (cx - x0)) / L >= r - scale
            for px, py in corners:
                assert ((x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)) / L >= -scale


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 1, exclude_max=True), st.floats(5, 30)), min_size=3,
                max_size=9, unique_by=lambda t: round(t[0], 2) % 1),
       st.floats(-4, 6).filter(lambda d: abs(d) > 0.05))
@example(polar=[(0.0, 5.0), (0.5, 5.0), (0.75, 5.0), (0.99, 5.0)], d=1.0)
def test_offset_matches_shapely_buffer(tmp_path_factory, polar, d):
    """A star-shaped polygon offset by d (round joins) covers what Shapely's (GEOS) buffer of
    it covers: the areas agree, and so does the region (symmetric difference ~ 0), up to
    GEOS's chords (256 per quarter circle); an inset that leaves nothing is E0406, where
    GEOS's buffer is empty too.  Angles are fractions of a turn in [0, 1), distinct to 0.01
    of a turn around the circle: 1 would be the vertex at 0 again (a zero-length edge, E0108;
    a run drew 0.0 and 1.0 together), and so is 0.9999999999999999 beside 0.0 (5.7e-15 mm
    apart, rounding to 1.0 when 0.0 rounds to 0.0: hence the rounding taken modulo 1)."""
    import shapely
    from aidl_lang.pipeline import compile_source
    pts = [(r * math.cos(2 * math.pi * t), r * math.sin(2 * math.pi * t))
           for t, r in sorted(polar)]
    poly = shapely.Polygon(pts)
    if not poly.is_valid or poly.area < 1:
        return
    src = ("solid p {\n    s = Polygon([" + ", ".join(f"({x!r}, {y!r})" for x, y in pts)
           + f"])\n    o = Offset(s, {d!r})\n}}\n")
    ref = poly.buffer(d, quad_segs=256)
    c = compile_source(src, "t.aidl")
    if ref.is_empty or ref.area < 1e-6:
        assert [x.code for x in c.sink.items if x.severity == "error"] == ["E0406"]
        return
    assert c.ok, [(x.code, x.message) for x in c.sink.items]
    assert exact_area(c) == pytest.approx(ref.area, rel=2e-5, abs=1e-6)
    from aidl_lang.output.part.part import build
    ours = shapely.unary_union([shapely.Polygon(lp.points()) if lp.area > 0 else None
                                for p in build(c.drawing).parts for lp in p.loops
                                if lp.area > 0])
    holes = [shapely.Polygon(lp.points()) for p in build(c.drawing).parts for lp in p.loops
             if lp.area < 0]
    if holes:
        ours = ours.difference(shapely.unary_union(holes))
    # our loops drawn with chords of sagitta <= 0.005 mm (CHORD_TOL) along the outline; both
    # snapped to a 1e-9 mm grid first: GEOS 3.14's overlay of two triangles equal to 1e-15 mm
    # returned both whole (a saved example: 306.9 mm^2 for two identical insets)
    ours, ref = shapely.set_precision(ours, 1e-9), shapely.set_precision(ref, 1e-9)
    assert ours.symmetric_difference(ref).area <= 0.005 * ref.length


def test_a_pattern_of_a_hull_copies_its_sources(tmp_path):
    """LinearPattern of a Hull copies the shapes it is made from (construction copies), so
    every copy is the same exact hull moved by the step."""
    path = render(tmp_path, "solid plate {\n    body = Rectangle(center=(40, 0), width=120, "
                            "height=40)\n    hole cut {\n        a = Circle(center=(0, 0), "
                            "radius=5)\n        b = Circle(center=(10, 5), radius=3)\n"
                            "        h = Hull(a, b)\n        more = LinearPattern(h, 3, (30, 0))\n"
                            "    }\n}\n")
    holes = [segs for segs in cut_loops(path) if count(segs) == (2, 2, 0)]
    assert len(holes) == 3
    centers = sorted(a.center for segs in holes for a in segs if isinstance(a, A))
    assert flat(centers) == pytest.approx(flat([(k * 30 + dx, dy) for k in range(3)
                                                for dx, dy in ((0, 0), (10, 5))]), abs=DXF_TOL)
    for segs in holes:
        assert loop_defects(segs, radii=[5, 3], tangent="all") == []


@pytest.mark.parametrize("call,fix", [
    ("Offset(body, -5)", "`Shell(body, -thickness)` there"),
    ("Hull(body, body)", "write it in `frame`, where `body` is"),
])
def test_derived_shape_of_a_parent_shape_says_where_to_write_it(compile_text, call, fix):
    """`Offset(body, ...)` in a hole with `body` in its parent: E0201 says to write it where
    `body` is (a window or frame cut from it is a `Shell` there)."""
    c = compile_text("units mm\nsolid frame {\n    body = Rectangle(center=(0, 0), width=60, "
                     f"height=40)\n    hole window {{\n        w = {call}\n    }}\n}}\n")
    (d,) = [d for d in c.sink.items if d.code == "E0201"]
    assert (d.span.line, d.span.col) == (5, 14 + len(call.split("(")[0])) and fix in d.hint
