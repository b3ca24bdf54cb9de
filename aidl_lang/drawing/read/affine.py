"""Circles, ellipses and their arcs under an affine map, exactly: both readers hand a curve
as its centre and two *conjugate semi-diameters* ``u`` and ``v`` (the images of the two
semi-axes of the original curve: ``p(t) = center + u cos t + v sin t``, mm, y up), which
any affine map (a transform list with skews, a general matrix, nested DXF blocks with
non-uniform scales, mirrors, extrusions) keeps exact, and get back the true curve: its
principal semi-axes and turn from the singular value decomposition of ``[u v]``
(:func:`principal_axes`), a :class:`~aidl_lang.geometry.shapes.curves.Circle` or ``Arc`` when the
map is a similarity, else a whole ellipse ``(cx, cy, rx, ry, rotation)`` or an exact
:class:`~aidl_lang.geometry.shapes.curves.EllipticArc` (:func:`whole_curve`, :func:`arc_curve`).
A map that flattens the curve (``u`` and ``v`` parallel, or one of them zero) gives None:
the caller skips the shape with a note naming it (:func:`singular`)."""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Arc, Circle, elliptic_arc

SINGULAR = 1e-12        # |u x v| at or below this times |u| |v|: the map flattens the curve
ROUND = 1e-12           # semi-axes equal to this (relative): a circle


def singular(u, v) -> bool:
    """Whether the semi-diameters ``u`` and ``v`` (2D vectors) span no area: an affine map
    whose 2 x 2 part has a determinant of (relatively) zero, or a zero or non-finite vector."""
    nu, nv = math.hypot(u[0], u[1]), math.hypot(v[0], v[1])
    det = u[0] * v[1] - u[1] * v[0]
    if not (math.isfinite(nu) and math.isfinite(nv) and math.isfinite(det)):
        return True
    return nu == 0 or nv == 0 or abs(det) <= SINGULAR * nu * nv


def principal_axes(u, v) -> tuple[float, float, float]:
    """The semi-axes ``rx >= ry > 0`` (mm) and the turn of ``rx`` (radians) of the ellipse
    with conjugate semi-diameters ``u`` and ``v``: the singular values and the left
    singular vector of the 2 x 2 matrix ``[u v]`` (closed form; ``ry`` as ``|det| / rx``,
    which keeps its precision when the ellipse is thin)."""
    a, b, c, d = u[0], v[0], u[1], v[1]          # [[a, b], [c, d]]: columns u, v
    e, f = (a + d) / 2, (a - d) / 2
    g, h = (c + b) / 2, (c - b) / 2
    q, r = math.hypot(e, h), math.hypot(f, g)
    rx = q + r
    ry = abs(a * d - b * c) / rx
    rot = (math.atan2(g, f) + math.atan2(h, e)) / 2
    return rx, ry, rot


def point_at(center, u, v, t: float) -> tuple[float, float]:
    """The point of parameter ``t`` (radians): ``center + u cos t + v sin t``."""
    cs, sn = math.cos(t), math.sin(t)
    return (center[0] + u[0] * cs + v[0] * sn, center[1] + u[1] * cs + v[1] * sn)


def whole_curve(center, u, v):
    """The whole curve ``center + u cos t + v sin t``: a :class:`Circle` when its semi-axes
    are equal (a similarity's image of a circle), else the ellipse ``(cx, cy, rx, ry,
    rotation)``; None when the semi-diameters span no area (:func:`singular`)."""
    if singular(u, v):
        return None
    rx, ry, rot = principal_axes(u, v)
    c = (float(center[0]), float(center[1]))
    if rx - ry <= ROUND * rx:
        return Circle(c, (rx + ry) / 2)
    return (c[0], c[1], rx, ry, rot)


def arc_curve(center, u, v, t0: float, sweep: float, start=None, end=None):
    """The piece of ``center + u cos t + v sin t`` from parameter ``t0`` sweeping ``sweep``
    radians of the parameter (either sign): an :class:`Arc` when the semi-axes are equal,
    else an exact :class:`~aidl_lang.geometry.shapes.curves.EllipticArc` (counter-clockwise in the
    plane when ``sweep`` and ``u x v`` have one sign); ``start`` and ``end``: the ends as
    the file gives them (the pieces chain end to end), else computed.  None when the
    semi-diameters span no area (:func:`singular`)."""
    if singular(u, v):
        return None
    c = (float(center[0]), float(center[1]))
    a = start if start is not None else point_at(c, u, v, t0)
    b = end if end is not None else point_at(c, u, v, t0 + sweep)
    rx, ry, rot = principal_axes(u, v)
    turn = 1.0 if u[0] * v[1] - u[1] * v[0] > 0 else -1.0     # the parameter's sense
    if rx - ry <= ROUND * rx:
        r = (rx + ry) / 2
        return Arc(c, r, math.atan2(a[1] - c[1], a[0] - c[0]), sweep * turn)
    return elliptic_arc(c, rx, ry, rot, a, point_at(c, u, v, t0 + sweep / 2), b)


# ------------------------------------------------------------------ DXF (ezdxf) curves
def dxf_conic(e, t: str):
    """The DXF ``CIRCLE``, ``ARC`` or ``ELLIPSE`` ``e`` (of type ``t``) as ``(center, u, v,
    t0, sweep)`` in world coordinates of its block (drawing units; ezdxf ``Vec3``): a CIRCLE's
    and ARC's from its OCS (any extrusion), an ELLIPSE's major and minor axes; ``t0`` and
    ``sweep`` its parameter range (radians, counter-clockwise in its plane: an ARC's angles,
    an ELLIPSE's parameters), ``sweep`` None for a whole curve.  Raises ValueError (why) for
    a radius or semi-axis not above 0 or not finite."""
    from ezdxf.math import Vec3
    tau = 2 * math.pi
    if t == "ELLIPSE":
        c, u = Vec3(e.dxf.center), Vec3(e.dxf.major_axis)
        ratio = float(e.dxf.ratio)
        if not (u.magnitude > 0 and 0 < ratio < math.inf):
            raise ValueError("a semi-axis not above 0")
        v = Vec3(e.dxf.extrusion).normalize().cross(u) * ratio     # ezdxf's minor axis
        s0, s1 = float(e.dxf.start_param), float(e.dxf.end_param)
        sweep = (s1 - s0) % tau
        if sweep < 1e-9 or sweep > tau - 1e-9:
            return c, u, v, 0.0, None
        return c, u, v, s0, sweep
    r = float(e.dxf.radius)
    if not 0 < r < math.inf:
        raise ValueError("a radius not above 0")
    ocs = e.ocs()
    c = Vec3(ocs.to_wcs(e.dxf.center))
    u, v = Vec3(ocs.to_wcs((r, 0, 0))), Vec3(ocs.to_wcs((0, r, 0)))
    if t == "CIRCLE":
        return c, u, v, 0.0, None
    a1, a2 = math.radians(float(e.dxf.start_angle)), math.radians(float(e.dxf.end_angle))
    return c, u, v, a1, (a2 - a1) % tau or tau


def flattens(m) -> bool:
    """Whether the ezdxf ``Matrix44`` ``m`` maps the XY plane to no area (an INSERT's x or
    y scale of 0)."""
    from ezdxf.math import X_AXIS, Y_AXIS
    ux, uy = m.transform_direction(X_AXIS), m.transform_direction(Y_AXIS)
    n = ux.magnitude * uy.magnitude
    return not (n > 0 and ux.cross(uy).magnitude > SINGULAR * n)
