"""Geometry checks on the final shape: warnings about parts that solve but come out wrong.

The booleans (:mod:`.booleans`) record each structure's shape and what each hole cut; these
checks read them (docs/outputs.md, "Checks"; every code is in :mod:`aidl_lang.codes`):

* ``W0501`` a hole partly or wholly refilled by a sibling or ancestor solid (a hole cuts only
  the solid it is declared in; a solid united later fills it again);
* ``W0502`` a hole that cuts nothing (it lies outside its solid);
* ``W0503`` a hole that removes all of its solid;
* ``W0504`` a solid part whose final shape falls apart into separate pieces (assembly parts are
  separate by design and are not checked against each other);
* ``W0505`` engraving (a drawing) outside the material or across a hole;
* ``W0506`` a child solid that adds nothing: it lies wholly inside the rest of its parent (for
  example pattern copies that land inside a filled solid);
* ``W0507`` a wall thinner than ``min_wall`` (default :data:`MIN_WALL`, 0.5 mm): what a
  morphological opening of the part by a disc of that diameter removes (the erosion by
  ``min_wall / 2`` then the dilation back, Manifold offsets with round joins), in pieces of at
  least ``2 min_wall^2`` (so that sharp corners, which every opening rounds, do not count); the
  warning names the holes and the outer edge the wall lies between;
* ``W0402`` an open outline (lines and arcs that do not close), drawn as engraving.

Areas are compared with a tolerance that ignores the chord slivers of tessellated curves:
:data:`MIN_FRACTION` of the feature and at least :data:`MIN_AREA` mm^2.
"""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ..diagnostics import DiagnosticSink, Label
from ..geometry.model import Structure
from .booleans import Drawing

MIN_FRACTION = 0.02      # of a hole's or child's area
MIN_AREA = 0.05          # mm^2
ENGRAVE_TOL = 0.05       # mm: engraving this close to an edge still counts as on the material
MAX_CHILDREN = 64        # W0506 compares each child with the union of the others
MIN_WALL = 0.5           # mm: W0507's default minimum wall


def _area(cs) -> float:
    return 0.0 if cs is None or cs.is_empty() else float(cs.area())


def _union(shapes) -> mf.CrossSection:
    shapes = [s for s in shapes if s is not None and not s.is_empty()]
    return mf.CrossSection.batch_boolean(shapes, mf.OpType.Add) if shapes else mf.CrossSection()


def _significant(a: float, whole: float) -> bool:
    return a > MIN_AREA and a > MIN_FRACTION * whole


def _pct(a: float, whole: float) -> str:
    return f"{100.0 * a / whole:.0f}%" if whole > 0 else "0%"


def _part_roots(d: Drawing) -> dict[Structure, mf.CrossSection]:
    shapes = {}
    for p in d.parts:
        s = d.part_of.get(p.name)
        if s is not None:
            shapes[s] = p.shape
    return shapes


def _part_of(s: Structure, roots) -> Structure | None:
    node = s
    while node is not None:
        if node in roots:
            return node
        node = node.parent
    return None


def _contributors(d: Drawing, a: Structure, skip: Structure | None = None):
    """What a solid ``a`` unites: (name, span, shape) of its own faces and solid children."""
    out = []
    for g, f in d.own.get(a, []):
        out.append((f"`{g.label}`", g.span, f))
    for c in a.children.values():
        if c is skip or c.kind not in ("solid", "hole") or c.kind == "hole":
            continue
        if c in d.shapes:
            out.append((f"solid `{c.path}`", c.span, d.shapes[c]))
    return out


def check_drawing(d: Drawing, sink: DiagnosticSink, min_wall: float = MIN_WALL) -> None:
    """Append the geometry warnings for the booleans' result ``d`` to ``sink``; ``min_wall``
    (mm) is W0507's minimum wall (0 turns that check off)."""
    roots = _part_roots(d)
    for cut in d.cuts:
        _check_hole(d, cut, roots, sink)
    loops = {s: [np.asarray(p, dtype=float) for p in shape.to_polygons()]
             for s, shape in roots.items() if s.kind == "solid"}
    for s, shape in roots.items():
        if s.kind == "solid":
            _check_pieces(d, s, shape, sink, loops[s])
    for s in list(d.shapes):
        if s.kind == "solid":
            _check_invisible(d, s, sink)
    _check_engraving(d, roots, sink, loops)
    if min_wall > 0:
        by_part: dict = {}
        for c in d.cuts:
            by_part.setdefault(_part_of(c.owner, roots), []).append(c)
        for s, shape in roots.items():
            if s.kind == "solid":
                _check_walls(d, s, shape, min_wall, by_part.get(s, []), sink)
    for g in d.open_curves:
        sink.warning("W0402", f"`{g.label}` is not part of a closed outline, so it is drawn as a "
                     "line (engraved), not filled", g.span,
                     hint="share endpoints between lines and arcs so they form a loop, or put "
                          "the curve in a `drawing` structure")


def _check_hole(d: Drawing, cut, roots, sink: DiagnosticSink) -> None:
    h, s = cut.hole, cut.owner
    hole_shape = d.shapes.get(h)
    whole = _area(hole_shape)
    cut_area = _area(cut.region)
    before = _area(cut.before)
    if whole <= 0:
        return
    if cut_area <= max(1e-9, 1e-6 * whole):
        sink.warning("W0502", f"hole `{h.path}` cuts nothing: it lies outside solid `{s.path}`",
                     h.span, hint=f"move the hole inside `{s.path}` (for example "
                                  f"`CenterInside({h.name}, self)`), or declare it in the solid "
                                  "it should cut")
        return
    if before > 0 and _area(d.shapes.get(s)) <= max(1e-9, 1e-6 * before):
        sink.warning("W0503", f"hole `{h.path}` removes all of solid `{s.path}`", h.span,
                     hint=f"make the hole smaller than `{s.path}` or move it so that material "
                          "is left around it")
        return
    part = _part_of(s, roots)
    if part is None:
        return
    final = roots[part]
    refilled = _area(cut.region ^ final)
    if not _significant(refilled, cut_area):
        return
    # who refills it: the other contributors of each ancestor between the owner and the part
    culprits, node = [], s
    while node is not part and node.parent is not None:
        a = node.parent
        for name, span, shp in _contributors(d, a, skip=node):
            if _significant(_area(cut.region ^ shp), cut_area):
                culprits.append((name, span, a))
        if node.parent is part:
            break
        node = a
    survives = max(0.0, cut_area - refilled)
    who = ", ".join(c[0] for c in culprits[:3]) or "a solid united later"
    common = culprits[0][2] if culprits else part
    labels = [Label(span, "refills the hole", primary=False)
              for _, span, _ in culprits[:3] if span is not None]
    sink.warning(
        "W0501",
        f"hole `{h.path}` is refilled by {who}: only {_pct(survives, cut_area)} of it still "
        f"cuts through",
        h.span, labels=labels,
        hint=(f"a hole cuts only the solid it is declared in (`{s.path}`); declare the hole in "
              f"`{common.path}`, the common parent, so that it cuts everything united there, "
              "or move it clear of the solid that covers it"))


def _check_pieces(d: Drawing, s: Structure, shape, sink: DiagnosticSink,
                  loops: list | None = None) -> None:
    """W0504 for part ``s``.  A shape has one piece per outline loop that runs
    counter-clockwise (an outer boundary; holes run clockwise), so a shape with at most one
    such loop (``loops``: its polygons, when already at hand) is not split into pieces."""
    if shape.is_empty():
        return
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    if sum(_signed(p) > 0 for p in loops) < 2:
        return
    total = _area(shape)
    pieces = [p for p in shape.decompose() if _area(p) > max(1e-9, 1e-6 * total)]
    if len(pieces) < 2:
        return
    items = _contributors(d, s)
    groups = []
    for p in pieces:
        names = [n for n, _, shp in items if _area(p ^ shp) > max(1e-9, 1e-6 * _area(shp))]
        groups.append("{" + ", ".join(names[:4]) + (", ..." if len(names) > 4 else "") + "}")
    sink.warning(
        "W0504",
        f"solid `{s.path}` falls apart into {len(pieces)} separate pieces: "
        + "; ".join(groups[:6]) + ("; ..." if len(groups) > 6 else ""),
        s.span,
        hint="make the pieces overlap (for example `Above(a, b, gap=-1 mm)`) or share an edge "
             "(touching at a point is not enough), or, if they are separate parts, make the "
             "structure an `assembly`")


def _check_invisible(d: Drawing, s: Structure, sink: DiagnosticSink, quick: bool = True) -> None:
    """W0506 for the solid children of ``s`` that add nothing to it.  ``quick=False``
    measures every child (the reference for the area bound's test)."""
    items = _contributors(d, s)
    if len(items) < 2 or len(items) > MAX_CHILDREN:
        return
    areas = [_area(shp) for _, _, shp in items]
    total = sum(areas)
    for i, (name, span, shp) in enumerate(items):
        if not name.startswith("solid "):
            continue
        a = areas[i]
        if a <= MIN_AREA:
            continue
        # The others cover at most the sum of their areas, so at least `a - rest` of this
        # child shows; when that is far above the threshold (1e-6 of the areas: orders of
        # magnitude above Manifold's rounding) it is not measured.
        rest = total - a
        if quick and a - rest > max(1e-9, 1e-4 * a) + 1e-6 * (a + rest) + 1e-6:
            continue
        others = _union([o for j, (_, _, o) in enumerate(items) if j != i])
        if _area(shp - others) <= max(1e-9, 1e-4 * a):
            sink.warning("W0506", f"{name} adds nothing to `{s.path}`: it lies wholly inside "
                         "the rest of it", span,
                         hint="move it where it shows (it is probably mispositioned), make it a "
                              "`hole` if it should cut, or delete it")


def _check_walls(d: Drawing, s: Structure, shape, t: float, cuts, sink: DiagnosticSink,
                 quick: bool = True) -> None:
    """W0507 for part ``s`` (its final ``shape``, its ``cuts``) at minimum wall ``t`` mm: one
    warning per piece of at least ``2 t^2`` that the opening removes.  ``quick=False`` skips
    the whole-area bound below (the reference for its test)."""
    if shape.is_empty():
        return
    segs = 16
    opened = shape.offset(-t / 2, mf.JoinType.Round, 2.0, segs).offset(t / 2, mf.JoinType.Round,
                                                                       2.0, segs)
    thin = shape - opened
    if thin.is_empty():
        return
    # The pieces below partition `thin`, so none reaches 2 t^2 when the whole does not (the
    # same polygon areas summed in another order: the margin is far above the rounding).  On
    # a part without thin walls the opening removes only corner slivers (the telephone: 391
    # of them, 0.1 mm^2 in all against 0.5 mm^2), which are then neither split nor measured.
    if quick and _area(thin) < 2 * t * t * (1 - 1e-9):
        return
    holes = [c for c in cuts if c.hole in d.shapes]
    filled = None
    for piece in thin.decompose():
        a = _area(piece)
        if a < 2 * t * t:
            continue
        if filled is None:
            filled = _union([shape] + [d.shapes[c.hole] for c in holes])
        near = piece.offset(t, mf.JoinType.Round, 2.0, segs)
        names = [f"hole `{c.hole.path}`" for c in holes
                 if _area(near ^ d.shapes[c.hole]) > 1e-9]
        if _area(near - filled) > 1e-9:
            names.append(f"the outer edge of `{s.path}`")
        names = list(dict.fromkeys(names))
        x0, y0, x1, y1 = piece.bounds()
        length = max(x1 - x0, y1 - y0, 1e-9)
        width = min(t, a / length)
        between = (" between " + " and ".join(names[:2])) if len(names) >= 2 else (
            f" beside {names[0]}" if names else "")
        span = next((c.hole.span for c in holes if f"hole `{c.hole.path}`" in names), s.span)
        sink.warning("W0507", f"a wall of `{s.path}`{between} is thinner than {t:g} mm "
                     f"(about {width:.2f} mm over {length:.1f} mm, near "
                     f"({(x0 + x1) / 2:.1f}, {(y0 + y1) / 2:.1f}))", span,
                     hint=f"move or shrink the feature so that at least {t:g} mm of material is "
                          "left (a laser or router cannot hold a thinner wall); the minimum is "
                          "set with --min-wall")


def _inside_loops(pts: np.ndarray, loops) -> np.ndarray:
    """The reference even-odd test: every point against every edge of each loop in turn
    (O(points x edges) memory and time).  Kept for the property test of :func:`_inside`."""
    res = np.zeros(len(pts), dtype=bool)
    x, y = pts[:, 0], pts[:, 1]
    for lp in loops:
        P = np.asarray(lp, dtype=float)
        Q = np.roll(P, -1, axis=0)
        x1, y1, x2, y2 = P[:, 0][None], P[:, 1][None], Q[:, 0][None], Q[:, 1][None]
        yy = y[:, None]
        cond = (y1 > yy) != (y2 > yy)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            xi = x1 + (yy - y1) * (x2 - x1) / (y2 - y1)
        res ^= (np.sum(cond & (x[:, None] < xi), axis=1) % 2).astype(bool)
    return res


def _inside(pts: np.ndarray, loops) -> np.ndarray:
    """Even-odd point-in-polygon of ``pts`` (N x 2, mm) against the union of closed ``loops``
    (each M x 2, implicitly closed; or their :func:`_edges`): True where a ray to -x crosses the loops' edges an odd
    number of times (the crossing-number test, as in W. R. Franklin's ``pnpoly``).

    The edges of all loops are taken together (the parity of the total equals the XOR of the
    per-loop parities) and each edge is tested only against the points whose y lies in its
    half-open y range ``[min(y1, y2), max(y1, y2))``, found by binary search in the points
    sorted by y; so the work is O((N + E) log N + crossings-candidates), not O(N E).  The
    crossing abscissa is computed with the same floating-point expression as the reference
    :func:`_inside_loops`, so the result is identical to it."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 2)
    n = len(pts)
    x1, y1, x2, y2 = loops if isinstance(loops, tuple) else _edges(loops)
    if not n or not len(x1):
        return np.zeros(n, dtype=bool)
    x, y = pts[:, 0], pts[:, 1]
    order = np.argsort(y, kind="stable")
    ys = y[order]
    lo = np.searchsorted(ys, np.minimum(y1, y2), side="left")
    hi = np.searchsorted(ys, np.maximum(y1, y2), side="left")
    cnt = np.maximum(hi - lo, 0)
    total = int(cnt.sum())
    if not total:
        return np.zeros(n, dtype=bool)
    edge = np.repeat(np.arange(len(x1)), cnt)
    start = np.cumsum(cnt) - cnt
    pt = order[lo[edge] + (np.arange(total) - start[edge])]
    yy, ex1, ey1, ex2, ey2 = y[pt], x1[edge], y1[edge], x2[edge], y2[edge]
    cond = (ey1 > yy) != (ey2 > yy)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        xi = ex1 + (yy - ey1) * (ex2 - ex1) / (ey2 - ey1)
    hit = cond & (x[pt] < xi)
    return (np.bincount(pt[hit], minlength=n) % 2).astype(bool)


def _edges(loops) -> tuple:
    """The edges of closed ``loops`` as four arrays (x1, y1, x2, y2): each vertex to the next,
    the last back to the first; what :func:`_inside` takes (prepared once per part)."""
    polys = [np.asarray(lp, dtype=float).reshape(-1, 2) for lp in loops]
    polys = [P for P in polys if len(P)]
    if not polys:
        return (np.zeros(0),) * 4
    P = np.concatenate(polys)
    Q = np.concatenate([np.concatenate([p[1:], p[:1]]) for p in polys])   # np.roll(p, -1)
    return P[:, 0], P[:, 1], Q[:, 0], Q[:, 1]


_T9 = np.linspace(0, 1, 9)[:, None]


def _sample(item) -> np.ndarray:
    kind = item[0]
    if kind == "line":
        p, q = np.asarray(item[1], float), np.asarray(item[2], float)
        return p + _T9 * (q - p)
    if kind == "poly":
        P = np.asarray(item[1], float)
        return np.vstack([P, (P + np.roll(P, -1, axis=0)) / 2])
    if kind == "circle":
        c, r = np.asarray(item[1], float), float(item[2])
        t = np.linspace(0, 2 * math.pi, 32, endpoint=False)
        return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])
    _, c, r, a1, a2 = item
    sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
    t = a1 + np.linspace(0, sweep, 17)
    return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])


def _n_samples(item) -> int:
    """How many points :func:`_sample` gives for ``item``."""
    kind = item[0]
    if kind == "poly":
        return 2 * len(item[1])
    return {"line": 9, "circle": 32}.get(kind, 17)


_T32 = np.linspace(0, 2 * math.pi, 32, endpoint=False)
_COS32, _SIN32 = np.cos(_T32), np.sin(_T32)


def _samples(items) -> np.ndarray:
    """The sample points of engraving ``items``, in order: :func:`_sample` of each, with the
    runs of lines and of circles each taken as one array operation (the same floating-point
    operations per point)."""
    out, run, kind = [], [], None

    def flush():
        if kind == "line":
            L = np.asarray(run, dtype=float)             # k x 2 x 2
            p, q = L[:, 0][:, None, :], L[:, 1][:, None, :]
            out.append((p + _T9[None] * (q - p)).reshape(-1, 2))
        elif kind == "circle":
            C = np.asarray([c for c, _ in run], dtype=float)    # k x 2
            R = np.asarray([r for _, r in run], dtype=float)[:, None]
            xy = np.empty((len(run), 32, 2))
            xy[:, :, 0] = C[:, :1] + R * _COS32
            xy[:, :, 1] = C[:, 1:] + R * _SIN32
            out.append(xy.reshape(-1, 2))
        run.clear()
    for it in items:
        k = it[0]
        if k != kind and run:
            flush()
        if k == "line":
            run.append((it[1], it[2]))
        elif k == "circle":
            run.append((it[1], float(it[2])))
        else:
            out.append(_sample(it))
        kind = k if k in ("line", "circle") else None
    if run:
        flush()
    return np.vstack(out)


# Manifold's round offset puts its arc vertices on the circle (Clipper2's round joins, arc
# tolerance r (1 - cos(pi / segments)) with 16 segments), so the part grown by ENGRAVE_TOL
# holds every point within ENGRAVE_TOL cos(pi / 16) of the part, less the 1e-8 mm grid
_SURELY_GROWN = ENGRAVE_TOL * math.cos(math.pi / 16) - 1e-6


def _all_on_material(shape, pts: np.ndarray, loops: list | None = None) -> bool:
    """True when every point of ``pts`` is certainly inside ``shape`` grown by
    :data:`ENGRAVE_TOL` (what W0505 tests), without growing it: each point is inside the
    outline itself or within :data:`_SURELY_GROWN` of one of its edges.  False means "not
    shown": the grown outline then decides (engraving drawn on the edge is the usual case
    the outline alone cannot settle).  ``loops``: the shape's polygons, when at hand."""
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    edges = _edges(loops)
    out = ~_inside(pts, edges)
    if not out.any():
        return True
    return bool(_within(pts[out], edges, _SURELY_GROWN).all())


def _within(pts: np.ndarray, edges: tuple, dist: float, max_pairs: int = 2_000_000) -> np.ndarray:
    """True where a point of ``pts`` (N x 2) lies within ``dist`` of one of the segments
    ``edges`` (x1, y1, x2, y2 arrays).  Each segment is measured only against the points
    whose y lies within ``dist`` of its y range (binary search in the points sorted by y).
    All False when more than ``max_pairs`` pairs would be measured."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 2)
    n = len(pts)
    x1, y1, x2, y2 = edges
    res = np.zeros(n, dtype=bool)
    if not n or not len(x1):
        return res
    x, y = pts[:, 0], pts[:, 1]
    order = np.argsort(y, kind="stable")
    ys = y[order]
    lo = np.searchsorted(ys, np.minimum(y1, y2) - dist, side="left")
    hi = np.searchsorted(ys, np.maximum(y1, y2) + dist, side="right")
    cnt = np.maximum(hi - lo, 0)
    total = int(cnt.sum())
    if not total or total > max_pairs:
        return res
    edge = np.repeat(np.arange(len(x1)), cnt)
    start = np.cumsum(cnt) - cnt
    pt = order[lo[edge] + (np.arange(total) - start[edge])]
    ax, ay = x1[edge], y1[edge]
    dx, dy = x2[edge] - ax, y2[edge] - ay
    px, py = x[pt] - ax, y[pt] - ay
    L2 = dx * dx + dy * dy
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, (px * dx + py * dy) / L2, 0.0), 0.0, 1.0)
    ex, ey = px - t * dx, py - t * dy
    res[pt[ex * ex + ey * ey <= dist * dist]] = True
    return res


def _check_engraving(d: Drawing, roots, sink: DiagnosticSink, loops: dict | None = None) -> None:
    """W0505 for each engraved geometry with sample points off its part's material (the part
    grown by :data:`ENGRAVE_TOL`).  The points of all the geometries of one part are tested
    in one :func:`_inside` call (a point's verdict does not depend on the other points), and
    a part whose points are all certainly on it (:func:`_all_on_material`) is not grown."""
    by_geom: dict = {}
    for style, item, g in d.strokes:
        if style == "drawing" and g is not None:
            by_geom.setdefault(g, []).append(item)
    by_part: dict = {}
    for g, items in by_geom.items():
        part = _part_of(g.owner, roots)
        if part is None or part.kind != "solid" or roots[part].is_empty():
            continue
        by_part.setdefault(part, []).append((g, items))
    verdicts: dict = {}
    for part, geoms in by_part.items():
        shp = roots[part]
        pts = _samples([it for _, items in geoms for it in items])
        if _all_on_material(shp, pts, (loops or {}).get(part)):
            continue
        grown = shp.offset(ENGRAVE_TOL, mf.JoinType.Round, 2.0, 16)
        grown_loops = [np.asarray(p, dtype=float) for p in grown.to_polygons()]
        inside = _inside(pts, _edges(grown_loops))
        at = 0
        for g, items in geoms:
            n = sum(_n_samples(it) for it in items)
            verdicts[g] = (part, pts[at:at + n], inside[at:at + n], grown_loops)
            at += n
    outer_of: dict = {}
    for g in by_geom:
        if g not in verdicts:
            continue
        part, pts, inside, grown_loops = verdicts[g]
        if inside.all():
            continue
        if part not in outer_of:
            outer_of[part] = _edges([p for p in grown_loops if _signed(p) > 0])
        in_outline = _inside(pts[~inside], outer_of[part])
        where = "across a hole" if in_outline.all() else (
            "outside the outline" if not in_outline.any() else "outside the outline and across a hole")
        sink.warning("W0505", f"engraving `{g.label}` runs {where} of `{part.path}` "
                     f"({_pct(float((~inside).sum()), float(len(pts)))} of it is off the material)",
                     g.span,
                     hint="move or shrink the drawing so that it lies on the material (constrain "
                          "it, e.g. `Inside(label, body)`), or clear the hole it crosses")


def _signed(poly) -> float:
    P = np.asarray(poly, dtype=float)
    x, y = P[:, 0], P[:, 1]
    return 0.5 * float(np.dot(x, np.concatenate([y[1:], y[:1]]))       # np.roll(y, -1)
                       - np.dot(y, np.concatenate([x[1:], x[:1]])))
