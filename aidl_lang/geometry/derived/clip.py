"""Open curves clipped to an area (``Intersect(lines, shape)``): a racket's strings trimmed to
its head.

Each line or arc is cut where it crosses the area's outline (the exact crossings of the two
carriers, :func:`~.curves.crossings`: lines, circles, ellipses, splines), and a piece is kept
when its middle lies inside the outline (even-odd over the loops' fine polygons, which the
middle of a piece between two crossings never touches).  Every kept piece lies on its own
carrier and ends exactly on the outline.  Lengths in mm.
"""
from __future__ import annotations

import math

from ..shapes.curves import Arc, Line, carrier, crossings, with_ends

EPS = 1e-9          # relative: a crossing this near a segment's end is on it


def _angle_in(a: float, start: float, sweep: float, tol: float) -> bool:
    d = (a - start) % (2 * math.pi) if sweep > 0 else (start - a) % (2 * math.pi)
    return d <= abs(sweep) + tol or d >= 2 * math.pi - tol


def on_segment(s, p, tol: float | None = None) -> bool:
    """True when ``p`` (a point of ``s``'s carrier) lies within segment ``s``."""
    from ..shapes.curves import Circle, EllipticArc
    scale = max(1.0, abs(p[0]), abs(p[1]))
    tol = EPS * scale if tol is None else tol
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        L2 = (x1 - x0) ** 2 + (y1 - y0) ** 2
        if L2 == 0:
            return False
        u = ((p[0] - x0) * (x1 - x0) + (p[1] - y0) * (y1 - y0)) / L2
        return -tol / math.sqrt(L2) <= u <= 1 + tol / math.sqrt(L2)
    if isinstance(s, Circle):
        return True
    if isinstance(s, Arc):
        a = math.atan2(p[1] - s.center[1], p[0] - s.center[0])
        return _angle_in(a, s.start_angle, s.sweep, tol / max(s.radius, 1e-300))
    if isinstance(s, EllipticArc):
        if s.whole:
            return True
        return _angle_in(s.curve.param(p), s.start_param, s.sweep, tol / s.curve.ry)
    return True                     # a spline's crossings are points of the spline piece


def along(s, p) -> float:
    """How far along ``s`` its point ``p`` lies (any monotone measure)."""
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        return (p[0] - x0) * (x1 - x0) + (p[1] - y0) * (y1 - y0)
    a = math.atan2(p[1] - s.center[1], p[0] - s.center[0])
    d = (a - s.start_angle) % (2 * math.pi) if s.sweep > 0 else (s.start_angle - a) % (2 * math.pi)
    return d if d <= abs(s.sweep) + 1e-12 else d - 2 * math.pi


def midpoint(s):
    if isinstance(s, Line):
        return ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2)
    return s.at(s.start_angle + s.sweep / 2)


def inside(polys, p) -> bool:
    """Even-odd test of ``p`` against the closed polygons ``polys`` (arrays of points)."""
    x, y = p
    odd = False
    for pts in polys:
        n = len(pts)
        for i in range(n):
            x0, y0 = pts[i - 1]
            x1, y1 = pts[i]
            if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
                odd = not odd
    return odd


def clip(segments: list, loops: list) -> list:
    """The pieces of ``segments`` (open :class:`~.curves.Line` and :class:`~.curves.Arc`)
    inside the area bounded by ``loops`` (:class:`~.curves.Loop`, holes included), in order,
    each on its segment's carrier, cut exactly where it crosses the outline."""
    bounds = [b for lp in loops for b in lp.segments]
    polys = [lp.points(1e-4) for lp in loops]
    out: list = []
    for seg in segments:
        cuts = [seg.start, seg.end]
        for b in bounds:
            for p in crossings(carrier(seg), carrier(b)):
                if on_segment(seg, p) and on_segment(b, p):
                    cuts.append(p)
        cuts.sort(key=lambda p: along(seg, p))
        for p, q in zip(cuts, cuts[1:]):
            if math.dist(p, q) <= EPS * max(1.0, abs(p[0]), abs(p[1])):
                continue
            piece = with_ends(seg, p, q)
            if isinstance(piece, Arc) and piece.sweep == 0:
                continue
            if inside(polys, midpoint(piece)):
                out.append(piece)
    return out
