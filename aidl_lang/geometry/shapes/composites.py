"""The constructors of shapes made from other shapes: ``Offset``, ``Inset``, ``Shell``,
``Hull``, ``Intersect`` (lines clipped to an area), ``Stroke`` (a band along a path): their
arguments checked, the source geometry taken out of the drawing (:func:`_consume`); the shape
itself is made after the solve (:mod:`aidl_lang.geometry.derived`, the booleans' faces).
"""
from __future__ import annotations

import math

from ..core.expr import var
from ..core.model import Geometry
from ..core.values import GeomRef, type_name
from .primitives import PrimitiveError, _const, _positive


def _source(v, what: str) -> Geometry:
    """The shape an Offset, Shell or Hull is made from: geometry with an inside."""
    if not isinstance(v, GeomRef):
        raise PrimitiveError(f"{what} takes shapes (a Circle, Rectangle, Polygon, Slot, ...), "
                             f"got {type_name(v)}")
    g = v.geom
    if g.kind in ("Spline", "Bezier") and what == "Hull":
        raise PrimitiveError(f"{what} of a {g.kind} cannot be exact: the hull of a cubic "
                             f"spline is no cubic spline, and outputs here are exact or "
                             f"refused; hull a Polygon through its points, or arcs, instead")
    if not g.closed or g.kind == "Text":
        raise PrimitiveError(f"{what} takes closed shapes (a Circle, Rectangle, Polygon, "
                             f"Slot, ...)" + (", points, Lines and Arcs" if what == "Hull" else "")
                             + f", not a {g.kind}")
    return g


def _consume(g: Geometry, sources: list) -> None:
    """``g`` is made from ``sources``, which are no longer drawn (construction geometry:
    still solved, shown with ``--show construction``), as OpenSCAD's offset() and hull()
    replace their children."""
    for src in sources:
        src.construction = True
    g.data["sources"] = list(sources)
    g.closed = True


def _join(a) -> str:
    j = a.get("join", "round")
    if j not in ("round", "miter"):
        raise PrimitiveError(f'join must be "round" or "miter", got "{j}"')
    return j


def _flat(v) -> list:
    """``v`` as a flat list of items (lists and tuples in it spread out; one item: a list of
    it): the shapes an ``Offset`` or an ``Intersect`` is given."""
    out, stack = [], [v]
    while stack:
        x = stack.pop(0)
        if isinstance(x, (list, tuple)):
            stack[0:0] = list(x)
        else:
            out.append(x)
    return out


def _build_Offset(ctx, g, a, sign: float = 1.0):
    # a list of shapes: their union offset (run gb: two lobes of a heart inset one by one
    # parted at the point, a V slit 4 mm long; the union inset has one point)
    what = "Offset" if sign > 0 else "Inset"
    srcs = [_source(v, what) for v in _flat(a["shape"])] \
        if isinstance(a["shape"], list) else [_source(a["shape"], what)]
    if not srcs:
        raise PrimitiveError(f"{what} of an empty list: give a shape or a list of shapes")
    g.data["distance"] = sign * _const(ctx, a["distance"], "Offset distance")
    g.data["join"] = _join(a)
    _consume(g, srcs)


def _build_Inset(ctx, g, a):
    g.kind = "Offset"
    _build_Offset(ctx, g, a, -1.0)


def _build_Shell(ctx, g, a):
    src = _source(a["shape"], "Shell")
    t = _const(ctx, a["thickness"], "Shell thickness")
    if t == 0:
        raise PrimitiveError("a Shell needs a non-zero thickness (positive: the wall outside "
                             "the shape; negative: inside it)")
    g.data["thickness"] = t
    g.data["join"] = _join(a)
    _consume(g, [src])


HULL_CURVES = ("Point", "Line", "Arc")     # open geometry a Hull takes as its points


def _build_Hull(ctx, g, a):
    if "shapes" in a:
        v = a["shapes"]
        items = list(v) if isinstance(v, (list, tuple)) else [v]
    else:
        items = [a[f"shape{i}"] for i in range(1, 7) if a.get(f"shape{i}") is not None]
    if not items:
        raise PrimitiveError("Hull needs at least one shape")
    # a Point among them is a corner of the hull (a heart's sharp tip: Hull([lobe, tip])); a
    # Line or an Arc is its points (the arc's circle between its ends: run ed's coat hook, an
    # arc and two points)
    _consume(g, [v.geom if isinstance(v, GeomRef) and v.geom.kind in HULL_CURVES
                 else _source(v, "Hull") for v in items])
    if all(src.kind in ("Point", "Line") for src in g.data["sources"]):
        raise PrimitiveError("Hull of points and lines alone encloses no curve: draw a "
                             "Polygon through them, or add a shape (or an Arc)")


CLIPPED = ("Line", "Arc", "Polyline")       # open curves an Intersect clips


def _build_Intersect(ctx, g, a):
    """What the closed shapes have in common; open curves among them are clipped to it (a
    clip: ``g.data["clip"]``, the open sources, drawn as lines).  Lists are flattened."""
    raw = a["shapes"] if "shapes" in a else \
        [a[f"shape{i}"] for i in range(1, 7) if a.get(f"shape{i}") is not None]
    items = _flat(raw)
    closed, open_ = [], []
    for v in items:
        if not isinstance(v, GeomRef):
            raise PrimitiveError(f"Intersect takes shapes (a Circle, Rectangle, Ellipse, "
                                 f"Polygon, ...) and open Lines, Arcs or Polylines to clip, "
                                 f"got {type_name(v)}")
        src = v.geom
        if src.closed and src.kind != "Text":
            closed.append(src)
        elif src.kind in CLIPPED:
            open_.append(src)
        else:
            raise PrimitiveError(f"Intersect cannot take a {src.kind}: give closed shapes "
                                 f"(their common area) and open Lines, Arcs or Polylines "
                                 f"(clipped to it)")
    if not closed:
        raise PrimitiveError("Intersect needs at least one closed shape: the area to keep "
                             "(e.g. `Intersect(strings, head)` with `head` an Ellipse)")
    if not open_ and len(closed) < 2:
        raise PrimitiveError("Intersect needs two closed shapes (their common area), or open "
                             "Lines, Arcs or Polylines and the closed shape to clip them to")
    _consume(g, open_ + closed)      # (copies remap the sources: see region_of)
    g.closed = not open_


def region_of(g: Geometry) -> tuple[list, list]:
    """An ``Intersect``'s (closed shapes, open curves to clip) from its sources."""
    src = g.data["sources"]
    return [s for s in src if s.closed], [s for s in src if not s.closed]


_STROKE_PATHS = ("Line", "Arc", "Polyline", "Spline", "Bezier")


def _build_Stroke(ctx, g, a):
    """A band of constant width along an open path: the path's Minkowski sum with a disc of
    radius width/2 (round caps), or with the ends cut square (flat caps).  The path is one
    open curve or a list of them that join end to end (in any direction)."""
    v = a["path"]
    items = list(v) if isinstance(v, (list, tuple)) else [v]
    if not items:
        raise PrimitiveError("a Stroke needs a path: a Line, Arc, Polyline, Spline or Bezier, or a "
                             "list of them joined end to end")
    srcs = []
    for it in items:
        if not isinstance(it, GeomRef) or it.geom.kind not in _STROKE_PATHS:
            raise PrimitiveError(f"a Stroke follows a Line, Arc, open Polyline, Spline or Bezier "
                                 f"(or a list of them), got "
                                 f"{it.geom.kind if isinstance(it, GeomRef) else type_name(it)}"
                                 + (": for a band around a closed shape use Shell(shape, "
                                    "width)" if isinstance(it, GeomRef) else ""))
        src = it.geom
        if src.closed:
            raise PrimitiveError(f"a Stroke follows an open path, not a closed {src.kind}: "
                                 f"for a band around a closed shape use Shell(shape, width)")
        srcs.append(src)
    _positive(a["width"], "width", "Stroke")
    w = _const(ctx, a["width"], "Stroke width")
    cap = a.get("cap", "round")
    cap = {"square": "flat", "butt": "flat"}.get(cap, cap)
    if cap not in ("round", "flat"):
        raise PrimitiveError(f'a Stroke\'s cap must be "round" or "flat", not "{cap}"')
    _stroke_chain(ctx, srcs)
    g.data["width"] = w
    g.data["cap"] = cap
    _consume(g, srcs)


def _stroke_ends(ctx, src) -> tuple:
    names = src.data.get("order") or ["start", "end"]
    p, q = src.points[names[0]], src.points[names[-1]]
    return tuple((ctx.value_of(var(pt.ix)), ctx.value_of(var(pt.iy))) for pt in (p, q))


def _stroke_chain(ctx, srcs) -> None:
    """The pieces of a Stroke's path must join end to end (as they start): the first
    gap is named."""
    if len(srcs) < 2:
        return
    ends = [_stroke_ends(ctx, s) for s in srcs]
    tail = None
    for i in range(len(srcs) - 1):
        a, b = ends[i], ends[i + 1]
        cands = [a[1], a[0]] if tail is None else [tail]
        best = min(((math.dist(p, q), q, other) for p in cands for q, other in
                    ((b[0], b[1]), (b[1], b[0]))), key=lambda t: t[0])
        gap, _q, other = best
        scale = max(1.0, *(abs(c) for pt in a + b for c in pt))
        if gap > 1e-6 * scale:
            raise PrimitiveError(f"a Stroke's path pieces {i} and {i + 1} do not join: their "
                                 f"nearest ends are {gap:g} mm apart; start each piece where "
                                 f"the previous one ends (e.g. `start=a.end`)")
        tail = other
