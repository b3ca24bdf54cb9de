"""Exact outlines of shapes: the lines, arcs and spline pieces the booleans are made from.

In: a shape's solved points and dimensions (mm, radians; points as ``(x, y)`` tuples or
arrays).  Out: the exact segments of its outline (:mod:`aidl_lang.geometry.shapes.curves`: ``Line``,
``Arc``, ``Circle``, ``Spline``), counter-clockwise, each join exact (a slot's sides meet its
end arcs at their tangent points, a rounded rectangle's lines end where its quarter arcs do),
or a :class:`~aidl_lang.geometry.shapes.curves.Loop` of them.  The renderer (:mod:`.booleans`) makes
Manifold shapes of these loops and records which curve every chord came from (:mod:`.exact`).
A Stroke's band along a spline is within :data:`STROKE_TOL` of its true sides (the offset of
a cubic is no cubic); every other outline here is exact.
"""
from __future__ import annotations

import math

import numpy as np

from ....geometry.shapes.curves import Arc, Circle, Line, Loop, Spline, reverse, simplify


def _arc_through(c, s, e) -> Arc:
    """The arc about ``c`` counter-clockwise from ``s`` (its radius: the distance to ``s``)
    to the direction of ``e`` (a whole turn when they point the same way)."""
    r = math.hypot(s[0] - c[0], s[1] - c[1])
    a1 = math.atan2(s[1] - c[1], s[0] - c[0])
    a2 = math.atan2(e[1] - c[1], e[0] - c[0])
    sweep = (a2 - a1) % (2 * math.pi)
    if sweep < 1e-12:
        sweep = 2 * math.pi
    return Arc(c, r, a1, sweep)


def _weld(run: list) -> list:
    """A closed chain with each line's ends moved onto its neighbours' exact ends (an arc's
    ends are where its angles put them); consecutive lines share their solved points."""
    n = len(run)
    out = list(run)
    for i in range(n):
        a, b = out[i - 1], out[i]
        if isinstance(b, Line):
            out[i] = Line(a.end, b.end) if not isinstance(a, Line) or a.end != b.start else b
        elif isinstance(a, Line):
            out[i - 1] = Line(a.start, b.start)
    return simplify(out)


def _polygon(pts) -> Loop | None:
    """The exact loop of a polygon's vertices (N x 2), repeated vertices dropped."""
    P = [(float(x), float(y)) for x, y in np.asarray(pts, dtype=float)]
    segs = [Line(P[i], P[(i + 1) % len(P)]) for i in range(len(P))]
    segs = simplify(segs, max((abs(v) for p in P for v in p), default=1.0))
    return Loop(segs) if len(segs) >= 3 else Loop([])


def slot_outline(a, b, r: float) -> list:
    """The exact outline of a slot whose end circles (radius ``r`` mm) are centred on ``a``
    and ``b``: two lines and two half circles, counter-clockwise, the lines meeting the
    arcs at their tangent points; a circle when ``a`` and ``b`` coincide."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(dx, dy)
    if L <= 1e-12 * max(1.0, abs(a[0]), abs(a[1])):
        return [Circle((a[0], a[1]), r)]
    ux, uy = dx / L, dy / L
    nx, ny = -uy, ux                        # left of a -> b
    right = math.atan2(-ny, -nx)            # the angle of -n
    p1 = (a[0] - r * nx, a[1] - r * ny)
    p2 = (b[0] - r * nx, b[1] - r * ny)
    p3 = (b[0] + r * nx, b[1] + r * ny)
    p4 = (a[0] + r * nx, a[1] + r * ny)
    return [Line(p1, p2), Arc((b[0], b[1]), r, right, math.pi), Line(p3, p4),
            Arc((a[0], a[1]), r, right + math.pi, math.pi)]


def arc_slot_outline(c, R: float, h: float, a1: float, sweep: float) -> list:
    """The exact outline of an arc slot: the center line is the counter-clockwise arc of
    radius ``R`` about ``c`` from angle ``a1`` sweeping ``sweep`` (0..2 pi); the slot is
    ``2 h`` wide: the outer arc (R + h), a half circle around the end, the inner arc (R - h)
    back, a half circle around the start; counter-clockwise, every join tangent."""
    a2 = a1 + sweep
    cx, cy = c
    end = (cx + R * math.cos(a2), cy + R * math.sin(a2))
    start = (cx + R * math.cos(a1), cy + R * math.sin(a1))
    return [Arc((cx, cy), R + h, a1, sweep), Arc(end, h, a2, math.pi),
            Arc((cx, cy), R - h, a2, -sweep), Arc(start, h, a1 + math.pi, math.pi)]


STROKE_TOL = 1e-4     # mm: how far a Stroke's side along a Spline may be from the true offset


def spline_band(sg: Spline, h: float, flat=(False, False)) -> Loop:
    """The band ``2 h`` wide along a piece of spline, counter-clockwise: its two sides are
    cubic splines through points of the true offset curves (the offset of a cubic is no
    cubic), sampled until the spline between two samples is within :data:`STROKE_TOL` of the
    true offset everywhere checked (the midpoints of the samples); the ends are half circles
    of radius ``h`` (``flat[k]``: a straight end).  Raises ``SplineError`` where the path
    bends tighter than ``h`` (the inner side would fold over itself)."""
    from ....geometry.shapes.spline import SplineError, _polish_foot, bez_at, interpolate
    c, u0, u1 = sg.curve, sg.u0, sg.u1
    span = u1 - u0

    def true_offset(u: float, side: float):
        (x, y), (tx, ty) = c.at(u), c.tangent(u)
        if u1 < u0:
            tx, ty = -tx, -ty
        return (x - side * h * ty, y + side * h * tx)
    # the tightest bend: curvature from the derivatives by arc length, sampled finely
    m = max(16, 32 * int(math.ceil(abs(span))))
    for k in range(m + 1):
        u = u0 + span * k / m
        (dx, dy), (ex, ey) = c.d1(u), c.d2(u)
        v = math.hypot(dx, dy)
        if v > 0 and abs(dx * ey - dy * ex) / v ** 3 * h >= 1.0:
            x, y = c.at(u)
            raise SplineError(f"the Spline bends tighter than half the Stroke's width "
                              f"({h:g} mm) near ({x:g}, {y:g}): the band's inner side would "
                              f"fold over itself")
    per = 4
    while True:
        N = max(2, int(math.ceil(abs(span) * per)))
        us = [u0 + span * k / N for k in range(N + 1)]
        mids = [u0 + span * (k + 0.5) / N for k in range(N)]
        sides, worst = [], 0.0
        for side in (-1.0, 1.0):                       # right side, left side
            pts = [true_offset(u, side) for u in us]
            curve = interpolate(pts, False)
            for k, um in enumerate(mids):              # halfway between two samples: the
                q = true_offset(um, side)                # fit's span k, from its middle
                b = curve.span(k)
                f = bez_at(b, _polish_foot(b, q, 0.5))
                worst = max(worst, math.dist(f, q))
            sides.append(curve)
        if worst <= STROKE_TOL or per >= 512:
            break
        per *= 2
    if worst > STROKE_TOL:
        raise SplineError(f"the Stroke along a Spline cannot be made within {STROKE_TOL:g} "
                          f"mm of its true sides (off by {worst:.2g} mm)")
    right, left = sides
    R = Spline(right, 0.0, float(right.n))
    Lf = Spline(left, float(left.n), 0.0)
    end, start = sg.end, sg.start
    segs: list = [R]
    if flat[1]:
        segs.append(Line(R.end, Lf.start))
    else:
        a = math.atan2(R.end[1] - end[1], R.end[0] - end[0])
        segs.append(Arc((end[0], end[1]), h, a, math.pi))
    segs.append(Lf)
    if flat[0]:
        segs.append(Line(Lf.end, R.start))
    else:
        a = math.atan2(Lf.end[1] - start[1], Lf.end[0] - start[0])
        segs.append(Arc((start[0], start[1]), h, a, math.pi))
    return Loop(segs)


def _band(sg, h: float) -> Loop | None:
    """The square-ended band ``2 h`` wide along one line or arc (counter-clockwise): a
    rectangle, or the annulus segment between radii R - h and R + h; None for an arc of
    radius R <= h."""
    if isinstance(sg, Line):
        (ax, ay), (bx, by) = sg.start, sg.end
        L = math.hypot(bx - ax, by - ay)
        nx, ny = -(by - ay) / L * h, (bx - ax) / L * h
        return Loop([Line((ax - nx, ay - ny), (bx - nx, by - ny)),
                     Line((bx - nx, by - ny), (bx + nx, by + ny)),
                     Line((bx + nx, by + ny), (ax + nx, ay + ny)),
                     Line((ax + nx, ay + ny), (ax - nx, ay - ny))])
    a = sg if sg.sweep > 0 else reverse(sg)
    if not a.radius > h:
        return None
    return Loop(sector_outline(a.center, a.radius + h, a.radius - h, a.start_angle, a.sweep))


def sector_outline(c, R: float, r: float, a1: float, sweep: float) -> list:
    """The exact outline of a sector: the counter-clockwise arc of radius ``R`` about ``c``
    from angle ``a1`` sweeping ``sweep`` (0..2 pi), then a radial line to the center (``r``
    0: a pie slice) or to the inner arc of radius ``r``, that arc back and a radial line out
    (an annulus segment); counter-clockwise, the lines' ends the arcs' own ends."""
    outer = Arc((c[0], c[1]), R, a1, sweep)
    if r <= 0:
        return [outer, Line(outer.end, (c[0], c[1])), Line((c[0], c[1]), outer.start)]
    inner = Arc((c[0], c[1]), r, a1 + sweep, -sweep)
    return [outer, Line(outer.end, inner.start), inner, Line(inner.end, outer.start)]


def rounded_outline(corners, r: float) -> list:
    """The exact outline of a rectangle (four corners in order, N x 2, mm) with corners of
    radius ``r``, clamped to half the shorter side: four lines and four quarter arcs,
    counter-clockwise; at half the shorter side the short lines vanish and their arcs merge
    into half circles, a square at half its side is a circle."""
    P = [np.asarray(p, dtype=float) for p in corners]
    if _shoelace(P) < 0:
        P = P[::-1]
    edges = [P[(i + 1) % 4] - P[i] for i in range(4)]
    lengths = [float(np.hypot(*e)) for e in edges]
    r = min(r, min(lengths) / 2)
    u = [e / L for e, L in zip(edges, lengths)]
    segs = []
    for i in range(4):
        j = (i + 1) % 4
        a = P[i] + r * u[i]
        b = P[j] - r * u[i]
        segs.append(Line(_t(a), _t(b)))
        c = P[j] - r * u[i] + r * u[j]                  # the corner arc's center
        a0 = math.atan2(-u[j][1], -u[j][0])             # from the edge's end, inward normal
        segs.append(Arc(_t(c), r, a0, math.pi / 2))
    # each line starts where the previous arc ends (exactly, through the same angles)
    fixed = []
    for i in range(0, 8, 2):
        prev_arc = segs[i - 1]
        fixed += [Line(prev_arc.end, segs[i + 1].start), segs[i + 1]]
    return simplify(fixed, max(abs(float(v)) for p in P for v in p))


def star_outline(points, r: float) -> list:
    """The exact outline of a Star with rounded tips: ``points`` its vertices in order (N x 2,
    mm; tips at the even indices, notches sharp at the odd ones), each tip rounded by an arc
    of radius ``r`` tangent to its two sides (the primitive checks that it leaves each side
    some line: :func:`~aidl_lang.geometry.shapes.primitives._star_tip`); lines and arcs,
    counter-clockwise, each line from the previous arc's end exactly."""
    P = [np.asarray(p, dtype=float) for p in points]
    if _shoelace(P) < 0:
        P = P[::-1]
        P = P[-1:] + P[:-1]                             # tips stay at the even indices
    n = len(P)
    arcs = []
    for i in range(0, n, 2):
        tip, a, b = P[i], P[i - 1], P[(i + 1) % n]
        ua = (a - tip) / float(np.hypot(*(a - tip)))
        ub = (b - tip) / float(np.hypot(*(b - tip)))
        half = math.acos(max(-1.0, min(1.0, float(ua @ ub)))) / 2     # half the tip's angle
        bis = (ua + ub) / float(np.hypot(*(ua + ub)))
        c = tip + bis * (r / math.sin(half))
        ta = tip + ua * (r / math.tan(half))                # where the arc leaves side a
        a0 = math.atan2(ta[1] - c[1], ta[0] - c[0])
        arcs.append(Arc(_t(c), r, a0, math.pi - 2 * half))
    segs = []
    for k, arc in enumerate(arcs):
        notch = _t(P[(2 * k + 1) % n])
        nxt = arcs[(k + 1) % len(arcs)]
        segs += [arc, Line(arc.end, notch), Line(notch, nxt.start)]
    return simplify(segs, max(abs(float(v)) for p in P for v in p))


def rounded_outline_radii(corners, radii) -> list:
    """The exact outline of a rectangle (four corners in order, mm) whose corner ``k`` is
    rounded by ``radii[k]`` (mm; 0: a sharp corner): lines and quarter arcs,
    counter-clockwise.  The radii fit their sides (the primitive checks that two radii on a
    side add up to at most its length)."""
    P = [np.asarray(p, dtype=float) for p in corners]
    R = [float(r) for r in radii]
    if _shoelace(P) < 0:
        P, R = P[::-1], R[::-1]
    u = []
    for i in range(4):
        e = P[(i + 1) % 4] - P[i]
        u.append(e / float(np.hypot(*e)))
    arcs = []                            # corner k: (arc or None, its start, its end)
    for k in range(4):
        r, a, b = R[k], u[k - 1], u[k]      # the edge into corner k, and out of it
        if r <= 0:
            p = _t(P[k])
            arcs.append((None, p, p))
            continue
        c = P[k] - r * a + r * b
        arc = Arc(_t(c), r, math.atan2(-b[1], -b[0]), math.pi / 2)
        arcs.append((arc, arc.start, arc.end))
    segs = []
    for k in range(4):
        if arcs[k][0] is not None:
            segs.append(arcs[k][0])
        segs.append(Line(arcs[k][2], arcs[(k + 1) % 4][1]))
    return simplify(segs, max(abs(float(v)) for p in P for v in p))


def _shoelace(P) -> float:
    n = len(P)
    return 0.5 * sum(P[i][0] * P[(i + 1) % n][1] - P[(i + 1) % n][0] * P[i][1] for i in range(n))


def _t(p):
    return (float(p[0]), float(p[1]))
