"""Geometry constructors: each turns checked, unit-converted arguments into model geometry.

A constructor creates points (starting guesses, or shared when the argument is a point of the
same structure), held scalar parameters for dimensions, and the *implicit* constraints that
keep the shape's form (e.g. a rectangle's corners stay a ``width`` x ``height`` rectangle at the
given rotation: six linear equations).  Paper section "AIDL by example": shared references are
implicit coincidence constraints.

Members (``rect.top_left``, ``line.midpoint`` ...) are resolved by :func:`.members.member`.
This module holds the basic shapes and the helpers every constructor shares; shapes given by
points are :mod:`.point_shapes`', shapes made from shapes :mod:`.composites`', and the entry,
:func:`~.constructors.build`, :mod:`.constructors`'.
"""
from __future__ import annotations

import math

from ..core.expr import Lin, _new, as_const, hypot, var
from ..core.model import Equation, Geometry, equation
from ..core.values import ANG, LEN, NUM, PV, GeomRef, Q, type_name


class PrimitiveError(Exception):
    """A primitive's arguments that make no shape (E0108); ``hint``: the fix, when one is
    known (else the caller gives the signature)."""

    def __init__(self, message: str, hint: str | None = None):
        super().__init__(message)
        self.hint = hint


def _cos_sin(rot: float) -> tuple[float, float]:
    return math.cos(rot), math.sin(rot)


def _const(ctx, q: Q, what: str) -> float:
    c = q.const()
    if c is None:
        c = ctx.value_of(q.expr)
        if not ctx.moves_only(q.expr):
            ctx.warn_nonconst(what)
    return c


MIN_SIZE = 1e-9     # mm: smaller sizes cannot be drawn (nor tessellated without overflow)


def _positive(q, what: str, kind: str) -> None:
    """A size known before solving must be at least :data:`MIN_SIZE` (a zero or negative size
    draws nothing; a subnormal one overflows the tessellation)."""
    c = q.const() if isinstance(q, Q) else None
    if c is not None and not c > 0:
        raise PrimitiveError(f"a {kind} needs a positive {what}, got {c:g}")
    if c is not None and c < MIN_SIZE:
        raise PrimitiveError(f"a {kind}'s {what} of {c:g} mm is below the smallest size, "
                             f"{MIN_SIZE:g} mm")


def _build_Point(ctx, g, a):
    if "at" in a:
        g.points["p"] = ctx.point(a["at"], "p")
    else:
        x, y = a["x"], a["y"]
        v = _new(PV)                   # PV(x, y, None, owners) without the class call
        v.x = x.expr
        v.y = y.expr
        v.obj = None
        v.owners = x.owners | y.owners
        g.points["p"] = ctx.point(v, "p")


def _build_Line(ctx, g, a):
    s = g.points["start"] = ctx.point(a["start"], "start")
    if "length" in a:               # polar: from start, length and angle held
        _positive(a["length"], "length", "Line")
        L = _const(ctx, a["length"], "Line length")
        t = _const(ctx, a["angle"], "Line angle")
        ox, oy = L * math.cos(t), L * math.sin(t)
        sx, sy = ctx.value_of(var(s.ix)), ctx.value_of(var(s.iy))
        e = g.points["end"] = ctx.point(PV(sx + ox, sy + oy), "end")
        ctx.internal(g, [Equation(var(e.ix) - var(s.ix) - ox),
                         Equation(var(e.iy) - var(s.iy) - oy)], "Line length and angle")
        return
    g.points["end"] = ctx.point(a["end"], "end")


def _build_Circle(ctx, g, a):
    for k in ("radius", "diameter"):
        if k in a:
            _positive(a[k], k, "Circle")
    g.points["center"] = ctx.point(a["center"], "center")
    if "diameter" in a:
        r = Q(a["diameter"].expr * 0.5, LEN, a["diameter"].owners)
    else:
        r = a["radius"]
    g.scalars["radius"] = ctx.scalar(r, "radius", held=True)
    g.closed = True


def _build_Arc(ctx, g, a):
    t, cw = None, False
    if "through" in a:
        t, cw, center = _circumcenter(ctx, a["start"], a["through"], a["end"])
        g.points["through"] = t
        a = dict(a, center=center)
    c = g.points["center"] = ctx.point(a["center"], "center")
    if "radius" in a:
        _positive(a["radius"], "radius", "Arc")
        r = _const(ctx, a["radius"], "Arc radius")
        a1 = _const(ctx, a["start_angle"], "Arc start_angle")
        a2 = _const(ctx, a["end_angle"], "Arc end_angle")
        cx, cy = ctx.value_of(var(c.ix)), ctx.value_of(var(c.iy))
        sx, sy, ex, ey = r * math.cos(a1), r * math.sin(a1), r * math.cos(a2), r * math.sin(a2)
        s = g.points["start"] = ctx.point(PV(cx + sx, cy + sy), "start")
        e = g.points["end"] = ctx.point(PV(cx + ex, cy + ey), "end")
        # each end's offset from the center: ``var(s.ix) - var(c.ix) - r * cos(a1)``, the
        # same Lin (terms and floats) as the operators make it, built directly
        ci, cj = c.ix, c.iy
        eqs = [_offset(s.ix, ci, sx), _offset(s.iy, cj, sy),
               _offset(e.ix, ci, ex), _offset(e.iy, cj, ey)]
        ctx.internal(g, [equation(x) for x in eqs], "Arc radius and angles")
    else:
        s = g.points["start"] = ctx.point(a["start"], "start")
        e = g.points["end"] = ctx.point(a["end"], "end")
        if t is not None:
            rt = hypot(var(t.ix) - var(c.ix), var(t.iy) - var(c.iy))
            rs = hypot(var(s.ix) - var(c.ix), var(s.iy) - var(c.iy))
            ctx.internal(g, [Equation(rt - rs)], "Arc through three points")
            if cw:          # counter-clockwise from start to end must pass through `through`
                g.points["start"], g.points["end"] = e, s
                # its members `start` and `end` stay the points the program named so (run db:
                # `Coincident(outer.end, inner.start)` on the drawn ends tied two points 26 mm
                # apart and bent the arc to radius 11 for 15, unsaid)
                g.data["named_ends"] = {"start": s, "end": e}
        rs = hypot(var(s.ix) - var(c.ix), var(s.iy) - var(c.iy))
        re = hypot(var(e.ix) - var(c.ix), var(e.iy) - var(c.iy))
        ctx.internal(g, [Equation(rs - re)], "Arc start and end on one circle")


def _offset(i: int, j: int, d: float) -> Lin:
    """``var(i) - var(j) - d`` (``i != j``) as :func:`~.expr.sub` makes it: terms
    ``{i: 1.0, j: 0.0 + 1.0 * -1.0}``, constant ``(0.0 + 0.0 * -1.0) + d * -1.0``."""
    e = _new(Lin)
    e.terms = {i: 1.0, j: 0.0 + 1.0 * -1.0}
    e.const = (0.0 + 0.0 * -1.0) + d * -1.0
    return e


def _circumcenter(ctx, p, q, r):
    """(through point, clockwise?, starting center) of the circle through p, q, r."""
    t = ctx.point(q, "through")
    (ax, ay), (bx, by), (cx, cy) = ((ctx.value_of(v.x), ctx.value_of(v.y)) for v in (p, q, r))
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if abs(d) < 1e-12 * max(1.0, abs(ax), abs(bx), abs(cx), abs(ay), abs(by), abs(cy)) ** 2:
        raise PrimitiveError("an Arc through three points needs points that are not on one line")
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay)
          + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx)
          + (cx * cx + cy * cy) * (bx - ax)) / d
    cw = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0
    return t, cw, PV(ux, uy)


def _rect_frame(ctx, g, a):
    rot = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    g.data["rotation"] = rot
    return _cos_sin(rot)


def _build_bar(ctx, g, a):
    """Rectangle(start, end, width): a bar ``width`` wide along the segment start-end, which
    is its center line; its own up direction runs from start to end, so ``height`` is the
    segment's length (free) and ``width`` (held) is across; ``bottom`` is the start's end,
    ``top`` the end's.  The direction follows the two points (four quadratic equations)."""
    _positive(a["width"], "width", g.kind)
    s = g.points["start"] = ctx.point(a["start"], "start")
    e = g.points["end"] = ctx.point(a["end"], "end")
    sx, sy = ctx.value_of(var(s.ix)), ctx.value_of(var(s.iy))
    ex, ey = ctx.value_of(var(e.ix)), ctx.value_of(var(e.iy))
    L0 = math.hypot(ex - sx, ey - sy)
    if L0 <= 1e-9 * max(1.0, abs(sx), abs(sy)):
        raise PrimitiveError("a Rectangle along a segment needs start and end apart (they "
                             f"start at the same point ({sx:g}, {sy:g}))")
    w = ctx.scalar(a["width"], "width", held=True)
    h = ctx.new_scalar(L0, "height", held=False)
    wv = ctx.value_of(var(w.index))
    ux, uy = (ey - sy) / L0, -(ex - sx) / L0            # across: the bar's own +x
    g.data["rotation"] = math.atan2(uy, ux)
    W, H = var(w.index) * 0.5, var(h.index)
    DX, DY = var(e.ix) - var(s.ix), var(e.iy) - var(s.iy)
    names = ("bottom_left", "bottom_right", "top_right", "top_left")
    eqs = [Equation(H - hypot(DX, DY))]
    for nm, base, sg in zip(names, (s, s, e, e), (-1.0, 1.0, 1.0, -1.0)):
        bx, by = ctx.value_of(var(base.ix)), ctx.value_of(var(base.iy))
        p = g.points[nm] = ctx.point(PV(bx + sg * wv / 2 * ux, by + sg * wv / 2 * uy), nm)
        # p = base + sg * (w / 2) * (DY, -DX) / H, times H
        eqs += [Equation((var(p.ix) - var(base.ix)) * H - W * DY * sg),
                Equation((var(p.iy) - var(base.iy)) * H + W * DX * sg)]
    g.scalars["width"], g.scalars["height"] = w, h
    ctx.internal(g, eqs, "Rectangle along a segment")
    bl, br, tr, tl = (g.points[n] for n in names)
    _rectangle_edges(ctx, g, bl, br, tr, tl)


def _rectangle_edges(ctx, g, bl, br, tr, tl) -> None:
    """Give a four-cornered shape ``g`` its edges ``bottom right top left`` (construction
    Lines between its corner points, parts of ``g``) and mark it closed."""
    for nm, (p, q) in {"bottom": (bl, br), "right": (br, tr), "top": (tl, tr), "left": (bl, tl)}.items():
        edge = Geometry("Line", ctx.struct, g.span, name=f"{g.name}.{nm}" if g.name else nm,
                        points={"start": p, "end": q}, construction=True)
        edge.data["part_of"] = g
        g.parts[nm] = edge
    g.closed = True


def _build_Rectangle(ctx, g, a):
    if "start" in a:
        return _build_bar(ctx, g, a)
    ux, uy = _rect_frame(ctx, g, a)
    vx, vy = -uy, ux
    names = ("bottom_left", "bottom_right", "top_right", "top_left")
    if "corner" in a:
        p, q = a["corner"], a["opposite"]
        px, py = ctx.value_of(p.x), ctx.value_of(p.y)
        qx, qy = ctx.value_of(q.x), ctx.value_of(q.y)
        # which corner is which, from the starting coordinates in the rotated frame
        du = (qx - px) * ux + (qy - py) * uy
        dv = (qx - px) * vx + (qy - py) * vy
        slot_p = {(True, True): "bottom_left", (False, True): "bottom_right",
                  (True, False): "top_left", (False, False): "top_right"}[(du >= 0, dv >= 0)]
        slot_q = {"bottom_left": "top_right", "top_right": "bottom_left",
                  "bottom_right": "top_left", "top_left": "bottom_right"}[slot_p]
        pts = {slot_p: ctx.point(p, slot_p), slot_q: ctx.point(q, slot_q)}
        w0, h0 = abs(du), abs(dv)
        w = ctx.new_scalar(w0, "width", held=False)
        h = ctx.new_scalar(h0, "height", held=False)
        # the other two corners, from the given pair (bottom-left/top-right or
        # bottom-right/top-left) by the width along u and the height along v
        offset = {"bottom_left": (0.0, 0.0), "bottom_right": (w0, 0.0),
                  "top_right": (w0, h0), "top_left": (0.0, h0)}
        known = pts[slot_p]
        kx, ky = ctx.value_of(var(known.ix)), ctx.value_of(var(known.iy))
        k0 = offset[slot_p]
        for nm, (ou, ov) in offset.items():
            if nm not in pts:
                du_, dv_ = ou - k0[0], ov - k0[1]
                pts[nm] = ctx.point(PV(kx + du_ * ux + dv_ * vx, ky + du_ * uy + dv_ * vy), nm)
    else:
        _positive(a["width"], "width", g.kind)
        _positive(a["height"], "height", g.kind)
        w = ctx.scalar(a["width"], "width", held=True)
        h = ctx.scalar(a["height"], "height", held=True)
        wv, hv = ctx.value_of(var(w.index)), ctx.value_of(var(h.index))
        if "center" in a:
            c = a["center"]
            cx, cy = ctx.value_of(c.x), ctx.value_of(c.y)
            bx = cx - wv / 2 * ux - hv / 2 * vx
            by = cy - wv / 2 * uy - hv / 2 * vy
        else:
            c = None
        pts = {}
        if "bottom_left" in a:
            pts["bottom_left"] = ctx.point(a["bottom_left"], "bottom_left")
            bx, by = ctx.value_of(var(pts["bottom_left"].ix)), ctx.value_of(var(pts["bottom_left"].iy))
        else:
            pts["bottom_left"] = ctx.point(PV(bx, by), "bottom_left")
        offs = {"bottom_right": (wv, 0), "top_right": (wv, hv), "top_left": (0, hv)}
        for nm, (du, dv) in offs.items():
            pts[nm] = ctx.point(PV(bx + du * ux + dv * vx, by + du * uy + dv * vy), nm)
    bl, br, tr, tl = (pts[n] for n in names)
    W, H = var(w.index), var(h.index)
    eqs = [
        var(br.ix) - var(bl.ix) - W * ux, var(br.iy) - var(bl.iy) - W * uy,
        var(tl.ix) - var(bl.ix) - H * vx, var(tl.iy) - var(bl.iy) - H * vy,
        var(tr.ix) - var(br.ix) - H * vx, var(tr.iy) - var(br.iy) - H * vy,
    ]
    g.points.update({n: pts[n] for n in names})
    g.scalars["width"], g.scalars["height"] = w, h
    ctx.internal(g, [Equation(e) for e in eqs], f"{g.kind} shape")
    if "center" in a and a["center"] is not None:
        cen = a["center"]
        mx = (var(bl.ix) + var(tr.ix)) * 0.5
        my = (var(bl.iy) + var(tr.iy)) * 0.5
        if cen.obj is not None and cen.obj.owner is ctx.struct:
            # the center is a shared point: keep it at the rectangle's center
            ctx.internal(g, [Equation(var(cen.obj.ix) - mx), Equation(var(cen.obj.iy) - my)],
                         "rectangle center")
            g.points["center"] = cen.obj
        elif ctx.value_of(cen.x) is not None and not _is_const_pv(cen):
            ctx.internal(g, [Equation(cen.x - mx), Equation(cen.y - my)], "rectangle center")
    _rectangle_edges(ctx, g, bl, br, tr, tl)


def _is_const_pv(p: PV) -> bool:
    return as_const(p.x) is not None and as_const(p.y) is not None


def _build_RoundedRectangle(ctx, g, a):
    one, each = a.get("corner_radius"), a.get("corner_radii")
    if (one is None) == (each is None):
        raise PrimitiveError("a RoundedRectangle needs corner_radius (every corner) or "
                             "corner_radii=[top_left, top_right, bottom_right, bottom_left]"
                             + (", not both" if one is not None else ""))
    if each is not None:
        radii = _corner_radii(ctx, each)
        if "corner" in a:       # by two corners (run ek): their starting distance apart
            p, q = a["corner"], a["opposite"]
            w = abs(ctx.value_of(q.x) - ctx.value_of(p.x))
            h = abs(ctx.value_of(q.y) - ctx.value_of(p.y))
        else:
            w = _const(ctx, a["width"], "width")
            h = _const(ctx, a["height"], "height")
        tl, tr, br, bl = radii
        for side, (r1, n1), (r2, n2), L in (("top", (tl, "top_left"), (tr, "top_right"), w),
                                           ("bottom", (bl, "bottom_left"), (br, "bottom_right"), w),
                                           ("left", (tl, "top_left"), (bl, "bottom_left"), h),
                                           ("right", (tr, "top_right"), (br, "bottom_right"), h)):
            if r1 + r2 > L * (1 + 1e-12):
                raise PrimitiveError(
                    f"a RoundedRectangle's {n1} and {n2} radii ({r1:g} + {r2:g} mm) exceed its "
                    f"{side} side ({L:g} mm): two corners on a side may take at most its length")
    _build_Rectangle(ctx, g, a)
    if each is not None:
        g.data["corner_radii"] = [bl, br, tr, tl]          # in points_of order
        g.data["corner_radius"] = max(radii)
    else:
        g.data["corner_radius"] = _const(ctx, one, "corner_radius")


def _corner_radii(ctx, v) -> list[float]:
    """``corner_radii=[top_left, top_right, bottom_right, bottom_left]`` (the CSS order) as
    four lengths in mm, each >= 0 and known before solving."""
    if not isinstance(v, (list, tuple)) or len(v) != 4:
        n = f"{len(v)} values" if isinstance(v, (list, tuple)) else "one value"
        raise PrimitiveError(f"corner_radii takes four radii [top_left, top_right, "
                             f"bottom_right, bottom_left], got {n}")
    out = []
    for name, q in zip(("top_left", "top_right", "bottom_right", "bottom_left"), v):
        if not isinstance(q, Q) or q.dim not in (LEN, NUM):
            raise PrimitiveError(f"corner_radii: the {name} radius must be a length, got "
                                 f"{type_name(q)}")
        r = _const(ctx, q, f"corner_radii {name}")
        if q.dim == NUM:                  # a bare number: the file's units
            r *= ctx.unit_scale
        if not r >= 0:
            raise PrimitiveError(f"corner_radii: the {name} radius must be 0 (a sharp corner) "
                                 f"or positive, got {r:g}")
        out.append(r)
    return out


def _polygon_edges(ctx, g, pts: list):
    n = len(pts)
    edges = []
    for i in range(n):
        e = Geometry("Line", ctx.struct, g.span, points={"start": pts[i], "end": pts[(i + 1) % n]},
                     construction=True)
        e.data["part_of"] = g
        edges.append(e)
    return edges


def _build_Triangle(ctx, g, a):
    if "base" in a:
        b = _const(ctx, a["base"], "base")
        h = _const(ctx, a["height"], "height")
        if b <= 0 or h == 0:
            raise PrimitiveError("a Triangle needs a positive base and a nonzero height")
        pts = _rigid(ctx, g, a, {"a": (-b / 2, -h / 2), "b": (b / 2, -h / 2), "c": (0.0, h / 2)},
                     "Triangle")
    else:
        pts = [ctx.point(a[k], k) for k in ("a", "b", "c")]
        g.points.update(dict(zip(("a", "b", "c"), pts)))
        _hold_literal_shape(ctx, g, [a[k] for k in ("a", "b", "c")], pts, a)
    edges = _polygon_edges(ctx, g, pts)
    g.parts.update({"ab": edges[0], "bc": edges[1], "ca": edges[2]})
    g.data["order"] = ["a", "b", "c"]
    g.closed = True


def _rigid(ctx, g, a, offsets: dict, what: str) -> list:
    """Points at fixed ``offsets`` (name -> (u, v), unrotated) from a center point, turned by
    the held ``rotation``; the center is a starting guess.  Returns the points in order."""
    rot = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    g.data["rotation"] = rot
    cs, sn = _cos_sin(rot)
    c = g.points["center"] = ctx.point(a["center"], "center")
    cx, cy = ctx.value_of(var(c.ix)), ctx.value_of(var(c.iy))
    pts, eqs = [], []
    for nm, (u, v) in offsets.items():
        ox, oy = u * cs - v * sn, u * sn + v * cs
        p = g.points[nm] = ctx.point(PV(cx + ox, cy + oy), nm)
        pts.append(p)
        eqs += [Equation(var(p.ix) - var(c.ix) - ox), Equation(var(p.iy) - var(c.iy) - oy)]
    ctx.internal(g, eqs, f"{what} shape")
    return pts


def _build_Trapezoid(ctx, g, a):
    b = _const(ctx, a["bottom_width"], "bottom_width")
    t = _const(ctx, a["top_width"], "top_width")
    h = _const(ctx, a["height"], "height")
    if min(b, t) < 0 or h <= 0 or max(b, t) <= 0:
        raise PrimitiveError("a Trapezoid needs a positive height and widths >= 0 (not both 0)")
    names = ("bottom_left", "bottom_right", "top_right", "top_left")
    pts = _rigid(ctx, g, a, dict(zip(names, ((-b / 2, -h / 2), (b / 2, -h / 2), (t / 2, h / 2),
                                             (-t / 2, h / 2)))), "Trapezoid")
    edges = _polygon_edges(ctx, g, pts)
    g.parts.update(dict(zip(("bottom", "right", "top", "left"), edges)))
    g.data["order"] = list(names)
    g.data["edges"] = edges
    g.data["dims"] = {"bottom_width": b, "top_width": t, "height": h}
    g.closed = True


def _build_Ellipse(ctx, g, a):
    rx = _const(ctx, a["rx"], "rx")
    ry = _const(ctx, a["ry"], "ry")
    if rx <= 0 or ry <= 0:
        raise PrimitiveError(f"an Ellipse needs positive rx and ry, got {rx:g} and {ry:g}")
    if a.get("start_angle") is not None or a.get("end_angle") is not None:
        _elliptic_arc(ctx, g, a, rx, ry)
        return
    g.data["rotation"] = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    g.points["center"] = ctx.point(a["center"], "center")
    g.scalars["rx"] = ctx.new_scalar(rx, "rx", held=True)
    g.scalars["ry"] = ctx.new_scalar(ry, "ry", held=True)
    g.closed = True


def _elliptic_arc(ctx, g, a, rx: float, ry: float) -> None:
    """``Ellipse(..., start_angle=, end_angle=)``: the open arc of the ellipse running
    counter-clockwise from parameter angle ``start_angle`` to ``end_angle`` (the point of
    parameter ``t`` is ``center + R(rotation) (rx cos t, ry sin t)``, the eccentric anomaly
    of DXF's ELLIPSE).  Its kind is ``EllipticArc``: rigid, held by its center, ends,
    midpoint, ``vertex`` (the end of the rx semi-axis) and ``co_vertex`` (of ry), from which
    the exact arc of a copy (turned, mirrored) is taken after the solve."""
    if a.get("start_angle") is None or a.get("end_angle") is None:
        raise PrimitiveError("an elliptic arc needs both start_angle and end_angle (the "
                             "parameter angles it runs between, counter-clockwise); without "
                             "them the Ellipse is whole")
    a1 = _const(ctx, a["start_angle"], "Ellipse start_angle")
    a2 = _const(ctx, a["end_angle"], "Ellipse end_angle")
    sweep = (a2 - a1) % (2 * math.pi)
    if sweep < 1e-9 or sweep > 2 * math.pi - 1e-9:
        raise PrimitiveError("an elliptic arc needs different start and end angles (less than "
                             "a whole turn apart): for the whole ellipse leave both out")
    rot = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    cs, sn = _cos_sin(rot)

    def at(t):
        u, v = rx * math.cos(t), ry * math.sin(t)
        return (u * cs - v * sn, u * sn + v * cs)
    offs = {"start": at(a1), "end": at(a1 + sweep), "midpoint": at(a1 + sweep / 2),
            "vertex": (rx * cs, rx * sn), "co_vertex": (-ry * sn, ry * cs)}
    g.kind = "EllipticArc"
    _rigid(ctx, g, dict(a, rotation=Q.num(0.0, ANG)), offs, "elliptic arc")
    g.data["rotation"] = rot
    g.data["dims"] = {"rx": rx, "ry": ry}
    g.data["angles"] = (a1, sweep)
    g.closed = False


def _point_list(ctx, g, pts_in: list, a: dict) -> list:
    """The points of a Polygon, Polyline, Spline or Bezier: each of ``pts_in`` a point of
    ``g`` named ``p0``, ``p1``, ... (in ``g.data["order"]``), a literal shape held
    (:func:`_hold_literal_shape`); returns them."""
    pts = [ctx.point(p, f"points[{i}]") for i, p in enumerate(pts_in)]
    for i, p in enumerate(pts):
        g.points[f"p{i}"] = p
    _hold_literal_shape(ctx, g, pts_in, pts, a)
    g.data["order"] = [f"p{i}" for i in range(len(pts))]
    return pts


def _hold_literal_shape(ctx, g, given: list, pts: list, a: dict) -> None:
    """A shape written as literal coordinates keeps its shape: when every point was given as
    a value known before solving (numbers, params; no point of other geometry) and
    ``flexible`` is not set, each point is held at its offset from the first, so relations
    (RightOf, AlignTop, ...) move the shape without bending it.  Its position stays free."""
    if a.get("flexible") or not all(p.obj is None and _is_const_pv(p) for p in given):
        return
    g.data["rigid"] = True
    p0 = pts[0]
    x0, y0 = ctx.value_of(var(p0.ix)), ctx.value_of(var(p0.iy))
    eqs = []
    for p in pts[1:]:
        dx, dy = ctx.value_of(var(p.ix)) - x0, ctx.value_of(var(p.iy)) - y0
        eqs += [Equation(var(p.ix) - var(p0.ix) - dx), Equation(var(p.iy) - var(p0.iy) - dy)]
    ctx.internal(g, eqs, f"{g.kind} shape (literal coordinates)")


def _start_xy(ctx, pts) -> list[tuple[float, float]] | None:
    """The starting coordinates (mm) of a point list, or None when an item is not a point
    (its own error comes where the points are made)."""
    try:
        return [(ctx.value_of(p.x), ctx.value_of(p.y)) for p in pts]
    except (AttributeError, TypeError):
        return None


def _size(xy) -> float:
    """The scale for "the same point" tests on ``xy``: its largest coordinate, at least 1 mm."""
    return max(1.0, max(abs(v) for pt in xy for v in pt))


def _build_RegularPolygon(ctx, g, a):
    sides = _const(ctx, a["sides"], "sides")
    if abs(sides - round(sides)) > 1e-9:
        raise PrimitiveError(f"a RegularPolygon needs a whole number of sides, got {sides:g}")
    n = int(round(sides))
    if n < 3 or n > 1000:
        raise PrimitiveError(f"a RegularPolygon needs 3 to 1000 sides, got {n}")
    if "across_flats" in a:      # distance between opposite sides = 2 * apothem
        _positive(a["across_flats"], "across_flats", "RegularPolygon")
        r = _const(ctx, a["across_flats"], "across_flats") / 2 / math.cos(math.pi / n)
    elif "side" in a:            # one edge's length = 2 r sin(pi / n)
        _positive(a["side"], "side", "RegularPolygon")
        r = _const(ctx, a["side"], "side") / 2 / math.sin(math.pi / n)
    else:
        _positive(a["radius"], "radius", "RegularPolygon")
        r = _const(ctx, a["radius"], "radius")
    if r <= 0:
        raise PrimitiveError("a RegularPolygon needs a positive size")
    rot = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    g.data["rotation"] = rot
    c = g.points["center"] = ctx.point(a["center"], "center")
    cx, cy = ctx.value_of(var(c.ix)), ctx.value_of(var(c.iy))
    pts, eqs = [], []
    for k in range(n):       # vertex k at angle rotation + 360 deg * k / n from +x (CCW)
        t = rot + 2 * math.pi * k / n
        ox, oy = r * math.cos(t), r * math.sin(t)
        p = ctx.point(PV(cx + ox, cy + oy), f"points[{k}]")
        pts.append(p)
        g.points[f"p{k}"] = p
        eqs += [Equation(var(p.ix) - var(c.ix) - ox), Equation(var(p.iy) - var(c.iy) - oy)]
    ctx.internal(g, eqs, "RegularPolygon shape")
    g.data["order"] = [f"p{k}" for k in range(n)]
    g.data["edges"] = _polygon_edges(ctx, g, pts)
    g.scalars["radius"] = ctx.new_scalar(r, "radius", held=True)
    g.closed = True


def _build_Star(ctx, g, a):
    n = _const(ctx, a["points"], "points")
    if abs(n - round(n)) > 1e-9 or not 2 <= round(n) <= 500:
        raise PrimitiveError(f"a Star needs a whole number of points from 2 to 500, got {n:g}")
    n = int(round(n))
    _positive(a["outer_radius"], "outer_radius", "Star")
    _positive(a["inner_radius"], "inner_radius", "Star")
    ro = _const(ctx, a["outer_radius"], "outer_radius")
    ri = _const(ctx, a["inner_radius"], "inner_radius")
    if not ri < ro:
        raise PrimitiveError(f"a Star's inner_radius ({ri:g} mm) must be smaller than its "
                             f"outer_radius ({ro:g} mm)")
    rot = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    offsets = {}
    for k in range(2 * n):        # tip k/2 straight up (+y) turned by rotation, notches between
        t = math.pi / 2 + math.pi * k / n
        r = ro if k % 2 == 0 else ri
        offsets[f"p{k}"] = (r * math.cos(t), r * math.sin(t))
    rt = _const(ctx, a.get("tip_radius", Q.num(0.0, LEN)), "tip_radius")
    if rt < 0:
        raise PrimitiveError(f"a Star's tip_radius is 0 (sharp) or more, got {rt:g} mm")
    pts = _rigid(ctx, g, a, offsets, "Star")
    g.data["order"] = list(offsets)
    g.data["edges"] = _polygon_edges(ctx, g, pts)
    g.data["dims"] = {"outer_radius": ro, "inner_radius": ri, "tip_radius": rt}
    if rt > 0:
        g.data["tip"] = _star_tip(n, ro, ri, rt)
    g.closed = True


def _star_tip(n: int, ro: float, ri: float, rt: float) -> tuple[float, float]:
    """A Star's rounded tip (``tip_radius`` ``rt``): ``(the distance from the star's center
    to the fillet arc's center, the arc's half sweep)`` (mm, radians).  The tip's interior
    angle is ``2 h``; the arc is tangent to both sides ``rt / tan(h)`` from the sharp tip,
    which must leave some of the side to the notch: else PrimitiveError, naming the largest
    radius (to a thousandth of a mm below the one that leaves none)."""
    tip = (0.0, ro)
    notch = (ri * math.cos(math.pi / 2 + math.pi / n), ri * math.sin(math.pi / 2 + math.pi / n))
    side = (notch[0] - tip[0], notch[1] - tip[1])
    length = math.hypot(*side)
    h = math.asin(min(1.0, abs(side[0]) / length))     # half the tip's angle (the axis: -y)
    reach = rt / math.tan(h)
    if not reach < length * (1 - 1e-9):
        most = length * math.tan(h)
        raise PrimitiveError(f"a Star's tip_radius ({rt:g} mm) is too large for its tips: "
                             f"the rounding would run past the notches (less than "
                             f"{math.floor(most * 1000) / 1000:g} mm here)")
    return ro - rt / math.sin(h), math.pi / 2 - h


def _build_ArcSlot(ctx, g, a):
    _positive(a["radius"], "radius", "ArcSlot")
    _positive(a["width"], "width", "ArcSlot")
    R = _const(ctx, a["radius"], "radius")
    w = _const(ctx, a["width"], "width")
    a1 = _const(ctx, a["start_angle"], "ArcSlot start_angle")
    a2 = _const(ctx, a["end_angle"], "ArcSlot end_angle")
    if not w / 2 < R:
        raise PrimitiveError(f"an ArcSlot's width ({w:g} mm) must be less than twice its "
                             f"radius ({R:g} mm): its inner side would cross the center")
    sweep = (a2 - a1) % (2 * math.pi)
    if sweep < 1e-9 or sweep > 2 * math.pi - 1e-9:
        raise PrimitiveError("an ArcSlot needs different start and end angles (less than a "
                             "whole turn apart): for a ring use a Circle with a hole")
    mid = a1 + sweep / 2
    pts = _rigid(ctx, g, dict(a, rotation=Q.num(0.0, ANG)),
                 {"start": (R * math.cos(a1), R * math.sin(a1)),
                  "end": (R * math.cos(a1 + sweep), R * math.sin(a1 + sweep)),
                  "midpoint": (R * math.cos(mid), R * math.sin(mid))}, "ArcSlot")
    del pts
    g.data["dims"] = {"radius": R, "width": w, "inner_radius": R - w / 2,
                      "outer_radius": R + w / 2}
    g.data["angles"] = (a1, sweep)
    g.closed = True


def _build_Sector(ctx, g, a):
    """A pie slice (``inner_radius`` 0) or an annulus segment: the counter-clockwise arc of
    ``radius`` about center from start_angle to end_angle, closed by two radial lines (to the
    center, or to the inner arc of ``inner_radius`` back); rigid, every dimension held."""
    _positive(a["radius"], "radius", "Sector")
    R = _const(ctx, a["radius"], "radius")
    r = _const(ctx, a.get("inner_radius", Q.num(0.0, LEN)), "inner_radius")
    a1 = _const(ctx, a["start_angle"], "Sector start_angle")
    a2 = _const(ctx, a["end_angle"], "Sector end_angle")
    if r < 0 or not r < R:
        raise PrimitiveError(f"a Sector's inner_radius ({r:g} mm) must be 0 (a pie slice) or "
                             f"between 0 and its radius ({R:g} mm)")
    sweep = (a2 - a1) % (2 * math.pi)
    if sweep < 1e-9 or sweep > 2 * math.pi - 1e-9:
        raise PrimitiveError("a Sector needs different start and end angles (less than a "
                             "whole turn apart): for a disc use a Circle, for a ring a "
                             "Circle with a hole")
    mid = a1 + sweep / 2
    offs = {"start": (R * math.cos(a1), R * math.sin(a1)),
            "end": (R * math.cos(a1 + sweep), R * math.sin(a1 + sweep)),
            "midpoint": (R * math.cos(mid), R * math.sin(mid))}
    if r > 0:
        offs["inner_start"] = (r * math.cos(a1), r * math.sin(a1))
        offs["inner_end"] = (r * math.cos(a1 + sweep), r * math.sin(a1 + sweep))
    _rigid(ctx, g, dict(a, rotation=Q.num(0.0, ANG)), offs, "Sector")
    g.data["dims"] = {"radius": R, "width": R - r, "inner_radius": r, "outer_radius": R}
    g.data["angles"] = (a1, sweep)
    g.closed = True


def _build_Slot(ctx, g, a):
    if "angle" in a:                # polar: from start (an end arc's center) by length, angle
        _positive(a["length"], "length", "Slot")
        _positive(a["width"], "width", "Slot")
        L = _const(ctx, a["length"], "length")
        W = _const(ctx, a["width"], "width")
        if L < W:
            raise PrimitiveError(f"a Slot's length ({L:g} mm, end to end) must be at least its "
                                 f"width ({W:g} mm)")
        t = _const(ctx, a["angle"], "Slot angle")
        ox, oy = (L - W) * math.cos(t), (L - W) * math.sin(t)
        s = ctx.point(a["start"], "start")
        sx, sy = ctx.value_of(var(s.ix)), ctx.value_of(var(s.iy))
        e = ctx.point(PV(sx + ox, sy + oy), "end")
        ctx.internal(g, [Equation(var(e.ix) - var(s.ix) - ox),
                         Equation(var(e.iy) - var(s.iy) - oy)], "Slot length and angle")
        g.scalars["radius"] = ctx.new_scalar(W / 2, "radius", held=True)
        g.points["start"], g.points["end"] = s, e
        g.closed = True
        return
    if "center" in a:
        _positive(a["length"], "length", "Slot")
        _positive(a["width"], "width", "Slot")
        L = _const(ctx, a["length"], "length")
        W = _const(ctx, a["width"], "width")
        rot = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
        ux, uy = _cos_sin(rot)
        c = g.points["center"] = ctx.point(a["center"], "center")
        cx, cy = ctx.value_of(var(c.ix)), ctx.value_of(var(c.iy))
        half = max(0.0, (L - W) / 2)     # length is overall, end to end
        s = ctx.point(PV(cx - half * ux, cy - half * uy), "start")
        e = ctx.point(PV(cx + half * ux, cy + half * uy), "end")
        ctx.internal(g, [Equation(var(s.ix) - var(c.ix) + half * ux),
                         Equation(var(s.iy) - var(c.iy) + half * uy),
                         Equation(var(e.ix) - var(c.ix) - half * ux),
                         Equation(var(e.iy) - var(c.iy) - half * uy)], "Slot shape")
        g.scalars["radius"] = ctx.new_scalar(W / 2, "radius", held=True)
    else:
        for k in ("radius", "width"):
            if k in a:
                _positive(a[k], k, "Slot")
        s = ctx.point(a["start"], "start")
        e = ctx.point(a["end"], "end")
        r = a["radius"] if "radius" in a else Q(a["width"].expr * 0.5, LEN, a["width"].owners)
        g.scalars["radius"] = ctx.scalar(r, "radius", held=True)
    g.points["start"], g.points["end"] = s, e
    g.closed = True


def _build_Text(ctx, g, a):
    if a.get("along") is not None:
        if a.get("position") is not None:
            raise PrimitiveError("a Text takes a position or along=, not both: along= puts "
                                 "it on the curve (angle= says where)")
        _text_along(ctx, g, a)
    elif a.get("position") is None:
        raise PrimitiveError("a Text needs a position (on its baseline, e.g. `position=(0, "
                             "0)`) or along=circle_or_arc")
    else:
        g.points["position"] = ctx.point(a["position"], "position")
    g.data["text"] = a["text"]
    g.data["size"] = _const(ctx, a.get("size", Q.num(5.0, LEN)), "size")
    anchor = a.get("anchor", "middle")
    if anchor in ("left", "center", "right"):           # the words of CSS and most CAD tools
        anchor = {"left": "start", "center": "middle", "right": "end"}[anchor]
    if anchor not in ("start", "middle", "end"):
        raise PrimitiveError(f"anchor must be \"start\", \"middle\" or \"end\", not \"{anchor}\"")
    g.data["anchor"] = anchor
    valign = {"center": "middle", "centre": "middle"}.get(a.get("valign", "baseline"),
                                                          a.get("valign", "baseline"))
    if valign not in ("baseline", "middle", "top", "bottom"):
        raise PrimitiveError(f"valign must be \"baseline\", \"middle\", \"top\" or \"bottom\", "
                             f"not \"{valign}\"")
    g.data["valign"] = valign
    g.data["rotation"] = _const(ctx, a.get("rotation", Q.num(0.0, ANG)), "rotation")
    if a.get("_font") is not None:
        from .font import FontError
        from .text_outlines import build_font_text
        try:
            build_font_text(ctx, g, a, _const)
        except FontError as ex:
            raise PrimitiveError(str(ex), hint=ex.hint) from None
        return
    if a.get("max_width") is not None:
        _fit_width(ctx, g, a)
    if a.get("stencil"):
        _stencil(ctx, g, a)
    if a.get("along") is not None:
        from .text import text_strokes_along
        ang = g.data["angle"]
        if ang is None:
            ang = g.data["start_angle"]
        segs = text_strokes_along(g.data["text"], g.data["size"], g.data["radius0"], ang,
                                  anchor, valign, g.data["flip"])
        xs = [p[0] for s_ in segs for p in s_] or [0.0]
        ys = [p[1] for s_ in segs for p in s_] or [0.0]
        g.data["extent"] = (min(xs), max(xs), min(ys), max(ys))


def _fit_width(ctx, g, a) -> None:
    """``Text(..., max_width=)``: the size lowered, when the text is wider than ``max_width``
    along its baseline (a stencil's letters with their stroke ``weight``), to the size at
    which it is exactly that wide; ``data["shrunk"]`` = (size asked, width at it) for the
    note the interpreter gives (W0113).  Along a curve the width is its length along it."""
    from .text import fit_size
    m = _const(ctx, a["max_width"], "max_width")
    if not m > 0:
        raise PrimitiveError(f"a Text's max_width is more than 0, got {m:g} mm")
    size = g.data["size"]
    weight = a.get("weight") if a.get("stencil") else None
    fixed = _const(ctx, weight, "weight") if weight is not None else 0.0
    per_size = 1 / 6 if a.get("stencil") and weight is None else 0.0
    if fixed >= m:
        raise PrimitiveError(f"a stencil Text's weight ({fixed:g} mm) leaves nothing of its "
                             f"max_width ({m:g} mm): give a wider max_width or a thinner weight")
    fit, wide = fit_size(g.data["text"], size, m, fixed, per_size)
    g.data["max_width"] = m
    if fit < size:
        g.data["size"] = fit
        g.data["shrunk"] = (size, wide)


def _stencil(ctx, g, a) -> None:
    """``Text(..., stencil=true)``: a closed shape, the letters' openings with bridges
    (:mod:`aidl_lang.output.part.build.stencil`); ``weight`` and ``bridge`` in mm."""
    if a.get("along") is not None:
        raise PrimitiveError("a stencil Text is written on a straight baseline: leave out "
                             "along=, or engrave the text along the curve (stencil=false)")
    size = g.data["size"]
    for key, dflt in (("weight", size / 6), ("bridge", size / 10)):
        v = a.get(key)
        g.data[key] = dflt if v is None else _const(ctx, v, key)
        if not g.data[key] > 0:
            raise PrimitiveError(f"a stencil Text's {key} is more than 0, got {g.data[key]:g}")
    if g.data["bridge"] >= size / 2:
        raise PrimitiveError(f"a stencil Text's bridges ({g.data['bridge']:g} mm) must be "
                             f"narrower than half its size ({size:g} mm)")
    g.data["stencil"] = True
    g.closed = True


def _text_along(ctx, g, a) -> None:
    """``Text(..., along=circle_or_arc, angle=)``: the position is the curve's center
    (shared); the radius and, without ``angle``, the arc's middle angle are read after the
    solve (at their starting values for the bounding box)."""
    v = a["along"]
    if not isinstance(v, GeomRef) or v.geom.kind not in ("Circle", "Arc"):
        raise PrimitiveError("a Text along a curve follows a Circle or an Arc (of its drawing; "
                             "a construction one is not drawn), got "
                             + (v.geom.kind if isinstance(v, GeomRef) else type_name(v)))
    src = v.geom
    c = src.points["center"]
    g.points["position"] = c if c.owner is ctx.struct else ctx.point(
        PV(ctx.value_of(var(c.ix)), ctx.value_of(var(c.iy))), "position")
    cx, cy = ctx.value_of(var(c.ix)), ctx.value_of(var(c.iy))
    if src.kind == "Circle":
        r = ctx.value_of(var(src.scalars["radius"].index))
        mid = math.pi / 2
    else:
        s_, e_ = src.points["start"], src.points["end"]
        sx, sy = ctx.value_of(var(s_.ix)) - cx, ctx.value_of(var(s_.iy)) - cy
        ex, ey = ctx.value_of(var(e_.ix)) - cx, ctx.value_of(var(e_.iy)) - cy
        r = math.hypot(sx, sy)
        a1 = math.atan2(sy, sx)
        sweep = (math.atan2(ey, ex) - a1) % (2 * math.pi) or 2 * math.pi
        mid = a1 + sweep / 2
    if not r > 0:
        raise PrimitiveError("a Text along a curve needs a curve of positive radius")
    ang = a.get("angle")
    g.data["along"] = src
    g.data["angle"] = None if ang is None else _const(ctx, ang, "Text angle")
    g.data["start_angle"] = mid if not a.get("flip") else mid + math.pi * (src.kind == "Circle")
    g.data["radius0"] = r
    g.data["flip"] = bool(a.get("flip"))


def _build_Drawing2D(ctx, g, a):
    """A drawing read by the interpreter, placed rigidly (:func:`.drawing2d.build`)."""
    from .drawing2d import build
    build(ctx, g, a, _const)


