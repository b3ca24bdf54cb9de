"""Holes that makers draw and no one primitive draws, recognised from a hole's exact loop
(issue 85, "recognise what makers draw"): an arc slot (:func:`arc_slot`: two concentric arcs
closed by two half circles, ``ArcSlot``), a keyhole (:func:`keyhole`: a head circle and a
slot running from its centre, the standard library's ``keyhole``) and a D-hole
(:func:`d_hole`: a circle with one flat).  Each returns the numbers the program writes (mm,
radians) or None; the loop's pieces are :class:`~aidl_lang.geometry.shapes.curves.Arc` and
``Line`` in any order and direction."""
from __future__ import annotations

import math

from ....geometry.shapes.curves import Arc, Line
from ..shapes import EQUAL_TOL, _close, arcs_and_lines, merged


def _ccw(a: Arc) -> tuple[float, float]:
    """``(start angle, sweep > 0)`` of arc ``a`` run counter-clockwise (radians)."""
    return (a.start_angle, a.sweep) if a.sweep > 0 else (a.start_angle + a.sweep, -a.sweep)


def arc_slot(segs: list) -> tuple | None:
    """``(centre, radius of the centre line, start angle, end angle, width)`` of a loop of
    four arcs: an outer and an inner arc about one centre over one span, and two half circles
    of half the width whose centres are on the centre line at the span's ends; else None."""
    if len(segs) != 4 or not all(isinstance(s, Arc) for s in segs):
        return None
    by_r = sorted(segs, key=lambda s: -s.radius)
    outer, inner = by_r[0], by_r[1]
    caps = by_r[2:]
    if not _close(outer.center, inner.center) or outer.radius - inner.radius <= EQUAL_TOL:
        return None
    w = outer.radius - inner.radius
    R = (outer.radius + inner.radius) / 2
    C = outer.center
    if any(abs(c.radius - w / 2) > EQUAL_TOL or abs(math.dist(c.center, C) - R) > EQUAL_TOL or
           abs(abs(c.sweep) - math.pi) > 1e-6 for c in caps):
        return None
    a0, sweep = _ccw(outer)
    b0, bsweep = _ccw(inner)
    if abs(sweep - bsweep) * R > EQUAL_TOL or sweep >= 2 * math.pi - 1e-9:
        return None
    ends = [(C[0] + R * math.cos(a), C[1] + R * math.sin(a)) for a in (a0, a0 + sweep)]
    if not all(any(_close(e, c.center) for c in caps) for e in ends):
        return None
    return C, R, a0, a0 + sweep, w


def keyhole(segs: list) -> tuple | None:
    """``(head centre, head diameter, slot width, length, direction)`` of a loop of a large
    arc (the head), two parallel lines ``width`` apart and a half circle (the slot's end),
    the slot running ``length`` from the head's centre toward ``direction`` (radians); else
    None."""
    if len(segs) != 4:
        return None
    arcs = sorted((s for s in segs if isinstance(s, Arc)), key=lambda s: -s.radius)
    lines = [s for s in segs if isinstance(s, Line)]
    if len(arcs) != 2 or len(lines) != 2:
        return None
    head, end = arcs
    a = end.radius
    if abs(abs(end.sweep) - math.pi) > 1e-6 or head.radius - a <= EQUAL_TOL:
        return None
    c, e = head.center, end.center
    L = math.dist(c, e)
    if L <= head.radius - a + EQUAL_TOL:
        return None
    ux, uy = (e[0] - c[0]) / L, (e[1] - c[1]) / L
    for ln in lines:        # each side a line of the slot: `a` off its axis, along it
        for p in (ln.start, ln.end):
            across = (p[0] - c[0]) * -uy + (p[1] - c[1]) * ux
            if abs(abs(across) - a) > EQUAL_TOL:
                return None
    return c, 2 * head.radius, 2 * a, L, math.atan2(uy, ux)


def d_hole(segs: list) -> tuple | None:
    """``(centre, diameter, flat, direction)`` of a loop of one arc of more than a half
    circle and the line joining its ends: the flat ``flat`` from the centre, its normal
    toward ``direction`` (radians); else None."""
    got = arcs_and_lines(segs, 1, 1)
    if got is None:
        return None
    (arc,), (ln,) = got
    if abs(arc.sweep) <= math.pi + 1e-9:
        return None
    c = arc.center
    m = ((ln.start[0] + ln.end[0]) / 2, (ln.start[1] + ln.end[1]) / 2)
    flat = math.dist(c, m)
    if flat <= EQUAL_TOL:
        return None
    return c, 2 * arc.radius, flat, math.atan2(m[1] - c[1], m[0] - c[0])


def edge_notches(segs: list) -> tuple | None:
    """A body's outline with notches cut into its sides (square, round-bottom or V):
    ``(the outline with each notch closed by its side's straight line, [(side, shape, lo,
    hi, depth)])``, ``side`` one of ``"left" "right" "bottom" "top"``, ``shape`` one of
    ``"square" "round" "V"``, ``lo..hi`` the notch's span along the side (mm) and ``depth``
    from the side to its bottom; None when the loop has no such notch or a piece off the
    sides that is none of them.  Corners may be rounded or cut (a piece from one side to the
    next)."""
    if len(segs) < 5 or len(segs) > 4096 or not all(isinstance(s, (Line, Arc)) for s in segs):
        return None
    segs = merged(segs)
    boxes = [s.box() for s in segs]
    x0, y0 = min(b[0] for b in boxes), min(b[1] for b in boxes)
    x1, y1 = max(b[2] for b in boxes), max(b[3] for b in boxes)
    sides = {"left": (0, x0, -1), "right": (0, x1, 1), "bottom": (1, y0, -1), "top": (1, y1, 1)}

    def side_of(p) -> set:
        return {k for k, (ax, v, _) in sides.items() if abs(p[ax] - v) <= EQUAL_TOL}

    def boundary(s) -> bool:        # along a side, or a corner from one side to the next
        a, b = side_of(s.start), side_of(s.end)
        if isinstance(s, Line) and a & b:
            return True
        return bool(a) and bool(b) and not (a & b)
    n = len(segs)
    start = next((i for i in range(n) if boundary(segs[i])), None)
    if start is None or all(boundary(s) for s in segs):
        return None
    body, notches, run = [], [], []
    for k in range(1, n + 1):
        s = segs[(start + k) % n]
        if not boundary(s):
            run.append(s)
            continue
        if run:
            got = _notch(run, sides, side_of)
            # a notch that meets a rounded corner: a rounding of the whole body would not
            # be the drawing's (it takes at most half a side); one that meets a cut corner
            # is kept (a chamfered body is then written corner by corner)
            if got is None or not isinstance(body[-1] if body else segs[start], Line) or \
                    not isinstance(s, Line):
                return None
            notches.append(got)
            body.append(Line(run[0].start, run[-1].end))
            run = []
        body.append(s)
    return _straight(body), notches


def _straight(segs: list) -> list:
    """The loop ``segs`` with each run of lines along one line joined into one."""
    def along(p: Line, q: Line) -> bool:
        ux, uy = p.end[0] - p.start[0], p.end[1] - p.start[1]
        vx, vy = q.end[0] - q.start[0], q.end[1] - q.start[1]
        return abs(ux * vy - uy * vx) <= EQUAL_TOL * math.hypot(ux, uy) * 1e-3 * max(
            1.0, math.hypot(vx, vy)) and ux * vx + uy * vy > 0
    out: list = []
    for s in segs:
        p = out[-1] if out else None
        if isinstance(s, Line) and isinstance(p, Line) and along(p, s):
            out[-1] = Line(p.start, s.end)
        else:
            out.append(s)
    if len(out) > 2 and isinstance(out[0], Line) and isinstance(out[-1], Line) and \
            along(out[-1], out[0]):
        out = [Line(out[-1].start, out[0].end)] + out[1:-1]
    return out


def _notch(run: list, sides: dict, side_of) -> tuple | None:
    """``(side, shape, lo, hi, depth)`` of the pieces ``run`` of an outline between two
    points of one side, when they are a square, round-bottom or V notch; else None."""
    a, d = run[0].start, run[-1].end
    common = side_of(a) & side_of(d)
    if len(common) != 1:
        return None
    side = common.pop()
    ax, v, _ = sides[side]
    along = 1 - ax
    lo, hi = sorted((a[along], d[along]))
    w = hi - lo
    mid = (lo + hi) / 2
    if w <= EQUAL_TOL:
        return None
    kinds = [type(s).__name__ for s in run]
    if kinds == ["Line"] * 3:
        b, c = run[1].start, run[1].end
        depth = abs(b[ax] - v)
        if abs(abs(c[ax] - v) - depth) > EQUAL_TOL or abs(b[along] - a[along]) > EQUAL_TOL \
                or abs(c[along] - d[along]) > EQUAL_TOL or depth <= EQUAL_TOL:
            return None
        return side, "square", lo, hi, depth
    if kinds == ["Line", "Arc", "Line"]:
        arc = run[1]
        if abs(arc.radius - w / 2) > EQUAL_TOL or abs(abs(arc.sweep) - math.pi) > 1e-6 or \
                abs(arc.center[along] - mid) > EQUAL_TOL:
            return None
        depth = abs(arc.center[ax] - v) + arc.radius
        for ln in (run[0], run[2]):     # straight sides across the side
            if abs(ln.start[along] - ln.end[along]) > EQUAL_TOL:
                return None
        return side, "round", lo, hi, depth
    if kinds == ["Line", "Line"]:
        apex = run[0].end
        if abs(apex[along] - mid) > EQUAL_TOL:
            return None
        depth = abs(apex[ax] - v)
        return (side, "V", lo, hi, depth) if depth > EQUAL_TOL else None
    return None


def notch_rows(cuts: list) -> list[list]:
    """The notches of :func:`edge_notches` (``(side, shape, lo, hi, depth)``) in groups to
    write: the notches of one side, shape, width and depth evenly spaced along it (three or
    more: a comb's teeth, finger slots, castellations) as one group, in order; each other
    notch a group of its own."""
    by: dict = {}
    for cut in cuts:
        side, shape, lo, hi, dep = cut
        by.setdefault((side, shape, round(hi - lo, 6), round(dep, 6)), []).append(cut)
    out = []
    for group in by.values():
        group.sort(key=lambda c: c[2])
        mids = [(c[2] + c[3]) / 2 for c in group]
        steps = [b - a for a, b in zip(mids, mids[1:])]
        if len(group) > 2 and max(steps) - min(steps) <= EQUAL_TOL:
            out.append(group)
        else:
            out += [[c] for c in group]
    return out
