"""Curves as G-code's lines and arcs (split from :mod:`.gcode`): an ellipse or spline piece
cut into biarcs (two tangent arcs from each end's position and direction, equal tangent
lengths), halved until every sample of the curve lies within :data:`CURVE_TOL` mm of them;
the ends are the exact ends.  Lengths in mm."""
from __future__ import annotations

import math

from ..part.part import Arc, Circle, EllipticArc, Line, OutputError, Spline

CURVE_TOL = 1e-3       # mm: the largest distance of an ellipse or spline piece from its arcs
_MAX_DEPTH = 24        # halvings of one curve piece at most (2^24 arcs: never reached)


# ------------------------------------------------------------------ curves to lines and arcs
def _arc_through(p, t, q):
    """The arc from ``p`` leaving in unit direction ``t`` to ``q``: (center, radius,
    start_angle, sweep), or None when it is straight."""
    n = (-t[1], t[0])
    dx, dy = q[0] - p[0], q[1] - p[1]
    den = 2 * (n[0] * dx + n[1] * dy)
    d2 = dx * dx + dy * dy
    if d2 == 0.0 or abs(den) <= 1e-12 * math.sqrt(d2):
        return None
    s = d2 / den
    c = (p[0] + s * n[0], p[1] + s * n[1])
    a0 = math.atan2(p[1] - c[1], p[0] - c[0])
    a1 = math.atan2(q[1] - c[1], q[0] - c[0])
    sw = (a1 - a0) % (2 * math.pi)
    if s < 0:                         # centre on the right: clockwise
        sw = sw - 2 * math.pi if sw > 0 else 0.0
    return c, abs(s), a0, sw


def _biarc(p0, t0, p1, t1):
    """Two tangent arcs (or lines) from ``p0`` leaving along ``t0`` to ``p1`` arriving
    along ``t1`` (unit vectors), equal tangent lengths; None when degenerate."""
    vx, vy = p1[0] - p0[0], p1[1] - p0[1]
    tx, ty = t0[0] + t1[0], t0[1] + t1[1]
    vt = vx * tx + vy * ty
    vv = vx * vx + vy * vy
    den = 2 * (1 - (t0[0] * t1[0] + t0[1] * t1[1]))
    if vv == 0.0:
        return None
    if abs(den) < 1e-12:
        v2 = vx * t1[0] + vy * t1[1]
        if abs(v2) < 1e-12 * math.sqrt(vv):
            return None
        d = vv / (4 * v2)
    else:
        disc = vt * vt + den * vv
        d = (-vt + math.sqrt(max(disc, 0.0))) / den
    if not d > 0:
        return None
    q0 = (p0[0] + d * t0[0], p0[1] + d * t0[1])
    q1 = (p1[0] - d * t1[0], p1[1] - d * t1[1])
    m = ((q0[0] + q1[0]) / 2, (q0[1] + q1[1]) / 2)
    out = []
    a = _arc_through(p0, t0, m)
    out.append(Line(p0, m) if a is None else Arc(*a))
    b = _arc_through(p1, (-t1[0], -t1[1]), m)
    if b is None:
        out.append(Line(m, p1))
    else:
        c, r, a0, sw = b
        out.append(Arc(c, r, a0 + sw, -sw))
    return out, m


def _dist_to(seg, p) -> float:
    """Distance from ``p`` to a line or arc segment."""
    if isinstance(seg, Line):
        (x0, y0), (x1, y1) = seg.start, seg.end
        dx, dy = x1 - x0, y1 - y0
        L2 = dx * dx + dy * dy
        u = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / L2))
        return math.hypot(p[0] - x0 - u * dx, p[1] - y0 - u * dy)
    c = seg.center
    a = math.atan2(p[1] - c[1], p[0] - c[0])
    rel = (a - seg.start_angle) % (2 * math.pi) if seg.sweep > 0 else \
        (seg.start_angle - a) % (2 * math.pi)
    if rel <= abs(seg.sweep):
        return abs(math.hypot(p[0] - c[0], p[1] - c[1]) - seg.radius)
    return min(math.dist(p, seg.start), math.dist(p, seg.end))


def _fit(f, d, t0, t1, p0, p1, depth=0) -> list:
    """Biarcs within :data:`CURVE_TOL` of the curve ``f`` (parameter -> point; ``d``:
    parameter -> unit direction) from ``t0`` to ``t1``, whose ends ``p0``, ``p1`` are
    kept exactly."""
    got = _biarc(p0, d(t0), p1, d(t1)) if math.dist(p0, p1) > 0 else None
    if got is not None:
        arcs, _ = got
        # 15 samples of the curve within half the tolerance of the arcs (the other half for
        # what falls between them); no arc of more than a quarter turn and the arcs no longer
        # than the samples' polyline allows (an arc the wrong way round is never kept)
        pts = [p0] + [f(t0 + (t1 - t0) * k / 16) for k in range(1, 16)] + [p1]
        chord = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
        ok = all(min(_dist_to(s, q) for s in arcs) <= CURVE_TOL / 2 for q in pts[1:-1]) \
            and all(isinstance(s, Line) or abs(s.sweep) <= math.pi / 2 for s in arcs) \
            and sum(s.length for s in arcs) <= chord + CURVE_TOL
        if ok or depth >= _MAX_DEPTH:
            return arcs
    elif depth >= _MAX_DEPTH:
        return [Line(p0, p1)] if math.dist(p0, p1) > 0 else []
    tm = (t0 + t1) / 2
    pm = f(tm)
    return _fit(f, d, t0, tm, p0, pm, depth + 1) + _fit(f, d, tm, t1, pm, p1, depth + 1)


def _unit(v):
    L = math.hypot(v[0], v[1])
    return (v[0] / L, v[1] / L) if L > 0 else None


def as_arcs(s) -> list:
    """Segment ``s`` as G-code's lines and arcs: a line or an arc of at most half a turn
    itself, a longer arc in two halves, a circle as two half-circles from its point of angle
    0, an ellipse or spline piece as biarcs within :data:`CURVE_TOL`."""
    if isinstance(s, Line):
        return [s] if s.start != s.end else []
    if isinstance(s, Circle):
        sw = math.pi if s.ccw else -math.pi
        return [Arc(s.center, s.radius, 0.0, sw), Arc(s.center, s.radius, math.pi, sw)]
    if isinstance(s, Arc):
        if abs(s.sweep) <= math.pi:
            return [s]
        h = s.sweep / 2
        return [Arc(s.center, s.radius, s.start_angle, h),
                Arc(s.center, s.radius, s.start_angle + h, h)]
    if isinstance(s, EllipticArc):
        e, a, sw = s.curve, s.start_param, s.sweep
        sg = 1.0 if sw > 0 else -1.0

        def f(t):
            return e.at(a + sw * t)

        def d(t):
            x, y = e.tangent(a + sw * t)
            return (sg * x, sg * y)
        # quarter turns at most per piece to start with
        n = max(1, math.ceil(abs(sw) / (math.pi / 2) - 1e-9))
        pts = [s.start] + [f(k / n) for k in range(1, n)] + [s.end]
        return [g for k in range(n) for g in _fit(f, d, k / n, (k + 1) / n, pts[k], pts[k + 1])]
    if isinstance(s, Spline):
        from ...geometry.shapes.spline import bez_at, bez_d1, bez_d2
        out = []
        for b in s.spans:
            def f(t, b=b):
                return bez_at(b, t)

            def d(t, b=b):
                u = _unit(bez_d1(b, t))
                if u is None:               # a cusp of the control polygon
                    u = _unit(bez_d2(b, t)) or _unit((b[3][0] - b[0][0], b[3][1] - b[0][1])) \
                        or (1.0, 0.0)
                    if t > 0.5:         # d2 points backwards at an end cusp
                        u = (-u[0], -u[1])
                return u
            out += _fit(f, d, 0.0, 1.0, b[0], b[3])
        return out
    raise OutputError(f"cannot write a {type(s).__name__} as G-code")
