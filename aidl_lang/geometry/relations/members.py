"""Members of geometry: what ``rect.top_left``, ``line.midpoint``, ``poly.centroid`` ... are.

In: a shape (:class:`~.model.Geometry`, built by :mod:`.primitives`), a member's name and the
structure it is read from.  Out: its value, an expression of the solver's unknowns seen from
that structure's frame (:class:`~.values.PV` for a point, :class:`~.values.Q` with its unit for
a length or angle, a :class:`~.values.GeomRef` or a list of them for parts), so a constraint
on it follows the solved shape.  The members each kind lists are the registry's
(``ENTRIES[kind].members``, :mod:`aidl_lang.registry`; docs/language.md section 3).
"""
from __future__ import annotations

import math

from ..core.expr import Lin, _new, func, hypot, var
from ..core.model import Geometry
from ..core.values import ANG, LEN, PV, GeomRef, Q

def _pv(p, frame) -> PV:
    o = p.owner
    if o is frame:                     # Point.in_frame's common case, inline
        x = _new(Lin)
        x.terms = {p.ix: 1.0}
        x.const = 0.0
        y = _new(Lin)
        y.terms = {p.iy: 1.0}
        y.const = 0.0
    else:
        x, y = p.in_frame(frame)
    v = _new(PV)                       # PV(x, y, p, owners) without __init__
    v.x = x
    v.y = y
    v.obj = p
    v.owners = o._own or o.owner_set()
    return v


def points_of(g: Geometry) -> list:
    """The outline points of a closed polygonal shape, in order."""
    if g.kind in ("Rectangle", "RoundedRectangle"):
        return [g.points[n] for n in ("bottom_left", "bottom_right", "top_right", "top_left")]
    order = g.data.get("order")
    if order:
        return [g.points[n] for n in order]
    return list(g.points.values())


_REGULAR = ("side", "across_flats", "apothem")
# shapes whose points are numbered `p0`, `p1`, ... inside (their members are `points[i]`)
_NUMBERED = ("Polygon", "RegularPolygon", "Star", "Spline", "Polyline", "Bezier")


def _sizes(g: Geometry, name: str, own, frame):
    """An Offset's or Shell's ``center``: its shape's (run cn: a ring, `Shell(Circle(...),
    3)`, in `Concentric` was E0108 "got Shell"; None for a shape with none, the interpreter
    gives its box's).  A RegularPolygon's ``side``, ``across_flats`` or ``apothem`` (center
    to a side's middle), mm, from its radius (center to a vertex) and its number of sides:
    the sizes its other forms take (issue 111, run ck: `hex.side` was E0102)."""
    if g.kind != "RegularPolygon":
        srcs = g.data.get("sources") or []
        # (of several shapes, `Inset([a, b], d)`, none is its shape: its box's centre)
        return member(srcs[0], name, frame) if len(srcs) == 1 else None
    half = math.pi / len(points_of(g))
    f = {"side": 2 * math.sin(half), "across_flats": 2 * math.cos(half),
         "apothem": math.cos(half)}[name]
    return Q(var(g.scalars["radius"].index) * f, LEN, own)


def member(g: Geometry, name: str, frame):
    """Value of ``g.name`` seen from structure ``frame``; None if there is no such member."""
    k = g.kind
    if k == "Arc" and name in g.data.get("named_ends", ()):   # a clockwise Arc(start,
        return _pv(g.data["named_ends"][name], frame)          # through, end): as named
    if name in g.points and not (k in _NUMBERED and name[:1] == "p" and name[1:].isdigit()):
        return _pv(g.points[name], frame)
    own = g.owner.owner_set()
    if name in g.parts:
        return GeomRef(g.parts[name])
    if name in g.scalars:
        return Q(var(g.scalars[name].index), LEN, own)
    if k == "Point" and name in ("x", "y"):
        pv = _pv(g.points["p"], frame)
        return Q(pv.x if name == "x" else pv.y, LEN, own)
    if name == "diameter" and "radius" in g.scalars:
        return Q(var(g.scalars["radius"].index) * 2.0, LEN, own)
    if k in ("Line",) or (k == "Slot" and name in ("length", "spine")):
        s, e = _pv(g.points["start"], frame), _pv(g.points["end"], frame)
        if name == "midpoint" or (k == "Slot" and name == "center"):
            return PV((s.x + e.x) * 0.5, (s.y + e.y) * 0.5, None, own)
        if name == "length":
            L = hypot(e.x - s.x, e.y - s.y)
            if k == "Slot":
                L = L + var(g.scalars["radius"].index) * 2.0
            return Q(L, LEN, own)
        if name == "dx":
            return Q(e.x - s.x, LEN, own)
        if name == "dy":
            return Q(e.y - s.y, LEN, own)
        if name == "angle":
            return Q(func("atan2", e.y - s.y, e.x - s.x), ANG, own)
        if name == "spine":
            ln = Geometry("Line", g.owner, g.span, points=dict(g.points), construction=True)
            return GeomRef(ln)
    if k == "Slot":
        if name == "center":
            s, e = _pv(g.points["start"], frame), _pv(g.points["end"], frame)
            return PV((s.x + e.x) * 0.5, (s.y + e.y) * 0.5, None, own)
        if name == "width":
            return Q(var(g.scalars["radius"].index) * 2.0, LEN, own)
    if k == "Circle":
        c = _pv(g.points["center"], frame)
        r = var(g.scalars["radius"].index)
        off = {"top": (0, 1), "bottom": (0, -1), "left": (-1, 0), "right": (1, 0)}
        if name in off:
            dx, dy = off[name]
            return PV(c.x + r * dx, c.y + r * dy, None, own)
    if k == "Arc":
        c, s = g.points["center"], g.points["start"]
        r = hypot(var(s.ix) - var(c.ix), var(s.iy) - var(c.iy))
        if name == "radius":
            return Q(r, LEN, own)
        if name == "diameter":
            return Q(r * 2.0, LEN, own)
        if name == "midpoint":
            # point on the arc halfway between start and end (counter-clockwise)
            cc, ss, ee = (_pv(g.points[n], frame) for n in ("center", "start", "end"))
            a1 = func("atan2", ss.y - cc.y, ss.x - cc.x)
            # the counter-clockwise sweep from start to end, in (0, 2pi] as the drawn arc's
            # (outlines._arc_through): pi + atan2(-cross, -dot) (atan2(cross, dot) is the
            # short way round, clockwise for an arc of more than a half turn: issue 109)
            cross = (ss.x - cc.x) * (ee.y - cc.y) - (ss.y - cc.y) * (ee.x - cc.x)
            dot = (ss.x - cc.x) * (ee.x - cc.x) + (ss.y - cc.y) * (ee.y - cc.y)
            mid = a1 + func("atan2", cross * -1.0, dot * -1.0) * 0.5 + math.pi / 2
            return PV(cc.x + r * func("cos", mid), cc.y + r * func("sin", mid), None, own)
    if k in ("Rectangle", "RoundedRectangle"):
        if name == "center":
            bl, tr = _pv(g.points["bottom_left"], frame), _pv(g.points["top_right"], frame)
            return PV((bl.x + tr.x) * 0.5, (bl.y + tr.y) * 0.5, None, own)
        if name == "corner_radius" and "corner_radius" in g.data:
            return Q.num(g.data["corner_radius"], LEN)
        if name == "corners":
            return [_pv(p, frame) for p in points_of(g)]
    if k in ("Star", "ArcSlot", "Sector") and name in g.data["dims"]:
        return Q.num(g.data["dims"][name], LEN)
    if k == "Trapezoid":
        if name in g.data["dims"]:
            return Q.num(g.data["dims"][name], LEN)
        if name in ("points", "vertices", "corners"):
            return [_pv(p, frame) for p in points_of(g)]
        if name == "edges":
            return [GeomRef(e) for e in g.data["edges"]]
    if k == "Ellipse" and name in ("rx", "ry"):
        return Q(var(g.scalars[name].index), LEN, own)
    if (k in ("Offset", "Shell") and name == "center") or (
            k == "RegularPolygon" and name in _REGULAR and "radius" in g.scalars):
        return _sizes(g, name, own, frame)
    if k in ("Polygon", "RegularPolygon", "Triangle", "Star"):
        pts = points_of(g) if k != "Triangle" else [g.points[n] for n in ("a", "b", "c")]
        if name in ("points", "vertices", "corners"):
            return [_pv(p, frame) for p in pts]
        if name == "edges":
            edges = g.data.get("edges") or [g.parts[n] for n in ("ab", "bc", "ca")]
            return [GeomRef(e) for e in edges]
        if name == "center":
            if "center" in g.points:
                return _pv(g.points["center"], frame)
            pvs = [_pv(p, frame) for p in pts]
            n = float(len(pvs))
            sx = sum((p.x for p in pvs[1:]), pvs[0].x) * (1.0 / n)
            sy = sum((p.y for p in pvs[1:]), pvs[0].y) * (1.0 / n)
            return PV(sx, sy, None, own)
        if name == "centroid":
            return _centroid([_pv(p, frame) for p in pts], own)
        if k == "Triangle" and name in ("incenter", "inradius"):
            return _incircle([_pv(p, frame) for p in pts], name, own)
        if k == "Triangle" and name in ("base", "height"):     # run ac's obelisk
            a, b, c = (_pv(p, frame) for p in pts)
            ab = hypot(b.x - a.x, b.y - a.y)
            if name == "base":
                return Q(ab, LEN, own)
            cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
            return Q(func("abs", cross) / ab, LEN, own)
    if k == "Polyline" and name == "edges":
        return [GeomRef(e) for e in g.data["edges"]]
    if k in ("Spline", "Polyline", "Bezier"):
        pts = points_of(g)
        if k == "Bezier" and g.closed:
            pts = pts + pts[:1]             # as written: the last point repeats the first
        if name in ("points", "vertices", "through"):
            return [_pv(p, frame) for p in pts]
        if name == "start":
            return _pv(pts[0], frame)
        if name == "end":
            return _pv(pts[-1 if not g.closed else 0], frame)
    if k == "Drawing2D":
        if name == "circles":            # made when first named (drawing2d.build)
            from ..shapes.drawing2d import drawing_circles
            return [GeomRef(e) for e in drawing_circles(g)]
        if name == "outlines":
            return [GeomRef(e) for e in g.data.get(name, [])]
        if name == "paths":
            return [GeomRef(e) for e in g.data.get("path_parts", [])]
        if name == "origin":
            return _pv(g.points["origin"], frame)
    if k == "Text" and name == "size":
        return Q.num(g.data["size"], LEN)
    if k == "Text" and name == "text":            # what it reads (run aa's sundial asserts)
        return g.data["text"]
    if k == "Text" and name == "center" and g.data.get("stencil"):
        # the middle of its box: the letters' openings as drawn (bbox: bridges cut)
        from .bbox import BBTerm
        lo, hi, bo, to = (BBTerm(g, s, frame) for s in ("left", "right", "bottom", "top"))
        return PV((lo + hi) * 0.5, (bo + to) * 0.5, None, own)
    if k == "Text" and name == "center":          # the middle of the strokes' box
        p = _pv(g.points["position"], frame)
        x0, x1, y0, y1 = g.data.get("extent", (0.0, 0.0, 0.0, 0.0))
        return PV(p.x + (x0 + x1) / 2, p.y + (y0 + y1) / 2, None, own)
    return None


def _incircle(pvs: list, name: str, own):
    """A triangle's inscribed circle, exactly, as expressions of its vertices ``a, b, c``:
    ``incenter`` the mean of the vertices weighted by the lengths of the sides opposite them,
    ``(|bc| a + |ca| b + |ab| c) / (|ab| + |bc| + |ca|)`` (a point), ``inradius`` twice the
    area over the perimeter, ``|(b - a) x (c - a)| / (|ab| + |bc| + |ca|)`` (a length)."""
    a, b, c = pvs
    la, lb, lc = (hypot(c.x - b.x, c.y - b.y), hypot(a.x - c.x, a.y - c.y),
                  hypot(b.x - a.x, b.y - a.y))
    per = la + lb + lc
    if name == "inradius":
        cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
        return Q(func("abs", cross) / per, LEN, own)
    return PV((a.x * la + b.x * lb + c.x * lc) / per, (a.y * la + b.y * lb + c.y * lc) / per,
              None, own)


def _centroid(pvs: list, own) -> PV:
    """The area centroid of the closed polygon through ``pvs`` (point values), exactly: the
    shoelace sums relative to the first vertex, ``c = p0 + sum((q_i + q_i+1) x_i) / (6 A)``
    with ``x_i = q_i x q_i+1`` and ``A = sum(x_i) / 2`` (``q_i = p_i - p0``); for a triangle
    the mean of its vertices.  Expressions of the vertices, so it follows a solved shape."""
    if len(pvs) == 3:
        a, b, c = pvs
        return PV((a.x + b.x + c.x) * (1.0 / 3.0), (a.y + b.y + c.y) * (1.0 / 3.0), None, own)
    p0 = pvs[0]
    q = [(p.x - p0.x, p.y - p0.y) for p in pvs[1:]]
    area2 = sx = sy = None
    for (x1, y1), (x2, y2) in zip(q, q[1:]):
        cr = x1 * y2 - x2 * y1
        area2 = cr if area2 is None else area2 + cr
        tx, ty = (x1 + x2) * cr, (y1 + y2) * cr
        sx = tx if sx is None else sx + tx
        sy = ty if sy is None else sy + ty
    return PV(p0.x + sx / (area2 * 3.0), p0.y + sy / (area2 * 3.0), None, own)


def member_names(g: Geometry) -> list[str]:
    from ...registry import ENTRIES
    names = set(ENTRIES[g.kind].members) if g.kind in ENTRIES else set()
    names |= set(g.points) | set(g.parts) | set(g.scalars)
    return sorted(n for n in names if not (n[:1] == "p" and n[1:].isdigit()))
