"""The DXF ``SPLINE`` as exact cubic Bézier pieces: its definition checked before ezdxf's
tools compute with it (:func:`_check_spline`: a named ``W0130`` reason for each defect),
then its B-spline cut into Bézier pieces, each raised to a cubic (:func:`_dxf_spline`; an
unclamped one clamped first, :func:`_clamped`).  Used by :mod:`.dxf`'s SPLINE reader."""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Spline
from ..model import _lerp, _plural, _Skip, bezier_spline


def _check_spline(e, P) -> None:
    """Raise :class:`_Skip` (class ``spline``, the entity named in the note) saying what is
    wrong with the definition of SPLINE ``e`` before ezdxf's tools compute with it (they raise
    ValueError, TypeError, IndexError or LinAlgError): a degree below 1 (past 3: no exact form
    here), fewer control points than the degree needs, a count of knots or weights that does
    not match the control points, knots that decrease or span nothing, a knot repeated past
    the degree inside the range (the curve breaks apart: ezdxf's Bézier pieces of it are
    wrong) or past degree + 1 at an end, a weight not above 0;
    without control points, fewer than two fit points or two consecutive ones at one place
    (``P``: a point in mm)."""
    deg = e.dxf.get("degree", 3)
    if deg < 1:
        raise _Skip(f"degree {deg}: a spline's degree is 1 or more", cls="spline", named=True)
    if deg > 3:
        raise _Skip(f"degree {deg}: no exact form here", named=True)
    n, knots, w = len(e.control_points), list(e.knots), list(e.weights)
    if n == 0:
        fit = [P(v) for v in e.fit_points]
        if len(fit) < 2:
            raise _Skip("no control points and no fit points" if not fit else
                        "one fit point and no control points: a curve needs two or more",
                        cls="spline", named=True)
        for k, (a, b) in enumerate(zip(fit, fit[1:])):
            if math.dist(a, b) <= 1e-9:
                raise _Skip(f"fit points {k + 1} and {k + 2} at one place ({a[0]:g}, "
                            f"{a[1]:g}) mm", cls="spline", named=True)
        return
    if n < deg + 1:
        raise _Skip(f"{_plural(n, 'control point')}: a spline of degree {deg} needs "
                    f"{deg + 1} or more", cls="spline", named=True)
    if knots and len(knots) != n + deg + 1:
        raise _Skip(f"{len(knots)} knots for {n} control points of degree {deg} (it needs "
                    f"{n + deg + 1})", cls="spline", named=True)
    if any(b < a for a, b in zip(knots, knots[1:])):
        raise _Skip("knots that decrease", cls="spline", named=True)
    if knots and not knots[n] > knots[deg]:
        raise _Skip("knots that span no parameter range", cls="spline", named=True)
    most = max((knots.count(k) for k in set(knots)), default=0)
    inner = max((knots.count(k) for k in set(knots) if knots and knots[deg] < k < knots[n]),
                default=0)
    if most > deg + 1 or inner > deg:     # past degree + 1 (degree, inside): it breaks apart
        raise _Skip(f"a knot repeated {max(most, inner)} times: the curve breaks apart there "
                    f"(degree {deg} allows {deg} inside its range, {deg + 1} at its ends)",
                    cls="spline", named=True)
    if w and len(w) != n:
        raise _Skip(f"{_plural(len(w), 'weight')} for {n} control points", cls="spline",
                    named=True)
    if any(not x > 0 for x in w):
        raise _Skip("a weight not above 0", cls="spline", named=True)


def _dxf_spline(e, P) -> Spline:
    """The :class:`Spline` of SPLINE ``e`` (checked by :func:`_check_spline`; ``P``: a point
    in mm): its B-spline (equal weights are no rational curve: dropped; an unclamped one is
    clamped, :func:`_clamped`) cut into Bézier pieces, each raised to a cubic."""
    bs = e.construction_tool()
    if bs.is_rational:
        w = list(bs.weights())
        if max(w) - min(w) > 1e-12 * max(w):
            raise _Skip("rational: no exact form here", named=True)
        from ezdxf.math import BSpline
        bs = BSpline(bs.control_points, order=bs.order, knots=bs.knots())
    if not bs.is_clamped:
        bs = _clamped(bs)
    deg = bs.degree
    if deg > 3:
        raise _Skip(f"degree {deg}: no exact form here")
    knots = list(bs.knots())
    spans = []
    for ctrl in bs.bezier_decomposition():
        pts = [P(v) for v in ctrl]
        if deg == 1:
            a, b = pts
            pts = [a, _lerp(a, b, 1 / 3), _lerp(a, b, 2 / 3), b]
        elif deg == 2:
            a, b, c = pts
            pts = [a, _lerp(a, b, 2 / 3), _lerp(c, b, 2 / 3), c]
        spans.append(pts)
    distinct = []
    for k in knots[deg:len(knots) - deg]:
        if not distinct or k - distinct[-1] > 1e-15 * max(1.0, abs(k)):
            distinct.append(k)
    steps = [b - a for a, b in zip(distinct, distinct[1:])]
    if len(steps) != len(spans) or min(steps, default=0) <= 0:
        steps = None
    return bezier_spline(spans, steps)


def _clamped(bs):
    """The B-spline ``bs`` (unclamped: its ends are not knots of multiplicity ``order``) as a
    clamped one: the same curve over its domain ``knots[degree]`` to ``knots[count]``, each end
    inserted until it is a knot of multiplicity ``order`` and the control points and knots
    outside dropped (the curve between is unchanged, Boehm's knot insertion)."""
    from ezdxf.math import BSpline
    k = list(bs.knots())
    a, b = k[bs.degree], k[bs.count]
    for t in (a, b):
        while list(bs.knots()).count(t) < bs.order:
            bs = bs.insert_knot(t)
    k = list(bs.knots())
    i, j = k.index(a), len(k) - 1 - k[::-1].index(b)
    sub = k[i:j + 1]
    return BSpline(list(bs.control_points)[i:i + len(sub) - bs.order], order=bs.order,
                   knots=sub)
