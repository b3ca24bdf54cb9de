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

A segment its neighbours' offsets cover (eaten) is left out, and they are joined where they
cross: the exact offset there.  A concave arc of radius <= ``d`` cannot be cut at that kerf:
:class:`OffsetError` names it.
"""
from __future__ import annotations

import math

from ..shapes.curves import (EllipticArc, Spline, Arc, Circle, Line, Loop, Segment, carrier, crossings,
                     intersect, reverse, simplify,
                     tangent_at, turn_between, with_ends)

TANGENT_TURN = 1e-9      # radians: a join turning less than this is a tangent join
MITER_LIMIT = 4.0        # a miter reaching farther than this many distances is cut (bevel)


class OffsetError(ValueError):
    """The loop cannot be offset by this distance; the message says where and why.
    ``curve``: the :class:`~.spline.CubicSpline` or :class:`~.ellipse.EllipseCurve` that
    cannot be offset exactly, else None; ``where``: the point (x, y), mm, the message names."""
    curve = None
    where = None

    def __init__(self, message: str, where=None):
        super().__init__(message)
        self.where = where


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
                              f"{s.center[1]:g}) is no larger than the offset of {d:g} mm",
                              s.center)
        return Circle(s.center, r, s.ccw)
    r = s.radius + d if s.sweep > 0 else s.radius - d
    if r <= 0:
        x, y = s.start
        raise OffsetError(f"the arc of radius {s.radius:g} mm at ({x:g}, {y:g}) is no larger "
                          f"than the offset of {d:g} mm: the beam cannot follow it", (x, y))
    return Arc(s.center, r, s.start_angle, s.sweep)


def _forward(orig: Segment, new: Segment, reach: float = 0.0) -> bool:
    """True when the trimmed offset ``new`` still runs the way ``orig`` does; an arc may be
    no longer than ``orig`` but by ``reach`` mm at each end (where it runs on to a kept
    neighbour's line: :func:`_join`, at most :data:`MITER_LIMIT` offsets)."""
    if isinstance(orig, Line):
        (x0, y0), (x1, y1) = orig.start, orig.end
        (p0, q0), (p1, q1) = new.start, new.end
        return (p1 - p0) * (x1 - x0) + (q1 - q0) * (y1 - y0) > 0
    return new.sweep != 0 and (new.sweep > 0) == (orig.sweep > 0) \
        and abs(new.sweep) <= abs(orig.sweep) + 2 * reach / new.radius + 1e-9


def offset_loop(loop: Loop, d: float, keep=()) -> Loop:
    """``loop`` offset ``d`` mm (>= 0) to the right of its direction of travel: outward for
    an outer (counter-clockwise) loop, into the hole for a hole (see the module text).
    ``keep``: indices of segments left where they are (offset 0: an edge shared with a
    neighbouring piece, cut once along its line); where a kept segment meets an offset one the
    two carriers are joined where they cross (a kept line is lengthened by ``d`` past a square
    corner), or, where they do not cross near the corner (a tangent or collinear join), the
    kept segment runs ``d`` on along its direction and a line steps to the offset one.
    Raises :class:`OffsetError` where a feature is too small for the offset."""
    for g in loop.segments:
        if isinstance(g, EllipticArc):
            e = OffsetError(f"the ellipse through ({g.start[0]:g}, {g.start[1]:g}) cannot be "
                            f"offset exactly (the offset of an ellipse is no ellipse, and "
                            f"chords are not written)", g.start)
            e.curve = g.curve
            raise e
        if isinstance(g, Spline):
            e = OffsetError(f"the spline through ({g.start[0]:g}, {g.start[1]:g}) cannot be "
                            f"offset exactly (the offset of a cubic spline is no cubic "
                            f"spline, and chords are not written)", g.start)
            e.curve = g.curve
            raise e
    segs = loop.segments
    keep = frozenset(keep)
    if d == 0 or not segs or len(keep) >= len(segs):
        return loop
    if any(isinstance(g, Line) and g.start == g.end for g in segs):
        # a line of no length (a cusp of an imported Bezier: its handles on its ends) has
        # no direction to offset along: left out, the lines either side meet without it
        idx = [k for k, g in enumerate(segs) if not (isinstance(g, Line) and g.start == g.end)]
        keep = frozenset(i for i, k in enumerate(idx) if k in keep)
        segs = [segs[k] for k in idx]
        if not segs or len(keep) >= len(segs):
            return Loop(segs) if segs else loop
    if len(segs) == 1 and isinstance(segs[0], Circle):
        return Loop([_right(segs[0], d)])
    first = None
    while True:
        try:
            return _offset_once(segs, keep, d)
        except _Eaten as ex:
            # a segment its neighbours' offsets cover (a gear's short root arc under a
            # 0.15 mm kerf, run al's spirograph): left out, the neighbours' offsets meet where
            # they cross, which is the exact offset there (the region grown by d has no point
            # of that segment's offset on its boundary); compensate's _narrow then checks that
            # the path keeps d from every drawn curve
            # (all found in one pass, a neighbour of one dropped kept for the next: a gear's
            # 52 root arcs cost 108 passes one at a time, 1.4 s of a 2.1 s render)
            first = first or ex.error
            drop = set()
            for k in ex.ks:
                if (k - 1) % len(segs) not in drop and (k + 1) % len(segs) not in drop:
                    drop.add(k)
            if drop & keep or len(segs) - len(drop) < 3:
                raise first from None
            segs = [g for k, g in enumerate(segs) if k not in drop]
            keep = frozenset(i - sum(k < i for k in drop) for i in keep)


class _Eaten(Exception):
    """The segments ``ks`` have offsets their neighbours' cover (``error``: what to say of
    the first)."""

    def __init__(self, ks: list, error: OffsetError):
        self.ks, self.error = ks, error


def _offset_once(segs: list, keep: frozenset, d: float) -> Loop:
    """:func:`offset_loop` of the segments ``segs`` (none of no length); raises
    :class:`_Eaten` naming the segments its neighbours' offsets cover."""
    n = len(segs)
    eaten: list = []
    moved = [s if k in keep else _right(s, d) for k, s in enumerate(segs)]
    # the join before segment k: (end of moved k-1, start of moved k, segments between)
    joins = [_join(segs[k - 1], segs[k], moved[k - 1], moved[k], d,
                   ((k - 1) % n in keep, k in keep)) for k in range(n)]
    out: list[Segment] = []
    for k in range(n):
        out += joins[k][2]
        start, end = joins[k][1], joins[(k + 1) % n][0]
        g = moved[k]
        # an arc beside a kept segment may run on to where the kept one's carrier crosses it
        reach = MITER_LIMIT * d if {(k - 1) % n, (k + 1) % n} & keep and k not in keep \
            and isinstance(g, Arc) else 0.0
        if reach:
            e = math.copysign(reach / g.radius, g.sweep)
            g = Arc(g.center, g.radius, g.start_angle - e, g.sweep + 2 * e)
        t = with_ends(g, start, end) if (start, end) != (g.start, g.end) else g
        if not _forward(segs[k], t, reach):
            eaten.append(k)
            continue
        out.append(t)
    if eaten:
        x, y = segs[eaten[0]].start
        raise _Eaten(eaten, OffsetError(
            f"the {'line' if isinstance(segs[eaten[0]], Line) else 'arc'} from ({x:g}, {y:g}) "
            f"is too short for an offset of {d:g} mm: its neighbours' offsets cover it", (x, y)))
    scale = max(max(abs(v) for g in segs for v in g.start), 1.0)
    return Loop(simplify(out, scale))


def _on_carrier(p, g: Line) -> bool:
    """Point ``p`` lies on line ``g``'s carrier (to 1e-9 of its size)."""
    (x0, y0), (x1, y1) = g.start, g.end
    L = math.hypot(x1 - x0, y1 - y0)
    if L == 0.0:
        return False
    scale = max(1.0, abs(x0), abs(y0), abs(x1), abs(y1))
    return abs((p[0] - x0) * (y1 - y0) - (p[1] - y0) * (x1 - x0)) / L <= 1e-9 * scale


def _join(a: Segment, b: Segment, ma: Segment, mb: Segment, d: float, kept) -> tuple:
    """The join at the corner from ``a`` into ``b`` (``ma``, ``mb``: their offsets; ``kept``:
    (a kept, b kept)): (where ``ma`` ends, where ``mb`` starts, the segments between)."""
    v = b.start
    turn = turn_between(a, b)
    if kept[0] and kept[1]:                            # both on their lines: the corner
        return (v, v, [])
    if kept[0] or kept[1]:                             # one kept, one offset
        pts = crossings(carrier(ma), carrier(mb))
        if pts and abs(turn) > TANGENT_TURN:
            p = min(pts, key=lambda q: math.dist(q, v))
            if math.dist(p, v) <= MITER_LIMIT * d:
                return (p, p, [])
        # a tangent or collinear join: the kept segment runs d on past the corner and a
        # square step (d across) meets the offset one there, d from the corner everywhere
        if kept[0]:
            tx, ty = tangent_at(a, True)
            e = (v[0] + d * tx, v[1] + d * ty)
            ux, uy = tangent_at(b, False)
            f = (e[0] + d * uy, e[1] - d * ux)
            if not (isinstance(mb, Line) and _on_carrier(f, mb)):
                f = mb.start                           # no square step: straight to mb
            head = [] if isinstance(a, Line) else [Line(v, e)]
            return (e if isinstance(a, Line) else v, f, head + [Line(e, f)])
        tx, ty = tangent_at(b, False)
        e = (v[0] - d * tx, v[1] - d * ty)
        ux, uy = tangent_at(a, True)
        f = (e[0] + d * uy, e[1] - d * ux)
        if not (isinstance(ma, Line) and _on_carrier(f, ma)):
            f = ma.end
        tail = [] if isinstance(b, Line) else [Line(e, v)]
        return (f, e if isinstance(b, Line) else v, [Line(f, e)] + tail)
    if abs(turn) <= TANGENT_TURN:                      # tangent: the offsets meet
        p = ma.end
        return (p, p, [])
    if turn > 0:                                       # convex: round the corner
        tx, ty = tangent_at(a, True)
        start = math.atan2(-tx, ty)                    # the right normal of a at its end
        return (ma.end, mb.start, [Arc(v, d, start, turn)])
    p = intersect(carrier(ma), carrier(mb), v)         # concave: where the offsets cross
    return (p, p, [])


# ------------------------------------------------------------------ Offset(shape, distance)


def sweep_loops(s: Segment, d: float) -> list[Loop]:
    """The region every point of segment ``s`` reaches within ``d`` mm (> 0), as exact
    counter-clockwise loops whose union it is: a line gives a stadium (two lines, two half
    circles of radius ``d`` around its ends); an arc of radius R an arc slot (arcs R + d and
    R - d, half circles around its ends) or, when ``d`` >= R, the pie of radius R + d and the
    two end circles; a circle the ring from r - d to r + d (two half rings; the whole disk
    of r + d when ``d`` >= r).  Used by :func:`offset_pieces`."""
    if isinstance(s, Line):
        (ax, ay), (bx, by) = s.start, s.end
        L = math.hypot(bx - ax, by - ay)
        if L <= 0.0:
            return [Loop([Circle((ax, ay), d)])]
        nx, ny = -(by - ay) / L, (bx - ax) / L            # left of a -> b
        right = math.atan2(-ny, -nx)
        p1, p2 = (ax - d * nx, ay - d * ny), (bx - d * nx, by - d * ny)
        p3, p4 = (bx + d * nx, by + d * ny), (ax + d * nx, ay + d * ny)
        return [Loop([Line(p1, p2), Arc((bx, by), d, right, math.pi), Line(p3, p4),
                      Arc((ax, ay), d, right + math.pi, math.pi)])]
    if isinstance(s, Circle):
        c, R = s.center, s.radius
        if d >= R:
            return [Loop([Circle(c, R + d)])]
        out = []                               # the ring as two half rings
        for a1 in (0.0, math.pi):
            outer, inner = Arc(c, R + d, a1, math.pi), Arc(c, R - d, a1 + math.pi, -math.pi)
            out.append(Loop([outer, Line(outer.end, inner.start), inner,
                             Line(inner.end, outer.start)]))
        return out
    a = s if s.sweep > 0 else reverse(s)
    c, R, a1, sw = a.center, a.radius, a.start_angle, a.sweep
    if d < R:
        return [Loop([Arc(c, R + d, a1, sw), Arc(a.end, d, a1 + sw, math.pi),
                      Arc(c, R - d, a1 + sw, -sw), Arc(a.start, d, a1 + math.pi, math.pi)])]
    big = Arc(c, R + d, a1, sw)
    return [Loop([Line(c, big.start), big, Line(big.end, c)]),
            Loop([Circle(a.start, d)]), Loop([Circle(a.end, d)])]


def _miter_kite(a: Segment, b: Segment, d: float) -> Loop | None:
    """The miter at the corner from line ``a`` into line ``b`` turning left (the corner's
    outside on the right): the quadrilateral from the corner out to both offset ends and the
    point where the offset lines meet; None (the round join's disk is the bevel) when that
    point lies farther than :data:`MITER_LIMIT` x ``d`` from the corner."""
    ma, mb = _right(a, d), _right(b, d)
    m = intersect(carrier(ma), carrier(mb), b.start)
    v = b.start
    if math.dist(m, v) > MITER_LIMIT * d * (1 + 1e-12):
        return None
    return Loop([Line(v, ma.end), Line(ma.end, m), Line(m, mb.start), Line(mb.start, v)])


def offset_pieces(loops: list[Loop], d: float, join: str = "round") -> list[Loop]:
    """The exact loops whose union, added to the shape (``d`` > 0) or cut from it
    (``d`` < 0), is the shape offset by ``d`` mm: the sweep of every segment by a disk of
    radius ``|d|`` (:func:`sweep_loops`; its disks at the corners are the round joins), and
    with ``join="miter"`` the miter kite of every corner between two lines that turns away
    from the offset side (see :func:`_miter_kite`; sharper than the miter limit: a bevel).

    ``loops``: the shape's outline, outer loops counter-clockwise, holes clockwise.  Source:
    the offset of a region is its Minkowski sum with a disk (outward) or the complement's
    (inward); exact because every piece is made of lines and arcs of the offset carriers."""
    r = abs(d)
    out: list[Loop] = []
    for lp in loops:
        segs = lp.segments
        for s in segs:
            out += sweep_loops(s, r)
        if join != "miter" or len(segs) < 2:
            continue
        for k in range(len(segs)):
            a, b = segs[k - 1], segs[k]
            if not (isinstance(a, Line) and isinstance(b, Line)):
                continue
            turn = turn_between(a, b)
            if abs(turn) <= TANGENT_TURN:
                continue
            if d > 0 and turn > 0:          # convex corner, outward offset
                kite = _miter_kite(a, b, r)
            elif d < 0 and turn < 0:        # reflex corner, inset: the kite on the inside
                kite = _miter_kite(reverse(b), reverse(a), r)
            else:
                continue
            if kite is not None:
                out.append(kite if kite.area > 0 else kite.reversed())
    return out
