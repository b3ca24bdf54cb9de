"""Corner finishing of a solid's (or hole's) exact outline, after its booleans: ``Fillet``
and ``Chamfer`` (:func:`.finishing.finish`, called by the renderer, makes the passes of
:func:`corners`), on every corner or on the corners a
call chose with ``at`` (:class:`Chosen`); a chosen corner that is no corner of the outline
(E0408), one rounded smaller than asked and an operation that rounds nothing (W0406) are said
(:func:`report`).  See :mod:`.operations` for the rules."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .outline_distance import _sizes, one_radius, outline_distance

if TYPE_CHECKING:
    from ..core.model import Structure

CORNER_TURN = 1e-3      # rad: a join that turns less is tangent (a slot's side into its end)
CORNER_TOL = 0.01       # mm: a chosen corner matches an outline vertex this close (a point
#                         worked out by hand to 0.01 mm, run bu: 0.001 mm off was refused)
SHRUNK = 1e-6           # a chosen corner rounded this much (relatively) under its size: said


class SplineCorner(ValueError):
    """A Fillet or Chamfer asked for a corner where a spline or an ellipse meets another
    curve: the rounding arc would have to be tangent to a cubic spline or an ellipse at a
    point no closed form gives; ``curve``: the spline's :class:`~.spline.CubicSpline` or the
    :class:`~.ellipse.EllipseCurve`, ``hint``: what to do."""

    def __init__(self, message: str, curve, hint: str):
        super().__init__(message)
        self.curve = curve
        self.hint = hint


class FinishCall:
    """Where a ``Fillet``/``Chamfer`` is written (``span``) and the structure it finishes
    (``owner``): what its messages are located at (E0408, W0406)."""
    __slots__ = ("span", "owner", "kind")

    def __init__(self, span, owner, kind: str):
        self.span, self.owner, self.kind = span, owner, kind


class Chosen:
    """Corners a ``Fillet``/``Chamfer``'s ``at`` names.  ``what``: "point" (one point,
    ``name`` the point's name or ""), "edges" (two edges: ``points`` their ends a1, b1, a2, b2,
    ``name`` the two names; the corner is where they meet: at their ends, where they cross, or
    where one ends on the other), "ends" (a line's two ends) or "corners" (a shape's corners;
    ``name`` the line's or shape's).  ``points``: (x, y) expressions in the structure's frame
    plus its offset (floats once :meth:`placed`).  ``alts``: for two edges, the other edges
    of their shapes as ``(name, start, end)`` (E0408's hint names those that do meet, issue
    111: a Fillet between a turned Trapezoid's parallel `right` and `top`)."""
    __slots__ = ("what", "points", "name", "alts", "curve", "quiet")

    def __init__(self, what: str, points: tuple, name, alts: tuple = (), curve=None):
        self.what, self.points, self.name, self.alts = what, points, name, alts
        self.quiet = False      # a pattern copy's corners (sinks.fillet_copies): none, unsaid
        # "shapes_meet" (two shapes, or an edge and a shape: ``points`` their points in
        # order): ((kind, count) of each, then each Geometry; placed: each one's sizes)
        self.curve = curve

    def moved(self, f) -> "Chosen":
        """The same corners under ``f`` (a copy's transform of a point's coordinates)."""
        c = Chosen(self.what, tuple(f(px, py) for px, py in self.points), self.name,
                   tuple((n, f(*a), f(*b)) for n, a, b in self.alts), self.curve)
        c.quiet = self.quiet
        return c

    def placed(self, x) -> "Chosen":
        from ..core.expr import evaluate

        def at(px, py):
            return (float(evaluate(px, x)), float(evaluate(py, x)))
        curve = self.curve
        if self.what == "shapes_meet" and not isinstance(curve[2], tuple):
            curve = tuple(curve[:2]) + tuple(_sizes(g, x) for g in curve[2:])   # placed
        c = Chosen(self.what, tuple(at(px, py) for px, py in self.points), self.name,
                   tuple((n, at(*a), at(*b)) for n, a, b in self.alts), curve)
        c.quiet = self.quiet
        return c

    def meeting(self) -> list:
        """For two edges that make no corner: the pairs of this shape's edges that do,
        each ``(name1, name2)``, one of the two named kept (placed)."""
        if self.what != "edges" or not self.alts:
            return []
        (a1, b1, a2, b2), (n1, n2) = self.points, self.name
        out = []
        for n, a, b in self.alts:
            for keep, (p, q), first in ((n1, (a1, b1), True), (n2, (a2, b2), False)):
                if n.rsplit(".", 1)[0] == keep.rsplit(".", 1)[0]:
                    continue                       # an edge of the kept one's own shape
                if edges_meet((p, q, a, b), (keep, n))[0]:
                    out.append((keep, n) if first else (n, keep))
        return list(dict.fromkeys(out))

    def targets(self, loops=None) -> tuple[list, str | None]:
        """(the points to round, why there are none): for two edges the point where they
        meet, or no point and the reason (parallel, apart, of no length); for two shapes the
        corners of ``loops`` (the outline) that lie on both of their outlines."""
        if self.what == "shapes_meet":
            return shapes_meet(self.points, self.curve, self.name, loops or [])
        if self.what != "edges":
            return list(self.points), None
        return edges_meet(self.points, self.name)

    def describe(self, off=(0.0, 0.0)) -> str:
        """The corners in words, a point in the frame its ``Fillet`` is written in (``off``:
        that frame's offset from the outline's)."""
        if self.what == "edges":
            return f"the corner of `{self.name[0]}` and `{self.name[1]}`"
        if self.what == "shapes_meet":
            return f"the corners where `{self.name[0]}` and `{self.name[1]}` meet"
        if self.what == "ends":
            return f"the ends of `{self.name}`"
        if self.what == "corners":
            return f"the corners of `{self.name}`"
        (x, y), = self.points
        x, y = x - off[0], y - off[1]
        return (f"`{self.name}` at ({x:.6g}, {y:.6g}) mm" if self.name
                else f"the point ({x:.6g}, {y:.6g}) mm")


def edges_meet(pts, names) -> tuple[list, str | None]:
    """([the point where two edges meet], None), or ([], why they make no corner): edge 1
    from ``pts[0]`` to ``pts[1]``, edge 2 from ``pts[2]`` to ``pts[3]``; they meet where
    their lines cross, on both edges (ends included, within :data:`CORNER_TOL`)."""
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = pts
    ux, uy, vx, vy = bx - ax, by - ay, dx - cx, dy - cy
    L1, L2 = math.hypot(ux, uy), math.hypot(vx, vy)
    for L, nm in ((L1, names[0]), (L2, names[1])):
        if L <= 1e-9:
            return [], f"`{nm}` has no length (its ends are one point), so it has no direction"
    den = ux * vy - uy * vx
    if abs(den) <= math.sin(CORNER_TURN) * L1 * L2:
        gap = abs(ux * (cy - ay) - uy * (cx - ax)) / L1
        how = ("lie on one line" if gap <= CORNER_TOL else
               f"are parallel, {gap:.6g} mm apart")
        return [], f"they {how}: parallel edges never meet, so they make no corner"
    t = ((cx - ax) * vy - (cy - ay) * vx) / den           # along edge 1, 0..1
    u = ((cx - ax) * uy - (cy - ay) * ux) / den           # along edge 2
    p = (ax + t * ux, ay + t * uy)
    past = [(nm, max(-tt * L, (tt - 1) * L)) for tt, L, nm in ((t, L1, names[0]),
                                                                  (u, L2, names[1]))]
    off = [(nm, d) for nm, d in past if d > CORNER_TOL]
    if not off:
        return [p], None
    says = " and ".join(f"{d:.6g} mm past an end of `{nm}`" for nm, d in off)
    return [], (f"they do not meet: their lines cross at ({p[0]:.6g}, {p[1]:.6g}) mm, "
                f"{says}")


def shapes_meet(pts, curve, names, loops) -> tuple[list, str | None]:
    """([the corners of ``loops`` on both shapes' outlines], None), or ([], why there are
    none): the shapes of ``Fillet([a, b], r)`` (``curve``: their (kind, count) and sizes,
    ``pts`` their placed points in order), within :data:`CORNER_TOL` of both (issue 111, run
    z3's hair catcher: `Fillet([tab, disc], 2)` where a round-ended tab meets a disc; run y's
    table-tennis blade: `Fillet([handle.left, blade], 8)`, an edge into an oval)."""
    (ka, na), (kb, nb), sa, sb = curve
    A, B = list(pts[:na]), list(pts[na:na + nb])
    out = []
    for lp in loops:
        for g in lp.segments:
            p = getattr(g, "start", None)          # (a whole circle has no corner)
            if p is not None and outline_distance(ka, A, sa, p) <= CORNER_TOL \
                    and outline_distance(kb, B, sb, p) <= CORNER_TOL:
                out.append(p)
    if out:
        return out, None
    return [], (f"no corner of the outline lies on both `{names[0]}` and `{names[1]}` (their "
                f"outlines do not cross there, or one lies inside the other)")


def outline_shapes(s) -> str | None:
    """Structure ``s``'s own outline shapes as a ``Fillet`` names them (`body`, or
    `[a, b]` up to four), None when it has none or more than four: what a hint to round
    the outline alone writes (W0410, W0517)."""
    names = [g.name for g in s.geometry if g.closed and g.name
             and not g.construction and not g.__dict__.get("copied")]
    return (None if not names else names[0] if len(names) == 1 else
            "[" + ", ".join(names[:4]) + "]" if len(names) <= 4 else None)


def _narrow_notches(lp, r: float) -> list:
    """The bottoms of notches cut into an outer outline ``lp`` narrower than two fillet radii
    ``r``: a straight piece between two inside corners, shorter than ``2 r`` (a 3 mm cable
    slit under ``Fillet(4)``, whose bottom comes out round and whose mouth flares: the fresh
    models' run data/model_runs/issue105c, request 15), as ``[(a Loop of the notch's three
    sides, the size its corners got)]`` for :func:`_narrow_holes`.  A straight piece between
    two convex arcs is a bar's side between two circles (a step, issue 111's spinner: a
    14 mm arm between a 36 mm hub and a 32 mm lobe leaves 2.03 mm): its fillets touch it
    less than ``r`` from the corners, so the size is what :func:`_fillet` fits there, and it
    is said only when that is less than ``r``."""
    from ..shapes.curves import Line, Loop, turn_between
    segs = lp.segments
    n = len(segs)
    out = []
    if n < 4:
        return out
    for k, g in enumerate(segs):
        if not isinstance(g, Line) or not g.length < 2 * r * (1 - SHRUNK):
            continue
        a, b = segs[k - 1], segs[(k + 1) % n]
        t1, t2 = turn_between(a, g), turn_between(g, b)
        if t1 < -CORNER_TURN and t2 < -CORNER_TURN:
            least = g.length / 2
            if _step(a, b):
                f1, f2 = _fillet(a, g, t1, r), _fillet(g, b, t2, r)
                least = min(0.0 if f is None else f[2].radius for f in (f1, f2))
                if least >= r * (1 - SHRUNK):
                    continue
            out.append((Loop([a, g, b]), least))
    return out


def _step(a, b) -> bool:
    """True when the straight piece between segments ``a`` and ``b`` of an outer outline runs
    between two convex arcs (each turns left, the material's way): a bar's side between two
    circles, not a notch cut into the outline."""
    from ..shapes.curves import Arc
    return isinstance(a, Arc) and isinstance(b, Arc) and a.sweep > 0 and b.sweep > 0


def _widen(a, g, b, r: float) -> tuple[float, float] | None:
    """How far from the centers of arcs ``a`` and ``b`` (convex, before and after the line
    ``g`` of an outer outline) the line must lie for fillets of radius ``r`` to fit at both
    of its corners, each within half of it (:func:`corners`' rule), the line moved out
    parallel to itself (a wider bar): ``(distance from a's center, from b's)`` in mm, or None
    when no such line meets both circles.  Along the line, a circle of radius R whose center
    is d inside it leaves it sqrt(R^2 - d^2) from the center's foot, and a fillet of radius r
    outside touches it sqrt((R + r)^2 - (d + r)^2) from there."""
    (x0, y0), (x1, y1) = g.start, g.end
    L = g.length
    ux, uy = (x1 - x0) / L, (y1 - y0) / L
    pos = [((c[0] - x0) * ux + (c[1] - y0) * uy, -(c[0] - x0) * uy + (c[1] - y0) * ux, R)
           for c, R in ((a.center, a.radius), (b.center, b.radius))]
    (s1, d1, R1), (s2, d2, R2) = pos
    if d1 <= 0 or d2 <= 0:
        return None

    def ok(e):
        h1, h2 = (math.sqrt(max(R * R - (d + e) ** 2, 0.0)) for _, d, R in pos)
        t1 = math.sqrt(max((R1 + r) ** 2 - (d1 + e + r) ** 2, 0.0)) - h1
        t2 = math.sqrt(max((R2 + r) ** 2 - (d2 + e + r) ** 2, 0.0)) - h2
        return max(t1, t2) <= (s2 - h2 - s1 - h1) / 2

    h1, h2 = math.sqrt(max(R1 * R1 - d1 * d1, 0.0)), math.sqrt(max(R2 * R2 - d2 * d2, 0.0))
    if abs(s2 - h2 - s1 - h1 - L) > 1e-6 * max(1.0, L):
        return None                         # not the circles' far and near crossings
    top = min(R1 - d1, R2 - d2)
    steps = 400
    hi = next((top * i / steps for i in range(1, steps + 1) if ok(top * i / steps)), None)
    if hi is None:
        return None
    lo = hi - top / steps
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if ok(mid) else (mid, hi)
    return d1 + hi, d2 + hi


def _narrow_holes(kind: str, r: float, call, narrow: list, body: str | None) -> list:
    """The note W0410 for each hole of the outline that a ``Fillet`` of the whole outline (no
    ``at``) could round only with less than its radius, because the hole is narrower than two
    of it: its ends come out round (a 4.2 mm slot under ``Fillet(4)``), which a reader of
    ``Fillet(4)`` written beside the plate did not expect (the fresh models' run
    data/model_runs/issue105b, request 8: a tab slot that no tab fits); the same for a notch
    of the outer outline (:func:`_narrow_notches`).  ``narrow``: [(the hole's loop, or the
    notch's three sides, the least radius its corners got)]; ``body``: the structure's own
    outline shapes as the hint writes them (None: said in words)."""
    out = []
    path = getattr(getattr(call, "owner", None), "path", "") or "?"
    for lp, least in narrow[:3]:
        step = None if lp.is_hole else lp.segments
        if step is not None and _step(step[0], step[2]):
            out.append(_step_note(kind, r, call, path, step, least, len(out)))
            continue
        if lp.is_hole:
            xy = lp.points()
            (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
            where = (f"the corners of the hole at ({(x0 + x1) / 2:.6g}, {(y0 + y1) / 2:.6g}) "
                     f"mm, {_width(xy):.6g} mm across")
            ends = "its ends come out round"
        else:
            g = lp.segments[1]
            mx, my = (g.start[0] + g.end[0]) / 2, (g.start[1] + g.end[1]) / 2
            where = (f"the inside corners of the notch whose bottom is at ({mx:.6g}, "
                     f"{my:.6g}) mm, {g.length:.6g} mm across")
            ends = "its bottom comes out round (and its mouth's corners flare it)"
        out.append((call, "W0410", -2 - len(out),
                    f"`{kind}` (radius {r:.6g} mm) of the whole outline of `{path}` also "
                    f"rounds {where}: only {least:.6g} mm fits, so {ends}",
                    "nothing to change if that is meant; to round the outside alone, "
                    + (f"name its shapes: `{kind}({body}, {r:.6g})`" if body else
                       f"name the outline's shapes: `{kind}([SHAPE, ...], {r:.6g})`")
                    + ("" if lp.is_hole else " (the corners beside the notch's mouth still "
                       "get only what fits, and W0406 says how much)")))
    return out


def _step_note(kind: str, r: float, call, path: str, segs: list, least: float,
               i: int) -> tuple:
    """W0410 for a step of the outer outline: a bar's side ``segs[1]`` between two circles'
    arcs ``segs[0]`` and ``segs[2]`` (:func:`_step`), shorter than the fillets at its two
    inside corners need.  No `Fillet` fills it (rounding only the outside leaves the step
    sharp: issue 111's spinner, "Fillet(hub, 4)"); the hint says how wide the bar must be
    for the fillet to fit (:func:`_widen`), or to draw the neck as the circles' `Hull`."""
    a, g, b = segs
    mx, my = (g.start[0] + g.end[0]) / 2, (g.start[1] + g.end[1]) / 2
    circles = " and ".join(f"radius {c.radius:.6g} mm at ({c.center[0]:.6g}, "
                           f"{c.center[1]:.6g})" for c in (a, b))
    far = _widen(a, g, b, r)
    if far is None:
        widen = ""
    else:
        (x0, y0), (x1, y1) = g.start, g.end
        now = [abs((c.center[0] - x0) * (y1 - y0) - (c.center[1] - y0) * (x1 - x0)) / g.length
               for c in (a, b)]
        need = [math.ceil(v * 100 - 1e-9) / 100 for v in far]
        if abs(now[0] - now[1]) <= 1e-6 * max(1.0, now[0]):
            widen = (f"widen the bar so that this side lies at least {need[0]:.6g} mm from "
                     f"the circles' centers (a bar centred on them: at least "
                     f"{2 * need[0]:.6g} mm wide, not {2 * now[0]:.6g} mm), where the "
                     f"{r:.6g} mm fillets fit; or ")
        else:
            widen = (f"widen the bar so that this side lies at least {need[0]:.6g} mm from "
                     f"the first circle's center and {need[1]:.6g} mm from the second's "
                     f"({now[0]:.6g} and {now[1]:.6g} mm now), where the {r:.6g} mm fillets "
                     f"fit; or ")
    return (call, "W0410", -2 - i,
            f"`{kind}` (radius {r:.6g} mm) of the whole outline of `{path}` also rounds the "
            f"step at ({mx:.6g}, {my:.6g}) mm where a straight side {g.length:.6g} mm long "
            f"runs between two circles ({circles}): only {least:.6g} mm fits at its "
            f"corners, so the step comes out as a small round pit",
            f"no `{kind}` fills this step (it is a bar's side between two circles, and naming "
            f"only the circles leaves it sharp): " + widen
            + "draw the neck as the circles' hull, `Hull(a, b)` of two circles in one "
              "structure (tangent to both, no step), in place of the bar")


def _width(xy) -> float:
    """The least width of a polygon's points ``xy`` (N x 2) across any of its edges'
    directions (rotating calipers: the least width of a convex outline is across one of its
    edges; a slot's short side)."""
    import numpy as np
    d = np.roll(xy, -1, axis=0) - xy
    n = np.hypot(d[:, 0], d[:, 1])
    keep = n > 1e-9
    if not keep.any():
        return 0.0
    u = d[keep] / n[keep, None]
    proj = xy @ np.stack([-u[:, 1], u[:, 0]])           # N x E: across each edge
    return float((proj.max(axis=0) - proj.min(axis=0)).min())


def report(kind: str, r: float, call, chosen: list, why: dict, pts, got: dict,
           loops: list, first: list | None = None, off=(0.0, 0.0)) -> list:
    """What a ``Fillet``/``Chamfer`` of size ``r`` (written at ``call``) did not do, as
    ``[(call, code, index, message, hint)]``: ``chosen`` (:class:`Chosen`, placed), ``why``
    (index -> why two edges make no corner), ``pts`` ([(point, index into chosen)], None
    for the whole outline), ``got`` (index into pts -> the size its corner got, from
    :func:`corners`), ``loops`` (the outline before the operation); ``off``: the offset of
    the frame the operation is written in, taken off every point it says (the points its
    hint writes are read in that frame)."""
    fillet = kind == "Fillet"
    size = f"{'radius' if fillet else 'distance'} {r:.6g} mm"
    head = f"`{kind}` ({size})"
    verb = "round" if fillet else "cut"
    path = getattr(getattr(call, "owner", None), "path", "") or "?"
    if pts is None:
        if got or r <= 0:       # (size 0 asks for nothing: an outline without corners too)
            return []
        kinks = _spline_kinks(loops) if fillet else []
        if kinks:               # (run ds: "no corners" and "delete the Fillet" for these)
            where = ", ".join(f"({x - off[0]:.6g}, {y - off[1]:.6g})" for x, y in kinks[:3])
            return [(call, "W0406", -1,
                     f"{head} changes nothing in `{path}`: the corners of its final outline "
                     f"are a Spline's own (its `corners=`, at {where}), which a Fillet does "
                     "not round",
                     "to round them, drop them from the Spline's `corners=` (it then runs "
                     "smooth through them), or draw the outline rounded: `Offset(Inset(NAME, "
                     f"{r:.6g} mm), {r:.6g} mm)`, NAME the Spline (it is then not drawn; every "
                     "convex corner rounded by the radius)")]
        return [(call, "W0406", -1,
                 f"{head} changes nothing in `{path}`: its final outline has no "
                 + ("corners (only circles and smooth joins)" if fillet else
                    "outside corners (only circles, smooth joins and inside corners, which "
                    "a Chamfer of the whole outline leaves)"),
                 "delete the `Fillet`: the outline has nothing for it to round" if fillet
                 else f"delete the `Chamfer`, or name the inside corners to fill: "
                      f"`Chamfer(at=[edge1, edge2], distance={r:.6g} mm)`")]
    out = []
    for i, c in enumerate(chosen):
        if c.quiet:
            continue
        if why.get(i):
            pairs = c.meeting()
            hint = ("name two edges that meet at the corner (at their ends, where they "
                    "cross, or where one ends on the other), or the corner's point "
                    "(`body.top_right`)")
            if pairs:
                said = " and ".join(f"`[{a}, {b}]`" for a, b in pairs[:4])
                hint = (f"of these shapes' edges, {said} do meet: name the pair at the "
                        "corner meant (a turned shape's edges keep the names they have "
                        "before its `rotation=`), or the corner's point")
            out.append((call, "E0408", i, f"{head} cannot {verb} {c.describe(off)}: {why[i]}",
                        hint))
            continue
        js = [j for j, (_, ci) in enumerate(pts) if ci == i]
        found = [got[j] for j in js if j in got]
        if not found:
            p = pts[js[0]][0] if js else c.points[0]
            if len(js) <= 1 and _spline_kink(p, loops):
                # run cp's sword tip: a Spline's own corner (`corners=[...]`) is no corner the
                # rounding can take (E0408 said "no corner there", its hint another corner)
                out.append((call, "E0407", i,
                            f"{kind} cannot {verb} the corner at ({p[0] - off[0]:.6g}, "
                            f"{p[1] - off[1]:.6g}) mm: it is a corner of a Spline (one of "
                            f"its `corners=`), and a {'fillet arc' if fillet else 'chamfer'} "
                            f"there would end on the spline at a point the exact output "
                            f"cannot place",
                            "round it within the spline: drop that index from `corners=` "
                            "and put two points of the spline close either side of the tip, "
                            "so the curve itself turns round it"))
                continue
            where, near = _where(p, loops)
            msg = f"{head} {verb}s nothing at {c.describe(off)}: "
            if near is not None:
                near = (near[0] - off[0], near[1] - off[1])
            if len(js) > 1:
                msg += f"none of them is a corner of the final outline of `{path}`"
            elif c.what == "edges":
                msg += f"they meet at ({p[0] - off[0]:.6g}, {p[1] - off[1]:.6g}) mm, and {where}"
            else:
                msg += where
            hint = (f"the nearest corner of the outline is at ({near[0]:.6g}, {near[1]:.6g}) "
                    f"mm: name the two edges that meet there, or give its point (the only "
                    f"way when an edge is an Ellipse's or a curve's, which has no name), "
                    f"`{kind}(at=({_mm4(near[0])}, {_mm4(near[1])}), "
                    f"{'radius' if fillet else 'distance'}={r:.6g} mm)`"
                    if near is not None else
                    "name two edges that meet at a corner of the outline, or delete the "
                    f"`{kind}`")
            was = _where(p, first)[1] if first is not None else None
            if was is not None and math.hypot(was[0] - p[0], was[1] - p[1]) <= CORNER_TOL:
                msg += (f" (it was a corner before an earlier `Fillet` or `Chamfer` of "
                        f"`{path}` finished it)")
                hint = (f"write this `{kind}` before the one that finishes the whole outline, "
                        "or give that one the other corners (`Fillet([...], r)`)")
            out.append((call, "E0408", i, msg, hint))
        elif min(found) < r * (1 - SHRUNK):
            least = min(found)
            fits = math.floor(least * 1000) / 1000          # asked for, it is made whole
            done = (f"{verb}s {c.describe(off)} with only {least:.6g} mm" if least > 0
                    else f"leaves {c.describe(off)} sharp")
            if len(js) > 1:
                # which of the corners it takes (run fn: where a rake's handle runs down to
                # its head's bottom edge, the gaps beside the middle tooth; no place said);
                # each short one with its size where they differ (run gk: a ring arm's two
                # neck corners, 1.51 and 3.2 mm, said as one place)
                short = [(got[j], pts[j][0]) for j in js if j in got
                         and got[j] < r * (1 - SHRUNK)]
                short.sort(key=lambda t: t[0])
                same = least * (1 + 1e-6) + 1e-9          # (mirror images differ by 1e-15)
                at = [q for v, q in short if v <= same]
                done += (" at (" + "), (".join(f"{q[0] - off[0]:.6g}, {q[1] - off[1]:.6g}"
                                              for q in at[:3])
                         + f") mm{f' and {len(at) - 3} more' if len(at) > 3 else ''}")
                more = [(v, q) for v, q in short if v > same]
                if more:
                    done += "".join(f", {v:.6g} mm at ({q[0] - off[0]:.6g}, "
                                    f"{q[1] - off[1]:.6g})" for v, q in more[:3])
                done += f" (of the {len(js)} corners where they meet)"
            out.append((call, "W0406", i,
                        f"{head} {done}: the outline's pieces next to the corner leave room "
                        f"for no more (a corner takes at most half of a piece between two "
                        f"corners"
                        f"{', and the arc must touch both' if fillet else ''})",
                        f"ask for at most {fits:g} mm there, or make the edges beside the "
                        f"corner longer" if fits > 0 else
                        f"make the edges beside the corner longer, or delete the `{kind}`"))
    return out


def _spline_kinks(loops: list) -> list:
    """The sharp corners inside the Spline pieces of ``loops`` (the knots a `corners=` names
    where the tangents turn by more than :data:`CORNER_TURN`), as (x, y)."""
    from ..shapes.curves import Spline
    out = []
    for lp in loops:
        for g in lp.segments:
            if isinstance(g, Spline):
                c, n = g.curve.ctrl, g.curve.n
                for i in (range(n) if g.curve.closed else range(1, n)):
                    q = c[3 * i]
                    if _spline_kink(q, [lp]):
                        out.append((float(q[0]), float(q[1])))
    return out


def _spline_kink(p, loops: list) -> bool:
    """Whether point ``p`` is a sharp corner inside a Spline piece of ``loops`` (a point of
    the spline its `corners=` names, where the tangents into and out of it turn by more than
    :data:`CORNER_TURN`), within :data:`CORNER_TOL`."""
    from ..shapes.curves import Spline
    for lp in loops:
        for g in lp.segments:
            if not isinstance(g, Spline):
                continue
            c, n = g.curve.ctrl, g.curve.n           # knot i is ctrl[3 i]
            for i in (range(n) if g.curve.closed else range(1, n)):
                q = c[3 * i]
                if math.hypot(q[0] - p[0], q[1] - p[1]) > CORNER_TOL:
                    continue
                a, b = c[3 * i - 1] if i else c[-2], c[3 * i + 1]   # (closed: ctrl[-1] is q)
                if a == q or b == q:
                    continue                        # a handle of no length: no tangent there
                t0 = math.atan2(q[1] - a[1], q[0] - a[0])
                t1 = math.atan2(b[1] - q[1], b[0] - q[0])
                turn = abs((t1 - t0 + math.pi) % (2 * math.pi) - math.pi)
                if turn > CORNER_TURN:
                    return True
    return False


def _where(p, loops: list) -> tuple[str, tuple | None]:
    """Why point ``p`` is no corner of ``loops`` (the outline runs straight through it, or
    it lies inside or outside the outline, how far), and the nearest corner of the outline
    (or None)."""
    from ..shapes.curves import turn_between
    best, inside = math.inf, False
    x, y = p
    for lp in loops:
        q = lp.points()
        if len(q) < 2:
            continue
        n = len(q)
        for k in range(n):
            (x0, y0), (x1, y1) = q[k - 1], q[k]
            dx, dy = x1 - x0, y1 - y0
            L2 = dx * dx + dy * dy
            t = min(1.0, max(0.0, ((x - x0) * dx + (y - y0) * dy) / L2)) if L2 else 0.0
            best = min(best, math.hypot(x - x0 - t * dx, y - y0 - t * dy))
            if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * dx / (y1 - y0):
                inside = not inside
    near, nd = None, math.inf
    for lp in loops:
        segs = lp.segments
        if len(segs) < 2:               # a whole circle (a round hole): no corner
            continue
        for k in range(len(segs)):
            if abs(turn_between(segs[k - 1], segs[k])) > CORNER_TURN:
                v = segs[k].start
                d = math.hypot(v[0] - x, v[1] - y)
                if d < nd:
                    near, nd = v, d
    if best <= 10 * CORNER_TOL:
        what = "the outline runs on through that point with no corner there"
    elif inside:
        what = (f"that point lies {best:.6g} mm inside the outline (other shapes cover it), "
                f"so it is no corner")
    else:
        what = f"that point lies {best:.6g} mm outside the outline, so it is no corner"
    return what, near


TIP_BACK = 5.0       # mm: a fillet that cuts a tip back farther (and more than 3 radii): W0411


def _tip_back(call, k: int, p, back: float, angle: float, radius: float) -> tuple:
    """W0411 for a fillet of ``radius`` that cut the tip at ``p`` (a corner of ``angle``
    radians inside the material, or of the hole) back by ``back`` mm: how far, why, and the
    radius that cuts it back 1 mm at most (issue 111, run z2's dinosaur: `Fillet(tail.points
    [2], 3)` on a 15 deg tail tip made the tail 19.3 mm short, said only by a W0405 about a
    box)."""
    deg = math.degrees(angle)
    keep = 1.0 / (1.0 / math.sin(angle / 2) - 1.0)
    return (call, "W0411", -1000 - k,
            f"`Fillet` (radius {radius:.6g} mm) cuts the {deg:.3g}° tip at ({p[0]:.6g}, "
            f"{p[1]:.6g}) mm back by {back:.2f} mm: the outline now ends that much short of "
            f"the point drawn (a round of radius r in a corner of angle a lies r / sin(a / 2) "
            f"- r from its point)",
            f"to keep the tip's length, draw the tip round: the `Hull` of the shape and a "
            f"`Circle(radius={radius:.6g})` whose edge touches the point; or round it less "
            f"(radius {keep:.3g} mm cuts it back 1 mm)")


def corners(loop, size: float, fillet: bool, only=None, got=None, deep=None):
    """``loop`` with its corners rounded (``fillet``: every corner, convex or concave, by an
    arc of radius ``size`` tangent to both of its segments) or cut (chamfer: every convex
    corner, by a line between the points ``size`` mm along each segment, arc length on an
    arc; ``size`` 0: none, the loop as it is).  A corner is a join where the direction turns
    by more than :data:`CORNER_TURN` (tangent joins are not corners); with ``only`` (points,
    mm), just the corners within :data:`CORNER_TOL` of one of them, and a chamfer there cuts
    concave corners too (it adds the triangle between its legs); ``size`` may then be a
    list, one size per point of ``only`` (consecutive Fillets of chosen corners, one pass:
    :func:`finish`).  No corner takes more than half of a segment between two corners (all
    of one whose other end is a tangent join): where a segment is too short the fillet
    radius (or chamfer leg) shrinks to fit.  Lines stay on their lines and arcs on their
    circles, so the result is exact (:mod:`.curves`).  ``got`` (a dict): for each corner
    rounded (or found and not rounded), the index into ``only`` (or -1 without ``only``) ->
    the smallest radius (or leg) it got, 0 for none.  ``deep`` (a list): gets ``(point,
    setback, angle, radius, index into only or -1)`` for each sharp tip a fillet cuts back
    more than :data:`TIP_BACK` and 3 radii (W0411)."""
    from ..shapes.curves import Arc, Circle, Loop, simplify, turn_between, with_ends
    segs = loop.segments
    n = len(segs)
    if n < 2 or any(isinstance(g, Circle) for g in segs):
        return loop
    cut = [None] * n                 # corner k (before segment k): (end of k-1, start of k, new)
    turns = [turn_between(segs[k - 1], segs[k]) for k in range(n)]
    sharp = [abs(t) > CORNER_TURN for t in turns]
    for k in range(n):
        a, b = segs[k - 1], segs[k]
        p = b.start
        turn = turns[k]
        # a piece between two corners gives each at most half; one whose other end is a
        # smooth join (a tangent arc's) gives all of it (run fs: a 25 mm piece between the
        # corner and a paddle's R10 corner, R15 capped at 12.5 mm)
        share = (0.5 if sharp[k - 1] else 1.0, 0.5 if sharp[(k + 1) % n] else 1.0)
        hits = [-1] if only is None else [i for i, (qx, qy) in enumerate(only)
                                           if math.hypot(p[0] - qx, p[1] - qy) <= CORNER_TOL]
        if not sharp[k] or not hits or (not fillet and turn < 0 and only is None):
            continue
        here = size if not isinstance(size, list) else size[hits[0]]
        if here <= 0:               # size 0: the corner found, left sharp (nothing asked)
            if got is not None:
                for i in hits:
                    got[i] = 0.0
            continue
        cut[k] = _corner(a, b, turn, here, fillet, share)
        if deep is not None and fillet and cut[k] is not None and turn > 0:
            # (a tip of the material: a window's sharp end rounded is material kept, run ai's
            # hanger)
            arc = cut[k][2]
            back = math.hypot(p[0] - arc.center[0], p[1] - arc.center[1]) - arc.radius
            if back > max(TIP_BACK, 3 * arc.radius):
                deep.append((p, back, math.pi - abs(turn), arc.radius, hits[0]))
        if got is not None:
            size_got = (0.0 if cut[k] is None else cut[k][2].radius if fillet
                        else min(here, a.length * share[0], b.length * share[1]))
            for i in hits:
                got[i] = min(got.get(i, size_got), size_got)
    if not any(cut):
        return loop
    out = []
    for k in range(n):
        g = segs[k]
        if cut[k] is not None:
            out.append(cut[k][2])
        start = cut[k][1] if cut[k] is not None else g.start
        nxt = cut[(k + 1) % n]
        end = nxt[0] if nxt is not None else g.end
        out.append(with_ends(g, start, end) if (start, end) != (g.start, g.end) else g)
    scale = max(max(abs(v) for g in segs for v in g.start), 1.0)
    return Loop(simplify([g for g in out if not isinstance(g, Arc) or g.sweep != 0], scale))


def _corner(a, b, turn: float, size: float, fillet: bool, share=(0.5, 0.5)):
    """(end of ``a``, start of ``b``, the fillet Arc or chamfer Line) at the corner where
    segment ``a`` runs into ``b`` (None: no fillet arc fits), taking at most the fractions
    ``share`` of ``a`` and of ``b`` next to the corner; raises :class:`SplineCorner`
    where a spline, or an ellipse beside another ellipse, makes it inexact."""
    from ..shapes.curves import EllipticArc, Spline
    p = b.start
    el = next((g for g in (a, b) if isinstance(g, EllipticArc)), None)
    what = "Fillet" if fillet else "Chamfer"
    if el is not None and isinstance(a if el is b else b, (EllipticArc, Spline)):
        raise SplineCorner(
            f"{what} cannot round the corner at ({p[0]:g}, {p[1]:g}) mm where an Ellipse "
            f"meets another curve: a {'fillet arc' if fillet else 'chamfer'} there would end "
            f"on the ellipse at a point the exact output cannot place (the offset of an "
            f"ellipse is no ellipse), and the result would be chords", el.curve,
            f"choose corners away from the ellipse with `{what}(..., at=[...])`, round "
            f"the corner with an arc of your own (a Circle placed tangent to both), or draw "
            f"the ellipse as a Polygon of its points, which {what} rounds (`Polygon([(cx + "
            f"rx * cos(t * 1 deg), cy + ry * sin(t * 1 deg)) for t in range(0, 360, 5)])`; "
            f"run dt's 72-sided oval)")
    # (an ellipse beside a line or an arc: the fillet's centre is found on the ellipse's
    # offset curve, a root in its parameter; the chamfer's ends by arc length)
    sp = next((g for g in (a, b) if isinstance(g, Spline)), None)
    if sp is not None and el is None:
        raise SplineCorner(
            f"{what} cannot round the corner at ({p[0]:g}, {p[1]:g}) mm where a Spline "
            f"meets another curve: a {'fillet arc' if fillet else 'chamfer'} there would end "
            f"on the spline at a point the exact output cannot place, and the result would "
            f"be chords", sp.curve,
            f"choose corners away from the spline with `{what}(..., at=[...])`, or make "
            f"the corner part of the spline (a point of it placed there, so the curve "
            f"itself turns smoothly)")
    return _fillet(a, b, turn, size, share) if fillet else _chamfer(a, b, size, share)


def _offset(g, d: float):
    """The carrier of segment ``g`` moved ``d`` mm to its left (None: a circle shrunk away)."""
    from ..shapes.curves import Line, carrier
    c = carrier(g)
    if isinstance(g, Line):
        _, px, py, ux, uy = c
        return ("L", px - d * uy, py + d * ux, ux, uy)
    r = c[3] - d if g.sweep > 0 else c[3] + d       # left of a counter-clockwise arc: inward
    return ("C", c[1], c[2], r) if r > 1e-12 else None


def _fraction(g, p, from_end: bool) -> float:
    """How far along segment ``g`` point ``p`` (on its carrier) lies from its start (or its
    end), as a fraction of its length; negative before it (an elliptic arc: of its
    parameter's sweep)."""
    from ..shapes.curves import EllipticArc, Line
    if isinstance(g, Line):
        (x0, y0), (x1, y1) = g.start, g.end
        L2 = (x1 - x0) ** 2 + (y1 - y0) ** 2
        t = ((p[0] - x0) * (x1 - x0) + (p[1] - y0) * (y1 - y0)) / L2 if L2 else 0.0
    elif isinstance(g, EllipticArc):
        d = ((g.curve.foot(p) - g.start_param) * (1 if g.sweep > 0 else -1)) % (2 * math.pi)
        if d > (abs(g.sweep) + 2 * math.pi) / 2:              # nearer before its start
            d -= 2 * math.pi
        t = d / abs(g.sweep) if g.sweep else 0.0
    else:
        a = math.atan2(p[1] - g.center[1], p[0] - g.center[0])
        d = ((a - g.start_angle) * (1 if g.sweep > 0 else -1)) % (2 * math.pi)
        if d > (abs(g.sweep) + 2 * math.pi) / 2:              # nearer before its start
            d -= 2 * math.pi                                  # (an arc over half a turn too)
        t = d / abs(g.sweep) if g.sweep else 0.0
    return 1.0 - t if from_end else t


def _fillet_at(a, b, turn: float, r: float, share=(0.5, 0.5)):
    """(tangent point on a, tangent point on b, the fillet Arc) for radius ``r``, or None when
    no arc of that radius fits: its center is where ``a`` and ``b``'s carriers offset by
    ``r`` toward the corner's inside cross, it must run the way both segments run where it
    touches them, and its tangent points must lie in the parts of ``a`` and ``b`` next to
    the corner that ``share`` gives it (fractions of each: a half, or all of a piece whose
    other end is no corner)."""
    from ..shapes.curves import Arc, EllipticArc, carrier, crossings, foot, tangent_at
    s = 1.0 if turn > 0 else -1.0
    p = b.start
    best = None
    if isinstance(a, EllipticArc) or isinstance(b, EllipticArc):
        found = _ellipse_centres(a, b, s, r)
    else:
        oa, ob = _offset(a, s * r), _offset(b, s * r)
        if oa is None or ob is None:
            return None
        found = [(c, foot(carrier(a), c), foot(carrier(b), c)) for c in crossings(oa, ob)]
    for c, ta, tb in found:
        # offsets that only nearly touch give their touching point, which may lie off the
        # circle of radius r around the tangent points: not a fillet
        tol = 1e-9 * max(1.0, abs(c[0]), abs(c[1]))
        if abs(math.dist(ta, c) - r) > tol or abs(math.dist(tb, c) - r) > tol:
            continue
        fa, fb = _fraction(a, ta, True), _fraction(b, tb, False)
        if not (-1e-12 <= fa <= share[0] + 1e-12 and -1e-12 <= fb <= share[1] + 1e-12):
            continue
        # the arc, turning the corner's way, runs along a at ta and along b at tb
        a1 = math.atan2(ta[1] - c[1], ta[0] - c[0])
        a2 = math.atan2(tb[1] - c[1], tb[0] - c[0])
        arc_a = (-s * math.sin(a1), s * math.cos(a1))
        arc_b = (-s * math.sin(a2), s * math.cos(a2))
        da = tangent_at(with_ends_at(a, ta), True)
        db = tangent_at(with_ends_at(b, tb, start=True), False)
        if arc_a[0] * da[0] + arc_a[1] * da[1] < 0.5 or arc_b[0] * db[0] + arc_b[1] * db[1] < 0.5:
            continue
        sw = (a2 - a1) % (2 * math.pi)
        if s < 0:
            sw -= 2 * math.pi
        d = math.hypot(c[0] - p[0], c[1] - p[1])
        if best is None or d < best[0]:
            best = (d, (ta, tb, Arc(c, r, a1, sw)))
    return best[1] if best is not None else None


ELLIPSE_SCAN = 64      # parameter steps over the half of an elliptic arc next to a corner


def _ellipse_centres(a, b, s: float, r: float) -> list:
    """``[(centre, point on a, point on b)]`` of the arcs of radius ``r`` tangent to the
    elliptic arc and the line or arc beside it on the corner's inside (``s`` = 1: the left):
    the centre is the ellipse's point ``P(t)`` moved ``r`` along its normal, ``t`` the root of
    its signed distance from the other segment's carrier offset by ``r`` (sign changes over
    :data:`ELLIPSE_SCAN` steps of the half next to the corner, then bisection to the last
    bit); the tangent point on the ellipse is ``P(t)`` itself, on the other its foot."""
    from ..shapes.curves import EllipticArc, carrier, foot
    el_first = isinstance(a, EllipticArc)
    el, other = (a, b) if el_first else (b, a)
    if isinstance(other, EllipticArc):
        return []
    oo = _offset(other, s * r)
    if oo is None:
        return []
    e, sg = el.curve, (1.0 if el.sweep > 0 else -1.0)

    def centre(t):
        tx, ty = e.tangent(t)
        q = e.at(t)
        return (q[0] - s * r * sg * ty, q[1] + s * r * sg * tx)

    def gap(t):
        x, y = centre(t)
        if oo[0] == "L":
            _, px, py, ux, uy = oo
            return ux * (y - py) - uy * (x - px)
        return math.hypot(x - oo[1], y - oo[2]) - oo[3]

    near = el.end_param if el_first else el.start_param
    far = el.start_param + el.sweep / 2
    ts = [near + (far - near) * i / ELLIPSE_SCAN for i in range(ELLIPSE_SCAN + 1)]
    gs = [gap(t) for t in ts]
    out = []
    for i in range(ELLIPSE_SCAN):
        if gs[i] == 0.0 or gs[i] * gs[i + 1] < 0:
            lo, hi, glo = ts[i], ts[i + 1], gs[i]
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if mid in (lo, hi):
                    break
                gm = gap(mid)
                if (gm < 0) == (glo < 0) and gm != 0.0:
                    lo, glo = mid, gm
                else:
                    hi = mid
            t = lo if gs[i] == 0.0 else 0.5 * (lo + hi)
            c = centre(t)
            pe, po = e.at(t), foot(carrier(other), c)
            out.append((c, pe, po) if el_first else (c, po, pe))
            break                       # the crossing nearest the corner
    return out


def with_ends_at(g, t, start: bool = False):
    """``g`` cut to end (or, with ``start``, to begin) at ``t`` on its carrier."""
    from ..shapes.curves import with_ends
    return with_ends(g, t, g.end) if start else with_ends(g, g.start, t)


def _fillet(a, b, turn: float, r: float, share=(0.5, 0.5)):
    got = _fillet_at(a, b, turn, r, share)
    if got is not None:
        return got
    lo, hi = 0.0, r                  # the largest radius that fits: bisection
    best = None
    for _ in range(60):
        mid = (lo + hi) / 2
        got = _fillet_at(a, b, turn, mid, share)
        if got is None:
            hi = mid
        else:
            lo, best = mid, got
    return best


def _dir(g, end: bool):
    from ..shapes.curves import tangent_at
    return tangent_at(g, end)


def _chamfer(a, b, d: float, share=(0.5, 0.5)):
    """(point on a, point on b, the chamfer Line) ``d`` mm from the corner along each
    segment: two equal legs, at most the fractions ``share`` of ``a`` and ``b``."""
    from ..shapes.curves import Line
    d = min(d, a.length * share[0], b.length * share[1])
    pa, pb = _along(a, d, True), _along(b, d, False)
    return pa, pb, Line(pa, pb)


def _along(g, d: float, from_end: bool):
    """The point ``d`` mm (at most half the segment) from ``g``'s end (or start)."""
    from ..shapes.curves import Line
    from ..shapes.curves import EllipticArc
    d = min(d, g.length / 2)
    if isinstance(g, EllipticArc):       # the parameter whose arc length is d: bisection
        lo, hi = 0.0, abs(g.sweep) / 2
        sg = 1.0 if g.sweep > 0 else -1.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            piece = EllipticArc(g.curve, g.end_param - sg * mid if from_end else g.start_param,
                                sg * mid)
            lo, hi = (mid, hi) if piece.length < d else (lo, mid)
        return g.at(g.end_param - sg * lo if from_end else g.start_param + sg * lo)
    if isinstance(g, Line):
        (x0, y0), (x1, y1) = g.start, g.end
        L = g.length or 1.0
        t = 1.0 - d / L if from_end else d / L
        return (x0 + (x1 - x0) * t, y0 + (y1 - y0) * t)
    da = d / g.radius * (1 if g.sweep > 0 else -1)
    return g.at(g.end_angle - da if from_end else g.start_angle + da)


def _mm4(v: float) -> str:
    """``v`` to 1e-4 mm, trailing zeros dropped (a corner's point a hint writes: within
    :data:`CORNER_TOL` of the corner)."""
    t = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if t in ("", "-0") else t
