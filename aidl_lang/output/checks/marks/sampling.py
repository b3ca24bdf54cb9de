"""The sample points of engraving items (:func:`_sample`, :func:`_samples`), which the
engraving checks (:mod:`.engravings`) and the text check (:mod:`.text`) measure marks with;
which of them lie on the material (:func:`_surely_on_material`) or near an outline
(:func:`_within`); and how much of a mark's length does (:func:`_length_share`)."""
from __future__ import annotations

import math

import numpy as np

from ..common import _edges, _inside

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
        from ....geometry.shapes.spline import bez_at
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
_EPS = 2.220446049250313e-16      # np.finfo(float).eps, without its first call


def _all_on_material(shape, pts: np.ndarray, loops: list | None = None) -> bool:
    """True when every point of ``pts`` is certainly inside ``shape`` grown by
    :data:`ENGRAVE_TOL` (what W0505 tests), without growing it: each point is inside the
    outline itself or within :data:`_SURELY_GROWN` of one of its edges.  False means "not
    shown": the grown outline then decides (engraving drawn on the edge is the usual case
    the outline alone cannot settle).  ``loops``: the shape's polygons, when at hand."""
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    return bool(_surely_on_material(pts, loops).all())


def _surely_on_material(pts: np.ndarray, loops: list) -> np.ndarray:
    """Per point of ``pts`` (N x 2, mm): True when it is certainly inside the outline
    ``loops`` grown by :data:`ENGRAVE_TOL`: inside the outline or within
    :data:`_SURELY_GROWN` of an edge.  Loops of less than ``ENGRAVE_TOL^2`` of area are left
    out: a sliver the booleans leave (a circle added, then cut again: 3e-9 mm^2) is no
    material, and Manifold's offset drops it; a hole that small holds no point farther than
    ``ENGRAVE_TOL / sqrt(pi)`` from its edge, which the grown outline covers."""
    loops = [p for p in loops if len(p) >= 3 and abs(_loop_area(p)) >= ENGRAVE_TOL ** 2]
    edges = _edges(loops)
    surely = _inside(pts, edges)
    out = ~surely
    if out.any():
        surely[out] = _within(pts[out], edges, _SURELY_GROWN)
    return surely


def _loop_area(p: np.ndarray) -> float:
    """The signed area of closed polygon ``p`` (N x 2, mm^2; the shoelace formula)."""
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _within(pts: np.ndarray, edges: tuple, dist: float, max_pairs: int = 2_000_000) -> np.ndarray:
    """True where a point of ``pts`` (N x 2) lies within ``dist`` of one of the segments
    ``edges`` (x1, y1, x2, y2 arrays).  Each segment is measured only against the points
    in its box grown by ``dist`` (a grid over the points, :class:`..nearby._Grid`).  All
    False when more than ``max_pairs`` pairs would be measured."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 2)
    n = len(pts)
    x1, y1, x2, y2 = edges
    res = np.zeros(n, dtype=bool)
    if not n or not len(x1):
        return res
    from ...part.measure.nearby import TooManyPairs, _Grid, _median
    x, y = pts[:, 0], pts[:, 1]
    lo = np.column_stack([np.minimum(x1, x2), np.minimum(y1, y2)])
    hi = np.column_stack([np.maximum(x1, x2), np.maximum(y1, y2)])
    # the window is wider than ``dist`` by a few units in the last place, so that a point
    # which the distance below rounds to exactly ``dist`` is never filtered out first; the
    # points in each edge's box so grown, from a grid over the points (box tests first: the
    # band of y alone held every point across a round part)
    pad = (dist + 8 * _EPS * (np.abs(lo) + np.abs(hi) + dist))
    try:
        edge, pt = _Grid(pts, max(_median(np.hypot(x2 - x1, y2 - y1)), dist, 1e-9)).in_boxes(
            lo - pad, hi + pad, limit=max_pairs)
    except TooManyPairs:
        return res
    if not len(edge):
        return res
    ax, ay = x1[edge], y1[edge]
    dx, dy = x2[edge] - ax, y2[edge] - ay
    px, py = x[pt] - ax, y[pt] - ay
    L2 = dx * dx + dy * dy
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, (px * dx + py * dy) / L2, 0.0), 0.0, 1.0)
    ex, ey = px - t * dx, py - t * dy
    res[pt[ex * ex + ey * ey <= dist * dist]] = True
    return res


ALONG = 400              # points spread by length over a mark's straight sides (W0516)


def _share_on(items, edges) -> float:
    """The share of engraving ``items``' length that lies within :data:`ENGRAVE_TOL` of the
    outline ``edges`` (:func:`_length_share`).  The samples of :func:`_sample` weigh a
    polygon's corners and side midpoints alike: a filled groove 200 x 6 mm running out at
    both ends of a deck had 6 of its 8 there, "75 % on the outline", for 3 % of its length
    (issue 111's run dh, a toy railway bridge)."""
    return _length_share(items, lambda P: _within(P, edges, ENGRAVE_TOL))


def _length_share(items, where) -> float:
    """The share of engraving ``items``' length at the points where ``where`` (N x 2 points
    -> N booleans) holds (:func:`_lengths`)."""
    part, whole = _lengths(items, where)
    return part / whole if whole > 0 else 0.0


def _lengths(items, where) -> tuple[float, float]:
    """``(length where ``where`` holds, whole length)`` of engraving ``items`` (mm):
    ``where`` maps N x 2 points to N booleans, asked at points spread evenly by length over
    its lines and polygons' sides (:data:`ALONG` in all) and at its curves' own samples
    (even along them)."""
    segs, curved = [], []
    for it in items:
        if it[0] == "line":
            segs.append((np.asarray(it[1], float), np.asarray(it[2], float)))
        elif it[0] == "poly":
            P = np.asarray(it[1], float)
            segs += list(zip(P, np.roll(P, -1, axis=0)))
        else:
            curved.append(_sample(it))
    pts, weight = [], []
    if segs:
        A = np.array([a for a, _ in segs])
        B = np.array([b for _, b in segs])
        L = np.hypot(*(B - A).T)
        total = float(L.sum())
        m = np.maximum(1, np.ceil(ALONG * L / total).astype(int)) if total > 0 else \
            np.ones(len(segs), dtype=int)
        seg = np.repeat(np.arange(len(segs)), m)
        u = (np.arange(len(seg)) - np.repeat(np.cumsum(m) - m, m) + 0.5) / m[seg]
        pts.append(A[seg] + u[:, None] * (B[seg] - A[seg]))
        weight.append(L[seg] / m[seg])
    for c in curved:
        if len(c) > 1:
            step = np.hypot(*np.diff(c, axis=0).T)
            pts.append(c)
            weight.append(np.r_[step, step[-1:]] if len(step) else np.ones(len(c)))
    if not pts:
        return 0.0, 0.0
    P, W = np.vstack(pts), np.concatenate(weight)
    return float(W[where(P)].sum()), float(W.sum())
