"""Spline: the interpolating cubic spline through points (aidl_lang/geometry/shapes/spline.py), its
exact segment in the output model, and `Spline(points=[...], closed=true)` in the language.

Numbers are checked against the definition (passes through the points, C2 joins, natural
ends), against independent readers (ezdxf evaluates the DXF SPLINE, svgelements the SVG path)
and against each other (de Casteljau halves, bounding box vs tessellation)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st

from aidl_lang.geometry.shapes.curves import Circle, Line, Loop, Spline, reverse, simplify
from aidl_lang.geometry.shapes.spline import (SplineError, bez_at, bez_box, bez_pieces, interpolate,
                                       split)
from aidl_lang.output.part.edges.exact import Provenance

GUITAR = [(0, -60), (38, -52), (44, -20), (26, 2), (32, 30), (18, 52), (0, 56), (-18, 52),
          (-32, 30), (-26, 2), (-44, -20), (-38, -52)]
WAVE = [(0, 0), (10, 8), (20, -3), (35, 5), (40, 0)]


def _dist(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1])


# ------------------------------------------------------------------ the curve
@pytest.mark.parametrize("closed", [True, False])
def test_passes_through_every_point(closed):
    pts = GUITAR if closed else WAVE
    c = interpolate(pts, closed)
    assert c.n == (len(pts) if closed else len(pts) - 1)
    for i, p in enumerate(pts):
        assert _dist(c.at(i), p) <= 1e-9
        # the span ends are the points themselves, and interior parameters are on the curve
        assert _dist(c.span(i % c.n)[0] if i < c.n else c.span(c.n - 1)[3], p) <= 1e-9


def test_closed_is_c2_at_every_join():
    c = interpolate(GUITAR, True)
    for i in range(c.n):
        a, b = c.span(i - 1), c.span(i)
        ha, hb = c.h[(i - 1) % c.n], c.h[i]
        # derivatives by the chord-length parameter at the end of span i-1 and start of i
        d1a = ((3 * (a[3][0] - a[2][0])) / ha, (3 * (a[3][1] - a[2][1])) / ha)
        d1b = ((3 * (b[1][0] - b[0][0])) / hb, (3 * (b[1][1] - b[0][1])) / hb)
        d2a = [6 * (a[3][k] - 2 * a[2][k] + a[1][k]) / ha ** 2 for k in (0, 1)]
        d2b = [6 * (b[2][k] - 2 * b[1][k] + b[0][k]) / hb ** 2 for k in (0, 1)]
        s1 = max(1.0, math.hypot(*d1a))
        s2 = max(1e-3, math.hypot(*d2a))
        assert _dist(d1a, d1b) <= 1e-9 * s1, i
        assert _dist(d2a, d2b) <= 1e-9 * s2, i
    assert c.at(0) == c.at(c.n)


def test_open_has_natural_ends_and_c2_inside():
    c = interpolate(WAVE, False)
    for u in (0.0, float(c.n)):
        assert math.hypot(*c.d2(u)) <= 1e-9
    for i in range(1, c.n):
        assert _dist(c.d1(i - 1e-13), c.d1(i)) <= 1e-6
        a, b = c.span(i - 1), c.span(i)
        d2a = [6 * (a[3][k] - 2 * a[2][k] + a[1][k]) / c.h[i - 1] ** 2 for k in (0, 1)]
        d2b = [6 * (b[2][k] - 2 * b[1][k] + b[0][k]) / c.h[i] ** 2 for k in (0, 1)]
        assert _dist(d2a, d2b) <= 1e-9 * max(1e-3, math.hypot(*d2a))


def test_two_points_open_is_the_straight_line():
    c = interpolate([(0, 0), (30, 40)], False)
    for t in np.linspace(0, 1, 11):
        x, y = c.at(float(t))
        assert abs(y * 30 - x * 40) <= 1e-9


def test_box_is_exact_against_dense_samples():
    c = interpolate(GUITAR, True)
    x0, y0, x1, y1 = c.box()
    S = np.array([c.at(u) for u in np.linspace(0, c.n, 200001)])
    # contains the curve, and touches it (dense sampling comes within its spacing)
    assert S[:, 0].min() >= x0 - 1e-9 and S[:, 0].max() <= x1 + 1e-9
    assert S[:, 1].min() >= y0 - 1e-9 and S[:, 1].max() <= y1 + 1e-9
    assert S[:, 0].min() - x0 <= 1e-6 and x1 - S[:, 0].max() <= 1e-6
    assert S[:, 1].min() - y0 <= 1e-6 and y1 - S[:, 1].max() <= 1e-6
    # the symmetric body: left and right extremes mirror each other
    assert abs(x0 + x1) <= 1e-9


def test_tessellation_within_chord_tolerance():
    from aidl_lang.geometry.shapes.tessellate import CHORD_TOL
    c = interpolate(GUITAR, True)
    for i in range(c.n):
        b = c.span(i)
        k = bez_pieces(b, CHORD_TOL)
        for j in range(k):
            p, q = bez_at(b, j / k), bez_at(b, (j + 1) / k)
            L = _dist(p, q)
            worst = 0.0
            for s in np.linspace(j / k, (j + 1) / k, 41):
                r = bez_at(b, float(s))
                worst = max(worst, abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])) / L)
            assert worst <= CHORD_TOL
    lp = Loop([Spline(c, 0, c.n)])
    x0, y0, x1, y1 = c.box()
    P = lp.points()
    assert P[:, 0].min() >= x0 - 1e-9 and P[:, 0].max() <= x1 + 1e-9
    assert P[:, 0].min() - x0 <= 0.05 and x1 - P[:, 0].max() <= 0.05


def test_area_and_length():
    # the circle through 4 points: a spline close to it; area and length near pi r^2, 2 pi r
    c = interpolate([(10, 0), (0, 10), (-10, 0), (0, -10)], True)
    lp = Loop([Spline(c, 0, c.n)])
    assert abs(lp.area - math.pi * 100) / (math.pi * 100) < 0.05      # 305 vs 314
    assert abs(c.length() - 20 * math.pi) / (20 * math.pi) < 0.05
    assert lp.area > 0 and Loop([Spline(c, c.n, 0)]).area == pytest.approx(-lp.area, abs=1e-9)
    # area exact: against the shoelace of a very fine polygon
    S = np.array([c.at(u) for u in np.linspace(0, c.n, 400001)])
    shoe = 0.5 * float(np.dot(S[:-1, 0], S[1:, 1]) - np.dot(S[:-1, 1], S[1:, 0]))
    assert abs(shoe - lp.area) < 1e-6
    poly = float(np.hypot(*np.diff(S, axis=0).T).sum())
    assert abs(poly - c.length()) < 1e-6


def test_crossings_with_line_circle_spline():
    c = interpolate(GUITAR, True)
    us = c.cross_line(-100.0, 10.0, 1.0, 0.0)
    assert len(us) == 2
    for u in us:
        assert abs(c.at(u)[1] - 10.0) <= 1e-9
    us = c.cross_circle(0.0, 56.0, 10.0)
    assert len(us) == 2
    for u in us:
        x, y = c.at(u)
        assert abs(math.hypot(x, y - 56.0) - 10.0) <= 1e-9
    o = interpolate([(-60, 0), (0, 10), (60, 0)], False)
    pairs = c.cross_spline(o)
    assert len(pairs) == 2
    for u, v in pairs:
        assert _dist(c.at(u), o.at(v)) <= 1e-9


def test_foot_of_a_point():
    c = interpolate(GUITAR, True)
    for u in (0.3, 2.5, 7.9, 11.2):
        p = c.at(u)
        tx, ty = c.tangent(u)
        q = (p[0] - 3 * ty, p[1] + 3 * tx)          # 3 mm off the curve along its normal
        assert abs(c.foot(q) - u) < 1e-9
        assert abs(c.distance(q) - 3.0) < 1e-9


def test_sub_pieces_and_reverse():
    c = interpolate(GUITAR, True)
    s = Spline(c, 10.5, 13.25)                   # wraps past the start
    assert _dist(s.start, c.at(10.5)) <= 1e-12 and _dist(s.end, c.at(1.25)) <= 1e-12
    r = reverse(s)
    assert _dist(r.start, s.end) <= 1e-12 and _dist(r.end, s.start) <= 1e-12
    assert r.length == pytest.approx(s.length, rel=1e-12)
    # two consecutive pieces merge back into one
    m = simplify([Spline(c, 0, 4.5), Spline(c, 4.5, 12)])
    assert len(m) == 1 and m[0].whole


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50)), min_size=4, max_size=4),
       st.floats(0.01, 0.99), st.floats(0, 1))
# a subnormal control point: the box's derivative roots overflowed NumPy (LinAlgError)
@example([(0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (2.225073858507203e-309, 0.0)], 0.5, 0.0)
def test_de_casteljau_halves_evaluate_to_the_original(b, t, s):
    """Law: split(b, t) = (L, R) with L(s) = b(s t) and R(s) = b(t + s (1 - t))."""
    L, R = split(b, t)
    scale = max(1.0, max(abs(v) for p in b for v in p))
    assert _dist(bez_at(L, s), bez_at(b, s * t)) <= 1e-12 * scale * 10
    assert _dist(bez_at(R, s), bez_at(b, t + s * (1 - t))) <= 1e-12 * scale * 10
    bx = bez_box(b)
    for p in (bez_at(L, s), bez_at(R, s)):
        assert bx[0] - 1e-9 <= p[0] <= bx[2] + 1e-9 and bx[1] - 1e-9 <= p[1] <= bx[3] + 1e-9


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(-40, 40), st.integers(-40, 40)), min_size=3, max_size=8,
                unique=True))
def test_interpolation_law_random_points(pts):
    """Law: the closed spline passes through its points and is C1 at every one of them."""
    pts = [(float(x), float(y)) for x, y in pts]
    try:
        c = interpolate(pts, True)
    except SplineError:
        return
    for i, p in enumerate(pts):
        assert _dist(c.at(i), p) <= 1e-9
        d0 = c.d1(i - 1e-12 if i else c.n - 1e-12)
        d1 = c.d1(i)
        assert _dist(d0, d1) <= 1e-6 * max(1.0, math.hypot(*d1))


def test_bad_points_are_refused():
    with pytest.raises(SplineError, match="at least 3"):
        interpolate([(0, 0), (1, 1)], True)
    with pytest.raises(SplineError, match=r"points\[1\] and points\[2\] are the same"):
        interpolate([(0, 0), (1, 1), (1, 1), (0, 3)], True)
    with pytest.raises(SplineError, match=r"points\[2\] and points\[0\]"):
        interpolate([(0, 0), (5, 1), (0, 0)], True)


# ------------------------------------------------------------------ booleans, recovered
def _closed_loop():
    c = interpolate(GUITAR, True)
    return c, Loop([Spline(c, 0, c.n)])


def test_untouched_spline_survives_the_booleans_exactly():
    c, lp = _closed_loop()
    pv = Provenance()
    shape = pv.face(lp) - pv.face(Loop([Circle((0, 20), 8)]))
    loops = pv.loops(shape)
    sp = [s for L in loops for s in L.segments if isinstance(s, Spline)]
    assert len(sp) == 1 and sp[0].whole and sp[0].curve == c
    assert sp[0].spans == [c.span(i) for i in range(c.n)]


def test_cut_spline_is_the_exact_sub_piece():
    c, lp = _closed_loop()
    pv = Provenance()
    cut = Loop([Line((-100, -100), (100, -100)), Line((100, -100), (100, -30)),
                Line((100, -30), (-100, -30)), Line((-100, -30), (-100, -100))])
    loops = pv.loops(pv.face(lp) - pv.face(cut))
    assert len(loops) == 1
    segs = loops[0].segments
    kinds = sorted(type(s).__name__ for s in segs)
    assert kinds == ["Line", "Spline"]
    sp = next(s for s in segs if isinstance(s, Spline))
    ln = next(s for s in segs if isinstance(s, Line))
    for p in (sp.start, sp.end):
        assert abs(p[1] + 30.0) <= 1e-9            # on the cut line
        assert c.distance(p) <= 1e-9               # and on the curve
    assert _dist(sp.end, ln.start) <= 1e-9 and _dist(ln.end, sp.start) <= 1e-9
    # every span of the piece is the curve itself (de Casteljau pieces, not chords)
    for b in sp.spans:
        for t in np.linspace(0, 1, 9):
            assert c.distance(bez_at(b, float(t))) <= 1e-9
    # the area is the exact area above y = -30
    S = np.array([c.at(u) for u in np.linspace(0, c.n, 400001)])
    above = S[S[:, 1] >= -30]
    assert loops[0].area > 0 and loops[0].area < Loop([Spline(c, 0, c.n)]).area
    assert len(above)


# ------------------------------------------------------------------ the language and writers
GUITAR_SRC = """units mm

solid guitar {
    body = Spline(points=[(0, -60), (38, -52), (44, -20), (26, 2), (32, 30), (18, 52),
                          (0, 56), (-18, 52), (-32, 30), (-26, 2), (-44, -20), (-38, -52)],
                  closed=true)
    hole sound {
        c = Circle(center=(0, 20), radius=12)
    }
    drawing deco {
        wave = Spline(points=[(-20, -45), (-8, -40), (0, -47), (10, -41), (20, -45)])
    }
}
"""

CUT_SRC = """units mm

solid pick {
    body = Spline(points=[(0, -30), (20, 0), (12, 20), (-12, 20), (-20, 0)], closed=true)
    hole notch {
        c = Circle(center=(20, 0), radius=5)
    }
    hole flat {
        r = Rectangle(center=(0, 25), width=60, height=10)
    }
}
"""


def _compile(src, tmp_path, name="p"):
    from aidl_lang.pipeline import compile_source
    c = compile_source(src, str(tmp_path / f"{name}.aidl"))
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    return c


def _output(src, tmp_path):
    from aidl_lang.output import build
    c = _compile(src, tmp_path)
    return build(c.drawing, c.model.root.name)


def _write(out, suffix, tmp_path):
    from aidl_lang.output import Options, encode
    p = tmp_path / f"out{suffix}"
    p.write_bytes(encode(out, suffix, Options()))
    return p


def _splines(out):
    segs = [s for p in out.parts for lp in p.loops for s in lp.segments] + \
        [s for st in out.engrave for s in st.segments]
    return [s for s in segs if isinstance(s, Spline)]


def _ours(sp, n=50):
    """Points of our exact Bézier spans at n parameters each."""
    return [bez_at(b, float(t)) for b in sp.spans for t in np.linspace(0, 1, n)]


def test_untouched_closed_spline_and_open_engraving_are_exact_in_the_output(tmp_path):
    out = _output(GUITAR_SRC, tmp_path)
    sps = _splines(out)
    assert len(sps) == 2
    body = next(s for s in sps if s.whole)
    wave = next(s for s in sps if not s.whole)
    pts = [(0, -60), (38, -52), (44, -20), (26, 2), (32, 30), (18, 52), (0, 56), (-18, 52),
           (-32, 30), (-26, 2), (-44, -20), (-38, -52)]
    ref = interpolate(pts, True)
    assert body.curve == ref                    # the program's curve, bit for bit
    assert _dist(wave.start, (-20, -45)) <= 1e-9 and _dist(wave.end, (20, -45)) <= 1e-9
    for i, p in enumerate([(-20, -45), (-8, -40), (0, -47), (10, -41), (20, -45)]):
        assert _dist(wave.curve.at(i), p) <= 1e-9
    part = out.parts[0]
    circles = [s for lp in part.loops for s in lp.segments if isinstance(s, Circle)]
    assert len(circles) == 1 and abs(circles[0].radius - 12) <= 1e-12
    assert abs(part.area - (Loop([Spline(ref, 0, ref.n)]).area - math.pi * 144)) <= 1e-9


def _dxf_splines(path):
    import ezdxf
    doc = ezdxf.readfile(str(path))
    return [e for e in doc.modelspace() if e.dxftype() == "SPLINE"]


def _eval_dxf(e, n_per_span):
    """Points of a DXF SPLINE evaluated by ezdxf from its control points and knots."""
    from ezdxf.math import BSpline
    ctrl = [(v[0], v[1]) for v in e.control_points]
    knots = list(e.knots)
    bs = BSpline(ctrl, order=e.dxf.degree + 1, knots=knots)
    distinct = sorted(set(knots))
    out = []
    for a, b in zip(distinct, distinct[1:]):
        for t in np.linspace(a, b, n_per_span):
            p = bs.point(float(t))
            out.append((p[0], p[1]))
    return out


def test_dxf_spline_reread_by_ezdxf_evaluates_to_our_beziers(tmp_path):
    out = _output(GUITAR_SRC, tmp_path)
    path = _write(out, ".dxf", tmp_path)
    ents = _dxf_splines(path)
    assert len(ents) == 2
    ours = sorted(_splines(out), key=lambda s: -len(s.spans))
    theirs = sorted(ents, key=lambda e: -len(e.control_points))
    for sp, e in zip(ours, theirs):
        assert e.dxf.degree == 3
        assert len(e.control_points) == 3 * len(sp.spans) + 1
        a, b = _ours(sp), _eval_dxf(e, 50)
        assert len(a) == len(b)
        assert max(_dist(p, q) for p, q in zip(a, b)) <= 1e-9
    # and the curve through the program's points
    body = theirs[0]
    from ezdxf.math import BSpline
    bs = BSpline([(v[0], v[1]) for v in body.control_points], order=4, knots=list(body.knots))
    ks = sorted(set(body.knots))
    pts = [(0, -60), (38, -52), (44, -20), (26, 2), (32, 30), (18, 52), (0, 56), (-18, 52),
           (-32, 30), (-26, 2), (-44, -20), (-38, -52)]
    for k, p in zip(ks, pts):
        q = bs.point(k)
        assert _dist((q[0], q[1]), p) <= 1e-9


def _svg_cubics(path):
    """The cubic Béziers of each path of the SVG file, as functions t -> model point (mm):
    the view transform made the identity as in tests/exact_geometry.py (width and height
    in user units), the viewBox corner moved back and the y flip undone."""
    import io
    import xml.etree.ElementTree as ET
    import svgelements as se
    ET.register_namespace("", "http://www.w3.org/2000/svg")
    root = ET.parse(str(path)).getroot()
    vb = root.get("viewBox").replace(",", " ").split()
    root.set("width", vb[2])
    root.set("height", vb[3])
    svg = se.SVG.parse(io.StringIO(ET.tostring(root, encoding="unicode")), reify=True)
    vx, vy = float(vb[0]), float(vb[1])
    out = []
    for el in svg.elements():
        if isinstance(el, se.Path):
            cub = [s for s in el if isinstance(s, se.CubicBezier)]
            if cub:
                out.append([(lambda t, c=c: (c.point(t).x + vx, -(c.point(t).y + vy)))
                            for c in cub])
    return out


def test_svg_path_reread_by_svgelements_evaluates_to_our_beziers(tmp_path):
    out = _output(GUITAR_SRC, tmp_path)
    path = _write(out, ".svg", tmp_path)
    paths = _svg_cubics(path)
    ours = sorted(_splines(out), key=lambda s: -len(s.spans))
    paths = sorted(paths, key=len, reverse=True)
    assert [len(p) for p in paths] == [len(s.spans) for s in ours]
    for sp, cubics in zip(ours, paths):
        for b, c in zip(sp.spans, cubics):
            for t in np.linspace(0, 1, 25):
                assert _dist(bez_at(b, float(t)), c(float(t))) <= 1e-9


def test_cut_spline_comes_out_as_exact_pieces_in_every_writer(tmp_path):
    out = _output(CUT_SRC, tmp_path)
    sps = _splines(out)
    assert len(sps) == 2 and not any(s.whole for s in sps)
    pts = [(0, -30), (20, 0), (12, 20), (-12, 20), (-20, 0)]
    ref = interpolate(pts, True)
    for s in sps:
        assert s.curve == ref
        for p in _ours(s, 20):
            assert ref.distance(p) <= 1e-9       # every point of the pieces on the curve
    ends = [p for s in sps for p in (s.start, s.end)]
    on_circle = [p for p in ends if abs(math.hypot(p[0] - 20, p[1]) - 5) <= 1e-9]
    on_flat = [p for p in ends if abs(p[1] - 20) <= 1e-9]
    assert len(on_circle) == 2 and len(on_flat) == 2
    # DXF: the pieces are SPLINE entities equal to our pieces
    ents = _dxf_splines(_write(out, ".dxf", tmp_path))
    assert len(ents) == 2
    for e in ents:
        a = _eval_dxf(e, 20)
        match = [s for s in sps if len(s.spans) * 20 == len(a) and
                 max(_dist(p, q) for p, q in zip(_ours(s, 20), a)) <= 1e-9]
        assert match


@pytest.mark.step
def test_step_holds_bspline_curves(tmp_path):
    """The STEP file, re-read by OCP: the body's edges are B-spline curves whose every
    point lies on the program's spline (5e-12 mm seen)."""
    pytest.importorskip("OCP")
    out = _output(GUITAR_SRC, tmp_path)
    data = _write(out, ".step", tmp_path).read_text()
    assert "B_SPLINE_CURVE_WITH_KNOTS" in data
    from exact_geometry import step_edge_points
    ref = interpolate(GUITAR, True)
    pts = step_edge_points(tmp_path / "out.step", 200, bsplines_only=True)
    assert len(pts) >= 201 and max(ref.distance(q) for q in pts) <= 1e-9


def test_open_spline_closed_by_a_line_is_a_face(tmp_path):
    src = """units mm
solid tab {
    top = Spline(points=[(-20, 0), (-10, 8), (0, 10), (10, 8), (20, 0)])
    bottom = Line(start=top.end, end=top.start)
}
"""
    out = _output(src, tmp_path)
    segs = out.parts[0].loops[0].segments
    assert sorted(type(s).__name__ for s in segs) == ["Line", "Spline"]
    c = interpolate([(-20, 0), (-10, 8), (0, 10), (10, 8), (20, 0)], False)
    assert abs(out.parts[0].area - abs(Loop([Spline(c, 0, c.n), Line((20, 0), (-20, 0))]).area)) <= 1e-9


def test_spline_points_are_members_and_the_box_is_exact(tmp_path):
    src = """units mm
solid s {
    body = Spline(points=[(0, 0), (30, 0), (30, 20), (0, 20)], closed=true)
    dot = Circle(center=body.points[2], radius=1)
    assert body.bb.right > 30.5
}
"""
    c = _compile(src, tmp_path)
    from aidl_lang.geometry.relations.bbox import numeric_box
    body = next(g for g in c.model.root.geometry if g.kind == "Spline")
    left, right, bottom, top = numeric_box(body, c.model.root, c.model.xs())
    ref = interpolate([(0, 0), (30, 0), (30, 20), (0, 20)], True).box()
    assert abs(left - ref[0]) <= 1e-9 and abs(right - ref[2]) <= 1e-9
    assert abs(bottom - ref[1]) <= 1e-9 and abs(top - ref[3]) <= 1e-9


def _diag(src, tmp_path):
    from aidl_lang.pipeline import compile_source
    c = compile_source(src, str(tmp_path / "bad.aidl"))
    assert not c.ok
    return [d for d in c.sink.items if d.severity == "error"]


@pytest.mark.parametrize("call, words", [
    ("Spline(points=[(0, 0), (10, 0)], closed=true)", "at least 3 points"),
    ("Spline(points=[(0, 0), (10, 0), (10, 0), (0, 9)], closed=true)",
     "points[1] and points[2] are the same point"),
    ("Spline(points=[(0, 0), 5, (10, 10)])", "point"),
    ("Spline(points=[(0, 0)])", "at least 2 points"),
])
def test_bad_input_is_a_located_diagnostic(tmp_path, call, words):
    src = f"units mm\nsolid s {{\n    body = {call}\n}}\n"
    errs = _diag(src, tmp_path)
    assert errs, src
    d = errs[0]
    assert words in d.message, d.message
    assert d.span is not None and d.span.line == 3 and d.span.col >= 5
    assert "Traceback" not in d.message and "internal" not in d.message


def test_offset_of_a_spline_within_the_bound_and_its_hull_refused(tmp_path):
    """`Offset` of a Spline (once refused: the offset of a cubic is no cubic; run ae's cat
    scratcher drew the grown outline by hand, 9.4 mm where 10 was meant): the spline followed
    by arcs within 1e-4 mm, offset exactly, so the outline lies 2 mm off the curve, +- 1e-4.
    Its `Hull` is refused at the call."""
    from aidl_lang.geometry.shapes.curves import Arc
    src = ("units mm\nsolid s {\n    body = Spline(points=[(0, 0), (30, 0), (30, 20)], "
           "closed=true, construction=true)\n    grown = Offset(body, 2)\n}\n")
    out = _output(src, tmp_path)
    curve = interpolate([(0, 0), (30, 0), (30, 20)], True)
    (lp,) = out.parts[0].loops
    d = [curve.distance(g.at(g.start_angle + g.sweep * i / 6)) for g in lp.segments
         if isinstance(g, Arc) for i in range(7)]
    assert len(d) > 50 and 2 - 1e-4 < min(d) and max(d) < 2 + 1e-4
    errs = _diag(src.replace("Offset(body, 2)", "Hull([body])"), tmp_path)
    assert errs[0].span.line == 4 and "Spline cannot be exact" in errs[0].message


def test_synonyms_map_to_spline(tmp_path):
    src = ("units mm\nsolid s {\n    body = BSpline(through=[(0, 0), (30, 0), (30, 20)], "
           "periodic=true)\n}\n")
    out = _output(src, tmp_path)
    assert _splines(out) and _splines(out)[0].whole


def test_fillet_at_a_spline_corner_is_a_located_refusal(tmp_path):
    src = """units mm
solid pick {
    body = Spline(points=[(0, -30), (20, 0), (0, 20), (-20, 0)], closed=true)
    hole notch {
        c = Circle(center=(20, 0), radius=5)
    }
    Fillet(1)
}
"""
    errs = _diag(src, tmp_path)
    assert [d.code for d in errs] == ["E0407"]
    d = errs[0]
    assert d.span.line == 3 and d.span.col == 12
    assert "Fillet cannot round the corner" in d.message and "at=" in d.hint


def test_kerf_on_a_spline_part_follows_the_offset_within_the_bound(tmp_path):
    """A kerf on a part with a spline (once refused: the offset of a cubic is no cubic): the
    spline is followed by circular arcs within 1e-4 mm (biarc.BIARC_TOL), which are offset
    exactly, so every point of the cut path lies half the kerf from the spline, +- 1e-4."""
    import math
    from aidl_lang.geometry.shapes.curves import Arc, Line
    from aidl_lang.output import build
    from aidl_lang.output.fabrication.layout import compensate
    src = ("units mm\nsolid pick {\n    body = Spline(points=[(0, -30), (20, 0), (0, 20), "
           "(-20, 0)], closed=true)\n}\n")
    c = _compile(src, tmp_path)
    out = build(c.drawing, c.model.root.name)
    cut = compensate(out, 0.2)
    curve = interpolate([(0, -30), (20, 0), (0, 20), (-20, 0)], True)
    (lp,) = cut.parts[0].loops
    assert all(isinstance(g, (Arc, Line)) for g in lp.segments) and len(lp.segments) > 8
    d = [curve.distance(g.at(g.start_angle + g.sweep * i / 8) if isinstance(g, Arc) else
                        (g.start[0] + (g.end[0] - g.start[0]) * i / 8,
                         g.start[1] + (g.end[1] - g.start[1]) * i / 8))
         for g in lp.segments for i in range(9)]
    assert min(d) > 0.1 - 1e-4 and max(d) < 0.1 + 1e-4
    assert lp.area > out.parts[0].loops[0].area            # outward: the part grew
    assert math.isclose(lp.area - out.parts[0].loops[0].area,
                        0.1 * curve.length(), rel_tol=0.01)   # a band 0.1 mm wide


def test_union_of_two_splines_and_a_spline_hole(tmp_path):
    src = """units mm
solid s {
    a = Spline(points=[(0, 0), (30, -5), (40, 15), (10, 20)], closed=true)
    b = Spline(points=[(25, 5), (60, 0), (55, 30), (30, 25)], closed=true)
    hole h {
        c = Spline(points=[(5, 5), (15, 3), (12, 12)], closed=true)
    }
}
"""
    out = _output(src, tmp_path)
    loops = out.parts[0].loops
    ca = interpolate([(0, 0), (30, -5), (40, 15), (10, 20)], True)
    cb = interpolate([(25, 5), (60, 0), (55, 30), (30, 25)], True)
    ch = interpolate([(5, 5), (15, 3), (12, 12)], True)
    outer = [lp for lp in loops if lp.area > 0]
    holes = [lp for lp in loops if lp.area < 0]
    assert len(outer) == 1 and len(holes) == 1
    # the hole: the whole spline, run clockwise
    (hs,) = holes[0].segments
    assert isinstance(hs, Spline) and hs.whole and hs.curve == ch
    # the outline: pieces of a and b meeting exactly where the curves cross
    segs = outer[0].segments
    assert all(isinstance(s, Spline) for s in segs) and {s.curve for s in segs} == {ca, cb}
    for s, t in zip(segs, segs[1:] + segs[:1]):
        assert _dist(s.end, t.start) <= 1e-9
        assert ca.distance(s.end) <= 1e-9 and cb.distance(s.end) <= 1e-9
    # the area: by the pieces' exact integrals, and the polygon area agrees to the chords
    sh = out.drawing.parts[0].shape.area()
    assert abs(out.parts[0].area - sh) <= 0.005 * (ca.length() + cb.length() + ch.length())


@settings(max_examples=25, deadline=None)
@given(st.floats(-50, 45), st.floats(-1.2, 1.2))
def test_law_a_line_cut_gives_pieces_of_the_curve_ending_on_the_line(y0, slope):
    """Law: a closed spline cut by a half-plane comes back as pieces of the same curve whose
    ends lie on the cutting line and on the curve (1e-9 mm), joined by that line."""
    c, lp = _closed_loop()
    ux, uy = 1 / math.hypot(1, slope), slope / math.hypot(1, slope)
    # a big quadrilateral below the line y = y0 + slope x
    far = 500.0
    p0 = (-far, y0 - slope * far)
    p1 = (far, y0 + slope * far)
    box = Loop([Line(p0, (-far, -far)), Line((-far, -far), (far, -far)), Line((far, -far), p1),
                Line(p1, p0)])
    pv = Provenance()
    loops = pv.loops(pv.face(lp) - pv.face(box))
    for L in loops:
        for s in L.segments:
            if isinstance(s, Spline):
                assert s.curve == c
                for p in _ours(s, 5):
                    assert c.distance(p) <= 1e-9
            else:
                assert isinstance(s, Line)
                for p in (s.start, s.end):
                    # on the cutting line
                    assert abs(ux * (p[1] - p0[1]) - uy * (p[0] - p0[0])) <= 1e-9
                    assert c.distance(p) <= 1e-9
        for s, t in zip(L.segments, L.segments[1:] + L.segments[:1]):
            assert _dist(s.end, t.start) <= 1e-9


def test_points_moved_together_by_the_solve_are_a_located_error(tmp_path):
    src = """units mm
solid s {
    body = Spline(points=[(0, 0), (30, 0), (30, 20), (0, 20)], closed=true, flexible=true)
    Coincident(body.points[1], body.points[2])
}
"""
    errs = _diag(src, tmp_path)
    assert [d.code for d in errs] == ["E0108"] and errs[0].span.line == 3
    assert "after the solve" in errs[0].message and "points[1] and points[2]" in errs[0].message


def test_mirrored_spline_is_the_mirror_image(tmp_path):
    src = """units mm
solid s {
    half = Spline(points=[(5, 0), (20, 5), (25, 20), (10, 30)], closed=true)
    axis = Line((0, -10), (0, 40), construction=true)
    Mirrored(half, about=axis)
}
"""
    out = _output(src, tmp_path)
    sps = _splines(out)
    assert len(sps) == 2 and all(s.whole for s in sps)
    a, b = sps
    for u in np.linspace(0, a.curve.n, 41):
        p = a.curve.at(float(u))
        assert b.curve.distance((-p[0], p[1])) <= 1e-9


_DENSE = None


@settings(max_examples=40, deadline=None)
@given(st.floats(-80, 80), st.floats(-90, 90))
def test_law_the_foot_is_the_nearest_point(x, y):
    """Law: no point of the curve is nearer to p than its foot (against 120,000 samples)."""
    global _DENSE
    c = interpolate(GUITAR, True)
    if _DENSE is None:
        _DENSE = np.array([c.at(float(u)) for u in np.linspace(0, c.n, 120001)])
    d = c.distance((x, y))
    dense = float(np.hypot(_DENSE[:, 0] - x, _DENSE[:, 1] - y).min())
    assert d <= dense + 1e-9
    assert dense - d <= 0.01          # the samples are at most ~2.5 um apart


def test_a_closed_spline_that_crosses_itself_is_a_located_error(tmp_path):
    src = ("units mm\nsolid s {\n    body = Spline(points=[(0, 0), (20, 15), (40, 0), (40, 15), "
           "(20, 0), (0, 15)], closed=true)\n}\n")
    errs = _diag(src, tmp_path)
    assert [d.code for d in errs] == ["E0108"] and errs[0].span.line == 3
    assert "crosses itself at (9.24204, 7.5)" in errs[0].message
    from aidl_lang.geometry.shapes.spline import self_crossings
    c = interpolate([(0, 0), (20, 15), (40, 0), (40, 15), (20, 0), (0, 15)], True)
    cross = self_crossings(c)
    assert len(cross) == 2                       # a pretzel: it crosses itself twice
    for u, v in cross:                           # on its mirror line y = 7.5
        assert _dist(c.at(u), c.at(v)) <= 1e-9 and abs(c.at(u)[1] - 7.5) <= 1e-9
    assert self_crossings(interpolate(GUITAR, True)) == []


def test_a_spline_that_doubles_back_is_E0108_after_bounded_work(tmp_path):
    """Points that double back make spans that lie on each other: the subdivision search
    stopped after MAX_LEAVES small boxes per span pair (it took 28 s / 90 s before), and
    the compile's deadline stops it too."""
    from aidl_lang.geometry.shapes import spline as sp
    back = [(0, 0), (10, 0), (0, 0), (10, 0), (0, 0), (10, 0), (0, 0), (10, 0), (0, 0), (5, 5)]
    src = f"units mm\nsolid s {{\n    body = Spline(points={back}, closed=true)\n}}\n"
    errs = _diag(src, tmp_path)
    assert [d.code for d in errs] == ["E0108"] and errs[0].span.line == 3
    c = interpolate(back, True)
    calls = []
    cross = sp.self_crossings(c, lambda: calls.append(1))
    assert all(_dist(c.at(u), c.at(v)) <= 1e-6 and v - u >= 1 for u, v in cross)
    assert (0.0, 2.0) in [(round(u, 6), round(v, 6)) for u, v in cross]  # (0, 0), twice
    pairs = int(np.triu(np.ones((c.n, c.n)), 1).sum())
    # every span pair stops at MAX_LEAVES leaves, so at most ~(40 + 4) x MAX_LEAVES boxes
    assert 0 < len(calls) <= pairs * 44 * sp.MAX_LEAVES // 4096

    class Stop(Exception):
        pass

    def stop():
        raise Stop

    with pytest.raises(Stop):                    # the deadline's check ends the search
        sp.self_crossings(c, stop)


def test_an_open_spline_returning_to_its_start_is_a_face(tmp_path):
    src = ("units mm\nsolid s {\n    body = Spline(points=[(0, 0), (20, 15), (40, 0), "
           "(20, -15), (0, 0)])\n}\n")
    out = _output(src, tmp_path)
    (lp,) = out.parts[0].loops
    (s,) = lp.segments
    c = interpolate([(0, 0), (20, 15), (40, 0), (20, -15), (0, 0)], False)
    assert isinstance(s, Spline) and s.curve == c and lp.area > 0
    assert abs(lp.area - abs(Loop([Spline(c, 0, c.n)]).area)) <= 1e-9



def test_a_closed_bezier_through_cusps_is_no_crossing():
    """ezdxf's no_layouts.dxf draws polylines as cubics with zero-length handles at every
    corner: the curve stops there and turns. The self-crossing search took each such corner for
    a crossing (E0108 "crosses itself" on both outlines), and the importer cut the chains in
    pieces to get past it; a crossing leaves the point and comes back, a cusp does not."""
    from pathlib import Path
    from aidl_lang.pipeline import compile_source
    f = Path(__file__).parent / "data" / "cusped_bezier.aidl"
    c = compile_source(f.read_text(), str(f))
    assert c.ok and not [d for d in c.sink.items if d.code == "E0108"], \
        [d.message for d in c.sink.items]
    eight = ("solid s {\n    b = Bezier(points=[(0, 0), (10, 10), (10, -10), (0, 0), (-10, 10), "
             "(-10, -10), (0, 0)], closed=true)\n}\n")
    c = compile_source(eight, "eight.aidl")
    assert [d.code for d in c.sink.items if d.is_error] == ["E0108"]
    assert "crosses itself at (0, 0)" in c.sink.items[0].message


def test_curves_that_run_along_each_other_start_few_newton_polishes(monkeypatch):
    """Two cubics within 1e-4 mm of each other along 30 mm (a curve drawn back over another,
    as Boxes.py's burn-corrected end caps along a fan blade's edge): the box halving leaves
    2,048 small box pairs along the stretch and each was polished by Newton (FanHole's import:
    9.3 of its 10.2 s CPU in crossings); 33 of them, evenly along, still find the crossing."""
    import aidl_lang.geometry.shapes.spline as S
    line = [(0, 0), (10, 10 / 3), (20, 20 / 3), (30, 10)]           # y = x / 3
    a = S.bezier_chain(line)
    b = S.bezier_chain([(x, y + e) for (x, y), e in zip(line, (-1e-4, 4e-5, 4e-5, 1e-4))])
    calls = []
    newton = S.newton2
    monkeypatch.setattr(S, "newton2", lambda *x, **k: calls.append(1) or newton(*x, **k))
    found = a.cross_spline(b)
    assert len(calls) == S.RUN_SEEDS + 1                  # was 2,048
    assert len(found) == 1
    (u, v), = found
    # b is a lifted by -1e-4 (1-t)^3 + 1.2e-4 (1-t)^2 t + 1.2e-4 (1-t) t^2 + 1e-4 t^3: it
    # crosses where that is 0, on the line
    t = v % 1
    lift = -1e-4 * (1 - t) ** 3 + 1.2e-4 * (1 - t) ** 2 * t + 1.2e-4 * (1 - t) * t * t \
        + 1e-4 * t ** 3
    x, y = b.at(v)
    assert abs(lift) < 1e-12 and abs(y - x / 3) < 1e-12 and math.dist(a.at(u), (x, y)) < 1e-9
