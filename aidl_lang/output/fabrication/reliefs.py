"""Reliefs: the inside corners of a part that a router's round bit cannot reach, and the
moves that reach them (docs/machines.md, "Inside corners and reliefs"; issue 102).

A router's bit of radius ``r`` runs its centre along the outline offset by ``r``
(:func:`~..writers.gcode.tool_path`).  Where two straight edges of the material meet at an
inside corner (a finger joint's slot, a tab's slot, a halving, a dovetail's socket, a
rectangular hole: the material turns away from the tool), the two offset lines cross at ``P``,
``r / sin(a/2)`` from the drawn corner ``C`` (``a``: the corner's angle, measured in the free
space the tool runs in), so the bit's edge stays ``r / sin(a/2) - r`` from ``C`` (0.658 mm for
a 90 degree corner and the built-in 3.175 mm bit) and a square tenon, tab or finger does not
seat.  A relief runs the tool's centre from ``P`` into the corner and back, to the point
``Q`` where its edge touches ``C`` (``|Q - C| = r``):

* ``dogbone``: along the corner's bisector, ``Q = C + r u`` (``u`` the bisector's unit
  vector into the free space);
* ``tbone``: along the longer of the two edges, ``Q = C + r n`` (``n`` the unit normal of that
  edge on the tool's side): the relief is hidden in the shorter side, the longer face stays
  straight.

The loops keep their direction (material on the left: outlines counter-clockwise, holes
clockwise), so an inside corner is a turn to the right between two lines.  Only corners
between two straight edges are relieved (a mating part's square corner is two straight
edges); a corner next to an arc is reached by the arc's own tangency.  What a profile
without a relief leaves is :func:`unreached` (W0527, located by the caller).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ...geometry.shapes.curves import Loop
from ..part.part import Line, Output, PartOutline
from .machine import RELIEFS

# rad: a turn of less than this between two lines is no corner (collinear pieces of one edge)
TURN_EPS = 1e-7
# mm: the tool path's corner is found within this of where the two offset lines cross
MATCH_TOL = 1e-6


@dataclass(frozen=True)
class Corner:
    """An inside corner of part ``part``'s material: ``at`` (x, y mm, the drawn corner),
    ``angle`` (radians, the free space's angle there, 0..pi), ``into`` (unit vector along the
    bisector into the free space), ``normals`` (the unit normals of the incoming and outgoing
    edges on the tool's side), ``lengths`` (mm, the two edges').  ``left`` (mm): how far the
    material stays from ``at`` when a bit of the given radius runs the offset path, no
    relief."""
    part: str
    at: tuple
    angle: float
    into: tuple
    normals: tuple
    lengths: tuple
    left: float


def _dir(s: Line):
    dx, dy = s.end[0] - s.start[0], s.end[1] - s.start[1]
    L = math.hypot(dx, dy)
    return (dx / L, dy / L) if L > 0 else None


def _runs(segs: list) -> list:
    """The loop's segments with collinear neighbouring lines joined (an edge cut in pieces
    by the booleans is one edge): a list of segments, lines merged."""
    out: list = []
    for s in segs:
        if out and isinstance(s, Line) and isinstance(out[-1], Line):
            a, b = _dir(out[-1]), _dir(s)
            if a is not None and b is not None and \
                    abs(a[0] * b[1] - a[1] * b[0]) < TURN_EPS and a[0] * b[0] + a[1] * b[1] > 0:
                out[-1] = Line(out[-1].start, s.end)
                continue
        out.append(s)
    if len(out) > 2 and isinstance(out[0], Line) and isinstance(out[-1], Line):
        a, b = _dir(out[-1]), _dir(out[0])
        if a is not None and b is not None and \
                abs(a[0] * b[1] - a[1] * b[0]) < TURN_EPS and a[0] * b[0] + a[1] * b[1] > 0:
            out[0] = Line(out[-1].start, out[0].end)
            out.pop()
    return out


def inside_corners(part: PartOutline, radius: float) -> list[Corner]:
    """The inside corners of ``part``'s material between two straight edges (a right turn of
    its loop), with what a bit of ``radius`` mm leaves there (:attr:`Corner.left`)."""
    out = []
    if part.kind != "solid":
        return out
    for lp in part.loops:
        segs = _runs(lp.segments)
        n = len(segs)
        if n < 2:
            continue
        for i in range(n):
            a, b = segs[i], segs[(i + 1) % n]
            if not (isinstance(a, Line) and isinstance(b, Line)):
                continue
            d1, d2 = _dir(a), _dir(b)
            if d1 is None or d2 is None:
                continue
            cross = d1[0] * d2[1] - d1[1] * d2[0]
            dot = d1[0] * d2[0] + d1[1] * d2[1]
            turn = math.atan2(cross, dot)
            if turn > -TURN_EPS or turn <= -math.pi + TURN_EPS:
                continue                        # a left turn (outside corner) or straight
            angle = math.pi + turn              # the free space's angle, 0 < angle < pi
            bx, by = d2[0] - d1[0], d2[1] - d1[1]
            L = math.hypot(bx, by)
            into = (bx / L, by / L)
            m1, m2 = (d1[1], -d1[0]), (d2[1], -d2[0])        # right normals: the tool's side
            left = radius / math.sin(angle / 2) - radius
            out.append(Corner(part.name, tuple(a.end), angle, into, (m1, m2),
                              (a.length, b.length), left))
    return out


def relief_point(c: Corner, radius: float, style: str) -> tuple:
    """Where the tool's centre goes to reach corner ``c`` (its edge on the drawn corner):
    ``dogbone`` along the bisector, ``tbone`` along the longer edge."""
    if style == "tbone":
        m = c.normals[0] if c.lengths[0] >= c.lengths[1] else c.normals[1]
        return (c.at[0] + radius * m[0], c.at[1] + radius * m[1])
    return (c.at[0] + radius * c.into[0], c.at[1] + radius * c.into[1])


def path_corner(c: Corner, radius: float) -> tuple:
    """Where the tool path's two offset lines cross at corner ``c`` (``radius`` mm off each)."""
    (m1x, m1y), (m2x, m2y) = c.normals
    k = radius / (1 + m1x * m2x + m1y * m2y)
    return (c.at[0] + k * (m1x + m2x), c.at[1] + k * (m1y + m2y))


def _cell(p) -> tuple:
    """The grid cell of point ``p`` (cells of 10 x :data:`MATCH_TOL`)."""
    return (math.floor(p[0] / (10 * MATCH_TOL)), math.floor(p[1] / (10 * MATCH_TOL)))


def relieve(design: Output, tooled: Output, radius: float,
            style: str) -> tuple[Output, list[Corner]]:
    """``tooled`` (``design`` offset by the tool's ``radius`` mm, its parts in the same order)
    with a relief of ``style`` (:data:`RELIEFS`) run into every inside corner of ``design``'s
    parts whose tool-path corner is there (a corner the offset path cut off, in a feature
    narrower than the bit, is not): at the path's corner ``P`` a line to the relief point and
    back.  Returns the new output and the corners relieved.  ``style`` ``none``: ``tooled``
    unchanged, no corner."""
    if style == "none" or radius <= 0:
        return tooled, []
    by_name = {p.name: p for p in design.parts}
    parts, done = [], []
    for tp in tooled.parts:
        dp = by_name.get(tp.name)
        corners = inside_corners(dp, radius) if dp is not None else []
        if not corners:
            parts.append(tp)
            continue
        want: dict = {}
        for c in corners:
            p = path_corner(c, radius)
            want.setdefault(_cell(p), []).append((p, c))
        loops = []
        for lp in tp.loops:
            segs, new = lp.segments, []
            for j, s in enumerate(segs):
                new.append(s)
                nxt = segs[(j + 1) % len(segs)]
                if not (isinstance(s, Line) and isinstance(nxt, Line)) or len(segs) < 2:
                    continue
                e = s.end
                kx, ky = _cell(e)
                hit = next((c for dx in (-1, 0, 1) for dy in (-1, 0, 1)
                            for p, c in want.get((kx + dx, ky + dy), ())
                            if math.dist(p, e) <= MATCH_TOL), None)
                if hit is None:
                    continue
                q = relief_point(hit, radius, style)
                if math.dist(q, e) <= 1e-9:
                    continue
                new += [Line(e, q), Line(q, e)]
                done.append(hit)
            loops.append(Loop(new))
        parts.append(PartOutline(tp.name, tp.kind, loops, tp.thickness))
    return Output(parts, list(tooled.engrave), tooled.title, tooled.drawing, tooled.page), done


def relieved(design: Output, tooled: Output, m, tag: str = "") -> tuple[Output, list[str]]:
    """``tooled`` (``design`` offset by router profile ``m``'s tool radius) with the
    profile's ``relief`` run into every inside corner (:func:`relieve`), and its words: a
    note of the corners relieved, or (``relief = "none"``) a warning per part naming the
    corners the bit leaves material in, each ending ``tag``."""
    r = m.tool_diameter / 2
    if m.relief == "none":
        return tooled, [unreached_message(part, cs, m.tool_diameter) + tag
                        for part, cs in unreached(design, r).items()]
    tooled, done = relieve(design, tooled, r, m.relief)
    if not done:
        return tooled, []
    n, parts = len(done), len({c.part for c in done})
    return tooled, [f"{n} inside corner{'s' if n != 1 else ''} of {parts} part"
                    f"{'s' if parts != 1 else ''} relieved ({m.relief}): the bit runs into "
                    "each until its edge touches the drawn corner"]


def routed_shape(part: PartOutline, radius: float, style: str):
    """The material of ``part`` as a router's bit of ``radius`` mm leaves it (a manifold3d
    ``CrossSection``, chords within the part's own): the part closed by the bit (every inside
    corner rounded to the bit's radius, a gap narrower than the bit filled), less the stroke
    of each relief of ``style`` (:data:`RELIEFS`; ``none``: no relief).  What the assembled fit
    check of a routed job reads."""
    import manifold3d as mf
    shape = part.shape
    if radius <= 0 or part.kind != "solid" or shape.is_empty():
        return shape
    n = max(16, int(math.ceil(2 * math.pi / math.acos(max(-1.0, 1 - 1e-3 / radius)))))
    n = min(n, 720)
    rnd = mf.JoinType.Round
    got = shape.offset(radius, rnd, 2.0, n).offset(-radius, rnd, 2.0, n)
    if style != "none":
        strokes = []
        out = radius / math.cos(math.pi / n)       # the polygon holds the bit's whole disc
        for c in inside_corners(part, radius):
            p, q = path_corner(c, radius), relief_point(c, radius, style)
            strokes.append(mf.CrossSection.batch_hull([
                mf.CrossSection.circle(out, n).translate(list(p)),
                mf.CrossSection.circle(out, n).translate(list(q))]))
        if strokes:
            got = got - mf.CrossSection.batch_boolean(strokes, mf.OpType.Add)
    return got


def unreached(output: Output, radius: float) -> dict[str, list[Corner]]:
    """Part name -> its inside corners a bit of ``radius`` mm running the offset path leaves
    material in (more than 1e-6 mm from the drawn corner): what ``relief = "none"`` cuts."""
    got: dict[str, list[Corner]] = {}
    if radius <= 0:
        return got
    for p in output.parts:
        cs = [c for c in inside_corners(p, radius) if c.left > 1e-6]
        if cs:
            got[p.name] = cs
    return got


def unreached_message(part: str, corners: list[Corner], diameter: float,
                      shown: int = 4) -> str:
    """W0527's words for ``part``'s ``corners`` a ``diameter`` mm bit leaves material in."""
    far = max(c.left for c in corners)
    where = ", ".join(f"({c.at[0]:.4g}, {c.at[1]:.4g})" for c in corners[:shown])
    more = f" and {len(corners) - shown} more" if len(corners) > shown else ""
    n = len(corners)
    return (f"the router's {diameter:g} mm bit does not reach {n} inside corner"
            f"{'s' if n != 1 else ''} of part `{part}`: the material stays up to {far:.3g} mm "
            f"from the drawn corner at {where}{more}, so a square corner of a mating part "
            "does not seat")


RELIEF_HINT = ("set `relief = \"dogbone\"` (or `\"tbone\"`) in the machine profile: the bit "
               "then runs into each inside corner until its edge touches it")

__all__ = ["RELIEFS", "Corner", "inside_corners", "relief_point", "path_corner", "relieve",
           "relieved", "routed_shape", "unreached", "unreached_message", "RELIEF_HINT"]
