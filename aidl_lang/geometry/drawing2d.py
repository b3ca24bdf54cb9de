"""The exact curves of a ``Drawing2D`` (a DXF or SVG drawing read by :mod:`aidl_lang.drawing`)
in its own coordinates, turned by its rotation, and moved to where the solve puts its origin.

:func:`local_parts` orders the closed loops (outlines, circles, full ellipses) by nesting:
a loop inside an odd number of others is a hole and runs clockwise, the others
counter-clockwise, so the loops together are one face with its holes (even-odd, as laser
software and SVG ``fill-rule: evenodd`` read a drawing).  :func:`moved` translates exact
segments (lines, arcs, circles and spline pieces) by the solved origin.
"""
from __future__ import annotations

import math

import numpy as np

from .curves import Arc, Circle, EllipticArc, Line, Loop, Spline, reverse
from .ellipse import EllipseCurve, ellipse
from .spline import CubicSpline


def _rot_pt(p, cs, sn):
    return (p[0] * cs - p[1] * sn, p[0] * sn + p[1] * cs)


def _turn(s, rot: float):
    if rot == 0.0:
        return s
    cs, sn = math.cos(rot), math.sin(rot)
    if isinstance(s, Line):
        return Line(_rot_pt(s.start, cs, sn), _rot_pt(s.end, cs, sn))
    if isinstance(s, Arc):
        return Arc(_rot_pt(s.center, cs, sn), s.radius, s.start_angle + rot, s.sweep)
    if isinstance(s, Circle):
        return Circle(_rot_pt(s.center, cs, sn), s.radius, s.ccw)
    if isinstance(s, EllipticArc):
        e = s.curve
        return EllipticArc(EllipseCurve(_rot_pt(e.center, cs, sn), e.rx, e.ry, e.rotation + rot),
                           s.start_param, s.sweep)
    c = s.curve
    return Spline(CubicSpline(tuple(_rot_pt(p, cs, sn) for p in c.ctrl), c.h, c.closed),
                  s.u0, s.u1)


def _reflect_pt(p, c2, s2):
    return (p[0] * c2 + p[1] * s2, p[0] * s2 - p[1] * c2)


def _reflect(s, phi: float):
    """Segment ``s`` reflected about the line through the origin at angle ``phi`` (radians),
    run the same way along the image (so a loop's sense flips)."""
    c2, s2 = math.cos(2 * phi), math.sin(2 * phi)
    if isinstance(s, Line):
        return Line(_reflect_pt(s.start, c2, s2), _reflect_pt(s.end, c2, s2))
    if isinstance(s, Arc):
        return Arc(_reflect_pt(s.center, c2, s2), s.radius, 2 * phi - s.start_angle, -s.sweep)
    if isinstance(s, Circle):
        return Circle(_reflect_pt(s.center, c2, s2), s.radius, not s.ccw)
    if isinstance(s, EllipticArc):
        # M R(rot) (rx cos t, ry sin t) = R(2 phi - rot) (rx cos -t, ry sin -t)
        e = s.curve
        curve, shift = ellipse(_reflect_pt(e.center, c2, s2), e.rx, e.ry, 2 * phi - e.rotation)
        return EllipticArc(curve, -s.start_param - shift, -s.sweep)
    c = s.curve
    return Spline(CubicSpline(tuple(_reflect_pt(p, c2, s2) for p in c.ctrl), c.h, c.closed),
                  s.u0, s.u1)


def copied(loops, paths, rot: float = 0.0, mirror: float | None = None):
    """The local ``(loops, paths)`` of a copy of a drawing: reflected about the line through
    its origin at angle ``mirror`` (loops run the other way round again, so outer loops stay
    counter-clockwise), or turned by ``rot`` (radians)."""
    if mirror is not None:
        loops = [Loop([reverse(_reflect(s, mirror)) for s in reversed(lp.segments)])
                 for lp in loops]
        paths = [[_reflect(s, mirror) for s in p] for p in paths]
    elif rot:
        loops = [Loop([_turn(s, rot) for s in lp.segments]) for lp in loops]
        paths = [[_turn(s, rot) for s in p] for p in paths]
    return loops, paths


def _shift(s, dx: float, dy: float):
    if isinstance(s, Line):
        return Line((s.start[0] + dx, s.start[1] + dy), (s.end[0] + dx, s.end[1] + dy))
    if isinstance(s, Arc):
        return Arc((s.center[0] + dx, s.center[1] + dy), s.radius, s.start_angle, s.sweep)
    if isinstance(s, Circle):
        return Circle((s.center[0] + dx, s.center[1] + dy), s.radius, s.ccw)
    if isinstance(s, EllipticArc):
        e = s.curve
        return EllipticArc(EllipseCurve((e.center[0] + dx, e.center[1] + dy), e.rx, e.ry,
                                        e.rotation), s.start_param, s.sweep)
    c = s.curve
    return Spline(CubicSpline(tuple((p[0] + dx, p[1] + dy) for p in c.ctrl), c.h, c.closed),
                  s.u0, s.u1)


def _ellipse_loop(cx, cy, rx, ry, rot) -> Loop:
    """A full ellipse as the Ellipse primitive draws it: one exact elliptical arc of a whole
    turn (a circle when ``rx == ry``)."""
    if rx == ry:
        return Loop([Circle((float(cx), float(cy)), float(rx))])
    curve, _ = ellipse((float(cx), float(cy)), rx, ry, rot)
    return Loop([EllipticArc(curve, 0.0, 2 * math.pi)])


def _inside(p, P) -> bool:
    x, y = p
    X, Y = P[:, 0], P[:, 1]
    X2, Y2 = np.roll(X, -1), np.roll(Y, -1)
    cond = (Y > y) != (Y2 > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xs = X + (y - Y) * (X2 - X) / (Y2 - Y)
    return bool(np.count_nonzero(cond & (x < xs)) % 2)


def _probe(lp: Loop):
    s = lp.segments[0]
    if isinstance(s, Circle):
        return (s.center[0] + s.radius, s.center[1])
    if isinstance(s, Arc):
        return s.at(s.start_angle + s.sweep / 2)
    if isinstance(s, Spline):
        return s.curve.at((s.u0 + s.u1) / 2)
    if isinstance(s, EllipticArc):
        return s.curve.at(s.start_param + s.sweep / 2)
    return ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2)


def local_parts(d, rot: float):
    """``(loops, paths, circles, outlines)`` of drawing ``d`` turned by ``rot`` (radians):
    every closed loop oriented by its nesting depth (holes clockwise), the open paths (lists
    of segments), the circles, and the outlines alone (counter-clockwise, largest first)."""
    outlines = [Loop([_turn(s, rot) for s in o.segments]) for o in d.outlines]
    circles = [_turn(c, rot) for c in d.circles]
    ellipses = [_ellipse_loop(*_rot_pt((cx, cy), math.cos(rot), math.sin(rot)), rx, ry, r + rot)
                for cx, cy, rx, ry, r in d.ellipses]
    loops = outlines + [Loop([c]) for c in circles] + ellipses
    polys = [lp.points() for lp in loops]
    # each loop's box first: a probe is tested only against the loops whose box holds it (a
    # drawing of 19,000 holes in one outline: about a second; every pair took minutes)
    boxes = np.array([[P[:, 0].min(), P[:, 1].min(), P[:, 0].max(), P[:, 1].max()]
                      if len(P) >= 3 else [np.inf, np.inf, -np.inf, -np.inf] for P in polys]
                     ).reshape(-1, 4)
    out = []
    for i, lp in enumerate(loops):
        p = _probe(lp)
        cand = np.flatnonzero((boxes[:, 0] <= p[0]) & (p[0] <= boxes[:, 2])
                              & (boxes[:, 1] <= p[1]) & (p[1] <= boxes[:, 3]))
        depth = sum(1 for j in cand if j != i and _inside(p, polys[j]))
        ccw = lp.area > 0
        if (depth % 2 == 0) != ccw:
            if len(lp.segments) == 1 and isinstance(lp.segments[0], Circle):
                c = lp.segments[0]
                lp = Loop([Circle(c.center, c.radius, not ccw)])
            else:
                lp = Loop([reverse(s) for s in reversed(lp.segments)])
        out.append(lp)
    paths = [[_turn(s, rot) for s in p.segments] for p in d.paths]
    return out, paths, circles, outlines


def text_paths(texts, rot: float) -> list:
    """The pen strokes of a drawing's texts (``(text, (x, y), height, rotation, anchor,
    valign)``, :class:`~aidl_lang.drawing.model.Drawing`'s ``texts``) as open paths of
    :class:`Line` segments in its frame, turned by ``rot`` (radians) with the drawing: each
    text in the single-stroke font (:func:`~.text.text_strokes`), its height the cap
    height."""
    from .text import text_strokes
    out = []
    for text, (px, py), h, trot, anchor, valign in texts:
        segs = [_turn(Line((px + a[0], py + a[1]), (px + b[0], py + b[1])), rot)
                for a, b in text_strokes(text, h, anchor, valign, trot)]
        if segs:
            out.append(segs)
    return out


def moved(segments, dx: float, dy: float) -> list:
    """``segments`` translated by ``(dx, dy)`` mm."""
    if dx == 0.0 and dy == 0.0:
        return list(segments)
    return [_shift(s, dx, dy) for s in segments]


def local_box(loops, paths) -> tuple[float, float, float, float]:
    """The exact ``(x0, y0, x1, y1)`` of the loops and paths in the drawing's coordinates
    (each segment's ``box()``)."""
    bs = [s.box() for segs in [lp.segments for lp in loops] + list(paths) for s in segs]
    if not bs:
        return (0.0, 0.0, 0.0, 0.0)
    return (min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
            max(b[3] for b in bs))
