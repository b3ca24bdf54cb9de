"""Spline: the interpolating cubic spline through points (aidl_lang/geometry/spline.py), its
exact segment in the output model, and `Spline(points=[...], closed=true)` in the language.

Numbers are checked against the definition (passes through the points, C2 joins, natural
ends), against independent readers (ezdxf evaluates the DXF SPLINE, svgelements the SVG path)
and against each other (de Casteljau halves, bounding box vs tessellation)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from aidl_lang.geometry.curves import Circle, Line, Loop, Spline, reverse, simplify
from aidl_lang.geometry.spline import (SplineError, bez_at, bez_box, bez_pieces, interpolate,
                                       split)
from aidl_lang.output.exact import Provenance

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
    from aidl_lang.geometry.tessellate import CHORD_TOL
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
