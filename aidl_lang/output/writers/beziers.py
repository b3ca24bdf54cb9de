"""Cubic Béziers of arcs and elliptical arcs, for the formats that cannot hold an arc: the
LightBurn project (:mod:`.lightburn`, within 1e-4 mm) and the PDF template (:mod:`.pdf`,
within 1e-3 mm).  The machine files stay exact where the format holds it; here the bound is
stated and kept.

The standard construction (control arms ``4/3 tan(phi/4) r``, meeting the arc at both ends
and its middle) in equal pieces, at least one per quarter turn, and enough that the radial
error bound :func:`arc_error` of each piece is within the caller's ``tol`` mm (at most
:data:`MAX_PIECES`).  An elliptical arc is the unit circle's Béziers over its parameter mapped
by the ellipse's affine map (an affine image of a Bézier is the Bézier of the images), the
pieces counted for the major semi-axis.  Each list starts and ends exactly at the arc's own
end points, so a chain's joints meet.  Pieces are ``(p0, p1, p2, p3)``, (x, y) in mm.
"""
from __future__ import annotations

import math

from ..part.part import Arc, Circle, EllipticArc, Spline

MAX_PIECES = 4096          # Bézier pieces of one arc at most (a 40 m radius full circle)


def arc_error(radius: float, phi: float) -> float:
    """The bound (mm) of the radial error of the standard cubic Bézier of an arc of
    ``radius`` and sweep ``phi`` (radians, at most a half turn): ``r 4/27 sin^6(phi/4) /
    cos^2(phi/4)`` (twice the true maximum, which is 2/27 ...)."""
    q = abs(phi) / 4
    return radius * 4 / 27 * math.sin(q) ** 6 / math.cos(q) ** 2


def arc_pieces(radius: float, sweep: float, tol: float) -> int:
    """How many equal pieces of an arc of ``radius`` (mm) and ``sweep`` (radians) keep each
    piece's Bézier within ``tol`` mm of the arc (at least one per quarter turn)."""
    n = max(1, math.ceil(abs(sweep) / (math.pi / 2) - 1e-12))
    while n < MAX_PIECES and arc_error(radius, sweep / n) > tol:
        n = max(n + 1, int(n * 1.25))
    return n


def unit_arc_beziers(start: float, sweep: float, n: int) -> list:
    """The ``n`` cubic Béziers ((x, y) x 4) of the unit-circle arc from angle ``start``
    sweeping ``sweep`` radians, in equal pieces."""
    out = []
    phi = sweep / n
    k = 4.0 / 3.0 * math.tan(phi / 4)
    for i in range(n):
        a0 = start + phi * i
        a1 = a0 + phi
        c0, s0, c1, s1 = math.cos(a0), math.sin(a0), math.cos(a1), math.sin(a1)
        out.append(((c0, s0), (c0 - k * s0, s0 + k * c0), (c1 + k * s1, s1 - k * c1), (c1, s1)))
    return out


def arc_beziers(a: Arc, tol: float) -> list:
    """Cubic Béziers of arc ``a`` within ``tol`` mm of it (the ends exactly its ends)."""
    cx, cy = a.center
    r = a.radius
    bs = unit_arc_beziers(a.start_angle, a.sweep, arc_pieces(r, a.sweep, tol))
    out = [tuple((cx + r * x, cy + r * y) for x, y in b) for b in bs]
    # the ends exactly the arc's own (the chain's joints meet)
    out[0] = (a.start,) + out[0][1:]
    out[-1] = out[-1][:3] + (a.end,)
    return out


def ellipse_beziers(s: EllipticArc, tol: float) -> list:
    """Cubic Béziers of elliptical arc ``s``: the unit circle's arc over its parameters
    mapped by the ellipse's affine map (centre, axes, rotation); a point of the Bézier is off
    the ellipse by at most the major semi-axis times the unit error, kept within ``tol``."""
    e = s.curve
    rmax = max(e.rx, e.ry)
    bs = unit_arc_beziers(s.start_param, s.sweep, arc_pieces(rmax, s.sweep, tol))
    cr, sr = math.cos(e.rotation), math.sin(e.rotation)
    cx, cy = e.center

    def m(p):
        x, y = e.rx * p[0], e.ry * p[1]
        return (cx + cr * x - sr * y, cy + sr * x + cr * y)
    out = [tuple(m(p) for p in b) for b in bs]
    out[0] = (s.start,) + out[0][1:]
    out[-1] = out[-1][:3] + (s.end,)
    return out


def segment_beziers(s, tol: float) -> list:
    """Cubic Béziers of a curved segment: a spline piece its own spans (exact), an elliptical
    arc :func:`ellipse_beziers`, a whole circle its arc from angle 0 (:func:`arc_beziers`, in
    its own direction), an arc :func:`arc_beziers`; each within ``tol`` mm."""
    if isinstance(s, Spline):
        return [tuple(tuple(map(float, p)) for p in b) for b in s.spans]
    if isinstance(s, EllipticArc):
        return ellipse_beziers(s, tol)
    if isinstance(s, Circle):
        sweep = 2 * math.pi if s.ccw else -2 * math.pi
        return arc_beziers(Arc(s.center, s.radius, 0.0, sweep), tol)
    return arc_beziers(s, tol)
