"""Exact plane curves: lines, circular arcs and circles, closed loops of them, and the
computations on their *carriers* (the infinite line or the full circle a segment lies on).

These are the output's geometry (issue "Exact by construction"): every shape of a program has
an exact outline made of these segments (:mod:`aidl_lang.output.part.build.booleans` builds them from the
solved model), the booleans' polygons are put back on them (:mod:`aidl_lang.output.part.edges.exact`),
fillets and chamfers are cut on them (:mod:`aidl_lang.geometry.derived.operations`), and every writer
reads them.  All lengths are in millimetres, angles in radians, counter-clockwise positive,
y up.

Carriers are tuples, compared and intersected without building objects:

* ``("L", px, py, ux, uy)``: the line through ``(px, py)`` with unit direction ``(ux, uy)``;
* ``("C", cx, cy, r)``: the circle of center ``(cx, cy)`` and radius ``r > 0``;
* ``("S", curve)``: a whole :class:`~.spline.CubicSpline` (a :class:`Spline` segment is a piece
  of one, between two positions on it);
* ``("E", curve)``: a whole :class:`~.ellipse.EllipseCurve` (an :class:`EllipticArc` is a
  piece of one, between two values of its parameter).

Where two carriers meet, :func:`intersect` gives the meeting point nearest to a guess; where
they touch (a tangent join: a slot's side and its end, a fillet and its edges) or come within
:data:`TANGENT` of touching, it gives the touching point itself, so a tangent join stays
tangent instead of being split into two close, ill-conditioned roots.
"""
from __future__ import annotations

import math

from .ellipse import EllipseCurve, cross_circle as _e_circle, cross_ellipse as _e_ellipse, \
    cross_line as _e_line, cross_spline as _e_spline, nearest_approach as _e_nearest
from ...base.records import Compared, Frozen, kept

Point = tuple[float, float]

TANGENT = 1e-5       # relative half-chord below which two crossing points count as one touch
EPS = 1e-9           # mm: shorter segments are dropped, closer points are one point


def tolerance(scale: float) -> float:
    """:data:`EPS` for coordinates up to ``scale`` mm (grown past 1 m, where doubles hold
    fewer decimals)."""
    return EPS * max(1.0, scale * 1e-3)


class Line(Frozen):
    """The straight segment from ``start`` to ``end`` (mm)."""
    __slots__ = ("start", "end")

    def __init__(self, start: Point, end: Point):
        object.__setattr__(self, "start", start)
        object.__setattr__(self, "end", end)

    @property
    def length(self) -> float:
        return math.dist(self.start, self.end)

    def box(self) -> tuple[float, float, float, float]:
        """Exact ``(x0, y0, x1, y1)`` (mm)."""
        (x0, y0), (x1, y1) = self.start, self.end
        return min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)


class Arc(Frozen):
    """Circular arc from ``start_angle`` sweeping ``sweep`` radians (> 0 counter-clockwise)."""
    __slots__ = ("center", "radius", "start_angle", "sweep")

    def __init__(self, center: Point, radius: float, start_angle: float, sweep: float):
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "radius", radius)
        object.__setattr__(self, "start_angle", start_angle)
        object.__setattr__(self, "sweep", sweep)

    @property
    def end_angle(self) -> float:
        return self.start_angle + self.sweep

    @property
    def ccw(self) -> bool:
        return self.sweep > 0

    def at(self, a: float) -> Point:
        return (self.center[0] + self.radius * math.cos(a), self.center[1] + self.radius * math.sin(a))

    # the ends, computed on first use and kept (an arc is immutable; a gear's thousand arcs
    # are asked for their ends by the booleans, the recovery and every writer)
    @kept
    def start(self) -> Point:
        return self.at(self.start_angle)

    @kept
    def end(self) -> Point:
        return self.at(self.start_angle + self.sweep)

    @property
    def length(self) -> float:
        return self.radius * abs(self.sweep)

    def box(self) -> tuple[float, float, float, float]:
        """Exact ``(x0, y0, x1, y1)`` (mm): the ends' box, grown to ``center +- radius`` on
        each axis whose extreme (a multiple of 90 degrees) the sweep passes."""
        cx, cy = self.center
        r = self.radius
        if abs(self.sweep) >= 2 * math.pi:
            return cx - r, cy - r, cx + r, cy + r
        (sx, sy), (ex, ey) = self.start, self.end
        x0, x1 = min(sx, ex), max(sx, ex)
        y0, y1 = min(sy, ey), max(sy, ey)
        lo, hi = sorted((self.start_angle, self.start_angle + self.sweep))
        k = math.ceil(lo / (math.pi / 2))
        while k * math.pi / 2 <= hi:             # each multiple of 90 degrees the arc passes
            q = k % 4
            if q == 0:
                x1 = cx + r
            elif q == 1:
                y1 = cy + r
            elif q == 2:
                x0 = cx - r
            else:
                y0 = cy - r
            k += 1
        return x0, y0, x1, y1


class Circle(Frozen):
    """A full circle; ``ccw`` False when it is a hole (clockwise) of its part."""
    __slots__ = ("center", "radius", "ccw")

    def __init__(self, center: Point, radius: float, ccw: bool = True):
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "radius", radius)
        object.__setattr__(self, "ccw", ccw)

    @property
    def length(self) -> float:
        return 2 * math.pi * self.radius

    def box(self) -> tuple[float, float, float, float]:
        """Exact ``(x0, y0, x1, y1)`` (mm)."""
        (cx, cy), r = self.center, self.radius
        return cx - r, cy - r, cx + r, cy + r


class Spline(Frozen):
    """The piece of an interpolating cubic spline ``curve`` (:class:`~.spline.CubicSpline`)
    from position ``u0`` to ``u1`` (``u1 < u0``: run backwards; a closed curve wraps, so
    ``|u1 - u0|`` may be its whole ``n``).  Its exact form is :attr:`spans`: cubic Béziers
    cut from the curve's spans by de Casteljau at ``u0`` and ``u1``."""
    __slots__ = ("curve", "u0", "u1")

    def __init__(self, curve, u0: float, u1: float):
        object.__setattr__(self, "curve", curve)
        object.__setattr__(self, "u0", u0)
        object.__setattr__(self, "u1", u1)

    @kept
    def spans(self) -> list:
        return self.curve.spans_between(self.u0, self.u1)

    @property
    def start(self) -> Point:
        return self.spans[0][0] if self.spans else self.curve.at(self.u0)

    @property
    def end(self) -> Point:
        return self.spans[-1][3] if self.spans else self.curve.at(self.u1)

    @property
    def whole(self) -> bool:
        """The whole of a closed curve (a loop of its own, like a :class:`Circle`)."""
        return self.curve.closed and abs(abs(self.u1 - self.u0) - self.curve.n) < 1e-12

    @property
    def length(self) -> float:
        from .spline import bez_length
        return sum(bez_length(b) for b in self.spans)

    @property
    def area_term(self) -> float:
        """``1/2 * integral of (x dy - y dx)`` along the piece (mm^2)."""
        from .spline import bez_area
        return sum(bez_area(b) for b in self.spans)

    def box(self) -> tuple[float, float, float, float]:
        """Exact ``(x0, y0, x1, y1)`` of the piece (its spans' derivative roots)."""
        from .spline import bez_box
        bs = [bez_box(b) for b in self.spans]
        return (min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
                max(b[3] for b in bs))

    def bspline(self):
        """``(3, knots, control points)`` of the piece (clamped, triple interior knots;
        knot steps: each span's share of its curve's parameter step)."""
        from .spline import bspline_of
        ctrl = [self.spans[0][0]] if self.spans else []
        for b in self.spans:
            ctrl += [b[1], b[2], b[3]]
        return bspline_of(ctrl, _span_steps(self))


class EllipticArc(Frozen):
    """The piece of ellipse ``curve`` (:class:`~.ellipse.EllipseCurve`) from parameter
    ``start_param`` sweeping ``sweep`` radians of it (> 0 counter-clockwise; +-2 pi: the
    whole ellipse, a loop of its own like a :class:`Circle`)."""
    __slots__ = ("curve", "start_param", "sweep")

    def __init__(self, curve: EllipseCurve, start_param: float, sweep: float):
        object.__setattr__(self, "curve", curve)
        object.__setattr__(self, "start_param", start_param)
        object.__setattr__(self, "sweep", sweep)

    @property
    def end_param(self) -> float:
        return self.start_param + self.sweep

    @property
    def ccw(self) -> bool:
        return self.sweep > 0

    def at(self, t: float) -> Point:
        return self.curve.at(t)

    @property
    def start(self) -> Point:
        return self.curve.at(self.start_param)

    @property
    def end(self) -> Point:
        return self.curve.at(self.end_param)

    @property
    def whole(self) -> bool:
        return abs(abs(self.sweep) - 2 * math.pi) < 1e-12

    @property
    def length(self) -> float:
        """Arc length (mm): Gauss-Legendre quadrature of |P'(t)|, 32 nodes per quarter turn
        (exact to ~1e-15 relative for the ellipses a part holds)."""
        n = max(1, math.ceil(abs(self.sweep) / (math.pi / 2) - 1e-9))
        x, w = _gauss()
        h = self.sweep / n
        a, b = self.curve.rx, self.curve.ry
        tot = 0.0
        for k in range(n):
            t = self.start_param + h * (k + 0.5 + 0.5 * x)
            tot += float((w * ((a * _np().sin(t)) ** 2 + (b * _np().cos(t)) ** 2) ** 0.5).sum())
        return tot * abs(h) / 2

    @property
    def area_term(self) -> float:
        """``1/2 * integral of (x dy - y dx)`` along the arc (mm^2): with P = C + Q(t),
        ``C x (Q(t1) - Q(t0)) + rx ry sweep``, halved."""
        e = self.curve
        (cx, cy) = e.center
        (x0, y0), (x1, y1) = self.start, self.end
        qx, qy = (x1 - cx) - (x0 - cx), (y1 - cy) - (y0 - cy)
        return 0.5 * (cx * qy - cy * qx + e.rx * e.ry * self.sweep)

    def box(self) -> tuple[float, float, float, float]:
        return self.curve.box(self.start_param, self.sweep)


def elliptic_arc(center: Point, rx: float, ry: float, rotation: float, start: Point,
                 mid: Point, end: Point) -> EllipticArc:
    """The :class:`EllipticArc` of the ellipse ``center``, semi-axes ``rx`` (along
    ``rotation``, radians) and ``ry`` (mm) from its point ``start`` through ``mid`` to
    ``end`` (the way round that passes ``mid``): its canonical curve, the parameters of the
    ends taken from the points (a mirrored arc runs clockwise)."""
    from .ellipse import ellipse
    curve, _ = ellipse(center, rx, ry, rotation)
    t0, tm, t1 = curve.param(start), curve.param(mid), curve.param(end)
    tau = 2 * math.pi
    ccw = (t1 - t0) % tau
    if (tm - t0) % tau <= ccw:
        return EllipticArc(curve, t0, ccw or tau)
    return EllipticArc(curve, t0, -((t0 - t1) % tau or tau))


def _np():
    import numpy
    return numpy


_GAUSS: list = []


def _gauss():
    if not _GAUSS:
        _GAUSS.append(_np().polynomial.legendre.leggauss(32))
    return _GAUSS[0]


def _span_steps(s: "Spline") -> list[float]:
    """The parameter step (mm) of each span of ``s.spans``."""
    c = s.curve
    lo, hi = min(s.u0, s.u1), max(s.u0, s.u1)
    out = []
    i = math.floor(lo)
    while i < hi:
        t0, t1 = max(lo - i, 0.0), min(hi - i, 1.0)
        if t1 > t0:
            out.append(c.h[i % c.n] * (t1 - t0))
        i += 1
    return out if s.u1 >= s.u0 else out[::-1]


Segment = Line | Arc | Circle | Spline | EllipticArc


class Loop(Compared):
    """A closed outline: consecutive segments, each ending where the next starts.  A loop
    that runs clockwise (negative :attr:`area`) is a hole of its part."""
    __slots__ = ("segments",)

    def __init__(self, segments: list[Segment]):
        self.segments = segments

    @property
    def area(self) -> float:
        """Signed area (mm^2): shoelace over the segment ends plus each arc's circular segment."""
        if len(self.segments) == 1 and isinstance(self.segments[0], Circle):
            c = self.segments[0]
            return (1 if c.ccw else -1) * math.pi * c.radius ** 2
        a = 0.0
        for s in self.segments:
            if isinstance(s, (Spline, EllipticArc)):
                a += s.area_term
                continue
            (x0, y0), (x1, y1) = s.start, s.end
            a += 0.5 * (x0 * y1 - x1 * y0)
            if isinstance(s, Arc):
                t = s.sweep
                a += 0.5 * s.radius ** 2 * (t - math.sin(t))
        return a

    @property
    def perimeter(self) -> float:
        return sum(s.length for s in self.segments)

    @property
    def is_hole(self) -> bool:
        return self.area < 0

    def points(self, tol: float | None = None):
        """A polyline of the loop (N x 2 array, mm, closed implicitly), arcs and circles sampled
        by :func:`~aidl_lang.geometry.shapes.tessellate.segments_for` chords within ``tol`` (mm; None:
        ``CHORD_TOL``; splines and ellipses always within ``CHORD_TOL``), every vertex on the
        exact curve."""
        import numpy as np
        xs, ys = [], []
        sample_xy(self.segments, xs, ys, tol)
        return np.column_stack([np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)]) \
            if xs else np.zeros((0,), dtype=float)

    def reversed(self) -> "Loop":
        return Loop([reverse(s) for s in reversed(self.segments)])


def sample_xy(segments, xs: list, ys: list, tol: float | None = None) -> None:
    """Append the vertices of :meth:`Loop.points` of ``segments`` to ``xs`` and ``ys``: each
    line's start, each arc's start and its interior chord ends, each circle's chord ends
    (:func:`~aidl_lang.geometry.shapes.tessellate.segments_for` chords within ``tol`` mm, None:
    ``CHORD_TOL``)."""
    from .tessellate import CHORD_TOL, segments_for
    tol = CHORD_TOL if tol is None else max(float(tol), CHORD_TOL)
    cos, sin, pi = math.cos, math.sin, math.pi
    for s in segments:
        if isinstance(s, Line):
            xs.append(s.start[0])
            ys.append(s.start[1])
        elif isinstance(s, Spline):
            spline_xy(s, xs, ys)
        elif isinstance(s, EllipticArc):
            for x, y in ellipse_xy(s):
                xs.append(x)
                ys.append(y)
        elif isinstance(s, Arc):
            cx, cy = s.center
            r, a0, sw = s.radius, s.start_angle, s.sweep
            # a coarse view's arc may be one chord; the exact writers' keep at least 3
            n = max(1, segments_for(r, abs(sw), tol, 3 if tol == CHORD_TOL else 1))
            angles = [a0 + sw * i / n for i in range(n)]
            xs += [cx + r * cos(a) for a in angles]
            ys += [cy + r * sin(a) for a in angles]
        else:
            cx, cy = s.center
            r = s.radius
            n = segments_for(r, 2 * pi, tol)
            sg = 1 if s.ccw else -1
            angles = [sg * 2 * pi * i / n for i in range(n)]
            xs += [cx + r * cos(a) for a in angles]
            ys += [cy + r * sin(a) for a in angles]


def ellipse_chords(s: EllipticArc) -> int:
    """How many chords :func:`ellipse_xy` cuts ``s`` into: equal steps of the parameter, the
    sagitta of each at most that of the circle of radius ``rx`` (the major semi-axis) over
    the same angle, so within ``CHORD_TOL``."""
    from .tessellate import segments_for
    return max(1, segments_for(s.curve.rx, abs(s.sweep)))


def ellipse_xy(s: EllipticArc) -> list[Point]:
    """The chord starts of :class:`EllipticArc` ``s`` (:func:`ellipse_chords` of them)."""
    n = ellipse_chords(s)
    return [s.curve.at(s.start_param + s.sweep * i / n) for i in range(n)]


def spline_xy(s: Spline, xs: list, ys: list) -> None:
    """Append the chord starts of :class:`Spline` ``s`` (each span cut into
    :func:`~.spline.bez_pieces` chords within ``CHORD_TOL``) to ``xs`` and ``ys``."""
    from .spline import bez_at, bez_pieces
    from .tessellate import CHORD_TOL
    for b in s.spans:
        k = bez_pieces(b, CHORD_TOL)
        for i in range(k):
            x, y = bez_at(b, i / k) if i else b[0]
            xs.append(x)
            ys.append(y)


def spline_chords(s: Spline) -> int:
    """How many chords :func:`spline_xy` cuts ``s`` into."""
    from .spline import bez_pieces
    from .tessellate import CHORD_TOL
    return sum(bez_pieces(b, CHORD_TOL) for b in s.spans)


# ------------------------------------------------------------------ segments
def reverse(s: Segment) -> Segment:
    """The same segment run the other way."""
    if isinstance(s, Line):
        return Line(s.end, s.start)
    if isinstance(s, Spline):
        return Spline(s.curve, s.u1, s.u0)
    if isinstance(s, EllipticArc):
        return EllipticArc(s.curve, s.end_param, -s.sweep)
    if isinstance(s, Arc):
        return Arc(s.center, s.radius, s.start_angle + s.sweep, -s.sweep)
    return Circle(s.center, s.radius, not s.ccw)


def carrier(s: Segment) -> tuple:
    """The carrier of a segment: ``("L", px, py, ux, uy)`` or ``("C", cx, cy, r)``."""
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        L = math.hypot(x1 - x0, y1 - y0)
        if L == 0.0:
            return ("L", x0, y0, 1.0, 0.0)
        return ("L", x0, y0, (x1 - x0) / L, (y1 - y0) / L)
    if isinstance(s, Spline):
        return ("S", s.curve)
    if isinstance(s, EllipticArc):
        return ("E", s.curve)
    return ("C", float(s.center[0]), float(s.center[1]), float(s.radius))


def tangent_at(s: Segment, end: bool) -> Point:
    """Unit direction of travel of ``s`` at its end (``end``) or start."""
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        L = math.hypot(x1 - x0, y1 - y0) or 1.0
        return ((x1 - x0) / L, (y1 - y0) / L)
    if isinstance(s, Spline):
        dx, dy = s.curve.tangent(s.u1 if end else s.u0)
        return (dx, dy) if s.u1 >= s.u0 else (-dx, -dy)
    if isinstance(s, EllipticArc):
        dx, dy = s.curve.tangent(s.end_param if end else s.start_param)
        return (dx, dy) if s.sweep > 0 else (-dx, -dy)
    a = s.end_angle if end else s.start_angle
    sg = 1.0 if s.sweep > 0 else -1.0
    return (-sg * math.sin(a), sg * math.cos(a))


def turn_between(a: Segment, b: Segment) -> float:
    """Signed angle (radians, left turn positive) from ``a``'s direction at its end to
    ``b``'s at its start: 0 at a tangent join."""
    (ax, ay), (bx, by) = tangent_at(a, True), tangent_at(b, False)
    return math.atan2(ax * by - ay * bx, ax * bx + ay * by)


def with_ends(s: Segment, p: Point, q: Point) -> Segment:
    """``s`` cut to run from ``p`` to ``q`` (points of it, in its order) on its own carrier,
    turning the same way: an arc keeps the sign of its sweep, and never grows past its own
    (``p`` = ``q`` is no arc, not a whole turn)."""
    if isinstance(s, Line):
        return Line(p, q)
    if isinstance(s, Spline):
        return spline_between(s, p, q)
    if isinstance(s, EllipticArc):
        t1, t2 = s.curve.foot(p), s.curve.foot(q)
        sw = (t2 - t1) % (2 * math.pi)
        if s.sweep < 0:
            sw -= 2 * math.pi
        if abs(sw) > abs(s.sweep) + 1e-9:
            sw -= math.copysign(2 * math.pi, sw)
            if abs(sw) > 1e-9:
                sw = 0.0
        return EllipticArc(s.curve, t1, sw)
    cx, cy = s.center
    a1 = math.atan2(p[1] - cy, p[0] - cx)
    a2 = math.atan2(q[1] - cy, q[0] - cx)
    sw = (a2 - a1) % (2 * math.pi)
    if s.sweep < 0:
        sw -= 2 * math.pi
    if abs(sw) > abs(s.sweep) + 1e-9:        # past a whole turn: the same point, no arc
        sw -= math.copysign(2 * math.pi, sw)
        if abs(sw) > 1e-9:
            sw = 0.0
    return Arc(s.center, s.radius, a1, sw)


def simplify(segments: list[Segment], scale: float = 1.0) -> list[Segment]:
    """A closed chain without zero-length segments (below :data:`EPS`, relative to
    ``scale``), with consecutive segments on one carrier merged (two quarter arcs of one
    circle become a semicircle), and a chain that is one whole circle as a :class:`Circle`."""
    tol = tolerance(scale)
    segs = [s for s in segments if isinstance(s, Circle) or s.length > tol
            or (isinstance(s, (Spline, EllipticArc)) and s.whole)]
    changed = True
    while changed and len(segs) > 1:
        changed = False
        for i in range(len(segs)):
            a, b = segs[i - 1], segs[i]
            if _mergeable(a, b, tol):
                m = Line(a.start, b.end) if isinstance(a, Line) else \
                    Spline(a.curve, a.u0, a.u1 + (b.u1 - b.u0)) if isinstance(a, Spline) else \
                    EllipticArc(a.curve, a.start_param, a.sweep + b.sweep) \
                    if isinstance(a, EllipticArc) else \
                    Arc(a.center, a.radius, a.start_angle, a.sweep + b.sweep)
                if i == 0:
                    segs = [m] + segs[1:-1]
                else:
                    segs[i - 1:i + 1] = [m]
                changed = True
                break
    if len(segs) == 1 and isinstance(segs[0], Arc) and abs(abs(segs[0].sweep) - 2 * math.pi) < 1e-9:
        a = segs[0]
        return [Circle(a.center, a.radius, a.sweep > 0)]
    return segs


def _mergeable(a: Segment, b: Segment, tol: float) -> bool:
    if type(a) is Arc and type(b) is Arc:     # same_carrier(carrier(a), carrier(b)), inline
        (ax, ay), (bx, by) = a.center, b.center
        return (a.sweep > 0) == (b.sweep > 0) and math.hypot(ax - bx, ay - by) <= tol \
            and abs(a.radius - b.radius) <= tol and abs(a.sweep + b.sweep) <= 2 * math.pi + 1e-9
    if isinstance(a, Spline) and isinstance(b, Spline):
        n = a.curve.n
        return a.curve == b.curve and (a.u1 >= a.u0) == (b.u1 >= b.u0) and \
            abs(a.u1 - a.u0) + abs(b.u1 - b.u0) <= n + 1e-12 and \
            (abs(a.u1 - b.u0) < 1e-12 or (a.curve.closed and abs(abs(a.u1 - b.u0) - n) < 1e-12))
    if isinstance(a, Line) and isinstance(b, Line):
        return abs(turn_between(a, b)) < 1e-12 and same_carrier(carrier(a), carrier(b), tol)
    if isinstance(a, EllipticArc) and isinstance(b, EllipticArc):
        return (a.sweep > 0) == (b.sweep > 0) and a.curve.same(b.curve, tol) \
            and abs(a.sweep + b.sweep) <= 2 * math.pi + 1e-9 and math.dist(a.end, b.start) <= tol
    return False


# ------------------------------------------------------------------ carriers
def same_carrier(a: tuple, b: tuple, tol: float = EPS) -> bool:
    """True when two carriers are the same line or circle (within ``tol`` mm)."""
    if a[0] != b[0]:
        return False
    if a[0] == "S":
        return a[1] == b[1]
    if a[0] == "E":
        return a[1].same(b[1], tol)
    if a[0] == "C":
        return math.hypot(a[1] - b[1], a[2] - b[2]) <= tol and abs(a[3] - b[3]) <= tol
    _, px, py, ux, uy = a
    _, qx, qy, vx, vy = b
    if abs(ux * vy - uy * vx) > 1e-12:
        return False
    return abs(ux * (qy - py) - uy * (qx - px)) <= tol


def distance_to(c: tuple, p: Point) -> float:
    """Distance (mm) from point ``p`` to carrier ``c``."""
    if c[0] in ("S", "E"):
        return c[1].distance(p)
    if c[0] == "L":
        _, px, py, ux, uy = c
        return abs(ux * (p[1] - py) - uy * (p[0] - px))
    _, cx, cy, r = c
    return abs(math.hypot(p[0] - cx, p[1] - cy) - r)


def foot(c: tuple, p: Point) -> Point:
    """The point of carrier ``c`` nearest to ``p``."""
    if c[0] in ("S", "E"):
        return c[1].at(c[1].foot(p))
    if c[0] == "L":
        _, px, py, ux, uy = c
        t = (p[0] - px) * ux + (p[1] - py) * uy
        return (px + t * ux, py + t * uy)
    _, cx, cy, r = c
    dx, dy = p[0] - cx, p[1] - cy
    L = math.hypot(dx, dy)
    if L == 0.0:
        return (cx + r, cy)
    return (cx + dx / L * r, cy + dy / L * r)


def crossings(a: tuple, b: tuple) -> list[Point]:
    """Every point where carriers ``a`` and ``b`` meet: two, one (lines crossing, or a touch
    within :data:`TANGENT`) or none (parallel lines, circles apart); a spline's crossings
    are roots of its spans' polynomials, polished by Newton (:mod:`.spline`)."""
    if a[0] == "E" or b[0] == "E":
        return _ellipse_crossings(a, b)
    if a[0] == "S" or b[0] == "S":
        return _spline_crossings(a, b)
    if a[0] == "L" and b[0] == "L":
        return _line_line(a, b)
    if a[0] == "L":
        return _line_circle(a, b)
    if b[0] == "L":
        return _line_circle(b, a)
    return _circle_circle(a, b)


def intersect(a: tuple, b: tuple, near: Point) -> Point:
    """The point where carriers ``a`` and ``b`` meet nearest to ``near``.  Two crossing
    points closer together than :data:`TANGENT` times the radius count as one touch and give
    the touching point; carriers that do not meet (parallel lines, circles apart) give the
    point of ``a`` nearest to ``near``, or their point of closest approach."""
    pts = crossings(a, b)
    if not pts:
        return _closest(a, b, near)
    return min(pts, key=lambda q: math.hypot(q[0] - near[0], q[1] - near[1]))


def _spline_crossings(a, b) -> list[Point]:
    if a[0] != "S":
        a, b = b, a
    c = a[1]
    if b[0] == "L":
        return [c.at(u) for u in c.cross_line(*b[1:])]
    if b[0] == "C":
        return [c.at(u) for u in c.cross_circle(*b[1:])]
    if b[1] == c:
        return []
    return [c.at(u) for u, _ in c.cross_spline(b[1])]


def _ellipse_crossings(a, b) -> list[Point]:
    if a[0] != "E":
        a, b = b, a
    e = a[1]
    if b[0] == "L":
        return _e_line(e, *b[1:])
    if b[0] == "C":
        return _e_circle(e, *b[1:])
    if b[0] == "E":
        return _e_ellipse(e, b[1])
    return _e_spline(e, b[1])


def spline_between(s: Spline, p: Point, q: Point) -> Spline:
    """The piece of ``s``'s curve from its point nearest ``p`` to the one nearest ``q``, run
    in ``s``'s direction (a closed curve wraps forward or backward as ``s`` does)."""
    c = s.curve
    up, uq = c.foot(p), c.foot(q)
    if s.u1 >= s.u0:
        if c.closed:
            while uq < up:
                uq += c.n
        return Spline(c, up, uq)
    if c.closed:
        while uq > up:
            uq -= c.n
    return Spline(c, up, uq)


def _closest(a, b, near):
    if a[0] == "E" or b[0] == "E":
        return _approach(a, b, near)
    if a[0] == "S" or b[0] == "S":
        return foot(a, near)
    if a[0] == "C" and b[0] == "C" and math.hypot(a[1] - b[1], a[2] - b[2]) > 1e-15:
        return foot(a, (b[1], b[2])) if math.hypot(a[1] - b[1], a[2] - b[2]) > a[3] else \
            foot(a, (2 * a[1] - b[1], 2 * a[2] - b[2]))
    if a[0] == "L" and b[0] == "C":
        return foot(a, (b[1], b[2]))
    if a[0] == "C" and b[0] == "L":
        return foot(a, foot(b, (a[1], a[2])))
    return foot(a, near)


def _approach(a, b, near) -> Point:
    """Where carriers ``a`` and ``b`` (one an ellipse) that do not meet come closest near
    ``near``: the middle of the ellipse's point where the other's equation is extreme and the
    foot of that point on the other, the same point
    whichever is ``a``, so a sliver the chords made between two curves a hair apart closes
    on one point (as two circles' closest approach does) and is dropped."""
    if a[0] != "E" or (b[0] == "E" and (b[1].center, b[1].rx, b[1].ry, b[1].rotation) <
                       (a[1].center, a[1].rx, a[1].ry, a[1].rotation)):
        a, b = b, a                      # the same point whichever order they come in
    if b[0] == "S":
        p = foot(a, near)
        q = foot(b, p)
    else:
        p = _e_nearest(a[1], b, near)
        q = foot(b, p)
    return ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)


def _line_line(a, b):
    _, px, py, ux, uy = a
    _, qx, qy, vx, vy = b
    den = ux * vy - uy * vx
    if abs(den) < 1e-14:
        return []
    t = ((qx - px) * vy - (qy - py) * vx) / den
    return [(px + t * ux, py + t * uy)]


def _line_circle(ln, c):
    _, px, py, ux, uy = ln
    _, cx, cy, r = c
    fx, fy = cx - px, cy - py
    t0 = fx * ux + fy * uy                      # foot of the center on the line
    d = ux * fy - uy * fx                       # signed distance of the center from the line
    h2 = (r - d) * (r + d)
    if h2 < -(TANGENT * r) ** 2:
        return []
    if h2 <= (TANGENT * r) ** 2:
        return [(px + t0 * ux, py + t0 * uy)]
    h = math.sqrt(h2)
    return [(px + (t0 - h) * ux, py + (t0 - h) * uy), (px + (t0 + h) * ux, py + (t0 + h) * uy)]


def _circle_circle(c1, c2):
    _, x1, y1, r1 = c1
    _, x2, y2, r2 = c2
    dx, dy = x2 - x1, y2 - y1
    D = math.hypot(dx, dy)
    if D < 1e-15:
        return []
    ux, uy = dx / D, dy / D
    a = (r1 * r1 - r2 * r2 + D * D) / (2 * D)
    h2 = (r1 - a) * (r1 + a)
    tol = (TANGENT * min(r1, r2)) ** 2
    if h2 < -tol:
        return []
    if h2 <= tol:
        s = 1.0 if a >= 0 else -1.0                # the touching point, on the center line
        return [(x1 + s * r1 * ux, y1 + s * r1 * uy)]
    h = math.sqrt(h2)
    mx, my = x1 + a * ux, y1 + a * uy
    return [(mx - h * uy, my + h * ux), (mx + h * uy, my - h * ux)]
