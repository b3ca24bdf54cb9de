"""Holes that makers draw and no one primitive draws, recognised from a hole's exact loop
(issue 85, "recognise what makers draw"): an arc slot (:func:`arc_slot`: two concentric arcs
closed by two half circles, ``ArcSlot``), a keyhole (:func:`keyhole`: a head circle and a
slot running from its centre, the standard library's ``keyhole``) and a D-hole
(:func:`d_hole`: a circle with one flat).  Each returns the numbers the program writes (mm,
radians) or None; the loop's pieces are :class:`~aidl_lang.geometry.curves.Arc` and
``Line`` in any order and direction."""
from __future__ import annotations

import math

from ...geometry.curves import Arc, Line
from .shapes import EQUAL_TOL, _close


def merged(segs: list) -> list:
    """The loop ``segs`` (in order) with each run of arcs on one circle, turning one way,
    joined into one arc (a reader splits an arc at its quadrants, a writer at 180 degrees);
    lines as they are."""
    out: list = []
    for s in segs:
        p = out[-1] if out else None
        if isinstance(s, Arc) and isinstance(p, Arc) and _same_circle(p, s) and \
                (p.sweep > 0) == (s.sweep > 0) and _close(p.end, s.start):
            out[-1] = Arc(p.center, p.radius, p.start_angle, p.sweep + s.sweep)
        else:
            out.append(s)
    if len(out) > 1:
        a, b = out[-1], out[0]
        if isinstance(a, Arc) and isinstance(b, Arc) and _same_circle(a, b) and \
                (a.sweep > 0) == (b.sweep > 0) and _close(a.end, b.start):
            out = [Arc(a.center, a.radius, a.start_angle, a.sweep + b.sweep)] + out[1:-1]
    return out


def _same_circle(a: Arc, b: Arc) -> bool:
    return _close(a.center, b.center) and abs(a.radius - b.radius) <= EQUAL_TOL


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
    if len(segs) != 2:
        return None
    arcs = [s for s in segs if isinstance(s, Arc)]
    lines = [s for s in segs if isinstance(s, Line)]
    if len(arcs) != 1 or len(lines) != 1:
        return None
    (arc,), (ln,) = arcs, lines
    if abs(arc.sweep) <= math.pi + 1e-9:
        return None
    c = arc.center
    m = ((ln.start[0] + ln.end[0]) / 2, (ln.start[1] + ln.end[1]) / 2)
    flat = math.dist(c, m)
    if flat <= EQUAL_TOL:
        return None
    return c, 2 * arc.radius, flat, math.atan2(m[1] - c[1], m[0] - c[0])
