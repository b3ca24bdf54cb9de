"""The corners a ``Fillet(at, ...)`` or ``Chamfer(at, ...)`` names (:func:`chosen`): a point,
two edges, two shapes whose outlines cross (:data:`MEET`, :func:`outline_spec`), a line, a
polygonal shape, or a list of these; the names the messages give them (:func:`_name`).
Raises :class:`.errors.OperationError` for anything else."""
from __future__ import annotations

from .corners import Chosen
from .outline_distance import one_radius
from .errors import OperationError
from ..core.model import Geometry, Structure
from ..core.values import PV, GeomRef, Q


def _name(g: Geometry, S: Structure) -> str:
    """What the source calls ``g`` from ``S`` (`stem.body.right`: a shape's edge by its
    shape's name)."""
    own = g.owner
    where = own.path[len(S.path) + 1:] if own is not S and own.path.startswith(S.path + ".") \
        else ("" if own is S else own.path)
    name = g.name
    if not g.listed:                       # an edge or a spine: a part of a named shape
        for h in own.geometry:
            part = next((k for k, q in h.parts.items() if q is g), None)
            if part is None:                   # a polygon's `edges[i]`
                i = next((i for i, q in enumerate(h.data.get("edges") or ()) if q is g), None)
                part = None if i is None else f"edges[{i}]"
            if part is not None:
                name = f"{h.name}.{part}" if h.name else part
                break
    name = name or g.kind
    return f"{where}.{name}" if where else name


def _sibling_edges(edges: list) -> list:
    """The other named straight edges (``parts``) of the shapes ``edges`` are edges of (a
    Trapezoid's `left` and `right` beside its `top`), for E0408's hint."""
    out = []
    for g in edges:
        for h in g.owner.geometry:
            if any(q is g for q in h.parts.values()):
                out += [q for q in h.parts.values() if getattr(q, "kind", None) == "Line"
                        and all(q is not e for e in edges) and all(q is not o for o in out)]
                break
    return out


# the shapes whose outline `Fillet([a, b], r)` finds where two of them cross (corners.meet)
MEET = ("Circle", "Ellipse", "Slot", "ArcSlot", "Rectangle", "RoundedRectangle", "Polygon",
        "RegularPolygon", "Triangle", "Star", "Trapezoid", "Stroke")
# the paths of a Stroke whose band `Fillet([a, b], r)` finds (its outline: the points half
# its width from them)
STROKE_MEETS = ("Line", "Arc", "Polyline")


def meets(g: Geometry) -> bool:
    """``g``'s outline is one :func:`outline_spec` gives (a Stroke: along Lines, Arcs and
    Polylines only)."""
    return g.kind in MEET and (g.kind != "Stroke" or all(
        src.kind in STROKE_MEETS for src in g.data.get("sources", ())))


def outline_spec(g: Geometry, S) -> tuple:
    """(kind of outline, its points in ``S``'s frame) for :func:`.outline_distance.outline_distance`:
    "circle" (center), "ellipse" (center), "slot" (start, end), "segment" (start, end),
    "rounded" (a RoundedRectangle of one radius: its corners), "rounded_radii" (one of
    several radii: its corners) or "polygon" (its corners, in order: a Star's tips);
    radii are read from the solved unknowns."""
    from ..relations.members import _pv, member, points_of
    k = g.kind
    if k in ("Circle", "Ellipse"):
        return k.lower(), [member(g, "center", S)]
    if k == "Slot":
        return "slot", [member(g, "start", S), member(g, "end", S)]
    if k == "ArcSlot":      # run ab's boomerang: `Fillet([hub, blade.b], 8)`
        return "arcslot", [member(g, k, S) for k in ("center", "start", "end")]
    if k == "Line":
        return "segment", [member(g, "start", S), member(g, "end", S)]
    if k == "Stroke":
        # run he's hair-straightener hooks, `Fillet([horn, body], 4)`: each path piece's
        # points, a Line's ends, a Polyline's corners, an Arc's centre and ends as it is drawn
        # (counter-clockwise from `points["start"]`, which a three-point arc may have swapped)
        pts = []
        for src in g.data["sources"]:
            pts += ([_pv(src.points[n], S) for n in ("center", "start", "end")]
                    if src.kind == "Arc" else [_pv(p, S) for p in points_of(src)]
                    if src.kind == "Polyline" else [member(src, n, S) for n in ("start", "end")])
        return "stroke", pts
    if one_radius(g):
        return "rounded", [_pv(p, S) for p in points_of(g)]
    if g.kind == "RoundedRectangle" and g.data.get("corner_radii"):
        return "rounded_radii", [_pv(p, S) for p in points_of(g)]
    return "polygon", [_pv(p, S) for p in points_of(g)]


def chosen(ctx, v, S, kind: str) -> list:
    """The corners (:class:`~.corners.Chosen`, points in ``S``'s frame) a
    ``Fillet(at, ...)``/``Chamfer(at, ...)`` names: a point; two lines (the corner where they
    meet, found after the solve: at their ends, where they cross, or where one ends on the
    other); a line (both ends); a shape (its outline corners); or a list of these."""
    from ..relations.constraints import _kind
    from ..relations.members import member, points_of
    if isinstance(v, PV):
        return [Chosen("point", (v,), "")]
    if isinstance(v, (tuple, list)) and len(v) == 2 and all(isinstance(c, Q) for c in v):
        return [Chosen("point", (PV(v[0].expr, v[1].expr),), "")]
    if isinstance(v, (list, tuple)):
        if len(v) == 2 and all(isinstance(e, GeomRef) and e.geom.kind == "Line" for e in v):
            ends = tuple(member(e.geom, k, S) for e in v for k in ("start", "end"))
            alts = tuple((_name(q, S), member(q, "start", S), member(q, "end", S))
                         for q in _sibling_edges([e.geom for e in v]))
            return [Chosen("edges", ends, tuple(_name(e.geom, S) for e in v), alts)]
        if len(v) == 2 and all(isinstance(e, GeomRef) and e.geom.closed and meets(e.geom)
                               or isinstance(e, GeomRef) and e.geom.kind == "Line" for e in v):
            # two shapes (or a shape and an edge): the corners where their outlines cross
            specs, pts = [], []
            for e in v:
                spec, ps = outline_spec(e.geom, S)
                specs.append((spec, len(ps)))
                pts += ps
            return [Chosen("shapes_meet", tuple(pts), tuple(_name(e.geom, S) for e in v),
                           curve=tuple(specs) + tuple(e.geom for e in v))]
        odd = [e for e in v if isinstance(e, GeomRef) and e.geom.closed
               and not meets(e.geom)]
        if len(v) == 2 and odd and all(isinstance(e, GeomRef) and (
                e.geom.closed or e.geom.kind == "Line") for e in v):
            # a pair with a shape whose outline is not met (run bk: a Hull; the message
            # named the Ellipse beside it, which alone is no corner)
            g = odd[0].geom
            if g.kind in ("Spline", "Bezier") or g.kind == "Stroke":   # (a band along one)
                # no corner on a spline is rounded exactly (E0407): the point and the whole
                # outline, which this said to give, end there too (run hf's strop paddle)
                raise OperationError(
                    f"{kind} at [a, b]: `{_name(g, S)}` is a {g.kind}"
                    + (" along a Spline or Bezier" if g.kind == "Stroke" else "")
                    + f", and no corner where a "
                    f"spline meets another shape can be rounded exactly (an arc tangent to a "
                    f"cubic ends where the exact output has no piece: E0407), by its point or "
                    f"by `{kind}(r)`: draw that end of the outline with Lines and Arcs (an "
                    f"`Arc` through three points, a `Hull` with a `Circle`), which {kind} "
                    f"rounds, or let the spline itself turn there (a point of it placed near "
                    f"the corner)")
            raise OperationError(
                f"{kind} at [a, b]: the corners where two outlines cross are found for "
                f"{', '.join(k for k in MEET if k != 'Stroke')}, a Stroke along "
                f"{', '.join(STROKE_MEETS)} and lines; `{_name(g, S)}` is "
                f"{'an' if g.kind[0] in 'AEIOU' else 'a'} {g.kind}: give the corner's point "
                f"instead (`{kind}((x, y), r)`), or round every corner of the part "
                f"(`{kind}(r)`)")
        return [c for e in v for c in chosen(ctx, e, S, kind)]
    if isinstance(v, GeomRef):
        g = v.geom
        if g.kind == "Point":
            return [Chosen("point", (member(g, "p", S),), _name(g, S))]
        if g.kind == "Line":
            return [Chosen("ends", (member(g, "start", S), member(g, "end", S)), _name(g, S))]
        pts = points_of(g) if g.closed else []
        if pts and g.kind not in ("Circle", "Ellipse", "Slot"):
            from ..relations.members import _pv
            return [Chosen("corners", tuple(_pv(p, S) for p in pts), _name(g, S))]
    raise OperationError(f"{kind} at: give a point, two edges [a, b] (their corner), two "
                         f"shapes or an edge and a shape [a, b] (where their outlines cross: "
                         f"{', '.join(MEET)}), a line, a polygonal shape, or a list of these; "
                         f"got {_kind(v)}" + (f" (`{_name(v.geom, S)}`, "
                                              f"{'an' if v.geom.kind[0] in 'AEIOU' else 'a'} "
                                              f"{v.geom.kind})" if isinstance(v, GeomRef)
                                              else "")
                         + (f"; for the corner where `{_name(v.geom, S)}` meets an edge, give "
                            f"its point: `{_name(v.geom, S)}.start` or `.end`"
                            if isinstance(v, GeomRef) and v.geom.kind in ("Arc", "Spline",
                                                                          "Bezier") else ""))
