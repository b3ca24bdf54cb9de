"""Issue 36 section 3, the shapes makers reached for: Polyline, Spline corners, Stroke, Sector
(and the annulus segment), Text along a circle or arc, mirror() of a point list.

Real programs go through the real pipeline and writers; the DXF is re-read with ezdxf and the
SVG with svgelements (tests/exact_geometry.py) and compared with the design's numbers: 1e-9 mm
in the DXF, SVG_TOL in the SVG.  Bad input is a located E0108 at the call.
"""
from __future__ import annotations

import itertools
import math

import pytest
from hypothesis import Phase, given, settings, strategies as st

from exact_geometry import DXF_TOL, SVG_TOL, A, B, C, L, kink, read_dxf, read_svg_loops

_n = itertools.count()
TOL = 1e-9


def _compile(src: str, path):
    from aidl_lang.pipeline import compile_source
    return compile_source(src, str(path))


def render(outdir, src: str, suffix: str):
    """Compile ``src`` (it must check) and write it as ``suffix`` through the real writer."""
    from aidl_lang.output import Options, build, encode
    k = next(_n)
    c = _compile(src, outdir / f"s{k}.aidl")
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    out = build(c.drawing, c.model.root.name)
    path = outdir / f"s{k}{suffix}"
    path.write_bytes(encode(out, suffix, Options()))
    return path


def errors(outdir, src: str):
    c = _compile(src, outdir / f"e{next(_n)}.aidl")
    return [d for d in c.sink.items if d.severity == "error"]


@pytest.fixture(scope="module")
def outdir(tmp_path_factory):
    return tmp_path_factory.mktemp("shapes")


def cut(path):
    return [e for e in read_dxf(path) if e.layer.startswith("CUT")]


def near(p, q, tol=TOL):
    return math.dist(p, q) <= tol


def same_points(got, want, tol=TOL) -> bool:
    """The closed vertex lists ``got`` and ``want`` are the same cycle (any start, either
    way round: the writers turn outlines counter-clockwise)."""
    if len(got) != len(want):
        return False
    for w in (list(want), list(want)[::-1]):
        for k in range(len(got)):
            if all(near(got[(k + i) % len(got)], q, tol) for i, q in enumerate(w)):
                return True
    return False


# ------------------------------------------------------------------ Polyline
def test_open_polyline_is_engraved_exactly(outdir):
    pts = [(3, 3), (8, 10), (13, 3), (18, 10), (23, 3)]
    src = ("solid s {\n    body = Rectangle(bottom_left=(0, 0), width=30, height=15)\n"
           f"    drawing zig {{ z = Polyline({pts}) }}\n"
           "    Fixed(body)\n    Coincident(zig.z.start, (3, 3))\n}\n")
    eng = [e for e in read_dxf(render(outdir, src, ".dxf")) if e.layer == "ENGRAVE"]
    assert len(eng) == 1 and not eng[0].closed
    got = [eng[0].segments[0].start] + [s.end for s in eng[0].segments]
    assert all(isinstance(s, L) for s in eng[0].segments)
    assert len(got) == len(pts) and all(near(g, p) for g, p in zip(got, pts))


def test_open_polyline_closes_with_a_line_and_closed_is_a_polygon(outdir):
    chain = ("solid s {\n    edge = Polyline([(0, 0), (30, 0), (30, 20), (10, 25)])\n"
             "    back = Line(start=edge.end, end=edge.start)\n}\n")
    loop = cut(render(outdir, chain, ".dxf"))
    assert len(loop) == 1 and loop[0].closed
    assert same_points([s.start for s in loop[0].segments],
                       [(0, 0), (30, 0), (30, 20), (10, 25)])
    closed = "solid s {\n    p = Polyline([(0, 0), (30, 0), (30, 20), (10, 25)], closed=true)\n}\n"
    poly = "solid s {\n    p = Polygon([(0, 0), (30, 0), (30, 20), (10, 25)])\n}\n"
    a, b = (cut(render(outdir, s, ".dxf"))[0] for s in (closed, poly))
    assert a.segments == b.segments


@pytest.mark.parametrize("call, words", [
    ("Polyline([(0, 0)])", "at least 2 points"),
    ("Polyline([(0, 0), (5, 5), (5, 5)])", "points[1] and points[2] are the same point"),
])
def test_polyline_errors_are_located(outdir, call, words):
    errs = errors(outdir, f"solid s {{\n    drawing d {{ p = {call} }}\n}}\n")
    assert [e.code for e in errs] == ["E0108"] and words in errs[0].message
    assert errs[0].span.line == 2


# ------------------------------------------------------------------ Spline corners
LEAF = [(0, -25), (18, -8), (14, 14), (0, 30), (-14, 14), (-18, -8)]


def _joins(loop):
    """(end point, kink angle) at every join of a loop of Bézier segments."""
    return [(a.end, kink(a, b)) for a, b in zip(loop, loop[1:] + loop[:1])]


def test_spline_corners_are_sharp_and_the_rest_smooth_svg(outdir):
    src = f"solid s {{\n    body = Spline({LEAF}, closed=true, corners=[0, 3])\n}}\n"
    loops = read_svg_loops(render(outdir, src, ".svg"))
    assert len(loops) == 1 and all(isinstance(s, B) for s in loops[0])
    joins = _joins(loops[0])
    assert len(joins) == len(LEAF)
    for p, k in joins:
        corner = near(p, LEAF[0], SVG_TOL) or near(p, LEAF[3], SVG_TOL)
        assert any(near(p, q, SVG_TOL) for q in LEAF)           # through every point
        if corner:
            assert k > math.radians(30), (p, math.degrees(k))    # a pointed tip
        else:
            assert k < 1e-6, (p, math.degrees(k))                # smooth


def test_spline_corner_is_sharp_in_the_dxf_spline(outdir):
    """An open Spline with a corner at point 2, closed by a Line: the DXF SPLINE's Bézier
    pieces meet at (55, 18) with different tangents, elsewhere with equal ones."""
    pts = [(35, -10), (45, 12), (55, 18), (65, 12), (75, -10)]
    src = (f"solid s {{\n    top = Spline({pts}, corners=[2])\n"
           "    bottom = Line(start=top.end, end=top.start)\n}\n")
    spl = [e for e in read_dxf(render(outdir, src, ".dxf")) if e.dxftype == "SPLINE"]
    assert len(spl) == 1
    segs = spl[0].segments
    assert len(segs) == 4
    kinks = [kink(a, b) for a, b in zip(segs, segs[1:])]
    ends = [a.end for a in segs[:-1]]
    for p, k in zip(ends, kinks):
        if near(p, (55, 18), 1e-9):
            assert k > math.radians(20)
        else:
            assert k < 1e-9
    # a corner between runs of two points each: the spans are straight lines
    src2 = "solid s {\n    t = Spline([(0, 0), (20, 0), (10, 15)], closed=true, corners=[0, 1, 2])\n}\n"
    tri = [e for e in read_dxf(render(outdir, src2, ".dxf")) if e.layer.startswith("CUT")][0]
    for b in tri.segments:          # each Bézier's control points on its chord
        for q in (b.p1, b.p2):
            (x0, y0), (x1, y1) = b.p0, b.p3
            cross = (x1 - x0) * (q[1] - y0) - (y1 - y0) * (q[0] - x0)
            assert abs(cross) <= 1e-9 * math.dist(b.p0, b.p3)


@pytest.mark.parametrize("args, words", [
    ("[(0, 0), (10, 5), (20, 0)], corners=[0]", "is an end of the open Spline"),
    ("[(0, 0), (10, 5), (20, 0)], closed=true, corners=[3]", "not one of its points"),
    ("[(0, 0), (10, 5), (20, 0)], closed=true, corners=[1.5]", "whole numbers"),
])
def test_spline_corner_errors_are_located(outdir, args, words):
    errs = errors(outdir, f"solid s {{\n    drawing d {{ c = Spline({args}) }}\n}}\n")
    assert [e.code for e in errs] == ["E0108"] and words in errs[0].message
    assert errs[0].span.line == 2


# ------------------------------------------------------------------ Stroke
def test_stroke_of_a_line_is_a_stadium_or_a_bar(outdir):
    base = "solid s {{\n    l = Line((0, 0), (30, 0))\n    b = Stroke(l, width=4{cap})\n}}\n"
    loop = cut(render(outdir, base.format(cap=""), ".dxf"))[0]
    lines = [s for s in loop.segments if isinstance(s, L)]
    arcs = [s for s in loop.segments if isinstance(s, A)]
    assert len(lines) == 2 and len(arcs) == 2
    assert sorted(round(s.start[1], 12) for s in lines) == [-2, 2]
    for a in arcs:
        assert abs(a.radius - 2) <= TOL and abs(abs(a.sweep) - math.pi) <= TOL
        assert near(a.center, (0, 0)) or near(a.center, (30, 0))
    bar = cut(render(outdir, base.format(cap=', cap="flat"'), ".dxf"))[0]
    assert all(isinstance(s, L) for s in bar.segments)
    assert same_points([s.start for s in bar.segments], [(0, -2), (30, -2), (30, 2), (0, 2)])


def test_stroke_along_two_tangent_arcs_is_concentric_arcs(outdir):
    """An S of two arcs of radius 8 (centres (0, 8) and (0, -8)), 3 wide with flat ends: the
    band's sides are arcs of radii 9.5 and 6.5 about each centre, its ends flat, 3 long."""
    src = ("solid s {\n"
           "    top = Arc(center=(0, 8), radius=8, start_angle=-90, end_angle=90)\n"
           "    bottom = Arc(center=(0, -8), radius=8, start_angle=90, end_angle=270)\n"
           "    s = Stroke([top, bottom], width=3, cap=\"flat\")\n}\n")
    loop = cut(render(outdir, src, ".dxf"))[0]
    arcs = [s for s in loop.segments if isinstance(s, A)]
    lines = [s for s in loop.segments if isinstance(s, L)]
    radii = sorted(round(a.radius, 9) for a in arcs)
    assert radii == [6.5, 6.5, 9.5, 9.5]
    for a in arcs:
        assert near(a.center, (0, 8)) or near(a.center, (0, -8))
        assert abs(abs(a.sweep) - math.pi) <= 1e-9
    assert len(lines) == 2 and all(abs(s.length - 3) <= TOL for s in lines)
    svg = read_svg_loops(render(outdir, src, ".svg"))[0]
    assert sorted(round(s.radius, 6) for s in svg if isinstance(s, A)) == [6.5, 6.5, 9.5, 9.5]


def test_stroke_of_a_polyline_round_joins(outdir):
    """A bent wire: sides 2 mm from each run, a round join of radius 2 outside the bend."""
    src = ("solid s {\n    p = Polyline([(0, 0), (20, 0), (20, 20)])\n"
           "    w = Stroke(p, width=4)\n}\n")
    loop = cut(render(outdir, src, ".dxf"))[0]
    arcs = [s for s in loop.segments if isinstance(s, A)]
    assert all(abs(a.radius - 2) <= TOL for a in arcs)
    assert sorted(round(abs(a.sweep) / math.pi * 2) for a in arcs) == [1, 2, 2]   # join, caps
    assert any(near(a.center, (20, 0)) and abs(abs(a.sweep) - math.pi / 2) <= TOL for a in arcs)
    corner = [s.start for s in loop.segments if isinstance(s, L)]
    assert any(near(p, (18, 2)) for p in corner)                      # the inside corner


@pytest.mark.parametrize("body, words", [
    ("c = Circle(center=(0, 0), radius=5)\n    s = Stroke(c, width=2)", "Shell"),
    ("a = Line((0, 0), (10, 0))\n    b = Line((20, 0), (30, 0))\n    s = Stroke([a, b], width=2)",
     "do not join"),
    ("a = Line((0, 0), (10, 0))\n    s = Stroke(a, width=2, cap=\"pointy\")", "cap"),
    ("a = Line((0, 0), (10, 0))\n    s = Stroke(a, width=0)", "positive width"),
])
def test_stroke_errors_are_located(outdir, body, words):
    errs = errors(outdir, f"solid s {{\n    {body}\n}}\n")
    assert [e.code for e in errs] == ["E0108"] and words in errs[0].message, errs
    assert errs[0].span.line == body.count("\n") + 2


S_POINTS = [(0, 0), (10, 8), (20, 0), (30, -8), (40, 0)]


def test_stroke_along_a_spline_is_within_its_tolerance(outdir):
    """The sides of a Stroke along a Spline, re-read from the DXF, are width/2 from the
    centre line within STROKE_TOL (1e-4 mm): the centre line is scipy's natural cubic spline
    through the same points with chord-length parameters, sampled densely."""
    import numpy as np
    from scipy.interpolate import CubicSpline as SciSpline
    P = np.array(S_POINTS, dtype=float)
    t = np.concatenate([[0], np.cumsum(np.hypot(*np.diff(P, axis=0).T))])
    fine = SciSpline(t, P, bc_type="natural")(np.linspace(0, t[-1], 40001))
    src = f"solid s {{\n    c = Spline({S_POINTS})\n    s = Stroke(c, width=3)\n}}\n"
    ents = cut(render(outdir, src, ".dxf"))
    beziers = [b for e in ents for b in e.segments if isinstance(b, B)]
    arcs = [a for e in ents for a in e.segments if isinstance(a, A)]
    assert len(beziers) >= 8 and len(arcs) == 2
    assert all(abs(a.radius - 1.5) <= TOL for a in arcs)
    assert sorted(a.center for a in arcs) == [(0.0, 0.0), (40.0, 0.0)]
    worst = 0.0
    for b in beziers:
        for k in range(1, 8):
            q = np.array(b.at(k / 8))
            d = np.sqrt(((fine - q) ** 2).sum(axis=1)).min()
            worst = max(worst, abs(d - 1.5))
    assert worst <= 1e-4 + 1e-6, worst


def test_stroke_along_a_spline_too_tight_is_refused_at_the_call(outdir):
    errs = errors(outdir, "solid s {\n    c = Spline([(0, 0), (3, 4), (6, 0)])\n"
                          "    s = Stroke(c, width=8)\n}\n")
    assert [e.code for e in errs] == ["E0108"] and "bends tighter" in errs[0].message
    assert errs[0].span.line == 3


# ------------------------------------------------------------------ Sector
def test_sector_pie_and_annulus_segment(outdir):
    src = ("assembly a {\n"
           "    solid pie { s = Sector(center=(0, 0), radius=30, start_angle=30, end_angle=120) }\n"
           "    solid ring { s = Sector(center=(100, 0), radius=30, inner_radius=20, "
           "start_angle=-45, end_angle=225) }\n}\n")
    pie, ring = sorted(cut(render(outdir, src, ".dxf")), key=lambda e: e.layer)
    a = [s for s in pie.segments if isinstance(s, A)]
    ln = [s for s in pie.segments if isinstance(s, L)]
    assert len(a) == 1 and len(ln) == 2
    assert near(a[0].center, (0, 0)) and abs(a[0].radius - 30) <= TOL
    assert abs(a[0].sweep - math.pi / 2) <= TOL
    r30 = math.radians(30)
    assert near(a[0].start, (30 * math.cos(r30), 30 * math.sin(r30)))
    assert any(near(s.end, (0, 0)) for s in ln)
    arcs = [s for s in ring.segments if isinstance(s, A)]
    assert sorted(round(s.radius, 9) for s in arcs) == [20, 30]
    assert all(near(s.center, (100, 0)) and abs(abs(s.sweep) - 1.5 * math.pi) <= TOL
               for s in arcs)
    assert sorted(round(s.length, 9) for s in ring.segments if isinstance(s, L)) == [10, 10]
    loops = read_svg_loops(render(outdir, src, ".svg"))
    svg_arcs = [s for lp in loops for s in lp if isinstance(s, A)]
    assert {round(a.radius, 9) for a in svg_arcs} == {20, 30}      # arcs of a quarter turn
    turn = {r: sum(abs(a.sweep) for a in svg_arcs if round(a.radius, 9) == r) for r in (20, 30)}
    assert abs(turn[20] - 1.5 * math.pi) <= 1e-6 and abs(turn[30] - 2 * math.pi) <= 1e-6
    for a in svg_arcs:
        assert near(a.center, (0, 0), SVG_TOL) or near(a.center, (100, 0), SVG_TOL)


def test_sector_box_and_members(outdir):
    """The box of a quarter pie from 0 to 90 degrees is [0, 30] x [0, 30]: a rectangle placed
    by it lands at the design's numbers."""
    src = ("solid s {\n    p = Sector(center=(0, 0), radius=30, start_angle=0, end_angle=90)\n"
           "    Fixed(p.center)\n    r = Rectangle(center=(60, 0), width=5, height=5)\n"
           "    LeftOf(p, r, gap=10)\n    AlignTop(r, p)\n"
           "    assert p.inner_radius == 0 mm and p.outer_radius == 30 mm\n}\n")
    loops = cut(render(outdir, src, ".dxf"))
    xs = sorted({round(s.start[0], 9) for e in loops for s in e.segments})
    ys = sorted({round(s.start[1], 9) for e in loops for s in e.segments})
    assert 40 in xs and 45 in xs and 30 in ys and 25 in ys


@pytest.mark.parametrize("args, words", [
    ("radius=10, start_angle=0, end_angle=90, inner_radius=10", "inner_radius"),
    ("radius=10, start_angle=30, end_angle=390", "different start and end angles"),
])
def test_sector_errors_are_located(outdir, args, words):
    errs = errors(outdir, f"solid s {{\n    p = Sector(center=(0, 0), {args})\n}}\n")
    assert [e.code for e in errs] == ["E0108"] and words in errs[0].message
    assert errs[0].span.line == 2


def test_sector_synonyms(outdir):
    a = cut(render(outdir, "solid s {\n    p = Wedge(center=(0, 0), r=10, start=0, end=60)\n}\n",
                   ".dxf"))[0]
    b = cut(render(outdir, "solid s {\n    p = Sector((0, 0), 10, 0, 60)\n}\n", ".dxf"))[0]
    assert a.segments == b.segments


# ------------------------------------------------------------------ Text along a curve
def _engraved(path):
    return [s for e in read_dxf(path) if e.layer == "ENGRAVE" for s in e.segments]


@pytest.mark.parametrize("angle", [0, 30, 90, 135])
def test_text_along_a_circle_stands_upright_at_its_angle(outdir, angle):
    """"I" is one stroke from the baseline to the cap height: along a circle of radius 30 at
    ``angle`` it runs radially from radius 30 to 30 + size, at that angle."""
    src = ("solid s {\n    body = Circle(center=(0, 0), radius=50)\n    Fixed(body)\n"
           "    drawing t {\n        ring = Circle(center=(0, 0), radius=30, construction=true)\n"
           f"        i = Text(\"I\", along=ring, angle={angle} deg, size=5)\n    }}\n"
           "    Coincident(t.ring.center, body.center)\n}\n")
    segs = _engraved(render(outdir, src, ".dxf"))
    assert len(segs) == 1
    u = (math.cos(math.radians(angle)), math.sin(math.radians(angle)))
    ends = sorted([segs[0].start, segs[0].end], key=lambda p: math.hypot(*p))
    assert near(ends[0], (30 * u[0], 30 * u[1]), 1e-9)
    assert near(ends[1], (35 * u[0], 35 * u[1]), 1e-9)


def test_text_along_an_arc_reads_clockwise_with_upright_letters(outdir):
    """"II" centred on the top of an arc: each stroke radial, the first letter left of the
    top (reading clockwise, left to right), both at the arc's radius."""
    src = ("solid s {\n    body = Circle(center=(0, 0), radius=50)\n    Fixed(body)\n"
           "    drawing t {\n        a = Arc(center=(0, 0), radius=30, start_angle=45, "
           "end_angle=135, construction=true)\n"
           "        i = Text(\"II\", along=a, size=5)\n    }\n"
           "    Coincident(t.a.center, body.center)\n}\n")
    segs = _engraved(render(outdir, src, ".dxf"))
    assert len(segs) == 2
    for s in segs:
        (x0, y0), (x1, y1) = s.start, s.end
        assert abs(x0 * y1 - x1 * y0) <= 1e-9 * 35 * 35       # radial: through the centre
        r = sorted([math.hypot(x0, y0), math.hypot(x1, y1)])
        assert abs(r[0] - 30) <= 1e-9 and abs(r[1] - 35) <= 1e-9
    xs = sorted(s.start[0] for s in segs)
    assert xs[0] < 0 < xs[1] and abs(xs[0] + xs[1]) <= 1e-9      # symmetric about the top


def test_text_along_flipped_reads_counter_clockwise_under_the_circle(outdir):
    """flip=true: an "I" under a circle of radius 30 (its bottom by default) runs from radius
    30 in to 25, its up toward the centre; "IL" starting at the bottom reads left to right,
    counter-clockwise, so its L (foot on the circle) lies to the right, x > 0."""
    src = ("solid s {\n    body = Circle(center=(0, 0), radius=50)\n    Fixed(body)\n"
           "    drawing t {\n        ring = Circle(center=(0, 0), radius=30, construction=true)\n"
           "        i = Text(\"I\", along=ring, flip=true, size=5)\n    }\n"
           "    Coincident(t.ring.center, body.center)\n}\n")
    segs = _engraved(render(outdir, src, ".dxf"))
    assert len(segs) == 1
    ends = sorted([segs[0].start, segs[0].end], key=lambda p: p[1])
    assert near(ends[0], (0, -30)) and near(ends[1], (0, -25))
    src = src.replace('Text(\"I\", along=ring, flip=true, size=5)',
                      'Text(\"IL\", along=ring, flip=true, angle=-90 deg, size=5, '
                      'anchor=\"start\")')
    segs = _engraved(render(outdir, src, ".dxf"))
    xs = [p[0] for s in segs for p in (s.start, s.end)]
    assert min(xs) >= -1e-9 and max(xs) > 3          # from the bottom, to the right


@pytest.mark.parametrize("call, words", [
    ("l = Line((0, 0), (10, 0), construction=true)\n        t = Text(\"A\", along=l)",
     "Circle or an Arc"),
    ("c = Circle(center=(0, 0), radius=9, construction=true)\n"
     "        t = Text(\"A\", position=(0, 0), along=c)", "not both"),
    ("t = Text(\"A\")", "needs a position"),
])
def test_text_along_errors_are_located(outdir, call, words):
    errs = errors(outdir, f"solid s {{\n    drawing d {{\n        {call}\n    }}\n}}\n")
    assert [e.code for e in errs] == ["E0108"] and words in errs[0].message, errs
    assert errs[0].span.line == 3 + call.count("\n")


# ------------------------------------------------------------------ mirror()
def test_mirror_about_y_writes_the_symmetric_outline_exactly(outdir):
    half = [(0, -20), (12, -15), (15, 5), (6, 18), (0, 20)]
    src = f"solid s {{\n    p = Polygon(mirror({half}, about=\"y\"))\n}}\n"
    loop = cut(render(outdir, src, ".dxf"))[0]
    want = half + [(-x, y) for x, y in reversed(half[1:-1])]
    assert same_points([s.start for s in loop.segments], want, 0.0)     # bit for bit


def test_mirror_about_x_and_about_a_diagonal_line(outdir):
    src = "solid s {\n    p = Polygon(mirror([(-10, 0), (-5, 8), (5, 6), (10, 0)], about=\"x\"))\n}\n"
    loop = cut(render(outdir, src, ".dxf"))[0]
    assert same_points([s.start for s in loop.segments],
                       [(-10, 0), (-5, 8), (5, 6), (10, 0), (5, -6), (-5, -8)], 0.0)
    src = ("solid s {\n    axis = Line((60, 0), (80, 20), construction=true)\n"
           "    p = Polygon(mirror([(60, 0), (75, 2), (80, 20)], about=axis))\n}\n")
    loop = cut(render(outdir, src, ".dxf"))[0]
    assert same_points([s.start for s in loop.segments],
                       [(60, 0), (75, 2), (80, 20), (62, 15)], 0.0)


@pytest.mark.parametrize("call, words", [
    ("mirror(5)", "list of points"),
    ("mirror([(1, 0), (2, 3)], about=\"z\")", "reflects about"),
    ("mirror([(1, 0), (2, 3)], scale=2)", "about="),
])
def test_mirror_errors_are_located(outdir, call, words):
    errs = errors(outdir, f"solid s {{\n    p = Polygon({call})\n}}\n")
    assert errs and errs[0].code in ("E0108", "E0105") and words in errs[0].message, errs
    assert errs[0].span.line == 2


@settings(max_examples=15, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(st.lists(st.tuples(st.integers(1, 40), st.integers(-40, 40)), min_size=2, max_size=6,
                unique_by=lambda p: p[1]))
def test_mirror_law_the_outline_equals_its_reflection(tmp_path_factory, half):
    """Law: the outline of Polygon(mirror(points, about="y")) is its own reflection x -> -x,
    to the bit (shapely: the symmetric difference with its reflection has no area)."""
    from shapely.affinity import scale
    from shapely.geometry import Polygon as SP
    half = sorted(half, key=lambda p: p[1])
    out = tmp_path_factory.mktemp("law")
    text = ", ".join(f"({x}, {y})" for x, y in half)
    src = f"solid s {{\n    p = Polygon(mirror([{text}], about=\"y\"))\n}}\n"
    pts = [(x, y) for x, y in half] + [(-x, y) for x, y in reversed(half)]
    shape = SP(pts)
    if not shape.is_valid:    # a self-crossing outline is the generator's, not mirror's
        return
    loop = cut(render(out, src, ".dxf"))[0]
    got = SP([s.start for s in loop.segments])
    assert got.symmetric_difference(scale(got, -1, 1, origin=(0, 0))).area == 0.0
    assert abs(got.area - shape.area) <= 1e-9 * shape.area


# ------------------------------------------------------------------ laws under copies
def _exact_loops(c):
    """Every closed exact outline of the compiled model, as (vertices, arcs): the segment
    starts and the arcs' (centre, radius), each rounded for comparison."""
    from aidl_lang.output.part.build.booleans import Renderer
    from aidl_lang.geometry.shapes.curves import Arc as XA
    r = Renderer(c.model)
    out = []
    stack = [c.model.root]
    while stack:
        s = stack.pop()
        stack += list(s.children.values())
        for g in s.geometry:
            if g.kind in ("Sector", "Stroke") and not g.construction:
                lp = r.loops_of(g)[0]
                out.append(([sg.start for sg in lp.segments],
                            [(sg.center, sg.radius) for sg in lp.segments if isinstance(sg, XA)]))
    return out


def _same_shape(a, b, tol=1e-9) -> bool:
    (va, ca), (vb, cb) = a, b
    return (len(va) == len(vb) and len(ca) == len(cb)
            and all(any(near(p, q, tol) for q in vb) for p in va)
            and all(any(near(p, q, tol) and abs(r - s) <= tol for q, s in cb) for p, r in ca))


def _turn(shape, th, flip=False):
    """The reference motion: a rotation by ``th`` about the origin, or the mirror about the
    line through the origin at angle ``th``."""
    cs, sn = math.cos(th), math.sin(th)
    c2, s2 = math.cos(2 * th), math.sin(2 * th)

    def f(p):
        x, y = p
        return (x * c2 + y * s2, x * s2 - y * c2) if flip else (x * cs - y * sn, x * sn + y * cs)
    vs, cs_ = shape
    return ([f(p) for p in vs], [(f(p), r) for p, r in cs_])


@settings(max_examples=12, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(a1=st.integers(-180, 180), sweep=st.integers(10, 350), inner=st.sampled_from([0, 8]),
       th=st.integers(-170, 170), mirror=st.booleans())
def test_law_a_copied_sector_is_the_moved_original(tmp_path_factory, a1, sweep, inner, th, mirror):
    """Law: a Sector copied by Mirrored (about a line through the centre at angle th) or by
    CircularPattern (turned by th) is the reference motion of the original's exact outline
    (every vertex and every arc's centre and radius, to 1e-9 mm)."""
    out = tmp_path_factory.mktemp("law")
    th = th or 90           # a pattern turned by 0 puts its copy on the original: E0108
    t = math.radians(th)
    op = (f"axis = Line((0, 0), ({50 * math.cos(t)!r}, {50 * math.sin(t)!r}), construction=true)\n"
          f"    m = Mirrored(w, about=axis)" if mirror else
          f"m = CircularPattern(w, 2, center=(0, 0), angle={th} deg)")
    src = (f"solid s {{\n    w = Sector(center=(0, 0), radius=20, inner_radius={inner}, "
           f"start_angle={a1}, end_angle={a1 + sweep})\n    Fixed(w.center)\n    {op}\n}}\n")
    c = _compile(src, out / "law.aidl")
    assert c.ok, [d.message for d in c.sink.items]
    shapes = _exact_loops(c)
    assert len(shapes) == 2
    orig, copy = shapes
    assert _same_shape(copy, _turn(orig, t, mirror), 1e-9), src


def test_text_along_a_curve_of_another_structure_says_how(outdir):
    errs = errors(outdir, "solid s {\n    c = Circle(center=(0, 0), radius=20)\n"
                          "    drawing d { t = Text(\"A\", along=c) }\n}\n")
    assert [e.code for e in errs] == ["E0201"] and errs[0].span.line == 3
    assert "construction=true" in errs[0].hint and "Coincident" in errs[0].hint


def test_open_polyline_in_a_solid_is_engraved_with_a_warning(outdir):
    c = _compile("solid s {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
                 "    z = Polyline([(-10, 0), (0, 5), (10, 0)])\n}\n", outdir / "w.aidl")
    assert c.ok and [d.code for d in c.sink.items] == ["W0402"]
    assert c.sink.items[0].span.line == 3


def _loop_area(segs) -> float:
    """Signed area of a loop of lines and arcs read from a file (mm^2): the shoelace over the
    ends plus each arc's circular segment."""
    a = 0.0
    for s in segs:
        if isinstance(s, C):
            return math.pi * s.radius ** 2
        (x0, y0), (x1, y1) = s.start, s.end
        a += 0.5 * (x0 * y1 - x1 * y0)
        if isinstance(s, A):
            a += 0.5 * s.radius ** 2 * (s.sweep - math.sin(s.sweep))
    return a


@settings(max_examples=10, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(ys=st.lists(st.integers(-12, 12), min_size=2, max_size=6),
       dxs=st.lists(st.integers(4, 12), min_size=5, max_size=5),
       w=st.sampled_from([1, 2, 3]))
def test_law_a_round_stroke_is_the_buffer_of_its_path(tmp_path_factory, ys, dxs, w):
    """Law: Stroke(polyline, w) with round caps is the polyline's Minkowski sum with a disc of
    radius w/2, which is shapely's buffer (round caps and joins, 256 segments a quarter
    circle): equal areas to the buffer's polygon error (1e-5 relative)."""
    from shapely.geometry import LineString
    xs = [0]
    for d in dxs[:len(ys) - 1]:
        xs.append(xs[-1] + d)
    pts = list(zip(xs, ys))
    out = tmp_path_factory.mktemp("stroke")
    text = ", ".join(f"({x}, {y})" for x, y in pts)
    src = f"solid s {{\n    p = Polyline([{text}])\n    b = Stroke(p, width={w})\n}}\n"
    loops = cut(render(out, src, ".dxf"))
    got = sum(_loop_area(e.segments) for e in loops)
    ref = LineString(pts).buffer(w / 2, quad_segs=256).area
    assert abs(abs(got) - ref) <= 1e-5 * ref, (src, got, ref)
