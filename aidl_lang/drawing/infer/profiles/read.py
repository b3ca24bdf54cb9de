"""A profile read from a closed loop (issue 93, round five: "profiles stay literal chains"):
an outline of lines at right angles (an L, T, U or Z bracket, a stepped plate), its corners
sharp or rounded by quarter arcs tangent to both sides (fillets).

:func:`read_profile` returns the loop's corners (the sides' crossings, counter-clockwise),
each corner's radius (0: sharp) and whether it is convex, or None; the profile is made again
from them (:func:`profile_pieces`) and must match the loop piece for piece to
:data:`~..shapes.EQUAL_TOL`.  Where each corner's coordinates are placed from (the faces,
:mod:`.faces`) is not this module's.  Lengths in mm."""
from __future__ import annotations

import math

from ....geometry.shapes.curves import Arc, Line
from ..shapes import EQUAL_TOL, merged, same_pieces


def _dir(s: Line) -> tuple | None:
    """The unit direction of an upright or level line, else None."""
    dx, dy = s.end[0] - s.start[0], s.end[1] - s.start[1]
    if abs(dy) <= EQUAL_TOL and abs(dx) > EQUAL_TOL:
        return (1 if dx > 0 else -1, 0)
    if abs(dx) <= EQUAL_TOL and abs(dy) > EQUAL_TOL:
        return (0, 1 if dy > 0 else -1)
    return None


def _cross(a: Line, b: Line) -> tuple:
    """Where the carriers of an upright and a level line cross."""
    up, level = (a, b) if abs(a.end[0] - a.start[0]) <= EQUAL_TOL else (b, a)
    return (up.start[0], level.start[1])


def read_profile(segs: list) -> tuple | None:
    """``(corners, radii, convex)`` of a profile loop (module doc), counter-clockwise, with
    at least six corners; None when the loop is no such profile."""
    if not 6 <= len(segs) <= 400 or not all(isinstance(s, (Line, Arc)) for s in segs):
        return None
    segs = merged(segs)
    lines = []          # (line, radius of the arc before it)
    r_before = 0.0
    for s in segs:
        if isinstance(s, Arc):
            if r_before or abs(abs(s.sweep) - math.pi / 2) > 1e-9:
                return None
            r_before = s.radius
            continue
        if _dir(s) is None:
            return None
        if lines and r_before == 0.0 and _dir(lines[-1][0]) == _dir(s):
            prev = lines[-1][0]         # a side drawn in two pieces
            lines[-1] = (Line(prev.start, s.end), lines[-1][1])
            continue
        lines.append((s, r_before))
        r_before = 0.0
    if not lines:
        return None
    if r_before:                        # the arc closing the loop: before the first line
        if lines[0][1]:
            return None
        lines[0] = (lines[0][0], r_before)
    elif _dir(lines[0][0]) == _dir(lines[-1][0]):
        first, last = lines[0][0], lines[-1][0]
        lines[0] = (Line(last.start, first.end), lines[-1][1])
        lines.pop()
    n = len(lines)
    if n < 6:
        return None
    corners, radii = [], []
    for k in range(n):
        a, b = lines[k - 1][0], lines[k][0]
        da, db = _dir(a), _dir(b)
        if da[0] * db[0] + da[1] * db[1] != 0:
            return None             # not at a right angle
        corners.append(_cross(a, b))
        radii.append(lines[k][1])
    area = sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(corners, corners[1:] + corners[:1]))
    if abs(area) <= EQUAL_TOL:
        return None
    if area < 0:                    # counter-clockwise: corner k's radius stays its own
        corners = corners[::-1]
        radii = radii[::-1]
    for k in range(n):              # `Fillet` rounds with at most half of each side
        side = math.dist(corners[k], corners[(k + 1) % n])
        if max(radii[k], radii[(k + 1) % n]) > side / 2 + EQUAL_TOL:
            return None
    convex = []
    for k in range(n):
        p, q, r = corners[k - 1], corners[k], corners[(k + 1) % n]
        convex.append((q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]) > 0)
    if len({round(p[0], 6) for p in corners}) < 3 and len({round(p[1], 6) for p in corners}) < 3:
        return None
    if not same_pieces(profile_pieces(corners, radii), segs):
        return None
    return corners, radii, convex


def profile_pieces(corners: list, radii: list) -> list:
    """The pieces of a profile through ``corners`` (counter-clockwise), corner ``k`` rounded
    by a quarter arc of ``radii[k]`` tangent to both its sides (0: sharp)."""
    n = len(corners)
    ends = []           # each corner's (first point, last point, arc or None)
    for k in range(n):
        p, q, r = corners[k - 1], corners[k], corners[(k + 1) % n]
        rad = radii[k]
        if rad <= EQUAL_TOL:
            ends.append((q, q, None))
            continue
        u = _unit(q, p)
        v = _unit(q, r)
        a, b = (q[0] + u[0] * rad, q[1] + u[1] * rad), (q[0] + v[0] * rad, q[1] + v[1] * rad)
        c = (q[0] + (u[0] + v[0]) * rad, q[1] + (u[1] + v[1]) * rad)
        t0 = math.atan2(a[1] - c[1], a[0] - c[0])
        t1 = math.atan2(b[1] - c[1], b[0] - c[0])
        sweep = (t1 - t0 + math.pi) % (2 * math.pi) - math.pi
        ends.append((a, b, Arc(c, rad, t0, sweep)))
    out = []
    for k in range(n):
        if ends[k][2] is not None:
            out.append(ends[k][2])
        p, q = ends[k][1], ends[(k + 1) % n][0]
        if math.dist(p, q) > EQUAL_TOL:
            out.append(Line(p, q))
    return out


def _unit(a, b) -> tuple:
    d = math.dist(a, b)
    return ((b[0] - a[0]) / d, (b[1] - a[1]) / d)
