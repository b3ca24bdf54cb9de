"""Interpolating cubic splines, held exactly as cubic Bézier spans.

:func:`interpolate` gives the C2 cubic spline through ``m`` points with *chord-length*
parametrisation (the parameter step between two points is their distance): ``closed=True``
makes it periodic (the curve returns to the first point with equal first and second
derivatives there), ``closed=False`` uses *natural* end conditions (zero second derivative at
both ends).  Reference: de Boor, *A Practical Guide to Splines*, ch. IV (the tangent
equations of cubic Hermite interpolation); the C2 condition at point ``i`` between parameter
steps ``h[i-1]`` and ``h[i]`` is

    h[i] D[i-1] + 2 (h[i-1] + h[i]) D[i] + h[i-1] D[i+1]
        = 3 (h[i] (P[i] - P[i-1]) / h[i-1] + h[i-1] (P[i+1] - P[i]) / h[i])

for the tangents ``D`` (derivatives by the chord-length parameter), solved as one linear
system (periodic rows wrap around; natural ends: ``2 D[0] + D[1] = 3 (P[1] - P[0]) / h[0]``).
Span ``i`` is then the cubic Bézier ``P[i], P[i] + h[i] D[i] / 3, P[i+1] - h[i] D[i+1] / 3,
P[i+1]``, exactly the spline on that step.

:class:`CubicSpline` holds the control points (``3 n + 1`` points, mm, for ``n`` spans) and the
parameter steps.  A position on it is ``u`` in ``[0, n]``: span ``floor(u)`` at local parameter
``u - floor(u)`` (a closed curve takes ``u`` modulo ``n``).  Everything the outputs need is
computed on the spans: exact bounding box (roots of the derivative), de Casteljau splitting,
arc length (Gauss-Legendre), the clamped B-spline form (DXF ``SPLINE``, STEP
``B_SPLINE_CURVE_WITH_KNOTS``), tessellation within a chord-error bound, crossings with lines,
circles and other splines (polynomial roots polished by Newton to 1e-12 mm), the foot of a
point and the exact signed area under the curve.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

Point = tuple[float, float]
Bez = tuple[Point, Point, Point, Point]

MAX_POINTS = 2000           # points of one spline (the tangent system is dense)
_GL_X, _GL_W = np.polynomial.legendre.leggauss(16)


class SplineError(ValueError):
    """Points a spline cannot pass through smoothly (too few, repeated); the message says
    which and how to fix it."""


# ------------------------------------------------------------------ interpolation
def _steps(P: np.ndarray, closed: bool) -> np.ndarray:
    Q = np.roll(P, -1, axis=0) if closed else P[1:]
    D = Q - P[:len(Q)]
    return np.hypot(D[:, 0], D[:, 1])


def check_points(pts, closed: bool) -> None:
    """Raise :class:`SplineError` for points that give no spline: fewer than 3 (closed) or 2
    (open), more than :data:`MAX_POINTS`, or two consecutive points (the last and the first,
    closed) at the same place (within 1e-9 mm, relative past 1 m)."""
    m = len(pts)
    need = 3 if closed else 2
    if m < need:
        raise SplineError(f"a {'closed' if closed else 'open'} Spline needs at least {need} "
                          f"points, got {m}: add points along the curve"
                          + (" (a closed outline goes round at least 3)" if closed else ""))
    if m > MAX_POINTS:
        raise SplineError(f"a Spline takes at most {MAX_POINTS} points, got {m}")
    P = np.asarray(pts, dtype=float)
    scale = max(1.0, float(np.abs(P).max()))
    h = _steps(P, closed)
    for i, d in enumerate(h.tolist()):
        if d <= 1e-9 * scale:
            j = (i + 1) % m
            raise SplineError(f"a Spline's points[{i}] and points[{j}] are the same point "
                              f"({P[i, 0]:g}, {P[i, 1]:g}): a smooth curve cannot pass "
                              f"through one point twice in a row; remove one of them")


def interpolation_matrix(h: np.ndarray, closed: bool, corners=()) -> np.ndarray:
    """The ``(3 n + 1) x m`` matrix ``W`` with ``control points = W @ points`` for parameter
    steps ``h`` (``n`` spans, ``m`` points; ``n = m`` closed, ``m - 1`` open).

    ``corners``: indices of points where the curve may turn sharply (tangent-discontinuous):
    the spline is cut there into open runs, each the natural spline through its points (a
    run of two points is a straight line), so each corner is the end of one run and the start
    of the next; a closed curve with corners is the chain of runs from corner to corner."""
    cs = sorted(set(int(c) for c in corners))
    if cs:
        return _cornered_matrix(np.asarray(h, dtype=float), closed, cs)
    n = len(h)
    m = n if closed else n + 1
    A = np.zeros((m, m))
    R = np.zeros((m, m))            # right-hand side as a matrix on the points
    for i in range(m):
        if not closed and i == 0:
            A[0, 0], A[0, 1] = 2.0, 1.0
            R[0, 0], R[0, 1] = -3.0 / h[0], 3.0 / h[0]
            continue
        if not closed and i == m - 1:
            A[i, i - 1], A[i, i] = 1.0, 2.0
            R[i, i - 1], R[i, i] = -3.0 / h[-1], 3.0 / h[-1]
            continue
        hp, hn = h[i - 1], h[i % n]
        ip, inx = (i - 1) % m, (i + 1) % m
        A[i, ip] += hn
        A[i, i] += 2 * (hp + hn)
        A[i, inx] += hp
        R[i, i] += 3 * hn / hp - 3 * hp / hn
        R[i, ip] -= 3 * hn / hp
        R[i, inx] += 3 * hp / hn
    T = np.linalg.solve(A, R)       # tangents = T @ points
    W = np.zeros((3 * n + 1, m))
    eye = np.eye(m)
    for i in range(n):
        j = (i + 1) % m
        W[3 * i] = eye[i]
        W[3 * i + 1] = eye[i] + h[i] / 3 * T[i]
        W[3 * i + 2] = eye[j] - h[i] / 3 * T[j]
    W[3 * n] = eye[0] if closed else eye[m - 1]
    return W


def _cornered_matrix(h: np.ndarray, closed: bool, cs: list[int]) -> np.ndarray:
    """:func:`interpolation_matrix` with corners ``cs`` (sorted point indices): each run
    between consecutive corners (and, open, the ends) is interpolated on its own."""
    n = len(h)
    m = n if closed else n + 1
    stops = list(cs) if closed else sorted(set([0] + cs + [m - 1]))
    runs = []
    if closed:
        for k, c in enumerate(stops):
            nxt = stops[(k + 1) % len(stops)]
            length = (nxt - c) % m or m
            runs.append([(c + j) % m for j in range(length + 1)])
    else:
        runs = [list(range(a, b + 1)) for a, b in zip(stops, stops[1:])]
    W = np.zeros((3 * n + 1, m))
    for run in runs:
        k = len(run) - 1                        # spans of the run: run[j] -> run[j + 1]
        hr = np.array([h[run[j]] for j in range(k)])
        Wr = interpolation_matrix(hr, False)    # (3 k + 1) x (k + 1), on the run's points
        for j in range(k):
            span = run[j]                       # the global span starting at that point
            for q in range(4):
                W[3 * span + q] = 0.0
                for col, pt in enumerate(run):
                    W[3 * span + q, pt] += Wr[3 * j + q, col]
    last = np.zeros(m)
    last[0 if closed else m - 1] = 1.0
    W[3 * n] = last
    return W


def interpolate(points, closed: bool, corners=()) -> "CubicSpline":
    """The C2 cubic spline through ``points`` (m x 2, mm) with chord-length parametrisation:
    periodic when ``closed``, natural ends otherwise (see the module docstring); with
    ``corners`` (point indices), C2 between corners and sharp at them
    (:func:`interpolation_matrix`).  Raises :class:`SplineError` (:func:`check_points`)."""
    check_points(points, closed)
    P = np.asarray(points, dtype=float)
    h = _steps(P, closed)
    C = interpolation_matrix(h, closed, corners) @ P
    ctrl = [(float(x), float(y)) for x, y in C]
    for i in range(len(P)):         # the curve passes through the points bit for bit
        ctrl[3 * i if 3 * i < len(ctrl) else 0] = (float(P[i, 0]), float(P[i, 1]))
    if closed:
        ctrl[-1] = ctrl[0]
    return CubicSpline(tuple(ctrl), tuple(float(v) for v in h), closed)


def bezier_chain(points, closed: bool = False) -> "CubicSpline":
    """The :class:`CubicSpline` whose spans are the cubic Bézier segments of ``points``
    (``p0, c1, c2, p1, c3, c4, p2, ...``: ``3 k + 1`` points, mm; ``closed``: the last is the
    first), the control points exactly as given; each span's parameter step is its chord (its
    control polygon's length for a span that returns to its start).  Raises
    :class:`SplineError` for a count that is not ``3 k + 1``."""
    ctrl = [(float(p[0]), float(p[1])) for p in points]
    if len(ctrl) < 4 or (len(ctrl) - 1) % 3:
        raise SplineError(f"a Bezier chain takes 3k+1 points, got {len(ctrl)}")
    if closed:
        ctrl[-1] = ctrl[0]
    h = []
    for i in range(0, len(ctrl) - 1, 3):
        b = ctrl[i:i + 4]
        h.append(math.dist(b[0], b[3]) or sum(math.dist(b[j], b[j + 1]) for j in range(3))
                 or 1.0)
    return CubicSpline(tuple(ctrl), tuple(h), bool(closed))


# ------------------------------------------------------------------ Bézier spans
def bez_at(b, t: float) -> Point:
    s = 1.0 - t
    c0, c1, c2, c3 = s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t
    return (c0 * b[0][0] + c1 * b[1][0] + c2 * b[2][0] + c3 * b[3][0],
            c0 * b[0][1] + c1 * b[1][1] + c2 * b[2][1] + c3 * b[3][1])


def bez_d1(b, t: float) -> Point:
    s = 1.0 - t
    return tuple(3 * (s * s * (b[1][k] - b[0][k]) + 2 * s * t * (b[2][k] - b[1][k])
                      + t * t * (b[3][k] - b[2][k])) for k in (0, 1))


def bez_d2(b, t: float) -> Point:
    s = 1.0 - t
    return tuple(6 * (s * (b[2][k] - 2 * b[1][k] + b[0][k]) + t * (b[3][k] - 2 * b[2][k] + b[1][k]))
                 for k in (0, 1))


def split(b, t: float) -> tuple[Bez, Bez]:
    """De Casteljau: the span ``b`` cut at local parameter ``t`` into ``([0, t], [t, 1])``,
    each reparametrised to ``[0, 1]``; the halves share the point ``bez_at(b, t)``."""
    def lerp(p, q):
        return (p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t)
    p01, p12, p23 = lerp(b[0], b[1]), lerp(b[1], b[2]), lerp(b[2], b[3])
    p012, p123 = lerp(p01, p12), lerp(p12, p23)
    m = lerp(p012, p123)
    return (b[0], p01, p012, m), (m, p123, p23, b[3])


def piece(b, t0: float, t1: float) -> Bez:
    """The part of span ``b`` from local parameter ``t0`` to ``t1`` (``t0 > t1``: reversed)."""
    if t0 > t1:
        r = piece(b, t1, t0)
        return (r[3], r[2], r[1], r[0])
    if t1 < 1.0:
        b = split(b, t1)[0]
    if t0 > 0.0:
        b = split(b, t0 / t1 if t1 > 0 else 0.0)[1]
    return b


def _poly(b, k: int) -> np.ndarray:
    """Power-basis coefficients (highest first) of coordinate ``k`` of span ``b``."""
    p0, p1, p2, p3 = (c[k] for c in b)
    return np.array([-p0 + 3 * p1 - 3 * p2 + p3, 3 * p0 - 6 * p1 + 3 * p2, -3 * p0 + 3 * p1, p0])


ROOT_LEAD = 1e-14      # of the largest coefficient: a leading one below it is dropped


def _der(c: np.ndarray) -> np.ndarray:
    """Derivative of power-basis coefficients (highest first), length kept minus one."""
    n = len(c) - 1
    return c[:-1] * np.arange(n, 0, -1)


def _real_roots(coef: np.ndarray, lo=-1e-9, hi=1 + 1e-9) -> list[float]:
    """The real roots in ``[lo, hi]`` (clamped to [0, 1]) of the polynomial ``coef`` (power
    basis, highest first).  Leading coefficients below ``ROOT_LEAD`` of the largest are
    dropped: their roots lie past 1e14 (far outside the span), and a subnormal one (a control
    point at 2.2e-309 mm) overflowed NumPy's companion matrix to inf (LinAlgError)."""
    c = np.asarray(coef, dtype=float)
    scale = float(np.abs(c).max()) if len(c) else 0.0
    if scale == 0.0 or not math.isfinite(scale):
        return []
    c = c / scale
    c = c[np.argmax(np.abs(c) > ROOT_LEAD):] if (np.abs(c) > ROOT_LEAD).any() else c[:0]
    if len(c) <= 1:
        return []
    r = np.roots(c)
    out = []
    for z in r:
        if abs(z.imag) <= 1e-7 and lo <= z.real <= hi:
            out.append(min(1.0, max(0.0, float(z.real))))
    return out


# a point its neighbours' lines turn at by no more than this lies in a straight run of the
# points; the curve leaving such a run's chord by more than STRAY of the chord (and
# STRAY_MIN mm) has swung off it (:func:`strays`, W0412)
STRAIGHT_TURN = math.radians(3)
STRAY = 0.03
STRAY_MIN = 1.0
# points in line (turned by no more than LINED) mean the run straight: the curve may leave it
# by LINED_STRAY of the chord and LINED_MIN mm (run hb's paddle: sides through five points on
# x = 97.5 bowed 0.67 mm, 196.34 mm across where 195 was asked)
LINED = math.radians(0.5)
LINED_STRAY = 0.01
LINED_MIN = 0.25


def strays(c: "CubicSpline", corners=()) -> list[tuple[int, float, int]]:
    """Where the curve swings off a straight run of its points (issue 111, runs gu and gx: a
    fern board's flat top through (-100, 318), (0, 320), (100, 318) humped 5.6 mm between
    them, the curve overshooting the 35-degree shoulder at (100, 318); a canoe yoke's near
    straight edge swelled 9.7 mm into a knob before its rounded end): ``(span i, how far the
    curve leaves span i's chord (mm), the point near it where the points turn most)`` for
    each span from or to a point of a straight run (its turn at most :data:`STRAIGHT_TURN`,
    not a corner, not an open curve's end) that the curve leaves by more than
    ``max(STRAY_MIN, STRAY * chord)`` (points in line, turned at most :data:`LINED`:
    ``max(LINED_MIN, LINED_STRAY * chord)``), the farthest first.  The chord distance of a span is
    a cubic in its parameter: its extremes are exact."""
    n = c.n
    P = [c.ctrl[3 * i] for i in range(n)] + ([] if c.closed else [c.ctrl[3 * n]])
    m = len(P)

    def turn(i: int) -> float | None:           # signed: + to the left
        if not c.closed and (i <= 0 or i >= m - 1) or i % m in corners:
            return None
        a, b, d = P[(i - 1) % m], P[i % m], P[(i + 1) % m]
        u, v = (b[0] - a[0], b[1] - a[1]), (d[0] - b[0], d[1] - b[1])
        return math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])

    signed = [turn(i) for i in range(m)]
    turns = [None if t is None else abs(t) for t in signed]
    for i in range(m):
        # the middle of an S (its neighbours turn each way, more than a straight run's) is
        # no straight run: a snake's body, a wave
        a, b = signed[(i - 1) % m], signed[(i + 1) % m]
        if turns[i] is not None and turns[i] <= STRAIGHT_TURN and a is not None \
                and b is not None and abs(a) > STRAIGHT_TURN and abs(b) > STRAIGHT_TURN \
                and (a > 0) != (b > 0) and (c.closed or 0 < i < m - 1):
            turns[i] = math.inf
    out = []
    for i in range(n):
        j = (i + 1) % m
        ends = [t for t in (turns[i], turns[j]) if t is not None and t <= STRAIGHT_TURN]
        if not ends:
            continue
        b = c.span(i)
        cx, cy = P[j][0] - P[i][0], P[j][1] - P[i][1]
        chord = math.hypot(cx, cy)
        if chord <= 0.0:
            continue
        # the distance from the chord, signed: ((B - P0) x chord) / |chord|, a cubic in t
        d = (_poly(b, 0) * cy - _poly(b, 1) * cx) / chord
        d[-1] -= (P[i][0] * cy - P[i][1] * cx) / chord
        far = max(abs(float(np.polyval(d, t))) for t in _real_roots(_der(d)) + [0.0, 1.0])
        lined = min(ends) <= LINED
        if far > (max(LINED_MIN, LINED_STRAY * chord) if lined else
                  max(STRAY_MIN, STRAY * chord)):
            near = [k % m for k in (i - 1, i, i + 1, i + 2) if c.closed or 0 <= k < m]
            sharp = max(near, key=lambda k: abs(signed[k] or 0.0))
            out.append((i, far, sharp))
    return sorted(out, key=lambda r: -r[1])


def bez_extremes(b) -> tuple[list[float], list[float]]:
    """The local parameters in (0, 1) where span ``b``'s x (first list) and y (second) have
    zero derivative."""
    out = []
    for k in (0, 1):
        d = _der(_poly(b, k))
        out.append([t for t in _real_roots(d, 1e-12, 1 - 1e-12)])
    return out[0], out[1]


def bez_box(b) -> tuple[float, float, float, float]:
    """Exact ``(x0, y0, x1, y1)`` of span ``b``: its ends and its derivative roots."""
    tx, ty = bez_extremes(b)
    xs = [b[0][0], b[3][0]] + [bez_at(b, t)[0] for t in tx]
    ys = [b[0][1], b[3][1]] + [bez_at(b, t)[1] for t in ty]
    return min(xs), min(ys), max(xs), max(ys)


def bez_area(b) -> float:
    """``1/2 * integral of (x dy - y dx)`` over span ``b`` (mm^2): exact (the integrand is a
    polynomial of degree 5, 3-point Gauss-Legendre integrates it exactly)."""
    xs, ws = (-math.sqrt(0.6), 0.0, math.sqrt(0.6)), (5 / 9, 8 / 9, 5 / 9)
    a = 0.0
    for x, w in zip(xs, ws):
        t = 0.5 * (x + 1)
        p, d = bez_at(b, t), bez_d1(b, t)
        a += w * (p[0] * d[1] - p[1] * d[0])
    return 0.25 * a


def bez_length(b) -> float:
    """Arc length (mm) of span ``b``: 16-point Gauss-Legendre on each half."""
    total = 0.0
    for lo in (0.0, 0.5):
        for x, w in zip(_GL_X, _GL_W):
            dx, dy = bez_d1(b, lo + 0.25 * (x + 1))
            total += 0.25 * w * math.hypot(dx, dy)
    return total


def bez_pieces(b, tol: float) -> int:
    """Chords for span ``b`` (uniform in its parameter) so that no point of the curve is
    farther than ``tol`` mm from its chord: the linear-interpolation bound
    ``max|B''| / (8 k^2)`` with ``|B''| <= 6 max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|)``."""
    m = max(math.hypot(b[0][0] - 2 * b[1][0] + b[2][0], b[0][1] - 2 * b[1][1] + b[2][1]),
            math.hypot(b[1][0] - 2 * b[2][0] + b[3][0], b[1][1] - 2 * b[2][1] + b[3][1]))
    return max(1, min(20000, math.ceil(math.sqrt(0.75 * m / tol)))) if m > 0 else 1


# ------------------------------------------------------------------ the curve
@dataclass(frozen=True)
class CubicSpline:
    """``n`` cubic Bézier spans: ``ctrl`` holds ``3 n + 1`` control points (mm), span ``i``
    is ``ctrl[3 i : 3 i + 4]``; ``h[i]`` is span ``i``'s parameter step (its chord, mm), so
    the spline's own parameter ``s`` runs ``sum(h)``; ``closed``: the last point is the first
    and positions wrap around."""
    ctrl: tuple[Point, ...]
    h: tuple[float, ...]
    closed: bool = False

    @property
    def n(self) -> int:
        return len(self.h)

    def span(self, i: int) -> Bez:
        if self.closed:
            i %= self.n
        c = self.ctrl
        return (c[3 * i], c[3 * i + 1], c[3 * i + 2], c[3 * i + 3])

    def locate(self, u: float) -> tuple[int, float]:
        """``(span, local t)`` of position ``u``."""
        n = self.n
        if self.closed:
            u %= n
        else:
            u = min(max(u, 0.0), float(n))
        i = min(int(math.floor(u)), n - 1)
        return i, u - i

    def at(self, u: float) -> Point:
        i, t = self.locate(u)
        return bez_at(self.span(i), t)

    def d1(self, u: float) -> Point:
        """Derivative by the chord-length parameter ``s`` at ``u`` (unitless)."""
        i, t = self.locate(u)
        d = bez_d1(self.span(i), t)
        return (d[0] / self.h[i], d[1] / self.h[i])

    def d2(self, u: float) -> Point:
        """Second derivative by ``s`` at ``u`` (1/mm)."""
        i, t = self.locate(u)
        d = bez_d2(self.span(i), t)
        return (d[0] / self.h[i] ** 2, d[1] / self.h[i] ** 2)

    def tangent(self, u: float) -> Point:
        """Unit direction of increasing ``u``."""
        i, t = self.locate(u)
        b = self.span(i)
        dx, dy = bez_d1(b, t)
        L = math.hypot(dx, dy)
        if L < 1e-300:           # a cusp of the control polygon: look a little further
            dx, dy = bez_d2(b, t)
            L = math.hypot(dx, dy) or 1.0
        return (dx / L, dy / L)

    # ---------------------------------------------------------------- pieces
    def spans_between(self, u0: float, u1: float) -> list[Bez]:
        """The Bézier spans of the curve from ``u0`` to ``u1`` in that direction (a closed
        curve wraps: ``u1 - u0`` may reach ``n``), cut by de Casteljau at the ends."""
        if u1 < u0:
            return [(b[3], b[2], b[1], b[0]) for b in reversed(self.spans_between(u1, u0))]
        if not self.closed:
            u0, u1 = max(0.0, u0), min(float(self.n), u1)
        out = []
        i = math.floor(u0)
        while i < u1:
            t0 = max(u0 - i, 0.0)
            t1 = min(u1 - i, 1.0)
            if t1 > t0:
                out.append(self.span(i) if (t0, t1) == (0.0, 1.0) else piece(self.span(i), t0, t1))
            i += 1
        return out

    def box(self) -> tuple[float, float, float, float]:
        """Exact ``(x0, y0, x1, y1)`` of the whole curve."""
        bs = [bez_box(self.span(i)) for i in range(self.n)]
        return (min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
                max(b[3] for b in bs))

    def length(self) -> float:
        return sum(bez_length(self.span(i)) for i in range(self.n))

    def bspline(self) -> tuple[int, list[float], list[Point]]:
        """``(3, knots, control points)``: the clamped degree-3 B-spline equal to the curve
        (knots at the chord-length parameters, interior ones triple: each span is one
        Bézier piece), for DXF ``SPLINE`` and STEP."""
        return bspline_of(list(self.ctrl), list(self.h))

    # ---------------------------------------------------------------- queries
    def _hulls(self) -> np.ndarray:
        """``n x 4 x 2``: each span's control points (a span lies in their convex hull)."""
        got = self.__dict__.get("_hull_cache")
        if got is None:
            C = np.asarray(self.ctrl, dtype=float)
            idx = 3 * np.arange(self.n)[:, None] + np.arange(4)[None, :]
            got = C[idx]
            object.__setattr__(self, "_hull_cache", got)
        return got

    def foot(self, p: Point, spans=None) -> float:
        """The position ``u`` of the point of the curve nearest to ``p``: on each span, the
        roots of ``(B(t) - p) . B'(t)`` (degree 5) and the ends, the nearest kept; spans whose
        control box is farther than the best distance so far are skipped."""
        best, bu = math.inf, 0.0
        px, py = p
        H = self._hulls()
        lo, hi = H.min(axis=1), H.max(axis=1)
        dx = np.maximum(0.0, np.maximum(lo[:, 0] - px, px - hi[:, 0]))
        dy = np.maximum(0.0, np.maximum(lo[:, 1] - py, py - hi[:, 1]))
        bound = np.hypot(dx, dy)                       # no point of span i is nearer
        order = np.argsort(bound)
        for i in (order.tolist() if spans is None else spans):
            if spans is None and bound[i] ** 2 > best:     # sorted: no later span is nearer
                break
            b = self.span(i)
            X, Y = _poly(b, 0), _poly(b, 1)
            X[-1] -= px
            Y[-1] -= py
            g = np.convolve(X, _der(X)) + np.convolve(Y, _der(Y))
            for t in _real_roots(g) + [0.0, 1.0]:
                t = _polish_foot(b, p, t)
                q = bez_at(b, t)
                d = (q[0] - px) ** 2 + (q[1] - py) ** 2
                if d < best:
                    best, bu = d, i + t
        return bu

    def distance(self, p: Point) -> float:
        q = self.at(self.foot(p))
        return math.hypot(q[0] - p[0], q[1] - p[1])

    def cross_line(self, px, py, ux, uy) -> list[float]:
        """Positions ``u`` where the curve meets the line through ``(px, py)`` with unit
        direction ``(ux, uy)`` (roots of a cubic per span, Newton-polished)."""
        out = []
        H = self._hulls()
        sd = ux * (H[:, :, 1] - py) - uy * (H[:, :, 0] - px)       # control points' sides
        near = ~((sd > 0).all(axis=1) | (sd < 0).all(axis=1))
        for i in np.flatnonzero(near).tolist():
            b = self.span(i)
            f = ux * _poly(b, 1) - uy * _poly(b, 0)
            f[-1] -= ux * py - uy * px
            for t in _real_roots(f):
                out.append(i + _newton1(lambda s: ux * (bez_at(b, s)[1] - py) - uy * (bez_at(b, s)[0] - px),
                                        lambda s: ux * bez_d1(b, s)[1] - uy * bez_d1(b, s)[0], t))
        return _dedupe(out, self)

    def cross_circle(self, cx, cy, r) -> list[float]:
        """Positions ``u`` where the curve meets the circle (roots of a sextic per span)."""
        out = []
        H = self._hulls()
        lo, hi = H.min(axis=1), H.max(axis=1)
        dxn = np.maximum(0.0, np.maximum(lo[:, 0] - cx, cx - hi[:, 0]))
        dyn = np.maximum(0.0, np.maximum(lo[:, 1] - cy, cy - hi[:, 1]))
        far = np.hypot(np.maximum(np.abs(lo[:, 0] - cx), np.abs(hi[:, 0] - cx)),
                       np.maximum(np.abs(lo[:, 1] - cy), np.abs(hi[:, 1] - cy)))
        near = (np.hypot(dxn, dyn) <= r * (1 + 1e-9)) & (far >= r * (1 - 1e-9))
        for i in np.flatnonzero(near).tolist():
            b = self.span(i)
            X, Y = _poly(b, 0), _poly(b, 1)
            X[-1] -= cx
            Y[-1] -= cy
            f = np.convolve(X, X) + np.convolve(Y, Y)
            f[-1] -= r * r

            def g(s, b=b):
                q = bez_at(b, s)
                return math.hypot(q[0] - cx, q[1] - cy) - r

            def dg(s, b=b):
                q, d = bez_at(b, s), bez_d1(b, s)
                L = math.hypot(q[0] - cx, q[1] - cy) or 1.0
                return ((q[0] - cx) * d[0] + (q[1] - cy) * d[1]) / L
            for t in _real_roots(f, -1e-6, 1 + 1e-6):
                out.append(i + _newton1(g, dg, t))
        return _dedupe(out, self)

    def cross_spline(self, other: "CubicSpline", check=None) -> list[tuple[float, float]]:
        """``(u, v)`` pairs where this curve (at ``u``) meets ``other`` (at ``v``): spans
        whose boxes overlap are halved until small (:func:`_cross_bez`, ``check`` its
        deadline), then 2-D Newton."""
        out = []
        for i in range(self.n):
            for j in range(other.n):
                pair: list = []
                _cross_bez(self.span(i), other.span(j), i, j, pair, check)
                if len(pair) > RUN_LEAVES:
                    # the spans run along each other (within 1e-3 mm: a curve drawn out and
                    # back over another): a few of the leaves along the stretch will do
                    pair = pair[::math.ceil(len(pair) / RUN_SEEDS)] + pair[-1:]
                out += pair
        res = []
        for u, v in out:
            u, v = newton2(self, other, u, v)
            p, q = self.at(u), other.at(v)
            if math.hypot(p[0] - q[0], p[1] - q[1]) <= 1e-7 and not any(
                    abs(u - a) < 1e-7 and abs(v - b) < 1e-7 for a, b in res):
                res.append((u, v))
        return res


def self_crossings(c: CubicSpline, check=None) -> list[tuple[float, float]]:
    """``(u, v)``, ``u < v``: where curve ``c`` crosses itself (two spans that are not
    neighbours, or neighbours away from their shared point): spans whose control boxes
    overlap, halved until small (:func:`_cross_bez`), then 2-D Newton (:func:`newton2`).
    A stretch where the curve runs back along itself is found after at most
    :data:`MAX_LEAVES` small boxes, whatever its length.  ``check``: a callable that raises
    to stop (the compile's deadline), called every few thousand box pairs."""
    H = c._hulls()
    lo, hi = H.min(axis=1), H.max(axis=1)
    over = ((lo[:, None, 0] <= hi[None, :, 0]) & (lo[None, :, 0] <= hi[:, None, 0])
            & (lo[:, None, 1] <= hi[None, :, 1]) & (lo[None, :, 1] <= hi[:, None, 1]))
    n = c.n
    cand = []
    for i, j in zip(*np.nonzero(np.triu(over, 1))):
        i, j = int(i), int(j)
        cand_ij: list = []
        if not _cross_bez(c.span(i), c.span(j), i, j, cand_ij, check):
            cand_ij = cand_ij[::len(cand_ij) // 8]    # on a stretch run twice: a few will do
        cand += cand_ij
    out: list = []
    scale = max(1.0, float(np.abs(H).max()))
    for u, v in cand:
        u, v = newton2(c, c, u, v)
        if c.closed:
            u, v = u % n, v % n
        u, v = min(u, v), max(u, v)
        gap = v - u if not c.closed else min(v - u, n - (v - u))
        p, q = c.at(u), c.at(v)
        if gap < 1e-6 or math.hypot(p[0] - q[0], p[1] - q[1]) > 1e-7 * scale:
            continue                 # the shared point of neighbours, or no crossing
        if _stays_at(c, u, v, p, 1e-6 * scale):
            continue                 # a cusp: the curve stops there and turns (a zero handle)
        if not any(abs(u - a) < 1e-7 and abs(v - b) < 1e-7 for a, b in out):
            out.append((u, v))
    return out


def _stays_at(c: CubicSpline, u: float, v: float, p, tol: float) -> bool:
    """Whether curve ``c`` stays within ``tol`` of point ``p`` all the way from parameter
    ``u`` to ``v`` (the shorter way round a closed curve): two parameters at one point with
    nothing between them but that point are a cusp, where a span ends with a handle of zero
    length and the curve stops before it turns (a polyline written as a cubic, a DXF spline's
    repeated control point), not a crossing; a crossing leaves the point and comes back."""
    a, b = u, v
    if c.closed and v - u > c.n / 2:
        a, b = v, u + c.n
    for k in range(1, 16):
        x, y = c.at((a + (b - a) * k / 16) % c.n if c.closed else a + (b - a) * k / 16)
        if math.hypot(x - p[0], y - p[1]) > tol:
            return False
    return True


def bspline_of(ctrl: list, h: list) -> tuple[int, list[float], list[Point]]:
    """The clamped degree-3 B-spline of Bézier spans ``ctrl`` (``3 n + 1`` points) with
    parameter steps ``h``: knots ``0 0 0 0 s1 s1 s1 ... sn sn sn sn`` (``s`` the running sum
    of ``h``)."""
    s = [0.0]
    for v in h:
        s.append(s[-1] + v)
    knots = [0.0] * 4
    for v in s[1:-1]:
        knots += [v] * 3
    knots += [s[-1]] * 4
    return 3, knots, list(ctrl)


def _dedupe(us: list[float], c: CubicSpline) -> list[float]:
    out: list[float] = []
    for u in sorted(us):
        if c.closed:
            u %= c.n
        if not any(abs(u - v) < 1e-9 or (c.closed and abs(abs(u - v) - c.n) < 1e-9) for v in out):
            out.append(u)
    return out


def _newton1(f, df, t: float) -> float:
    for _ in range(30):
        d = df(t)
        if d == 0.0:
            break
        step = f(t) / d
        t2 = min(1.0, max(0.0, t - step))
        if abs(t2 - t) < 1e-16:
            t = t2
            break
        t = t2
    return t


def _polish_foot(b, p, t: float) -> float:
    for _ in range(20):
        q, d, dd = bez_at(b, t), bez_d1(b, t), bez_d2(b, t)
        rx, ry = q[0] - p[0], q[1] - p[1]
        g = rx * d[0] + ry * d[1]
        dg = d[0] * d[0] + d[1] * d[1] + rx * dd[0] + ry * dd[1]
        if dg <= 0.0:
            break
        t2 = min(1.0, max(0.0, t - g / dg))
        if abs(t2 - t) < 1e-16:
            return t2
        t = t2
    return t


def newton2(a: CubicSpline, b: CubicSpline, u: float, v: float, iters: int = 40):
    """Newton on ``a(u) - b(v) = 0`` from ``(u, v)``."""
    for _ in range(iters):
        p, q = a.at(u), b.at(v)
        fx, fy = p[0] - q[0], p[1] - q[1]
        i, _t = a.locate(u)
        j, _s = b.locate(v)
        da = bez_d1(a.span(i), _t)
        db = bez_d1(b.span(j), _s)
        det = -da[0] * db[1] + da[1] * db[0]
        if abs(det) < 1e-300:
            break
        du = (-fx * db[1] + fy * db[0]) / det
        dv = (da[0] * fy - da[1] * fx) / det
        u, v = u - du, v - dv
        if abs(du) + abs(dv) < 1e-15:
            break
    return u, v


MAX_LEAVES = 2048     # small box pairs of one span pair: past it the spans run along each other
RUN_LEAVES = 64       # more leaves than crossing spans make (9 crossings, 4 leaves each at most)
RUN_SEEDS = 32        # ... then Newton starts from this many of them, evenly along


def _cross_bez(A, B, i, j, out, check=None) -> bool:
    """Append to ``out`` the ``(i + a, j + b)`` centres of the pairs of pieces of Bézier spans
    ``A`` (number ``i``) and ``B`` (``j``) whose control boxes still overlap once halved to
    1e-3 mm (or 40 times): the starting points of the crossings' Newton polish.  Two spans
    that run along each other (a coincident stretch, as a Spline whose points double back)
    make such a pair at every 1e-3 mm of the stretch: the search stops at
    :data:`MAX_LEAVES` of them and returns ``False`` (the candidates so far lie on the
    stretch).  ``check``: called every 4 096 box pairs (the compile's deadline; it raises
    to stop)."""
    stack = [(A, B, 0.0, 1.0, 0.0, 1.0, 0)]
    nodes = leaves = 0
    while stack:
        A, B, a0, a1, b0, b1, depth = stack.pop()
        nodes += 1
        if check is not None and not nodes % 4096:
            check()
        ba, bb = _hull_box(A), _hull_box(B)
        if ba[0] > bb[2] or bb[0] > ba[2] or ba[1] > bb[3] or bb[1] > ba[3]:
            continue
        size = max(ba[2] - ba[0], ba[3] - ba[1], bb[2] - bb[0], bb[3] - bb[1])
        if depth >= 40 or size < 1e-3:
            out.append((i + 0.5 * (a0 + a1), j + 0.5 * (b0 + b1)))
            leaves += 1
            if leaves >= MAX_LEAVES:
                return False
            continue
        A1, A2 = split(A, 0.5)
        B1, B2 = split(B, 0.5)
        am, bm = 0.5 * (a0 + a1), 0.5 * (b0 + b1)
        for X, x0, x1 in ((A2, am, a1), (A1, a0, am)):
            for Y, y0, y1 in ((B2, bm, b1), (B1, b0, bm)):
                stack.append((X, Y, x0, x1, y0, y1, depth + 1))
    return True


def _hull_box(b):
    xs = [p[0] for p in b]
    ys = [p[1] for p in b]
    return min(xs), min(ys), max(xs), max(ys)
