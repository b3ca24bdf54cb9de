"""Engraving (the strokes of ``drawing`` structures) against the material it is drawn on:

* ``W0505`` engraving outside the material or across a hole (the part grown by
  :data:`ENGRAVE_TOL`);
* ``W0516`` an engraved mark that runs along the cut edge (the laser engraves over the cut,
  so it is not seen).

Also the sample points of engraving items (:func:`_sample`, :func:`_samples`), which the text
check (:mod:`.text`) measures marks with."""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ...diagnostics import DiagnosticSink
from ..booleans import Drawing
from .common import _edges, _inside, _part_of, _pct, _signed

ENGRAVE_TOL = 0.05       # mm: engraving this close to an edge still counts as on the material


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
    if kind == "ellipse_arc":            # 17 points along it
        arc = item[1]
        return np.array([arc.at(arc.start_param + arc.sweep * i / 16) for i in range(17)])
    if kind == "spline":                 # 9 points along each span
        from ...geometry.spline import bez_at
        return np.array([bez_at(b, float(t)) for b in item[1].spans for t in _T9[:, 0]])
    _, c, r, a1, a2 = item
    sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
    t = a1 + np.linspace(0, sweep, 17)
    return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])


def _n_samples(item) -> int:
    """How many points :func:`_sample` gives for ``item``."""
    kind = item[0]
    if kind == "poly":
        return 2 * len(item[1])
    if kind == "spline":
        return 9 * len(item[1].spans)
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
    ymin, ymax = np.minimum(y1, y2), np.maximum(y1, y2)
    # the window is wider than ``dist`` by a few units in the last place, so that a point
    # which the distance below rounds to exactly ``dist`` is never filtered out first
    pad = dist + 8 * np.finfo(float).eps * (np.abs(ymin) + np.abs(ymax) + dist)
    lo = np.searchsorted(ys, ymin - pad, side="left")
    hi = np.searchsorted(ys, ymax + pad, side="right")
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
        _check_on_cut(part, shp, geoms, pts, (loops or {}).get(part), sink)
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


ON_CUT = 1 / 3           # of an engraving's samples: more on the outline is engraved over the cut


def _check_on_cut(part, shape, geoms, pts: np.ndarray, loops, sink) -> None:
    """W0516 for each engraved geometry of ``part`` of which more than :data:`ON_CUT` of the
    sample points (at least 3) lie within :data:`ENGRAVE_TOL` of the part's outline: a mark
    drawn along the cut edge (a protractor's 0 and 180 deg ticks on its straight edge), which
    the laser engraves over the cut, so it is not seen.  ``pts``: the samples of ``geoms`` in
    order (:func:`_samples`)."""
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    on = _within(pts, _edges(loops), ENGRAVE_TOL)
    if not on.any():
        return
    at = 0
    for g, items in geoms:
        n = sum(_n_samples(it) for it in items)
        k = int(on[at:at + n].sum())
        at += n
        if k < 3 or k <= ON_CUT * n:
            continue
        sink.warning("W0516", f"engraving `{g.label}` runs along the cut edge of `{part.path}` "
                     f"({_pct(float(k), float(n))} of it lies on the outline): the laser "
                     "engraves over the cut, so the mark is not seen", g.span,
                     hint="move the mark inside the outline (start it at least its line "
                          "width from the edge) or leave it out; the cut already draws the edge")
