"""The exact area two regions share, for outlines of lines, arcs and circles (``measure``'s
``overlap_area``, issue 91: a polygon estimate said 263.7704 mm² for an exact 263.8938).

By Green's theorem the area of a region is ``1/2 * the integral of (x dy - y dx)`` around its
boundary, outer loops counter-clockwise and holes clockwise.  The boundary of ``A & B`` is made
of the pieces of A's outline that lie inside B and the pieces of B's outline that lie inside A
(an edge the two share counted once when both regions lie on its same side, not at all when
they lie on opposite sides).  :func:`shared_area` splits every segment at its crossings with
the other outline, finds which side each piece lies on by an exact ray cast (lines and arcs
crossed in closed form, no polygon), and sums the pieces' integrals, each in closed form: a
line ``p -> q`` gives ``(px qy - qx py) / 2``, an arc of centre ``c``, radius ``r`` from angle
``t0`` to ``t1`` gives ``(r^2 (t1 - t0) + cx r (sin t1 - sin t0) - cy r (cos t1 - cos t0)) /
2``.  The result is exact to rounding; outlines with splines or elliptic arcs give None (the
caller estimates instead).
"""
from __future__ import annotations

import math

from ....geometry.shapes.curves import Arc, Circle, Line, carrier, crossings

TAU = 2 * math.pi
# a direction no outline of a drawing runs along: the ray of the inside test
_RAY = (math.cos(0.7390851332), math.sin(0.7390851332))


def _arcs(loops) -> list[tuple] | None:
    """Each segment as ``("L", p, q)`` or ``("A", (cx, cy), r, t0, sweep)`` (sweep signed,
    the loop's direction kept; a circle: ``t0`` 0, sweep +-2 pi); None when a segment is
    neither a line nor an arc."""
    out = []
    for lp in loops:
        for s in lp.segments:
            if isinstance(s, Line):
                out.append(("L", tuple(map(float, s.start)), tuple(map(float, s.end))))
            elif isinstance(s, Arc):
                out.append(("A", tuple(map(float, s.center)), float(s.radius),
                            float(s.start_angle), float(s.sweep)))
            elif isinstance(s, Circle):
                out.append(("A", tuple(map(float, s.center)), float(s.radius), 0.0,
                            TAU if s.ccw else -TAU))
            else:
                return None
    return out


def _at(p: tuple, t: float) -> tuple[float, float]:
    """The point of piece ``p`` at parameter ``t`` (0..1)."""
    if p[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        return (ax + t * (bx - ax), ay + t * (by - ay))
    _, (cx, cy), r, t0, sw = p
    a = t0 + t * sw
    return (cx + r * math.cos(a), cy + r * math.sin(a))


def _param(p: tuple, x: tuple[float, float]) -> float:
    """The parameter (0..1) of the point ``x`` on piece ``p`` (its foot on the carrier)."""
    if p[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        dx, dy = bx - ax, by - ay
        L2 = dx * dx + dy * dy
        return 0.0 if L2 == 0 else ((x[0] - ax) * dx + (x[1] - ay) * dy) / L2
    _, (cx, cy), r, t0, sw = p
    a = math.atan2(x[1] - cy, x[0] - cx)
    off = (a - t0) % TAU if sw > 0 else (t0 - a) % TAU
    if abs(sw) >= TAU - 1e-15 and off > TAU - 1e-12:
        off = 0.0
    return off / abs(sw)


def _green(p: tuple, t0: float, t1: float) -> float:
    """``1/2 * integral of (x dy - y dx)`` along piece ``p`` from parameter ``t0`` to ``t1``."""
    if p[0] == "L":
        (x0, y0), (x1, y1) = _at(p, t0), _at(p, t1)
        return 0.5 * (x0 * y1 - x1 * y0)
    _, (cx, cy), r, a0, sw = p
    u, v = a0 + t0 * sw, a0 + t1 * sw
    return 0.5 * (r * r * (v - u) + cx * r * (math.sin(v) - math.sin(u))
                  - cy * r * (math.cos(v) - math.cos(u)))


def _ray_hits(p: tuple, o: tuple[float, float]) -> int:
    """How many times the ray from ``o`` along :data:`_RAY` crosses piece ``p``."""
    ux, uy = _RAY
    if p[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        ex, ey = bx - ax, by - ay
        den = ux * ey - uy * ex
        if den == 0:
            return 0
        fx, fy = ax - o[0], ay - o[1]
        s = (fx * ey - fy * ex) / den           # along the ray
        t = (fx * uy - fy * ux) / den           # along the segment
        return int(s > 0 and 0 <= t < 1)
    _, (cx, cy), r, t0, sw = p
    fx, fy = o[0] - cx, o[1] - cy
    b = fx * ux + fy * uy
    disc = b * b - (fx * fx + fy * fy - r * r)
    if disc <= 0:
        return 0
    n = 0
    for s in (-b - math.sqrt(disc), -b + math.sqrt(disc)):
        if s <= 0:
            continue
        x = (o[0] + s * ux, o[1] + s * uy)
        if abs(sw) >= TAU - 1e-15 or _param(p, x) < 1:
            n += 1
    return n


def _inside(o: tuple[float, float], outline: list[tuple]) -> bool:
    """Even-odd: ``o`` inside the region of ``outline`` (exact ray cast)."""
    return sum(_ray_hits(p, o) for p in outline) % 2 == 1


def _near(p: tuple, o: tuple[float, float]) -> float:
    """Distance from ``o`` to piece ``p``."""
    if p[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        dx, dy = bx - ax, by - ay
        L2 = dx * dx + dy * dy
        t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((o[0] - ax) * dx + (o[1] - ay) * dy) / L2))
        return math.hypot(o[0] - ax - t * dx, o[1] - ay - t * dy)
    _, (cx, cy), r, t0, sw = p
    if abs(sw) >= TAU - 1e-15 or _param(p, o) <= 1:
        return abs(math.hypot(o[0] - cx, o[1] - cy) - r)
    return min(math.dist(o, _at(p, 0.0)), math.dist(o, _at(p, 1.0)))


def _tangent(p: tuple, t: float) -> tuple[float, float]:
    if p[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        return (bx - ax, by - ay)
    _, _, r, a0, sw = p
    a = a0 + t * sw
    return (-math.sin(a) * sw, math.cos(a) * sw)


def _box(p: tuple) -> tuple[float, float, float, float]:
    """A box around piece ``p`` (an arc's: its circle's), 1e-9 mm wider."""
    e = 1e-9
    if p[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        return (min(ax, bx) - e, min(ay, by) - e, max(ax, bx) + e, max(ay, by) + e)
    (cx, cy), r = p[1], p[2]
    return (cx - r - e, cy - r - e, cx + r + e, cy + r + e)


def _meets(b: tuple, c: tuple) -> bool:
    return b[0] <= c[2] and c[0] <= b[2] and b[1] <= c[3] and c[1] <= b[3]


def _cuts(p: tuple, other: list[tuple]) -> list[float]:
    """The parameters where piece ``p`` meets the outline ``other``, with 0 and 1."""
    cp = carrier(_segment(p))
    ts = {0.0, 1.0}
    bp = _box(p)
    for q in other:
        if not _meets(bp, _box(q)):
            continue
        for x in crossings(cp, carrier(_segment(q))):
            if _near(p, x) <= 1e-9 and _near(q, x) <= 1e-9:
                t = _param(p, x)
                if 0.0 < t < 1.0:
                    ts.add(t)
    return sorted(ts)


def _segment(p: tuple):
    if p[0] == "L":
        return Line(p[1], p[2])
    return Circle(p[1], p[2]) if abs(p[4]) >= TAU - 1e-15 else Arc(p[1], p[2], p[3], p[4])


def _half(own: list[tuple], other: list[tuple], first: bool) -> float:
    """The integrals of the pieces of ``own`` inside ``other``; a piece on ``other``'s outline
    counts when ``first`` and both run the same way (the regions on its same side)."""
    total = 0.0
    for p in own:
        ts = _cuts(p, other)
        for t0, t1 in zip(ts, ts[1:]):
            if t1 - t0 <= 1e-15:
                continue
            m = _at(p, (t0 + t1) / 2)
            bm = (m[0], m[1], m[0], m[1])
            on = [q for q in other if _meets(bm, _box(q)) and _near(q, m) <= 1e-9]
            if on:
                q = on[0]
                u, v = _tangent(p, (t0 + t1) / 2), _tangent(q, _param(q, m))
                if first and u[0] * v[0] + u[1] * v[1] > 0:
                    total += _green(p, t0, t1)
                continue
            if _inside(m, other):
                total += _green(p, t0, t1)
    return total


def shared_area(loops_a, loops_b) -> float | None:
    """The area (mm²) the regions of ``loops_a`` and ``loops_b`` share (lists of
    :class:`~aidl_lang.geometry.shapes.curves.Loop`, holes clockwise), exact to rounding; None when
    an outline has a spline or an elliptic arc."""
    a, b = _arcs(loops_a), _arcs(loops_b)
    if a is None or b is None or not a or not b:
        return None
    return max(0.0, _half(a, b, True) + _half(b, a, False))
