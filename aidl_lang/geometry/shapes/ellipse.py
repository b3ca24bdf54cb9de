"""The exact ellipse: a carrier for :mod:`.curves` (``("E", curve)``), its points, nearest
points and crossings with lines, circles, ellipses and splines.

An :class:`EllipseCurve` is the set of points ``center + R(rotation) (rx cos t, ry sin t)``
for the *eccentric anomaly* ``t`` (radians; the parameter of DXF ``ELLIPSE`` entities and of
OCP's ``Geom_Ellipse``), in canonical form: ``rx >= ry > 0`` (``rx`` the major semi-axis)
and ``0 <= rotation < pi``, so one ellipse has one representation.  Lengths in mm.

Crossings are roots of trigonometric polynomials: a line's or a conic's implicit equation
taken along ``t`` is ``sum c_m e^(i m t)`` for ``|m| <= 2``, i.e. a quartic in ``z = e^(i t)``
whose roots on the unit circle are the crossings, each polished by Newton; two crossings
closer than :data:`~.curves.TANGENT` times the size are one touching point (the extremum of
the equation between them), as for circles.  A spline meets an ellipse where its control
points, mapped into the ellipse's frame (where it is the unit circle; a Bézier maps with its
control points), meet the unit circle: :meth:`~.spline.CubicSpline.cross_circle`.
"""
from __future__ import annotations

import cmath
import math

import numpy as np

from ...base.records import Frozen

Point = tuple[float, float]

TOUCH = 1e-5        # relative distance below which two crossings are one touch (curves.TANGENT)
NEAR = 1e-10        # relative gap (the equations are scaled as distances) that still touches


class EllipseCurve(Frozen):
    """The whole ellipse (see the module text); build it with :func:`ellipse`."""
    __slots__ = ("center", "rx", "ry", "rotation")

    def __init__(self, center: Point, rx: float, ry: float, rotation: float):
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "rx", rx)
        object.__setattr__(self, "ry", ry)
        object.__setattr__(self, "rotation", rotation)

    # ---------------------------------------------------------- points
    def at(self, t: float) -> Point:
        c, s = math.cos(self.rotation), math.sin(self.rotation)
        u, v = self.rx * math.cos(t), self.ry * math.sin(t)
        return (self.center[0] + u * c - v * s, self.center[1] + u * s + v * c)

    def d1(self, t: float) -> Point:
        """dP/dt (mm per radian)."""
        c, s = math.cos(self.rotation), math.sin(self.rotation)
        u, v = -self.rx * math.sin(t), self.ry * math.cos(t)
        return (u * c - v * s, u * s + v * c)

    def local(self, p: Point) -> Point:
        """``p`` in the ellipse's frame: centre at the origin, major axis along x (mm)."""
        c, s = math.cos(self.rotation), math.sin(self.rotation)
        dx, dy = p[0] - self.center[0], p[1] - self.center[1]
        return (dx * c + dy * s, -dx * s + dy * c)

    def unit(self, p: Point) -> Point:
        """``p`` in the frame where the ellipse is the unit circle."""
        u, v = self.local(p)
        return (u / self.rx, v / self.ry)

    def param(self, p: Point) -> float:
        """The parameter ``t`` of a point of the ellipse (its angle in the unit frame)."""
        u, v = self.unit(p)
        return math.atan2(v, u)

    def implicit(self, p: Point) -> float:
        """``(u / rx)^2 + (v / ry)^2 - 1``: 0 on the ellipse, negative inside."""
        u, v = self.unit(p)
        return u * u + v * v - 1.0

    def foot(self, p: Point) -> float:
        """The parameter of the point nearest to ``p``: Newton on ``(P(t) - p) . P'(t)``
        from the point's own angle and the four vertices, the nearest root kept."""
        best, bt = math.inf, 0.0
        u, v = self.local(p)
        starts = [math.atan2(v * self.rx, u * self.ry), 0.0, math.pi / 2, math.pi, -math.pi / 2]
        a, b = self.rx, self.ry
        for t in starts:
            for _ in range(40):
                ct, st = math.cos(t), math.sin(t)
                ex, ey = a * ct - u, b * st - v
                f = -ex * a * st + ey * b * ct
                df = (a * st) ** 2 + (b * ct) ** 2 - ex * a * ct - ey * b * st
                if df <= 0:
                    df = (a * st) ** 2 + (b * ct) ** 2 or 1.0
                step = f / df
                step = max(-0.5, min(0.5, step))
                t -= step
                if abs(step) < 1e-15:
                    break
            d = (a * math.cos(t) - u) ** 2 + (b * math.sin(t) - v) ** 2
            if d < best:
                best, bt = d, t
        return bt

    def distance(self, p: Point) -> float:
        q = self.at(self.foot(p))
        return math.hypot(q[0] - p[0], q[1] - p[1])

    def tangent(self, t: float) -> Point:
        dx, dy = self.d1(t)
        L = math.hypot(dx, dy) or 1.0
        return (dx / L, dy / L)

    def box(self, t0: float, sweep: float) -> tuple[float, float, float, float]:
        """Exact ``(x0, y0, x1, y1)`` of the arc from ``t0`` sweeping ``sweep``: its ends and
        the extremes of x and y (where dx/dt or dy/dt is 0) that it passes."""
        c, s = math.cos(self.rotation), math.sin(self.rotation)
        tx = math.atan2(-self.ry * s, self.rx * c)      # dx/dt = 0
        ty = math.atan2(self.ry * c, self.rx * s)       # dy/dt = 0
        ts = [t0, t0 + sweep]
        lo, hi = min(t0, t0 + sweep), max(t0, t0 + sweep)
        for e in (tx, tx + math.pi, ty, ty + math.pi):
            k = math.ceil((lo - e) / (2 * math.pi))
            if e + 2 * math.pi * k <= hi:
                ts.append(e + 2 * math.pi * k)
        pts = [self.at(t) for t in ts]
        xs, ys = [q[0] for q in pts], [q[1] for q in pts]
        return (min(xs), min(ys), max(xs), max(ys))

    def moved(self, f) -> "EllipseCurve":
        """The ellipse under the rigid motion (or reflection) ``f`` of points: its centre
        and two axis ends moved."""
        c = f(self.center)
        a = f(self.at(0.0))
        b = f(self.at(math.pi / 2))
        return ellipse(c, self.rx, self.ry, math.atan2(a[1] - c[1], a[0] - c[0]))[0]

    def same(self, other: "EllipseCurve", tol: float) -> bool:
        """True when the two are one ellipse within ``tol`` mm."""
        if math.dist(self.center, other.center) > tol or abs(self.rx - other.rx) > tol \
                or abs(self.ry - other.ry) > tol:
            return False
        d = (self.rotation - other.rotation) % math.pi
        d = min(d, math.pi - d)
        return d * self.rx <= tol or self.rx - self.ry <= tol


def ellipse(center: Point, rx: float, ry: float, rotation: float) -> tuple[EllipseCurve, float]:
    """The canonical :class:`EllipseCurve` of semi-axes ``rx`` (along ``rotation``, radians)
    and ``ry``, and the shift ``s`` of its parameter: the point of parameter ``t`` as given
    is the canonical curve's point ``t - s``."""
    shift = 0.0
    rx, ry = float(rx), float(ry)
    rot = float(rotation)
    if rx < ry:
        rx, ry = ry, rx
        rot += math.pi / 2
        shift += math.pi / 2
    k = math.floor(rot / math.pi)
    rot -= k * math.pi
    shift += k * math.pi
    if rot >= math.pi:
        rot -= math.pi
        shift += math.pi
    return EllipseCurve((float(center[0]), float(center[1])), rx, ry, rot), shift


# ------------------------------------------------------------------ crossings
def _trig(e: EllipseCurve, g) -> np.ndarray:
    """Coefficients ``c_m``, m = -2..2, of ``g(P(t)) = sum c_m e^(i m t)`` (``g`` a polynomial
    of degree <= 2 in x, y), from 8 samples."""
    t = 2 * math.pi * np.arange(8) / 8
    G = np.array([g(e.at(float(a))) for a in t])
    F = np.fft.fft(G) / 8
    return np.array([F[-2], F[-1], F[0], F[1], F[2]])       # c_-2 .. c_2


def _eval(c: np.ndarray, t: float, k: int = 0) -> float:
    """The ``k``-th derivative of the trigonometric polynomial ``c`` at ``t``."""
    m = np.arange(-2, 3)
    return float(np.real(np.sum(c * (1j * m) ** k * np.exp(1j * m * t))))


def _roots(e: EllipseCurve, g, scale: float) -> list[Point]:
    c = _trig(e, g)
    mag = float(np.max(np.abs(c))) or 1.0
    poly = c[::-1] / mag                                  # z^2 g: c_2 z^4 + ... + c_-2
    while len(poly) > 1 and abs(poly[0]) < 1e-14:
        poly = poly[1:]
    if len(poly) < 2:
        return []
    cand = sorted(cmath.phase(z) for z in np.roots(poly) if abs(abs(z) - 1) < 1e-4)
    ts: list[float] = []
    for t in cand:                                       # Newton on g along t
        t0 = t
        for _ in range(30):
            d = _eval(c, t, 1)
            if d == 0:
                break
            step = _eval(c, t) / d
            if abs(step) > 1e-3:                         # a touch: g' vanishes there too
                t = t0
                break
            t -= step
            if abs(step) < 1e-16:
                break
        ts.append(t)
    # crossings closer than TOUCH * scale are one touch: the extremum of g between them
    ts.sort()
    groups: list[list[float]] = []
    for t in ts:
        if groups and (math.dist(e.at(groups[-1][-1]), e.at(t)) <= 2 * TOUCH * scale):
            groups[-1].append(t)
        else:
            groups.append([t])
    if len(groups) > 1 and math.dist(e.at(groups[0][0]), e.at(groups[-1][-1] - 2 * math.pi)) \
            <= 2 * TOUCH * scale:
        groups[0] = [t - 2 * math.pi for t in groups.pop()] + groups[0]
    out = []
    for grp in groups:
        t = grp[0]
        if len(grp) > 1 or abs(_eval(c, t)) > 1e-12 * mag:
            t = sum(grp) / len(grp)
            for _ in range(30):
                d2 = _eval(c, t, 2)
                if d2 == 0:
                    break
                step = _eval(c, t, 1) / d2
                step = max(-1e-3, min(1e-3, step))
                t -= step
                if abs(step) < 1e-16:
                    break
            if abs(_eval(c, t)) > NEAR * scale:      # curves apart there: no crossing
                continue
        out.append(e.at(t))
    return out


def _implicit(other: tuple):
    """The equation of carrier ``other`` (``("L", ...)``, ``("C", ...)``, ``("E", curve)``),
    scaled as a distance near the curve (as :func:`_roots` takes it)."""
    if other[0] == "L":
        _, px, py, ux, uy = other
        return lambda q: ux * (q[1] - py) - uy * (q[0] - px)
    if other[0] == "C":
        _, cx, cy, r = other
        return lambda q: ((q[0] - cx) ** 2 + (q[1] - cy) ** 2 - r * r) / max(r, 1e-300)
    f = other[1]
    return lambda q: f.implicit(q) * f.ry


def nearest_approach(e: EllipseCurve, other: tuple, near: Point) -> Point:
    """The point of ``e`` where the equation of carrier ``other`` (a line, circle or
    ellipse that does not meet ``e``) is extreme along ``e`` nearest to ``near``: where the
    two come closest there (Newton on the derivative of the trigonometric polynomial)."""
    c = _trig(e, _implicit(other))
    t = e.foot(near)
    for _ in range(60):
        d2 = _eval(c, t, 2)
        if d2 == 0:
            break
        step = max(-0.1, min(0.1, _eval(c, t, 1) / d2))
        t -= step
        if abs(step) < 1e-15:
            break
    return e.at(t)


def cross_line(e: EllipseCurve, px, py, ux, uy) -> list[Point]:
    """Where the line through ``(px, py)`` with unit direction ``(ux, uy)`` meets ``e``."""
    return _roots(e, lambda q: ux * (q[1] - py) - uy * (q[0] - px), e.rx)


def cross_circle(e: EllipseCurve, cx, cy, r) -> list[Point]:
    return _roots(e, lambda q: ((q[0] - cx) ** 2 + (q[1] - cy) ** 2 - r * r) / max(r, 1e-300),
                  min(e.rx, r))


def cross_ellipse(e: EllipseCurve, f: EllipseCurve) -> list[Point]:
    if f == e:
        return []
    return _roots(e, lambda q: f.implicit(q) * f.ry, min(e.ry, f.ry))


def cross_spline(e: EllipseCurve, curve) -> list[Point]:
    """Where the cubic spline ``curve`` meets ``e``: its control points mapped into the frame
    where ``e`` is the unit circle, crossed with that circle; points of the spline."""
    from .spline import CubicSpline
    mapped = CubicSpline(tuple(e.unit(p) for p in curve.ctrl), curve.h, curve.closed)
    return [curve.at(u) for u in mapped.cross_circle(0.0, 0.0, 1.0)]
