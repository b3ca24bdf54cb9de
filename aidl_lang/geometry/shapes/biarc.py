"""An elliptic arc or a spline piece as tangent-continuous circular arcs (biarcs) within a
stated bound: the curve an ``Offset`` or ``Shell`` grows or shrinks, or a kerf offsets
(:func:`as_arcs`).

The offset of an ellipse is no ellipse (a curve of degree 8 that no output format holds),
so ``Offset(ellipse, d)`` and ``Shell(ellipse, t)`` offset, exactly, a chain of circular
arcs that stays within :data:`BIARC_TOL` of the ellipse: the offset of a region within
``e`` of another is within ``e`` of the other's offset (the Minkowski sum with a disc does
not increase the Hausdorff distance), so the written outline is within :data:`BIARC_TOL`
mm of the true offset curve, and tangent-continuous (no corner where the ellipse has none).

Each piece between parameters ``t0`` and ``t1`` is the biarc whose joint is the incentre of
the triangle formed by the two end points and the crossing of their tangents (Bolton 1975;
the two arcs meet tangent there); a piece whose deviation from the ellipse, measured at
:data:`SAMPLES` points, passes half the bound is split in two.  Lengths in mm, parameters
and angles in radians.
"""
from __future__ import annotations

import math

from .curves import Arc, EllipticArc, Line, Spline

BIARC_TOL = 1e-4      # mm: the stated bound between the written arcs and the true curve
SAMPLES = 12          # points of each piece where the deviation is measured
MAX_DEPTH = 24
# rad: an arc of a piece turning more is split: a piece across an inflection can give a biarc
# that doubles back in a hairpin of radius 1e-5 mm, within the bound in position yet a spike
# the kerf's offset turns inside out (run ep's knife scale: E0504 at a smooth spline)
MAX_SWEEP = math.pi / 2
KINK = math.radians(5)   # rad: the most an arc under the bound in radius may turn


def _unit(v):
    L = math.hypot(v[0], v[1])
    return (v[0] / L, v[1] / L)


def _arc_through(p, t, q):
    """The arc from ``p`` leaving along unit direction ``t`` that ends at ``q`` (a Line when
    ``q`` lies ahead on the tangent)."""
    n = (-t[1], t[0])
    w = (q[0] - p[0], q[1] - p[1])
    den = 2 * (n[0] * w[0] + n[1] * w[1])
    ww = w[0] * w[0] + w[1] * w[1]
    if abs(den) <= 1e-15 * math.sqrt(ww):
        return Line(p, q)
    s = ww / den
    c = (p[0] + s * n[0], p[1] + s * n[1])
    a0 = math.atan2(p[1] - c[1], p[0] - c[0])
    a1 = math.atan2(q[1] - c[1], q[0] - c[0])
    sweep = (a1 - a0) % (2 * math.pi) if s > 0 else -((a0 - a1) % (2 * math.pi))
    return Arc(c, abs(s), a0, sweep)


def _deviation(arc, p) -> float:
    """Distance (mm) from ``p`` to the arc or line ``arc``."""
    if isinstance(arc, Line):
        (x0, y0), (x1, y1) = arc.start, arc.end
        dx, dy = x1 - x0, y1 - y0
        L2 = dx * dx + dy * dy or 1.0
        u = max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / L2))
        return math.hypot(p[0] - x0 - u * dx, p[1] - y0 - u * dy)
    c = arc.center
    a = math.atan2(p[1] - c[1], p[0] - c[0])
    lo = arc.start_angle if arc.sweep > 0 else arc.start_angle + arc.sweep
    if (a - lo) % (2 * math.pi) <= abs(arc.sweep) + 1e-12:
        return abs(math.hypot(p[0] - c[0], p[1] - c[1]) - arc.radius)
    return min(math.dist(p, arc.start), math.dist(p, arc.end))


def _biarc(e, t0: float, t1: float, sign: float):
    p, q = e.at(t0), e.at(t1)
    tp = _unit(e.d1(t0))
    tq = _unit(e.d1(t1))
    tp, tq = (sign * tp[0], sign * tp[1]), (sign * tq[0], sign * tq[1])
    den = tp[0] * tq[1] - tp[1] * tq[0]
    w = (q[0] - p[0], q[1] - p[1])
    if abs(den) < 1e-12:        # parallel tangents: a straight piece is its chord, else split
        straight = abs(tp[0] * w[1] - tp[1] * w[0]) <= 1e-12 * math.hypot(*w)
        return [Line(p, q)] if straight and tp[0] * w[0] + tp[1] * w[1] > 0 else None
    k = (w[0] * tq[1] - w[1] * tq[0]) / den
    v = (p[0] + k * tp[0], p[1] + k * tp[1])        # the tangents' crossing
    a, b, c = math.dist(v, q), math.dist(p, q), math.dist(p, v)
    j = ((a * p[0] + b * v[0] + c * q[0]) / (a + b + c),
         (a * p[1] + b * v[1] + c * q[1]) / (a + b + c))
    first = _arc_through(p, tp, j)
    back = _arc_through(q, (-tq[0], -tq[1]), j)       # from q backwards, then turned round
    if isinstance(back, Line):
        second = Line(j, q)
    else:
        second = Arc(back.center, back.radius, back.start_angle + back.sweep, -back.sweep)
    return [first, second]


def _smooth(c, tol: float) -> bool:
    """Arc ``c`` (or a Line) turns as a smooth curve's piece may: at most :data:`MAX_SWEEP`,
    and, when its radius is under ``tol``, by no more than :data:`KINK` (a tiny arc turning
    more is a corner the curve does not have, which a kerf's offset turns inside out)."""
    sweep = abs(getattr(c, "sweep", 0.0))
    return sweep <= MAX_SWEEP and (c.radius >= tol or sweep <= KINK) if sweep else True


def _error(e, t0: float, t1: float, arcs) -> float:
    worst = 0.0
    for i in range(1, SAMPLES):
        pt = e.at(t0 + (t1 - t0) * i / SAMPLES)
        worst = max(worst, min(_deviation(a, pt) for a in arcs))
    for a in arcs:                          # and the arcs' own midpoints to the ellipse
        if isinstance(a, Arc):
            worst = max(worst, e.distance(a.at(a.start_angle + a.sweep / 2)))
    return worst


def biarcs(s: EllipticArc, tol: float = BIARC_TOL) -> list:
    """The elliptic arc ``s`` as circular arcs, in its direction of travel, each end on the
    ellipse and tangent to it, the chain tangent-continuous and within ``tol`` mm of ``s``
    (half of it at :data:`SAMPLES` points of every piece).  Raises ValueError when the
    bound cannot be met (a needle-thin ellipse beyond :data:`MAX_DEPTH` splits)."""
    e = s.curve
    n0 = max(4, math.ceil(abs(s.sweep) / (math.pi / 4)))
    return _fit(e, s.start_param, s.start_param + s.sweep, 1.0 if s.sweep > 0 else -1.0, n0,
                tol, f"the ellipse of semi-axes {e.rx:g} and {e.ry:g} mm")


def _fit(e, t0: float, t1: float, sign: float, n0: int, tol: float, what: str) -> list:
    """Biarcs of the curve ``e`` (``at``, ``d1``, ``distance``) from parameter ``t0`` to
    ``t1`` (``sign``: -1 where the travel runs against ``e``'s parameter), ``n0`` pieces to
    start with, each split in two until it lies within ``tol / 2``."""
    out: list = []
    stack = [(t0 + (t1 - t0) * (i + 1) / n0, t0 + (t1 - t0) * i / n0, 0)
             for i in reversed(range(n0))]
    while stack:
        b, a, depth = stack.pop()
        arcs = _biarc(e, a, b, sign)
        if arcs is not None and all(_smooth(c, tol) for c in arcs) \
                and _error(e, a, b, arcs) <= tol / 2:
            out += arcs
            continue
        if depth >= MAX_DEPTH:
            raise ValueError(f"{what} cannot be followed within {tol:g} mm by arcs")
        m = (a + b) / 2
        stack.append((b, m, depth + 1))
        stack.append((m, a, depth + 1))
    return out


class _Span:
    """One cubic Bezier span of a spline, as :func:`_fit` reads a curve (parameter 0..1 in
    the direction of travel); at an end where the handle lies on the point (a font's corner,
    an imported cusp) the direction is the second derivative's, as it arrives or leaves."""

    def __init__(self, b):
        from .spline import CubicSpline
        self.b = b
        self.one = CubicSpline(tuple(b), (1.0,))
        self.size = max(math.dist(b[0], q) for q in b[1:])

    def at(self, t: float):
        from .spline import bez_at
        return bez_at(self.b, t)

    def d1(self, t: float):
        from .spline import bez_d1, bez_d2
        d = bez_d1(self.b, t)
        if math.hypot(*d) > 1e-9 * self.size:
            return d
        d2 = bez_d2(self.b, t)
        return d2 if t < 0.5 else (-d2[0], -d2[1])

    def distance(self, p) -> float:
        return self.one.distance(p)


def spline_biarcs(s: Spline, tol: float = BIARC_TOL) -> list:
    """The spline piece ``s`` (:class:`~.curves.Spline`) as circular arcs and lines in its
    direction of travel, each span's ends on the curve and tangent to it, within ``tol`` mm
    of it (the kerf offset of a Spline, an Ellipse's too, and a font's letters: the offset of
    a cubic is no cubic).  Raises ValueError when the bound cannot be met."""
    out: list = []
    for b in s.spans:
        sp = _Span(b)
        if sp.size <= 1e-12:
            continue                    # a span of no length (all four points one)
        out += _fit(sp, 0.0, 1.0, 1.0, 2, tol,
                    f"the spline through ({b[0][0]:g}, {b[0][1]:g})")
    return out


def as_arcs(lp, keep=frozenset(), tol: float = BIARC_TOL) -> tuple:
    """The loop ``lp`` with every elliptic arc and spline piece as its biarcs (within ``tol``
    mm), and ``keep`` (indices of its segments) as the indices of their pieces: what the
    kerf offset (:func:`~..derived.offset.offset_loop`, exact on lines and arcs) reads."""
    from .curves import Loop
    if not any(isinstance(g, (EllipticArc, Spline)) for g in lp.segments):
        return lp, keep
    segs: list = []
    kept = set()
    for i, g in enumerate(lp.segments):
        new = biarcs(g, tol) if isinstance(g, EllipticArc) else spline_biarcs(g, tol) \
            if isinstance(g, Spline) else [g]
        if i in keep:
            kept.update(range(len(segs), len(segs) + len(new)))
        segs += new
    return Loop(segs), frozenset(kept)
