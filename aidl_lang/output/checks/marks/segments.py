"""Segments against segments for the engraving checks (:mod:`.engravings`, :mod:`.text`,
:mod:`.clearance`): the gap between paired segments (:func:`_pair_gap`) and whether they
cross (:func:`_crosses`), k pairs in one array operation each; the exact gap of an engraved
circle to edges (:func:`_exact_circle_gaps`)."""
from __future__ import annotations

import numpy as np

from ..common import _signed


def _pair_gap(a0, a1, b0, b1) -> tuple:
    """The distance (mm) between each segment ``a0[k]``-``a1[k]`` and ``b0[k]``-``b1[k]``
    (k x 2 arrays each, paired row by row): ``(d, pa, pb)``, the k distances and the nearest
    points on each (0 and the crossing point where two cross)."""
    da, db = a1 - a0, b1 - b0

    def foot(p, s0, dd):
        l2 = np.einsum("ij,ij->i", dd, dd)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.clip(np.where(l2 > 0, np.einsum("ij,ij->i", p - s0, dd) / l2, 0.0), 0, 1)
        return s0 + t[:, None] * dd
    cand = [(a0, foot(a0, b0, db)), (a1, foot(a1, b0, db)),
            (foot(b0, a0, da), b0), (foot(b1, a0, da), b1)]
    dist = np.array([np.hypot(*(p - q).T) for p, q in cand])       # 4 x k
    best = np.argmin(dist, axis=0)
    r = np.arange(len(a0))
    pa = np.stack([c[0] for c in cand])[best, r]
    pb = np.stack([c[1] for c in cand])[best, r]
    d = dist[best, r]

    def cross(u, v):
        return u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
    s1, s2 = cross(da, b0 - a0), cross(da, b1 - a0)
    s3, s4 = cross(db, a0 - b0), cross(db, a1 - b0)
    hit = (s1 * s2 < 0) & (s3 * s4 < 0)
    if hit.any():
        with np.errstate(divide="ignore", invalid="ignore"):
            t = s3[hit] / (s3[hit] - s4[hit])
        x = a0[hit] + t[:, None] * da[hit]
        d = np.where(hit, 0.0, d)
        pa[hit] = x
        pb[hit] = x
    return d, pa, pb


def _crosses(a0, a1, b0, b1) -> np.ndarray:
    """Whether each segment ``a0[k]``-``a1[k]`` crosses ``b0[k]``-``b1[k]`` (k x 2 arrays,
    paired row by row), their insides meeting at one point: an engraved line that runs
    across a cut edge, not one that ends on it or grazes it (k booleans)."""
    da, db = a1 - a0, b1 - b0

    def cross(u, v):
        return u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
    s1, s2 = cross(da, b0 - a0), cross(da, b1 - a0)
    s3, s4 = cross(db, a0 - b0), cross(db, a1 - b0)
    return (s1 * s2 < 0) & (s3 * s4 < 0)


def _edge_arrays(shape, loops) -> tuple | None:
    """A part's cut edges as arrays: ``(E0, E1, hole)``, each edge's two ends (k x 2) and
    whether it is a hole's (clockwise loop), from its outline ``loops`` (or the polygons of
    ``shape`` when None); None when it has no edge."""
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    loops = [lp for lp in loops if len(lp) >= 2]
    if not loops:
        return None
    return (np.concatenate(loops), np.concatenate([np.roll(lp, -1, axis=0) for lp in loops]),
            np.concatenate([np.full(len(lp), _signed(lp) < 0) for lp in loops]))


def _exact_circle_gaps(geoms, marks, A, B, d) -> None:
    """Replace in ``d`` the gap of each pair whose mark is an engraved circle (one
    ``circle`` item) by the exact gap between that circle and the edge from ``A`` to ``B``:
    its 32 samples' chords lie up to r (1 - cos(pi / 32)) inside it (0.02 mm at r 4), so a
    ring drawn exactly 0.5 mm clear of a hole inside it measured 0.4997 mm (W0516, run z5's
    buttons).  Outside the circle: the edge's distance to the centre less the radius;
    inside it: the radius less the edge's farther end's distance; across it: 0."""
    circ = {k: (np.asarray(items[0][1], float), float(items[0][2]))
            for k, (_, items) in enumerate(geoms) if len(items) == 1 and items[0][0] == "circle"}
    if not circ:
        return
    idx = np.flatnonzero(np.fromiter((int(k) in circ for k in marks), bool, len(marks)))
    if not len(idx):
        return
    C = np.array([circ[int(k)][0] for k in marks[idx]]).reshape(-1, 2)
    R = np.array([circ[int(k)][1] for k in marks[idx]])
    a, b = A[idx], B[idx]
    ab = b - a
    L2 = np.einsum("ij,ij->i", ab, ab)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, np.einsum("ij,ij->i", C - a, ab) / L2, 0.0), 0.0, 1.0)
    near = np.hypot(*(a + ab * t[:, None] - C).T)
    far = np.maximum(np.hypot(*(a - C).T), np.hypot(*(b - C).T))
    d[idx] = np.where(near >= R, near - R, np.where(far <= R, R - far, 0.0))
