"""Exact curves (aidl_lang/geometry/shapes/curves.py) and provenance (aidl_lang/output/part/edges/exact.py):
carriers meet where both say, and a boolean's result goes back onto the exact curves.

The laws: an intersection lies on both carriers; every output loop of a union or cut of
circles, slots and rectangles is closed, each vertex lies on the two curves that meet there,
no edge is left unexplained and no segment is shorter than 1e-9 mm; the exact area is within
the chords' sagitta of Manifold's polygon area."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from aidl_lang.geometry.shapes.curves import (Arc, Circle, Line, carrier, distance_to, intersect,
                                       tangent_at, turn_between)
from aidl_lang.output.part.part import build
from aidl_lang.pipeline import compile_source

coord = st.floats(-100, 100, allow_nan=False)
radius = st.floats(0.5, 60, allow_nan=False)
angle = st.floats(0, 2 * math.pi, allow_nan=False)


@settings(max_examples=300, deadline=None)
@given(coord, coord, angle, coord, coord, radius)
def test_line_circle_meet_on_both(px, py, th, cx, cy, r):
    ln = ("L", px, py, math.cos(th), math.sin(th))
    c = ("C", cx, cy, r)
    d = abs(math.cos(th) * (cy - py) - math.sin(th) * (cx - px))
    if d > r * (1 - 1e-6):
        return                                      # apart or touching: not a crossing
    p = intersect(ln, c, (cx, cy))
    assert distance_to(ln, p) <= 1e-9 * max(1.0, abs(px) + abs(cx))
    assert distance_to(c, p) <= 1e-9 * max(1.0, abs(px) + abs(cx))


@settings(max_examples=300, deadline=None)
@given(coord, coord, radius, coord, coord, radius)
def test_circle_circle_meet_on_both(x1, y1, r1, x2, y2, r2):
    D = math.hypot(x2 - x1, y2 - y1)
    if not abs(r1 - r2) * (1 + 1e-6) < D < (r1 + r2) * (1 - 1e-6):
        return
    a, b = ("C", x1, y1, r1), ("C", x2, y2, r2)
    p = intersect(a, b, (x1, y1))
    scale = max(1.0, abs(x1) + abs(x2) + r1 + r2)
    assert distance_to(a, p) <= 1e-9 * scale and distance_to(b, p) <= 1e-9 * scale


def test_tangent_carriers_meet_at_the_touching_point():
    # a line 5 mm above a circle's center touches the circle of radius 5 at (3, 5)
    p = intersect(("L", -10.0, 5.0, 1.0, 0.0), ("C", 3.0, 0.0, 5.0), (0.0, 0.0))
    assert p == pytest.approx((3.0, 5.0), abs=1e-12)
    # two circles touching from outside, and one inside another
    assert intersect(("C", 0.0, 0.0, 2.0), ("C", 5.0, 0.0, 3.0), (0, 0)) == \
        pytest.approx((2.0, 0.0), abs=1e-12)
    assert intersect(("C", 0.0, 0.0, 5.0), ("C", 2.0, 0.0, 3.0), (0, 0)) == \
        pytest.approx((5.0, 0.0), abs=1e-12)


def test_turn_and_tangent_directions():
    a = Line((0.0, 0.0), (10.0, 0.0))
    arc = Arc((10.0, 5.0), 5.0, -math.pi / 2, math.pi)     # ccw half circle from (10, 0)
    assert tangent_at(arc, False) == pytest.approx((1.0, 0.0), abs=1e-15)
    assert abs(turn_between(a, arc)) < 1e-15
    assert turn_between(arc, Line((10.0, 10.0), (0.0, 10.0))) == pytest.approx(0.0, abs=1e-15)
    assert turn_between(a, Line((10.0, 0.0), (10.0, 5.0))) == pytest.approx(math.pi / 2)


# ---------------------------------------------------------------- provenance laws
def _carrier_dist(seg, p) -> float:
    return distance_to(carrier(seg), p)


def _shape(kind: str, x: float, y: float, size: float, rot: float) -> str:
    if kind == "circle":
        return f"Circle(center=({x:.4f}, {y:.4f}), radius={size:.4f})"
    if kind == "slot":
        return (f"Slot(center=({x:.4f}, {y:.4f}), length={3 * size:.4f}, width={size:.4f}, "
                f"rotation={rot:.4f} deg)")
    if kind == "rounded":
        return (f"RoundedRectangle(center=({x:.4f}, {y:.4f}), width={3 * size:.4f}, "
                f"height={2 * size:.4f}, corner_radius={size:.4f}, rotation={rot:.4f} deg)")
    return (f"Rectangle(center=({x:.4f}, {y:.4f}), width={2 * size:.4f}, height={size:.4f}, "
            f"rotation={rot:.4f} deg)")


shape_st = st.tuples(st.sampled_from(["circle", "slot", "rounded", "rect"]),
                     st.floats(-20, 20), st.floats(-20, 20), st.floats(1, 12),
                     st.floats(0, 360))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(shape_st, min_size=1, max_size=4), st.lists(shape_st, max_size=3),
       st.sampled_from([0.0, 0.45]))   # below every shape radius (slots: size / 2 >= 0.5)
def test_union_and_cut_loops_lie_on_the_exact_curves(solids, holes, fillet):
    body = "\n".join(f"    f{i} = {_shape(*s)}" for i, s in enumerate(solids))
    cuts = "\n".join(f"    hole h{i} {{ g = {_shape(*s)} }}" for i, s in enumerate(holes))
    fin = f"    Fillet(radius={fillet})\n" if fillet else ""
    src = f"solid part {{\n{body}\n{cuts}\n{fin}}}\n"
    c = compile_source(src, "t.aidl")
    assert c.drawing is not None, [d.message for d in c.sink.items]
    o = build(c.drawing)
    assert c.drawing.exact.unmatched == 0, src
    for p in o.parts:
        manifold_area = p.shape.area() if p.shape is not None else None
        exact_area = sum(lp.area for lp in p.loops)
        for lp in p.loops:
            S = lp.segments
            if len(S) == 1:
                assert isinstance(S[0], Circle)
                continue
            for i, s in enumerate(S):
                a = S[i - 1]
                assert math.dist(a.end, s.start) <= 1e-9, src
                assert s.length > 1e-9, src
                v = s.start
                assert _carrier_dist(a, v) <= 1e-9 and _carrier_dist(s, v) <= 1e-9, src
                if fillet and isinstance(s, Arc) and abs(s.radius - fillet) < 1e-6:
                    # a fillet arc is tangent to both neighbours
                    assert abs(turn_between(a, s)) < 1e-9, src
                    assert abs(turn_between(s, S[(i + 1) % len(S)])) < 1e-9, src
        # the exact area differs from the chords' polygon by at most the sagitta strips
        perimeter = sum(lp.perimeter for lp in p.loops)
        assert abs(exact_area - manifold_area) <= 0.006 * perimeter + 1e-6, src


def test_a_slot_is_two_lines_and_two_half_circles():
    src = ("solid p {\n    r = Rectangle(center=(0, 0), width=60, height=30)\n"
           "    hole s { g = Slot(center=(0, 0), length=24, width=5.5, rotation=0 deg) }\n}\n")
    o = build(compile_source(src, "t.aidl").drawing)
    (hole,) = [lp for lp in o.parts[0].loops if lp.area < 0]
    lines = [s for s in hole.segments if isinstance(s, Line)]
    arcs = [s for s in hole.segments if isinstance(s, Arc)]
    assert len(lines) == 2 and len(arcs) == 2
    assert sorted(abs(s.start[1]) for s in lines) == pytest.approx([2.75, 2.75], abs=1e-12)
    assert sorted(abs(x) for s in lines for x in (s.start[0], s.end[0])) == \
        pytest.approx([9.25] * 4, abs=1e-12)
    assert [abs(a.sweep) for a in arcs] == pytest.approx([math.pi, math.pi], abs=1e-12)
    assert [a.radius for a in arcs] == pytest.approx([2.75, 2.75], abs=1e-15)


def test_segment_boxes_are_the_design_numbers():
    """Every segment kind has one exact ``box()`` (geometry/shapes/curves.py), which the extent, the
    PDF tiles, the layout, ``--describe`` and the drawing readers all use."""
    from aidl_lang.geometry.shapes.curves import Arc, Circle, Line
    assert Line((3, -1), (-2, 4)).box() == (-2, -1, 3, 4)
    assert Circle((1, 2), 5).box() == (-4, -3, 6, 7)
    assert Arc((0, 0), 5, 0.0, math.pi).box() == (-5.0, 0.0, 5.0, 5.0)          # upper half
    assert Arc((0, 0), 5, math.pi, -math.pi).box() == (-5.0, 0.0, 5.0, 5.0)     # the same, clockwise
    assert Arc((10, 0), 2, -0.25, 0.5).box()[2] == 12.0                         # through 0 degrees
    assert Arc((0, 0), 1, 0.0, 2 * math.pi).box() == (-1, -1, 1, 1)


@settings(max_examples=200, deadline=None)
@given(st.floats(-3 * math.pi, 3 * math.pi), st.floats(-2 * math.pi, 2 * math.pi).filter(lambda v: abs(v) > 1e-6),
       st.floats(0.01, 100))
def test_an_arc_box_holds_every_point_of_the_arc_and_no_more(a0, sweep, r):
    """The box holds 2,001 points along the arc and each of its sides is touched by one of
    them (within the spacing's sagitta)."""
    from aidl_lang.geometry.shapes.curves import Arc
    arc = Arc((1.5, -2.0), r, a0, sweep)
    x0, y0, x1, y1 = arc.box()
    t = a0 + sweep * np.linspace(0, 1, 2001)
    xs, ys = 1.5 + r * np.cos(t), -2.0 + r * np.sin(t)
    eps = 1e-12 * (1 + r)
    assert xs.min() >= x0 - eps and xs.max() <= x1 + eps
    assert ys.min() >= y0 - eps and ys.max() <= y1 + eps
    gap = r * (1 - math.cos(abs(sweep) / 2000)) + eps
    assert xs.min() <= x0 + gap and xs.max() >= x1 - gap
    assert ys.min() <= y0 + gap and ys.max() >= y1 - gap
