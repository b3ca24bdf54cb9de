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


_CHUNK = 1 << 20         # probe x edge cells of one even-odd test at a time


def _inside_many(px, py, P):
    """The even-odd test of :func:`_inside` for every probe ``(px[k], py[k])`` (1-D arrays,
    mm) against the polygon ``P`` (N x 2) at once: a bool array, the same number for number
    (the same crossings, computed the same way)."""
    X, Y = P[:, 0], P[:, 1]
    X2, Y2 = np.roll(X, -1), np.roll(Y, -1)
    out = np.zeros(len(px), dtype=bool)
    step = max(1, _CHUNK // max(1, len(X)))
    for k in range(0, len(px), step):
        x, y = px[k:k + step, None], py[k:k + step, None]
        cond = (Y > y) != (Y2 > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            xs = X + (y - Y) * (X2 - X) / (Y2 - Y)
        out[k:k + step] = np.count_nonzero(cond & (x < xs), axis=1) % 2 == 1
    return out


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


WORK = {"polygons": 0, "pairs": 0, "loops": 0}
"""What :func:`local_parts` did, summed over calls (the tests hold it linear in the holes):
``loops`` ordered, ``polygons`` sampled (:meth:`Loop.points`: the loops that are not circles,
and the circles some probe falls in the box of) and ``pairs``, probe-in-polygon tests."""

_BIG = 64                # grid cells a box may cover before it is tested against every probe


def _box_pairs(px, py, boxes):
    """Every ``(i, j)``, ``i != j``, whose probe ``(px[i], py[i])`` lies in box ``j``
    (``boxes``: M x 4 ``(x0, y0, x1, y1)``; an empty box, ``x0 > x1``, holds nothing): two
    int arrays.  A uniform grid of the typical box's size indexes the boxes; a box over
    :data:`_BIG` cells is tested against every probe, so a drawing of n small loops costs
    O(n), not O(n^2)."""
    n = len(px)
    live = np.flatnonzero(boxes[:, 0] <= boxes[:, 2])
    if n == 0 or len(live) == 0:
        return np.zeros(0, dtype=np.intp), np.zeros(0, dtype=np.intp)
    b = boxes[live]
    size = np.maximum(b[:, 2] - b[:, 0], b[:, 3] - b[:, 1])
    cell = float(np.median(size)) if len(size) else 1.0
    gx0, gy0 = float(b[:, 0].min()), float(b[:, 1].min())
    # at most 2^20 cells a side, so a cell's key (row * width + column) fits an int64
    extent = max(float(b[:, 2].max()) - gx0, float(b[:, 3].max()) - gy0)
    cell = max(cell, extent / (1 << 20))
    if not cell > 0 or not np.isfinite(cell):
        cell = 1.0
    cx0 = np.floor((b[:, 0] - gx0) / cell)
    cx1 = np.floor((b[:, 2] - gx0) / cell)
    cy0 = np.floor((b[:, 1] - gy0) / cell)
    cy1 = np.floor((b[:, 3] - gy0) / cell)
    ncell = (cx1 - cx0 + 1) * (cy1 - cy0 + 1)
    big = ncell > _BIG
    ii, jj = [], []
    for j in live[big]:                      # the outlines and other large loops
        x0, y0, x1, y1 = boxes[j]
        k = np.flatnonzero((x0 <= px) & (px <= x1) & (y0 <= py) & (py <= y1))
        ii.append(k)
        jj.append(np.full(len(k), j, dtype=np.intp))
    small = np.flatnonzero(~big)
    if len(small):
        # each small box in every cell it covers, keyed row-major; each probe looks up its own
        w = (cx1[small] - cx0[small] + 1).astype(np.int64)
        cnt = (w * (cy1[small] - cy0[small] + 1)).astype(np.int64)
        owner = np.repeat(small, cnt)
        off = np.arange(int(cnt.sum()), dtype=np.int64) - np.repeat(np.cumsum(cnt) - cnt, cnt)
        wo = np.repeat(w, cnt)
        kx = cx0[owner].astype(np.int64) + off % wo
        ky = cy0[owner].astype(np.int64) + off // wo
        span = int(kx.max()) + 1
        top = int(ky.max())
        with np.errstate(invalid="ignore"):
            fx, fy = np.floor((px - gx0) / cell), np.floor((py - gy0) / cell)
            ok = (fx >= 0) & (fx < span) & (fy >= 0) & (fy <= top)   # NaN: not in any cell
        qkey = np.where(ok, np.where(ok, fy, 0) * span + np.where(ok, fx, 0), -1
                        ).astype(np.int64)
        key = ky * span + kx
        order = np.argsort(key, kind="stable")
        key, owner = key[order], owner[order]
        lo = np.searchsorted(key, qkey, "left")
        hi = np.searchsorted(key, qkey, "right")
        m = hi - lo
        pi = np.repeat(np.arange(n, dtype=np.intp), m)
        pj = live[owner[np.repeat(lo, m) + (np.arange(int(m.sum())) - np.repeat(np.cumsum(m) - m, m))]]
        ii.append(pi)
        jj.append(pj)
    i = np.concatenate(ii) if ii else np.zeros(0, dtype=np.intp)
    j = np.concatenate(jj) if jj else np.zeros(0, dtype=np.intp)
    bj = boxes[j]
    keep = ((i != j) & (bj[:, 0] <= px[i]) & (px[i] <= bj[:, 2]) & (bj[:, 1] <= py[i])
            & (py[i] <= bj[:, 3]))
    return i[keep], j[keep]


def local_parts(d, rot: float):
    """``(loops, paths, circles, outlines)`` of drawing ``d`` turned by ``rot`` (radians):
    every closed loop oriented by its nesting depth (holes clockwise), the open paths (lists
    of segments), the circles, and the outlines alone (counter-clockwise, largest first).

    The nesting is array-shaped: each loop's probe point (:func:`_probe`) is tested only
    against the loops whose box holds it (:func:`_box_pairs`), all the probes in one polygon
    at once (:func:`_inside_many`); a circle's box is its exact one and its polygon is
    sampled only when a probe falls in that box (a panel of 19,000 holes in one outline:
    19,000 tests against the outline, no circle sampled)."""
    outlines = [Loop([_turn(s, rot) for s in o.segments]) for o in d.outlines]
    circles = [_turn(c, rot) for c in d.circles]
    ellipses = [_ellipse_loop(*_rot_pt((cx, cy), math.cos(rot), math.sin(rot)), rx, ry, r + rot)
                for cx, cy, rx, ry, r in d.ellipses]
    others = outlines + ellipses
    n_o, n_c = len(outlines), len(circles)
    polys = {}
    for k, lp in enumerate(others):
        polys[k if k < n_o else k + n_c] = lp.points()
    WORK["polygons"] += len(others)
    WORK["loops"] += len(others) + n_c
    cxy = np.array([c.center for c in circles], dtype=float).reshape(-1, 2)
    cr = np.array([c.radius for c in circles], dtype=float)
    # every loop's probe and box, in the order outlines, circles, ellipses
    n = len(others) + n_c
    px, py = np.empty(n), np.empty(n)
    boxes = np.empty((n, 4))
    for k in polys:
        P = polys[k]
        boxes[k] = ([P[:, 0].min(), P[:, 1].min(), P[:, 0].max(), P[:, 1].max()]
                    if len(P) >= 3 else [np.inf, np.inf, -np.inf, -np.inf])
        px[k], py[k] = _probe(others[k if k < n_o else k - n_c])
    sl = slice(n_o, n_o + n_c)
    px[sl], py[sl] = cxy[:, 0] + cr, cxy[:, 1]
    # a circle's exact box holds its sampled polygon (every vertex is cx + r cos t, ...)
    boxes[sl] = np.column_stack([cxy[:, 0] - cr, cxy[:, 1] - cr, cxy[:, 0] + cr,
                                 cxy[:, 1] + cr])
    pi, pj = _box_pairs(px, py, boxes)
    depth = np.zeros(n, dtype=np.int64)
    if len(pi):
        order = np.argsort(pj, kind="stable")
        pi, pj = pi[order], pj[order]
        cut = np.flatnonzero(np.diff(pj)) + 1
        for gi, gj in zip(np.split(pi, cut), np.split(pj, cut)):
            j = int(gj[0])
            P = polys.get(j)
            if P is None:
                P = polys[j] = Loop([circles[j - n_o]]).points()
                WORK["polygons"] += 1
            if len(P) < 3:
                continue
            WORK["pairs"] += len(gi)
            depth[gi] += _inside_many(px[gi], py[gi], P)
    even = depth % 2 == 0
    out = []
    for k, lp in enumerate(others[:n_o]):
        out.append(_oriented(lp, bool(even[k])))
    for k, c in enumerate(circles):
        out.append(Loop([c if bool(even[n_o + k]) == c.ccw else
                         Circle(c.center, c.radius, not c.ccw)]))
    for k, lp in enumerate(ellipses):
        out.append(_oriented(lp, bool(even[n_o + n_c + k])))
    paths = [[_turn(s, rot) for s in p.segments] for p in d.paths]
    return out, paths, circles, outlines


def _oriented(lp: Loop, outer: bool) -> Loop:
    """``lp`` run counter-clockwise when ``outer``, else clockwise (a hole)."""
    ccw = lp.area > 0
    if outer == ccw:
        return lp
    if len(lp.segments) == 1 and isinstance(lp.segments[0], Circle):
        c = lp.segments[0]
        return Loop([Circle(c.center, c.radius, not ccw)])
    return Loop([reverse(s) for s in reversed(lp.segments)])


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


def build(ctx, g, a, const) -> None:
    """A drawing read by the interpreter (``a["_drawing"]``: outlines, circles, ellipses and
    paths in mm, y up) placed rigidly at ``at`` (its origin; default (0, 0): where its file
    puts it) and turned by the held ``rotation`` (``const``: the primitives' constant of a
    quantity).  The loops are kept exact, in the drawing's own coordinates, in ``g.data``
    (:func:`local_parts`); the circles are made construction Circles, whose centres are held
    at their offsets from the origin, only when the program names them (``d.circles``,
    :func:`drawing_circles`): a panel of 19,000 holes that nothing refers to one by one adds
    no unknowns.

    The origin is *held* at a constant ``at`` (a :attr:`~.model.Constraint.hold`, issue 49):
    along every direction the program's constraints leave free it stays there, so a drawing
    nothing places sits exactly where its file (or ``at``) puts it, pinned as one rigid body
    (:func:`~aidl_lang.solver.core.system.pinned`), instead of floating with 2 freedoms that a
    solve may shift; a constraint that places it (``d.bb.left == 30``,
    ``Fixed(d.origin)``) takes that direction over.  A derived ``at`` (another shape's
    point) is an equation, as for any shape."""
    from ..core.expr import as_const, var
    from ..core.model import Constraint, Equation, Geometry
    from ..core.values import ANG, PV, Q
    d = a["_drawing"]
    rot = const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    at = a.get("at")
    at_pv = at if at is not None else PV(0.0, 0.0)
    o = g.points["origin"] = ctx.point(at_pv, "origin")
    ox, oy = ctx.value_of(var(o.ix)), ctx.value_of(var(o.iy))
    if at_pv.obj is None and as_const(at_pv.x) is not None and as_const(at_pv.y) is not None:
        where = "where `at` puts it" if at is not None else "where its file puts it"
        for ax, i, v in (("x", o.ix, ox), ("y", o.iy, oy)):      # one hold per axis
            c = Constraint("internal", ctx.struct, g.span, [Equation(var(i) - v)],
                           text=f"Drawing2D held at {ax} = {v:g} mm, {where}", implicit=True,
                           hold=True)
            ctx.struct.constraints.append(c)
            ctx.model.constraints.append(c)
            ctx.model.holds += 1
    loops, paths, circles, outlines = local_parts(d, rot)
    g.data.update(loops=loops, paths=paths, file=a["file"], rotation=rot)
    if ctx.struct.kind == "cut":
        # its open paths are cut through the part (issue 59)
        g.data["through_paths"] = len(paths)
    g.closed = True
    # the construction Circles, made when first named (a copy of the drawing shares them)
    g.data["circles"] = []
    if circles:
        g.data["make_circles"] = _CircleMaker(ctx, g, ctx.struct, o, circles)
    subs = []
    for lp in outlines:
        sg = Geometry("Drawing2D", ctx.struct, g.span, points={"origin": o}, construction=True)
        sg.data.update(loops=[lp], paths=[], circles=[], file=a["file"], rotation=rot,
                       part_of=g)
        sg.closed = True
        subs.append(sg)
    g.data["outlines"] = subs
    ps = []
    for segs in paths:
        sg = Geometry("Drawing2D", ctx.struct, g.span, points={"origin": o}, construction=True)
        sg.data.update(loops=[], paths=[segs], circles=[], file=a["file"], rotation=rot,
                       part_of=g)
        ps.append(sg)
    g.data["path_parts"] = ps
    n_file_paths = len(paths)
    e = getattr(d, "engrave", None)
    if e is not None and not e.empty:
        # the shapes of the role `engrave` (engrave=, roles="laser"): strokes on the part,
        # as the texts below (issue 49)
        strokes = [[_turn(s, rot) for s in o.segments] for o in e.outlines] + \
            [[_turn(s, rot) for s in p.segments] for p in e.paths] + \
            [[_turn(Arc(c.center, c.radius, 0.0, math.pi), rot),
              _turn(Arc(c.center, c.radius, math.pi, math.pi), rot)] for c in e.circles]
        g.data["paths"] = list(g.data["paths"]) + strokes
        paths = g.data["paths"]
    if getattr(d, "texts", None):
        # DXF TEXT and MTEXT as engraving strokes (the single-stroke font) in the drawing's
        # frame, turned with it; they move, turn and mirror as its open paths do
        g.data["paths"] = list(paths) + text_paths(d.texts, rot)
    # the paths from here on (the engrave role's shapes, the texts) are engraved on a part
    g.data["engraved_from"] = n_file_paths


class _CircleMaker:
    """What makes the construction Circles of Drawing2D ``g`` (of structure ``struct``,
    origin point ``o``) from its local ``circles``, once, into ``g.data["circles"]``: each
    centre a point held at its offset from the origin, each radius a held scalar, as the
    build made them before they were made on demand.  It holds the interpreter (``ctx``):
    a pickled model keeps the circles made and a maker that makes none."""

    def __init__(self, ctx, g, struct, o, circles) -> None:
        self.ctx, self.g, self.struct, self.o, self.circles = ctx, g, struct, o, circles

    def __reduce__(self):
        return (_CircleMaker, (None, None, None, None, []))

    def __call__(self) -> None:
        from ..core.expr import var
        from ..core.model import Equation, Geometry
        from ..core.values import PV
        ctx, g, struct, o, circles = self.ctx, self.g, self.struct, self.o, self.circles
        out = g.data["circles"] if g is not None else None
        if not circles or out:
            return
        self.circles = []                   # once
        saved = ctx.struct
        ctx.struct = struct
        try:
            ox, oy = ctx.value_of(var(o.ix)), ctx.value_of(var(o.iy))
            eqs = []
            for i, c in enumerate(circles):
                (cx, cy), r = c.center, c.radius
                p = ctx.point(PV(ox + cx, oy + cy), f"circles[{i}].center")
                eqs += [Equation(var(p.ix) - var(o.ix) - cx),
                        Equation(var(p.iy) - var(o.iy) - cy)]
                cg = Geometry("Circle", struct, g.span, points={"center": p}, construction=True)
                cg.scalars["radius"] = ctx.new_scalar(r, "radius", held=True)
                cg.closed = True
                cg.data["part_of"] = g
                out.append(cg)
            ctx.internal(g, eqs, "Drawing2D circles (rigid)")
        finally:
            ctx.struct = saved


def drawing_circles(g) -> list:
    """The construction Circles of Drawing2D ``g`` (``d.circles``: ``circles[i].center`` may
    be constrained), made on the first call (:class:`_CircleMaker`); call it only while the
    program is being interpreted."""
    make = g.data.get("make_circles")
    if make is not None:
        make()
    return g.data.get("circles", [])
