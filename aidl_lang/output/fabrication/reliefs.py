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

A relief is cut only where it takes no more than a disc of the bit's radius beside its corner
and keeps the part whole (:func:`plan`; issue 109): not at a corner sharper than
:data:`MIN_ANGLE` (the stroke from ``P``, ``r / sin(a/2)`` from the corner, gouges both edges on
its way in: 3.5 discs at 10 degrees), and not where the stroke would come nearer another edge
of the part than the bit's radius on the free side or the radius plus the minimum wall through
the material (a T-bone into a wall 1.2 mm thick cut the part in two).  A T-bone that does not
fit is cut as a dogbone when that fits; else the corner is left as the offset path leaves it.
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
# rad: the sharpest inside corner a relief is cut at.  From 60 degrees up, a dogbone takes at
# most 0.42 and a T-bone 0.87 of the bit's disc beside the corner, none of it farther than
# 2.31 r from it; below, the stroke from the path's corner gouges both edges on its way in
# (at 30 degrees 1.05 and 1.60 discs, at 10 degrees 3.50 and 4.11: docs/machines.md)
MIN_ANGLE = math.radians(60)
# mm: how much nearer another edge a relief's stroke may come than allowed (rounding)
WALL_TOL = 1e-6


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
    loop: int = -1          # the index of its loop in the part's loops


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
    for k, lp in enumerate(part.loops):
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
                              (a.length, b.length), left, k))
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


@dataclass(frozen=True)
class Planned:
    """What is cut at inside corner ``corner`` for a profile asking ``asked`` (dogbone |
    tbone): ``style``, the relief cut (``asked``, or ``dogbone`` in place of a T-bone that
    does not fit) or None (none: the offset path leaves the corner ``corner.left`` mm off);
    ``why``: the words of why ``asked`` is not cut ("" when it is)."""
    corner: Corner
    asked: str
    style: str | None
    why: str


def _edges(part: PartOutline):
    """Every chord of ``part``'s loops (within the loops' chord tolerance): ``(A, B, loop)``,
    N x 2 arrays of the starts and ends (mm, the material on the left) and each one's loop
    index."""
    import numpy as np
    A, B, K = [], [], []
    for k, lp in enumerate(part.loops):
        pts = lp.points()
        if len(pts) < 2:
            continue
        A.append(pts)
        B.append(np.roll(pts, -1, axis=0))
        K.append(np.full(len(pts), k))
    if not A:
        z = np.zeros((0, 2))
        return z, z, np.zeros(0, dtype=int)
    return np.concatenate(A), np.concatenate(B), np.concatenate(K)


def _point_seg(P, A, B):
    """Distances (mm) from points ``P`` (N x 2, or one point) to segments ``A``-``B`` (N x 2),
    and the parameter of the nearest point along each (0..1)."""
    import numpy as np
    e = B - A
    L2 = (e * e).sum(-1)
    t = np.where(L2 > 0, ((P - A) * e).sum(-1) / np.where(L2 > 0, L2, 1.0), 0.0)
    t = np.clip(t, 0.0, 1.0)
    X = A + t[..., None] * e
    return np.hypot(*(P - X).T), t


def _on_edges(c: Corner, A, B):
    """Which chords lie on corner ``c``'s own two edges (within 1e-7 mm)."""
    import numpy as np
    C = np.asarray(c.at)
    on = np.zeros(len(A), dtype=bool)
    for m, length, back in ((c.normals[0], c.lengths[0], True),
                            (c.normals[1], c.lengths[1], False)):
        d = np.array([-m[1], m[0]])                 # the edge's direction (material left)
        d = -d if back else d                       # from the corner along the edge
        ok = np.ones(len(A), dtype=bool)
        for X in (A, B):
            rel = X - C
            off = np.abs(rel @ np.array(m))
            along = rel @ d
            ok &= (off <= 1e-7) & (along >= -1e-7) & (along <= length + 1e-7)
        on |= ok
    return on


def _stroke_fits(part: PartOutline, c: Corner, radius: float, style: str, wall: float,
                 chords) -> str:
    """"" when the stroke of a ``style`` relief at corner ``c`` (the bit of ``radius`` mm
    from the tool path's corner ``P`` to the relief point ``Q`` and back) comes no nearer any
    edge of ``part`` but the corner's own two than the bit's radius on the edge's free side,
    or the radius plus ``wall`` (mm, the minimum wall) through the material behind it (or
    than ``P`` itself already does); else the words of what it would do."""
    import numpy as np
    A, B, K = chords
    if not len(A):
        return ""
    keep = ~_on_edges(c, A, B)
    A, B, K = A[keep], B[keep], K[keep]
    P, Q = np.asarray(path_corner(c, radius)), np.asarray(relief_point(c, radius, style))
    dP, _ = _point_seg(P, A, B)
    dQ, _ = _point_seg(Q, A, B)
    dA, tA = _point_seg(A, P[None, :], Q[None, :])
    dB, tB = _point_seg(B, P[None, :], Q[None, :])
    cand = np.stack([dP, dQ, dA, dB])
    which = cand.argmin(0)
    d = cand.min(0)
    # the stroke's point nearest each chord, and on which side of it that lies
    X = np.where((which == 0)[:, None], P, Q)
    X = np.where((which == 2)[:, None], P + tA[:, None] * (Q - P), X)
    X = np.where((which == 3)[:, None], P + tB[:, None] * (Q - P), X)
    e = B - A
    side = e[:, 0] * (X[:, 1] - A[:, 1]) - e[:, 1] * (X[:, 0] - A[:, 0])
    # a stroke that crosses a chord is nearer than any bound
    s1 = e[:, 0] * (P[1] - A[:, 1]) - e[:, 1] * (P[0] - A[:, 0])
    s2 = e[:, 0] * (Q[1] - A[:, 1]) - e[:, 1] * (Q[0] - A[:, 0])
    f = Q - P
    s3 = f[0] * (A[:, 1] - P[1]) - f[1] * (A[:, 0] - P[0])
    s4 = f[0] * (B[:, 1] - P[1]) - f[1] * (B[:, 0] - P[0])
    d = np.where((s1 * s2 < 0) & (s3 * s4 < 0), 0.0, d)
    through = side > 0                              # the material's side: a wall between
    need = np.where(through, radius + wall, radius)
    need = np.minimum(need, dP)                     # never more than the path keeps already
    short = need - d
    i = int(short.argmax())
    if short[i] <= WALL_TOL:
        return ""
    name = "a T-bone" if style == "tbone" else "a dogbone"
    k = int(K[i])
    if k == c.loop:
        other = "another edge of the same " + ("opening" if part.loops[k].is_hole
                                               else "outline")
    else:
        other = "another hole" if part.loops[k].is_hole else "the part's outer edge"
    near = X[i]
    left = max(0.0, float(d[i]) - radius)
    if not through[i]:
        return (f"{name} would cut {radius - float(d[i]):.3g} mm into {other} near "
                f"({near[0]:.2f}, {near[1]:.2f})")
    drawn, _ = _point_seg(np.asarray(c.at), A[i:i + 1], B[i:i + 1])
    if left <= 1e-9:
        return (f"{name} would cut through the {float(drawn[0]):.3g} mm of material between "
                f"the corner and {other}, {radius - float(d[i]):.3g} mm past it (a part can "
                "come apart there)")
    return (f"{name} would leave {left:.3g} mm of the {float(drawn[0]):.3g} mm wall between "
            f"the corner and {other}, thinner than the minimum wall {wall:g} mm")


def relief_area(part: PartOutline, c: Corner, radius: float, style: str) -> float:
    """mm^2: the material of ``part`` a ``style`` relief at corner ``c`` would take (the
    stroke of a bit of ``radius`` mm from the tool path's corner to the relief point,
    Manifold's area of it inside the part; the disc a polygon within 1e-3 mm of it)."""
    import manifold3d as mf
    n = max(16, min(720, int(math.ceil(2 * math.pi / math.acos(max(-1.0, 1 - 1e-3 / radius))))))
    p, q = path_corner(c, radius), relief_point(c, radius, style)
    stroke = mf.CrossSection.batch_hull([mf.CrossSection.circle(radius, n).translate(list(p)),
                                         mf.CrossSection.circle(radius, n).translate(list(q))])
    return (stroke ^ part.shape).area()


def _acute(part: PartOutline, c: Corner, radius: float, style: str) -> str:
    """The words of why a ``style`` relief is not cut at the acute corner ``c``."""
    name = "a T-bone" if style == "tbone" else "a dogbone"
    # how deep the stroke goes into the edges, square to them: a dogbone's disc at the relief
    # point into both, a T-bone's across the shorter edge
    deep = radius * (1 + math.cos(c.angle)) if style == "tbone" else \
        radius * (1 - math.sin(c.angle / 2))
    area = relief_area(part, c, radius, style)
    disc = math.pi * radius * radius
    return (f"an acute corner ({math.degrees(c.angle):.3g} deg, sharper than "
            f"{math.degrees(MIN_ANGLE):g}): {name} would take {area:.3g} mm^2 beside it, "
            f"{area / disc:.2g} times the bit's disc, {deep:.3g} mm deep into its edges")


def plan(part: PartOutline, radius: float, style: str, wall: float = 0.5,
         corners: list | None = None) -> list[Planned]:
    """What a router's bit of ``radius`` mm cuts at each inside corner of ``part``
    (``corners``: those of :func:`inside_corners`, else all) for a profile asking ``style``
    (dogbone | tbone; ``none``: no corner): the asked relief where it fits, a dogbone in
    place of a T-bone that does not, else none, with the reason.  A relief does not fit a
    corner sharper than :data:`MIN_ANGLE`, or where its stroke would come nearer another edge
    than the bit's radius (the free side) or the radius plus ``wall`` mm (through the
    material: the part's minimum wall) -- nearer than the tool path's corner already is."""
    if style == "none" or radius <= 0:
        return []
    corners = inside_corners(part, radius) if corners is None else corners
    chords = None
    out = []
    for c in corners:
        if c.angle < MIN_ANGLE - 1e-9:
            out.append(Planned(c, style, None, _acute(part, c, radius, style)))
            continue
        if chords is None:
            chords = _edges(part)
        why = _stroke_fits(part, c, radius, style, wall, chords)
        if not why:
            out.append(Planned(c, style, style, ""))
            continue
        if style == "tbone" and not _stroke_fits(part, c, radius, "dogbone", wall, chords):
            out.append(Planned(c, style, "dogbone", why))
            continue
        out.append(Planned(c, style, None, why))
    return out


def _cell(p) -> tuple:
    """The grid cell of point ``p`` (cells of 10 x :data:`MATCH_TOL`)."""
    return (math.floor(p[0] / (10 * MATCH_TOL)), math.floor(p[1] / (10 * MATCH_TOL)))


def _wall_of(wall):
    """``wall`` (mm, or a callable part name -> mm, or None: 0.5) as a callable."""
    if callable(wall):
        return wall
    w = 0.5 if wall is None else float(wall)
    return lambda name: w


def relieve(design: Output, tooled: Output, radius: float, style: str,
            wall=None) -> tuple[Output, list[Corner], list[Planned]]:
    """``tooled`` (``design`` offset by the tool's ``radius`` mm, its parts in the same order)
    with a relief run into every inside corner of ``design``'s parts whose tool-path corner is
    there (a corner the offset path cut off, in a feature narrower than the bit, is not) and
    where :func:`plan` finds one fits (``wall``: the minimum wall, mm or a callable part name
    -> mm; None: 0.5): at the path's corner ``P`` a line to the relief point and back, of
    ``style`` (:data:`RELIEFS`) or the style :func:`plan` puts in its place.  Returns the new
    output, the corners relieved and the plan of every corner whose tool-path corner is there
    (relieved or not).  ``style`` ``none``: ``tooled`` unchanged, no corner."""
    if style == "none" or radius <= 0:
        return tooled, [], []
    wall_of = _wall_of(wall)
    by_name = {p.name: p for p in design.parts}
    parts, done, planned = [], [], []
    for tp in tooled.parts:
        dp = by_name.get(tp.name)
        plans = plan(dp, radius, style, wall_of(dp.name)) if dp is not None else []
        want: dict = {}
        for pl in plans:
            p = path_corner(pl.corner, radius)
            want.setdefault(_cell(p), []).append((p, pl))
        if not want:
            parts.append(tp)
            continue
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
                hit = next((pl for dx in (-1, 0, 1) for dy in (-1, 0, 1)
                            for p, pl in want.get((kx + dx, ky + dy), ())
                            if math.dist(p, e) <= MATCH_TOL), None)
                if hit is None:
                    continue
                planned.append(hit)
                if hit.style is None:
                    continue
                q = relief_point(hit.corner, radius, hit.style)
                if math.dist(q, e) <= 1e-9:
                    continue
                new += [Line(e, q), Line(q, e)]
                done.append(hit.corner)
            loops.append(Loop(new))
        parts.append(PartOutline(tp.name, tp.kind, loops, tp.thickness))
    return (Output(parts, list(tooled.engrave), tooled.title, tooled.drawing, tooled.page),
            done, planned)


def not_relieved(planned: list[Planned]) -> dict:
    """``(part, loop index) -> [Planned]`` of the corners whose asked relief is not cut (cut
    another way, or not at all), in order."""
    got: dict = {}
    for pl in planned:
        if pl.why:
            got.setdefault((pl.corner.part, pl.corner.loop), []).append(pl)
    return got


def not_relieved_message(plans: list[Planned], diameter: float, shown: int = 4) -> str:
    """The words of a W0527 for one loop's corners whose asked relief is not cut
    (``plans``: :func:`plan`'s, all of one part and loop) with a bit of ``diameter`` mm."""
    first = plans[0]
    c, n = first.corner, len(plans)
    pt = [f"({p.corner.at[0]:.4g}, {p.corner.at[1]:.4g})" for p in plans]
    where = ", ".join(pt[:shown]) + (f" and {n - shown} more" if n > shown else "")
    asked = "T-bone" if first.asked == "tbone" else "dogbone"
    instead = [p for p in plans if p.style is not None]
    if len(instead) == n:
        done = "cut as a dogbone instead" if n == 1 else "each cut as a dogbone instead"
    elif not instead:
        far = max(p.corner.left for p in plans)
        done = (f"not relieved: the material stays up to {far:.3g} mm from the drawn "
                "corner, as the offset path leaves it")
    else:
        done = (f"{len(instead)} cut as a dogbone instead, {n - len(instead)} not relieved "
                "(the material stays as the offset path leaves it)")
    why = f"at {pt[0]} {first.why}" if n > 1 else first.why
    return (f"the router's {diameter:g} mm bit does not cut the {asked} relief at {n} inside "
            f"corner{'s' if n != 1 else ''} of part `{c.part}`, {where}: {why}; {done}")


NOT_RELIEVED_HINT = ("a relief is cut only where it takes at most a disc of the bit's radius "
                     "beside its corner and leaves the minimum wall: give the corner 60 deg "
                     "or more, or the wall the bit's radius plus the minimum wall, or use a "
                     "smaller bit (the profile's `tool_diameter`)")


def relieved(design: Output, tooled: Output, m, tag: str = "",
             wall=None) -> tuple[Output, list[str], list[str]]:
    """``tooled`` (``design`` offset by router profile ``m``'s tool radius) with the
    profile's ``relief`` run into every inside corner where it fits (:func:`relieve`;
    ``wall``: the minimum wall, mm or a callable part name -> mm), and its words: notes (the
    corners relieved) and warnings (one per loop whose corners' relief is not cut as asked:
    :func:`not_relieved_message`; with ``relief = "none"`` one per part naming the corners
    the bit leaves material in), each warning ending ``tag``."""
    r = m.tool_diameter / 2
    if m.relief == "none":
        return tooled, [], [unreached_message(part, cs, m.tool_diameter) + tag
                            for part, cs in unreached(design, r).items()]
    tooled, done, planned = relieve(design, tooled, r, m.relief, wall)
    warnings = [not_relieved_message(ps, m.tool_diameter) + tag
                for ps in not_relieved(planned).values()]
    if not done:
        return tooled, [], warnings
    n, parts = len(done), len({c.part for c in done})
    instead = sum(1 for p in planned if p.why and p.style is not None)
    also = (f", {instead} of them as dogbones where a T-bone does not fit" if instead
            else "")
    return tooled, [f"{n} inside corner{'s' if n != 1 else ''} of {parts} part"
                    f"{'s' if parts != 1 else ''} relieved ({m.relief}{also}): the bit runs "
                    "into each until its edge touches the drawn corner"], warnings


def routed_shape(part: PartOutline, radius: float, style: str, wall=None):
    """The material of ``part`` as a router's bit of ``radius`` mm leaves it (a manifold3d
    ``CrossSection``, chords within the part's own): the part closed by the bit (every inside
    corner rounded to the bit's radius, a gap narrower than the bit filled), less the stroke
    of each relief of ``style`` (:data:`RELIEFS`; ``none``: no relief) where :func:`plan`
    cuts one (``wall``: the minimum wall, mm; None: 0.5).  What the assembled fit check of a
    routed job reads."""
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
        for pl in plan(part, radius, style, _wall_of(wall)(part.name)):
            if pl.style is None:
                continue
            p, q = path_corner(pl.corner, radius), relief_point(pl.corner, radius, pl.style)
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

__all__ = ["RELIEFS", "MIN_ANGLE", "Corner", "Planned", "inside_corners", "relief_point",
           "path_corner", "plan", "relief_area", "relieve", "relieved",
           "not_relieved", "not_relieved_message", "NOT_RELIEVED_HINT", "routed_shape",
           "unreached", "unreached_message", "RELIEF_HINT"]
