"""Constraint builders: each turns a constraint call's arguments into residual equations.

Arguments arrive unit-converted and in the frame of the owning structure (the structure whose
body holds the constraint).  Equations are ``expr == 0`` or, for inequalities, ``expr >= 0``.
Convention-dependent constraints (Angle sense, Tangent side, point-to-line Distance side) pick
the branch nearest to satisfied at the starting geometry (paper, appendix "Solver Details",
*Deferred expressions*).
"""
from __future__ import annotations

import math

from .bbox import BBTerm
from ..core.expr import Expr, Lin, _new, add, evaluate, func, hypot, mul, sub, var
from ..core.model import Equation, equation
from .members import _pv, member
from ..core.values import PV, BBoxRef, GeomRef, Q, StructRef, type_name, unify_add


class ConstraintError(Exception):
    pass


def _pt(v, name: str, ctx=None) -> PV:
    """``v`` as a point value: a point value as it is, a ``Point`` shape's point seen from the
    constraint's structure (``ctx.struct``, the frame every other point of its equations is
    seen from; a ``Point`` seen from the model frame beside a point in a structure's own frame
    tied the wrong unknowns: issue 61, `spur_gear`'s `Coincident(teeth_ring.axis, hub.center)`)."""
    if isinstance(v, PV):
        return v
    if isinstance(v, GeomRef) and v.geom.kind == "Point":
        return member(v.geom, "p", ctx.struct if ctx is not None else None)
    raise ConstraintError(f"`{name}` must be a point, got {type_name(v)}")


def _line(ctx, v, name: str) -> tuple[PV, PV]:
    if isinstance(v, GeomRef) and v.geom.kind in ("Line", "Slot"):
        pts, frame = v.geom.points, ctx.struct       # member(g, "start" / "end", frame)
        return _pv(pts["start"], frame), _pv(pts["end"], frame)
    raise ConstraintError(f"`{name}` must be a Line, got {type_name(v)}")


def _directed_line(ctx, v, name: str) -> tuple[PV, PV]:
    """``_line`` for constraints that use the line's direction (they divide by its length):
    a line of zero starting length has none, and the solver's Jacobian is undefined there."""
    s, e, _dx, _dy = _direction(ctx, v, name)
    return s, e


def _direction(ctx, v, name: str):
    """:func:`_directed_line` and the line's ``end - start`` (``dx``, ``dy`` expressions;
    None when they could not be evaluated)."""
    s, e = _line(ctx, v, name)
    try:
        dx, dy = sub(e.x, s.x), sub(e.y, s.y)
        n = math.hypot(ctx.value_of(dx), ctx.value_of(dy))
    except (TypeError, ValueError):
        return s, e, None, None
    if not n > 1e-9:
        label = getattr(getattr(v, "geom", None), "label", None) or name
        raise ConstraintError(f"`{label}` has zero length (its start and end are the same "
                              "point), so it has no direction for this constraint; give it "
                              "distinct starting points")
    return s, e, dx, dy


def _circ(ctx, v, name: str) -> tuple[PV, Expr]:
    if isinstance(v, GeomRef) and v.geom.kind in ("Circle", "Arc"):
        return member(v.geom, "center", ctx.struct), member(v.geom, "radius", ctx.struct).expr
    raise ConstraintError(f"`{name}` must be a Circle or Arc, got {type_name(v)}")


def _kind(v) -> str:
    if isinstance(v, PV):
        return "point"
    if isinstance(v, GeomRef):
        return {"Line": "line", "Circle": "circular", "Arc": "circular",
                "Point": "point"}.get(v.geom.kind, v.geom.kind)
    if isinstance(v, Q):
        return "scalar"
    return type_name(v)


def _cross(ax, ay, bx, by):
    return ax * by - ay * bx


def _val(ctx, e) -> float:
    return ctx.value_of(e)


def _sign_nearest(ctx, e: Expr, target: float) -> float:
    """+1 or -1: which of ``e == target`` / ``e == -target`` is nearer at the start."""
    v = _val(ctx, e)
    return 1.0 if abs(v - target) <= abs(v + target) else -1.0


def coincident(ctx, a, b, **_):
    ka, kb = _kind(a), _kind(b)
    if ka == "point" and kb == "point":
        p, q = _pt(a, "a", ctx), _pt(b, "b", ctx)
        return [Equation(p.x - q.x), Equation(p.y - q.y)]
    if ka == "point" and kb == "line":
        return on_line(ctx, a, b)
    if kb == "point" and ka == "line":
        return on_line(ctx, b, a)
    if ka == "point" and kb == "circular":
        return on_circle(ctx, a, b)
    if kb == "point" and ka == "circular":
        return on_circle(ctx, b, a)
    if ka == "point" and kb in ("Ellipse", "EllipticArc"):
        return on_ellipse(ctx, a, b)
    if kb == "point" and ka in ("Ellipse", "EllipticArc"):
        return on_ellipse(ctx, b, a)
    if ka == kb == "line":
        (s1, e1), (s2, e2) = _line(ctx, a, "a"), _line(ctx, b, "b")
        return [Equation(s1.x - s2.x), Equation(s1.y - s2.y),
                Equation(e1.x - e2.x), Equation(e1.y - e2.y)]
    raise ConstraintError(f"Coincident takes two points (or a point and a line, circle, arc "
                          f"or ellipse), "
                          f"got {type_name(a)} and {type_name(b)}")


def _hv(ctx, a, b, axis: str, name: str):
    if b is None and type(a) is GeomRef:
        g, frame = a.geom, ctx.struct
        ps, pe = g.points.get("start"), g.points.get("end")
        if (g.kind == "Line" or g.kind == "Slot") and ps.owner is frame and pe.owner is frame:
            # the line's own end points: s.y - e.y (s.x - e.x) as sub() makes it, directly
            if axis == "h":
                return [equation(_own_delta(pe.iy, ps.iy))]
            return [equation(_own_delta(pe.ix, ps.ix))]
    if b is None:
        s, e = _line(ctx, a, "a")
    else:
        s, e = _pt(a, "a", ctx), _pt(b, "b", ctx)
    return [Equation(s.y - e.y if axis == "h" else s.x - e.x)]


def horizontal(ctx, a, b=None, **_):
    return _hv(ctx, a, b, "h", "Horizontal")


def vertical(ctx, a, b=None, **_):
    return _hv(ctx, a, b, "v", "Vertical")


def fixed(ctx, a, **_):
    if isinstance(a, (list, tuple)) and a and all(
            isinstance(x, (PV, GeomRef, StructRef, list, tuple)) for x in a):
        # a loop's list (run er's Geneva drive: `Fixed(slot)` after the loop): each item
        return [e for x in a for e in fixed(ctx, x)]
    pts = []
    if isinstance(a, PV):
        pts = [a]
    elif isinstance(a, GeomRef):
        pts = [_pv(p, ctx.struct) for p in a.geom.points.values()]   # every point, p0.. too
        eqs = [Equation(var(s.index) - ctx.value_of(var(s.index))) for s in a.geom.scalars.values()]
    elif isinstance(a, StructRef):
        s = a.struct
        if s.parent is None:
            return []
        return [Equation(var(s.fx) - ctx.value_of(var(s.fx))),
                Equation(var(s.fy) - ctx.value_of(var(s.fy)))]
    else:
        raise ConstraintError(f"Fixed takes a point, geometry or structure (or a list of "
                              f"them), got {type_name(a)}")
    out = [] if not isinstance(a, GeomRef) else eqs
    for p in pts:
        out += [Equation(p.x - _val(ctx, p.x)), Equation(p.y - _val(ctx, p.y))]
    return out


def distance(ctx, a, b, distance, **_):
    d = distance.expr
    ka, kb = _kind(a), _kind(b)
    if ka == "point" and kb == "point":
        p, q = _pt(a, "a", ctx), _pt(b, "b", ctx)
        return [Equation(hypot(p.x - q.x, p.y - q.y) - d)]
    if ka == "line" and kb == "point":
        a, b, ka, kb = b, a, kb, ka
    if ka == "point" and kb == "line":
        p = _pt(a, "a", ctx)
        s, e = _directed_line(ctx, b, "b")
        sd = _cross(e.x - s.x, e.y - s.y, p.x - s.x, p.y - s.y) / hypot(e.x - s.x, e.y - s.y)
        sign = _sign_nearest(ctx, sd, _val(ctx, d))
        return [Equation(sd - d * sign)]
    if ka == "point" and kb == "circular":
        p = _pt(a, "a", ctx)
        c, r = _circ(ctx, b, "b")
        return [Equation(hypot(p.x - c.x, p.y - c.y) - r - d)]
    if ka == "line" and kb == "line":
        # two parallel lines `distance` apart: parallel, and b's start that far from line a
        s, e = _line(ctx, a, "a")
        q, _qe = _line(ctx, b, "b")
        sd = _cross(e.x - s.x, e.y - s.y, q.x - s.x, q.y - s.y) / hypot(e.x - s.x, e.y - s.y)
        sign = _sign_nearest(ctx, sd, _val(ctx, d))
        return parallel(ctx, a, b) + [Equation(sd - d * sign)]
    raise ConstraintError(f"Distance takes two points, a point and a line, or two lines, "
                          f"got {type_name(a)} and {type_name(b)}")


def horizontal_distance(ctx, a, b, distance, **_):
    return [Equation(_pt(b, "b", ctx).x - _pt(a, "a", ctx).x - distance.expr)]


def vertical_distance(ctx, a, b, distance, **_):
    return [Equation(_pt(b, "b", ctx).y - _pt(a, "a", ctx).y - distance.expr)]


def at(ctx, a, b, dx, dy, **_):
    """``a == b + (dx, dy)``: two linear equations (points in the writing structure's frame)."""
    pa, pb = _pt(a, "a", ctx), _pt(b, "b", ctx)
    return [Equation(pa.x - pb.x - dx.expr), Equation(pa.y - pb.y - dy.expr)]


def _own_delta(a, b):
    """``b - a`` of two points of the structure being run, as ``sub()`` makes it from their
    coordinates (``Lin({b: 1.0}) - Lin({a: 1.0})``), without the point values in between."""
    t = {b: 1.0}
    t[a] = t.get(a, 0.0) + -1.0
    d = _new(Lin)
    d.terms, d.const = t, 0.0
    return d


def length(ctx, line, length, **_):
    if type(line) is GeomRef and (line.geom.kind == "Line" or line.geom.kind == "Slot"):
        pts, frame = line.geom.points, ctx.struct
        ps, pe = pts["start"], pts["end"]
        if ps.owner is frame and pe.owner is frame:     # _direction of the line's own points
            dx, dy = _own_delta(ps.ix, pe.ix), _own_delta(ps.iy, pe.iy)
            if not math.hypot(ctx.value_of(dx), ctx.value_of(dy)) > 1e-9:
                _direction(ctx, line, "line")           # its zero-length error
            return [equation(sub(hypot(dx, dy), length.expr))]
    s, e, dx, dy = _direction(ctx, line, "line")
    if dx is None:
        dx, dy = e.x - s.x, e.y - s.y
    return [equation(sub(hypot(dx, dy), length.expr))]


def radius(ctx, circle, radius, **_):
    _, r = _circ(ctx, circle, "circle")
    return [Equation(r - radius.expr)]


def diameter(ctx, circle, diameter, **_):
    _, r = _circ(ctx, circle, "circle")
    return [Equation(r * 2.0 - diameter.expr)]


def _size(ctx, v):
    """The 'size' of a value for Equal: list of expressions."""
    if isinstance(v, Q):
        return [v.expr]
    if isinstance(v, GeomRef):
        g = v.geom
        if g.kind == "Line":
            return [member(g, "length", ctx.struct).expr]
        if g.kind in ("Circle", "Arc", "Slot", "RegularPolygon"):
            return [member(g, "radius", ctx.struct).expr]
        if g.kind in ("Rectangle", "RoundedRectangle"):
            return [var(g.scalars["width"].index), var(g.scalars["height"].index)]
    raise ConstraintError(f"Equal cannot compare {type_name(v)}")


def equal(ctx, a, b, **_):
    if isinstance(a, PV) or isinstance(b, PV):
        return coincident(ctx, a, b)
    if isinstance(a, Q) and isinstance(b, Q):
        ea, eb, _d = unify_add(a, b, ctx.unit_scale, math.pi / 180)
        return [Equation(ea - eb)]
    ka = a.geom.kind if isinstance(a, GeomRef) else "value"
    kb = b.geom.kind if isinstance(b, GeomRef) else "value"
    fam = lambda k: {"Arc": "Circle", "RoundedRectangle": "Rectangle"}.get(k, k)
    if fam(ka) != fam(kb) and "value" not in (ka, kb):
        raise ConstraintError(f"Equal needs two things of the same kind, got {ka} and {kb}; "
                              f"compare members instead, e.g. `a.length == b.radius`")
    sa, sb = _size(ctx, a), _size(ctx, b)
    if len(sa) != len(sb):
        raise ConstraintError(f"Equal needs two things of the same kind, got {type_name(a)} "
                              f"and {type_name(b)}")
    return [Equation(x - y) for x, y in zip(sa, sb)]


def _dirs(ctx, a, b):
    (s1, e1), (s2, e2) = _directed_line(ctx, a, "a"), _directed_line(ctx, b, "b")
    return e1.x - s1.x, e1.y - s1.y, e2.x - s2.x, e2.y - s2.y


def parallel(ctx, a, b, **_):
    ax, ay, bx, by = _dirs(ctx, a, b)
    return [Equation(_cross(ax, ay, bx, by) / (hypot(ax, ay) * hypot(bx, by)))]


def perpendicular(ctx, a, b, **_):
    ax, ay, bx, by = _dirs(ctx, a, b)
    return [Equation((ax * bx + ay * by) / (hypot(ax, ay) * hypot(bx, by)))]


def angle(ctx, a, b, angle, **_):
    ax, ay, bx, by = _dirs(ctx, a, b)
    th = angle.const()
    if th is None:
        th = _val(ctx, angle.expr)
    n = hypot(ax, ay) * hypot(bx, by)
    cr, dt = _cross(ax, ay, bx, by) / n, (ax * bx + ay * by) / n
    phi = math.atan2(_val(ctx, cr), _val(ctx, dt))
    # lines are undirected: sin(phi - theta) == 0; pick the sense (theta or -theta) nearest
    best = min((th, -th), key=lambda t: abs(math.sin(phi - t)))
    # cos(phi - best) > 0: line b points the way it did at the start (not reversed)
    along = cr * math.sin(best) + dt * math.cos(best)
    sign = 1.0 if _val(ctx, along) >= 0 else -1.0
    return [Equation(cr * math.cos(best) - dt * math.sin(best), branch=along * sign)]


def tangent(ctx, a, b, **_):
    ka, kb = _kind(a), _kind(b)
    if ka == "circular" and kb == "line":
        a, b, ka, kb = b, a, kb, ka
    if ka == "line" and kb == "circular":
        s, e = _directed_line(ctx, a, "a")
        c, r = _circ(ctx, b, "b")
        sd = _cross(e.x - s.x, e.y - s.y, c.x - s.x, c.y - s.y) / hypot(e.x - s.x, e.y - s.y)
        sign = 1.0 if _val(ctx, sd) >= 0 else -1.0
        return [Equation(sd - r * sign)]
    if ka == kb == "circular":
        c1, r1 = _circ(ctx, a, "a")
        c2, r2 = _circ(ctx, b, "b")
        d = hypot(c1.x - c2.x, c1.y - c2.y)
        dv, v1, v2 = _val(ctx, d), _val(ctx, r1), _val(ctx, r2)
        if abs(dv - (v1 + v2)) <= abs(dv - abs(v1 - v2)):
            return [Equation(d - (r1 + r2))]
        return [Equation(d - (r1 - r2) * (1.0 if v1 >= v2 else -1.0))]
    raise ConstraintError(f"Tangent takes a line and a circle/arc or two circles/arcs, "
                          f"got {type_name(a)} and {type_name(b)}")


def _sym_points(s, e, p, q):
    mx, my = (p.x + q.x) * 0.5, (p.y + q.y) * 0.5
    return [Equation(_cross(e.x - s.x, e.y - s.y, mx - s.x, my - s.y)),
            Equation((q.x - p.x) * (e.x - s.x) + (q.y - p.y) * (e.y - s.y))]


def symmetric(ctx, a, b, about, **_):
    s, e = _directed_line(ctx, about, "about")
    ka, kb = _kind(a), _kind(b)
    if ka == kb == "point":
        return _sym_points(s, e, _pt(a, "a", ctx), _pt(b, "b", ctx))
    if ka == kb == "circular":
        c1, r1 = _circ(ctx, a, "a")
        c2, r2 = _circ(ctx, b, "b")
        return _sym_points(s, e, c1, c2) + [Equation(r1 - r2)]
    if ka == kb == "line":
        (s1, e1), (s2, e2) = _line(ctx, a, "a"), _line(ctx, b, "b")
        return _sym_points(s, e, s1, s2) + _sym_points(s, e, e1, e2)
    raise ConstraintError(f"Symmetric takes two points, circles or lines and a line, "
                          f"got {type_name(a)} and {type_name(b)}")


def midpoint(ctx, point, line, **_):
    p = _pt(point, "point", ctx)
    s, e = _line(ctx, line, "line")
    return [Equation(p.x - (s.x + e.x) * 0.5), Equation(p.y - (s.y + e.y) * 0.5)]


def on_line(ctx, point, line, **_):
    p = _pt(point, "point", ctx)
    s, e = _directed_line(ctx, line, "line")
    return [Equation(_cross(e.x - s.x, e.y - s.y, p.x - s.x, p.y - s.y) / hypot(e.x - s.x, e.y - s.y))]


def on_circle(ctx, point, circle, **_):
    p = _pt(point, "point", ctx)
    c, r = _circ(ctx, circle, "circle")
    return [Equation(hypot(p.x - c.x, p.y - c.y) - r)]


def on_ellipse(ctx, point, ellipse, **_):
    """``point`` on the ellipse (or elliptic arc's whole ellipse) ``ellipse``, exactly: with
    ``(u, v)`` the point's offset from the center along the two semi-axes (``u`` along
    ``rx``), the residual ``rx (hypot(u / rx, v / ry) - 1)`` is zero exactly on the ellipse
    ``(u / rx)^2 + (v / ry)^2 = 1`` and, for ``rx == ry``, the circle's ``|p - c| - r``; a
    length, with the Jacobian of its expression (exact).  The axes are the held rotation's
    (a mirrored copy's: its mirror line's as solved, ``2 phi - r``; an elliptic arc's: its
    ``vertex`` and ``co_vertex`` points)."""
    p = _pt(point, "point", ctx)
    g = ellipse.geom
    S = ctx.struct
    c = member(g, "center", S)
    dx, dy = p.x - c.x, p.y - c.y
    if g.kind == "EllipticArc":
        rx, ry = g.data["dims"]["rx"], g.data["dims"]["ry"]
        V, W = member(g, "vertex", S), member(g, "co_vertex", S)
        u = (dx * (V.x - c.x) + dy * (V.y - c.y)) * (1.0 / (rx * rx))
        v = (dx * (W.x - c.x) + dy * (W.y - c.y)) * (1.0 / (ry * ry))
        return [Equation((hypot(u, v) - 1.0) * rx)]
    rx = member(g, "rx", S).expr
    ry = member(g, "ry", S).expr
    m = g.data.get("mirror")
    if m is None:
        r = g.data.get("rotation", 0.0)
        cs, sn = math.cos(r), math.sin(r)
        u = dx * cs + dy * sn
        v = dy * cs - dx * sn
    else:       # rotation 2 phi - r0, phi the mirror line's direction as solved
        a, b, r0 = m
        lx, ly = b.x - a.x, b.y - a.y
        L2 = lx * lx + ly * ly
        c2, s2 = (lx * lx - ly * ly) / L2, (lx * ly * 2.0) / L2
        cs = c2 * math.cos(r0) + s2 * math.sin(r0)
        sn = s2 * math.cos(r0) - c2 * math.sin(r0)
        u = dx * cs + dy * sn
        v = dy * cs - dx * sn
    return [Equation((hypot(u / rx, v / ry) - 1.0) * rx)]


def collinear(ctx, a, b, c=None, **_):
    ka, kb = _kind(a), _kind(b)
    if c is not None:
        p, q, r = _pt(a, "a", ctx), _pt(b, "b", ctx), _pt(c, "c", ctx)
        # distance of b from the line through a and c
        # distance of b from the line through a and c (scaled by the starting |c - a|)
        n = max(_val(ctx, hypot(r.x - p.x, r.y - p.y)), 1e-9)
        return [Equation(_cross(r.x - p.x, r.y - p.y, q.x - p.x, q.y - p.y) * (1.0 / n))]
    if ka == kb == "line":
        s, e = _line(ctx, a, "a")
        s2, e2 = _line(ctx, b, "b")
        n = hypot(e.x - s.x, e.y - s.y)
        return [Equation(_cross(e.x - s.x, e.y - s.y, s2.x - s.x, s2.y - s.y) / n),
                Equation(_cross(e.x - s.x, e.y - s.y, e2.x - s.x, e2.y - s.y) / n)]
    raise ConstraintError(f"Collinear takes two lines or three points, "
                          f"got {type_name(a)} and {type_name(b)}")


def _center_of(ctx, v, name: str) -> PV:
    """The center of a shape with a ``center`` member (Circle, Arc, ArcSlot, Ellipse, Star,
    RegularPolygon, Slot, rectangles, ...), or a point itself."""
    if isinstance(v, PV):
        return v
    if isinstance(v, GeomRef):
        c = member(v.geom, "center", ctx.struct)
        if c is not None:
            return c
    raise ConstraintError(f"`{name}` must be a shape with a center or a point, "
                          f"got {type_name(v)}")


def concentric(ctx, a, b, **_):
    c1, c2 = _center_of(ctx, a, "a"), _center_of(ctx, b, "b")
    return [Equation(c1.x - c2.x), Equation(c1.y - c2.y)]


# ------------------------------------------------------------------ structural
def _target(v, name):
    if isinstance(v, StructRef):
        return v.struct
    if isinstance(v, GeomRef):
        return v.geom
    if isinstance(v, BBoxRef):
        return v.target
    raise ConstraintError(f"`{name}` must be a structure or geometry, got {type_name(v)}")


_POINT_AXIS = {"left": "x", "right": "x", "top": "y", "bottom": "y"}


def _bb(ctx, v, side, name):
    t = type(v)
    if t is StructRef:
        target = v.struct
    elif t is GeomRef:
        target = v.geom
    elif t is PV:               # a point of an Align relation: its box is the point itself
        return getattr(v, _POINT_AXIS[side])
    else:
        target = _target(v, name)
    b = _new(BBTerm)                 # BBTerm(target, side, ctx.struct) without __init__
    b.target, b.side, b.frame = target, side, ctx.struct
    return b


def _apart(ctx, far, near, gap) -> list:
    """``far``'s box side less ``near``'s is ``gap`` (0 when not given); each a triple
    ``(value, side, argument name)``: Above, Below, LeftOf, RightOf."""
    g = gap.expr if gap is not None else 0.0
    return [equation(sub(sub(_bb(ctx, *far), _bb(ctx, *near)), g))]


def above(ctx, a, b, gap=None, **_):
    return _apart(ctx, (a, "bottom", "a"), (b, "top", "b"), gap)


def below(ctx, a, b, gap=None, **_):
    return _apart(ctx, (b, "bottom", "b"), (a, "top", "a"), gap)


def left_of(ctx, a, b, gap=None, **_):
    return _apart(ctx, (b, "left", "b"), (a, "right", "a"), gap)


def right_of(ctx, a, b, gap=None, **_):
    return _apart(ctx, (a, "left", "a"), (b, "right", "b"), gap)


def inside(ctx, a, b, margin=None, **_):
    m = margin.expr if margin is not None else 0.0
    A = {s: _bb(ctx, a, s, "a") for s in ("left", "right", "bottom", "top")}
    B = {s: _bb(ctx, b, s, "b") for s in ("left", "right", "bottom", "top")}
    return [Equation(A["left"] - B["left"] - m, True), Equation(B["right"] - A["right"] - m, True),
            Equation(A["bottom"] - B["bottom"] - m, True), Equation(B["top"] - A["top"] - m, True)]


def gap(ctx, a, b, gap, axis="x", **_):
    if axis not in ("x", "y"):
        raise ConstraintError(f'Gap axis must be "x" or "y", not "{axis}"')
    lo, hi = ("left", "right") if axis == "x" else ("bottom", "top")
    # the space between the boxes whichever side each is on: max(lows) - min(highs)
    start = func("max", _bb(ctx, a, lo, "a"), _bb(ctx, b, lo, "b"))
    end = func("min", _bb(ctx, a, hi, "a"), _bb(ctx, b, hi, "b"))
    return [Equation(start - end - gap.expr)]


# shapes whose own center is not their box's (a 5-point star's box centre lies 0.095 x its
# outer radius above its center): a centring relation reads the center, as a maker means it
_OWN_CENTER = ("Star", "RegularPolygon")


def _center(ctx, v, axis, name):
    if type(v) is GeomRef and v.geom.kind in _OWN_CENTER:
        c = member(v.geom, "center", ctx.struct)
        return c.x if axis == "x" else c.y
    lo, hi = ("left", "right") if axis == "x" else ("bottom", "top")
    return mul(add(_bb(ctx, v, lo, name), _bb(ctx, v, hi, name)), 0.5)


def center_inside(ctx, a, b, **_):
    return [equation(sub(_center(ctx, a, "x", "a"), _center(ctx, b, "x", "b"))),
            equation(sub(_center(ctx, a, "y", "a"), _center(ctx, b, "y", "b")))]


def align_center_x(ctx, a, b, **_):
    return [equation(sub(_center(ctx, a, "x", "a"), _center(ctx, b, "x", "b")))]


def align_center_y(ctx, a, b, **_):
    return [equation(sub(_center(ctx, a, "y", "a"), _center(ctx, b, "y", "b")))]


def _align(side):
    def f(ctx, a, b, **_):
        return [equation(sub(_bb(ctx, a, side, "a"), _bb(ctx, b, side, "b")))]
    return f


def _extent(ctx, v, axis, name):
    lo, hi = ("left", "right") if axis == "x" else ("bottom", "top")
    return _bb(ctx, v, hi, name) - _bb(ctx, v, lo, name)


def taller(ctx, a, b, **_):
    return [Equation(_extent(ctx, a, "y", "a") - _extent(ctx, b, "y", "b"), True)]


def wider(ctx, a, b, **_):
    return [Equation(_extent(ctx, a, "x", "a") - _extent(ctx, b, "x", "b"), True)]


BUILDERS = {
    "Coincident": coincident, "Horizontal": horizontal, "Vertical": vertical, "Fixed": fixed,
    "Distance": distance, "HorizontalDistance": horizontal_distance,
    "VerticalDistance": vertical_distance, "At": at, "Length": length, "Radius": radius,
    "Diameter": diameter, "Equal": equal, "Parallel": parallel, "Perpendicular": perpendicular,
    "Tangent": tangent, "Symmetric": symmetric, "Midpoint": midpoint, "OnLine": on_line,
    "OnCircle": on_circle, "Concentric": concentric, "Angle": angle, "Collinear": collinear,
    "Gap": gap,
    "Above": above, "Below": below, "LeftOf": left_of, "RightOf": right_of, "Inside": inside,
    "CenterInside": center_inside, "Taller": taller, "Wider": wider,
    "AlignCenterX": align_center_x, "AlignCenterY": align_center_y,
    "AlignLeft": _align("left"), "AlignRight": _align("right"), "AlignTop": _align("top"),
    "AlignBottom": _align("bottom"),
}

__all__ = ["BUILDERS", "ConstraintError", "evaluate"]
