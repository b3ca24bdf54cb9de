"""Exact offset of a closed outline: kerf compensation (docs/outputs.md, "Kerf").

A laser burns away a strip ``kerf`` wide centred on its path, so a part cut along its own
outline comes out ``kerf / 2`` too small on every side.  :func:`offset_loop` moves the path
``d`` = ``kerf / 2`` to the *right* of the loop's direction of travel, which is outward for an
outer loop (counter-clockwise) and into the hole for a hole (clockwise): the part comes out at
its designed size.

The result is exact, made of the same kinds of segments (:mod:`.curves`):

* a line moves parallel to itself by ``d``;
* an arc keeps its center and sweep, its radius grows by ``d`` when the material is on its
  inside (a counter-clockwise arc) and shrinks by ``d`` otherwise; a circle likewise;
* a convex corner (the path turns left) is joined by an arc of radius ``d`` around the
  original corner, from one offset end to the other: the path the edge of the beam takes;
* a concave corner (the path turns right) is joined where the two offset carriers cross
  (:func:`~.curves.intersect`, nearest the corner);
* a tangent join (a slot's side and its end) stays a tangent join.

A feature smaller than the offset (a concave arc of radius <= ``d``, a segment eaten by its
neighbours' offsets) cannot be cut at that kerf: :class:`OffsetError` names it.
"""
from __future__ import annotations

import math

from .curves import (Arc, Circle, Line, Loop, Segment, carrier, intersect, simplify,
                     tangent_at, turn_between, with_ends)

TANGENT_TURN = 1e-9      # radians: a join turning less than this is a tangent join


class OffsetError(ValueError):
    """The loop cannot be offset by this distance; the message says where and why."""


def _right(s: Segment, d: float) -> Segment:
    """``s`` moved ``d`` mm to the right of its direction of travel."""
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        L = math.hypot(x1 - x0, y1 - y0)
        nx, ny = (y1 - y0) / L * d, -(x1 - x0) / L * d
        return Line((x0 + nx, y0 + ny), (x1 + nx, y1 + ny))
    if isinstance(s, Circle):
        r = s.radius + d if s.ccw else s.radius - d
        if r <= 0:
            raise OffsetError(f"the hole of radius {s.radius:g} mm at ({s.center[0]:g}, "
                              f"{s.center[1]:g}) is no larger than the offset of {d:g} mm")
        return Circle(s.center, r, s.ccw)
    r = s.radius + d if s.sweep > 0 else s.radius - d
    if r <= 0:
        x, y = s.start
        raise OffsetError(f"the arc of radius {s.radius:g} mm at ({x:g}, {y:g}) is no larger "
                          f"than the offset of {d:g} mm: the beam cannot follow it")
    return Arc(s.center, r, s.start_angle, s.sweep)


def _forward(orig: Segment, new: Segment) -> bool:
    """True when the trimmed offset ``new`` still runs the way ``orig`` does."""
    if isinstance(orig, Line):
        (x0, y0), (x1, y1) = orig.start, orig.end
        (p0, q0), (p1, q1) = new.start, new.end
        return (p1 - p0) * (x1 - x0) + (q1 - q0) * (y1 - y0) > 0
    return new.sweep != 0 and (new.sweep > 0) == (orig.sweep > 0) \
        and abs(new.sweep) <= abs(orig.sweep) + 1e-9


def offset_loop(loop: Loop, d: float) -> Loop:
    """``loop`` offset ``d`` mm (>= 0) to the right of its direction of travel: outward for
    an outer (counter-clockwise) loop, into the hole for a hole (see the module text).
    Raises :class:`OffsetError` where a feature is too small for the offset."""
    segs = loop.segments
    if d == 0 or not segs:
        return loop
    if len(segs) == 1 and isinstance(segs[0], Circle):
        return Loop([_right(segs[0], d)])
    n = len(segs)
    moved = [_right(s, d) for s in segs]
    # the join before segment k: (end of moved k-1, start of moved k, corner arc or None)
    joins = []
    for k in range(n):
        a, b = segs[k - 1], segs[k]
        turn = turn_between(a, b)
        if abs(turn) <= TANGENT_TURN:                 # tangent: the offsets meet
            p = moved[k - 1].end
            joins.append((p, p, None))
        elif turn > 0:                                 # convex: round the corner
            v = b.start
            tx, ty = tangent_at(a, True)
            start = math.atan2(-tx, ty)                # the right normal of a at its end
            joins.append((moved[k - 1].end, moved[k].start, Arc(v, d, start, turn)))
        else:                                          # concave: where the offsets cross
            p = intersect(carrier(moved[k - 1]), carrier(moved[k]), b.start)
            joins.append((p, p, None))
    out: list[Segment] = []
    for k in range(n):
        if joins[k][2] is not None:
            out.append(joins[k][2])
        start, end = joins[k][1], joins[(k + 1) % n][0]
        g = moved[k]
        t = with_ends(g, start, end) if (start, end) != (g.start, g.end) else g
        if not _forward(segs[k], t):
            x, y = segs[k].start
            raise OffsetError(f"the {'line' if isinstance(segs[k], Line) else 'arc'} from "
                              f"({x:g}, {y:g}) is too short for an offset of {d:g} mm: its "
                              "neighbours' offsets cover it")
        out.append(t)
    scale = max(max(abs(v) for g in segs for v in g.start), 1.0)
    return Loop(simplify(out, scale))
