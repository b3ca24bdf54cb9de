"""Which features are near each other, without comparing every pair: the spatial index that
keeps the geometry checks (:mod:`.checks`) O(n log n) in the number of holes.

* :func:`box_pairs`: the pairs of axis-aligned boxes that overlap (each grown by a pad), from a
  k-d tree over the box centres (``scipy.spatial.cKDTree``): two boxes can overlap only when
  their centres are within the sum of their half diagonals, so the boxes up to four times
  the median half diagonal are paired by one ``query_pairs`` at twice the largest of them, and
  the larger ones (the outline of a plate, a few long slots) are treated the same way among
  themselves and queried against the small ones' tree; the candidates are then tested exactly.
* :func:`close_pairs`: the (vertex, segment) pairs of different features closer than a
  distance, with the exact point-segment distance and the foot of the perpendicular: the
  minimum distance between two non-crossing polygon boundaries is the least of these (it is
  reached at a vertex of one of them).  A k-d tree over the vertices is searched around each
  segment's midpoint, within half the segment's length plus the distance.

Small inputs (at most :data:`SMALL_BOXES` boxes, :data:`SMALL_VERTS` vertices) are measured
without SciPy: every pair of boxes, and each segment against the vertices in its y band (found
by binary search in the vertices sorted by y).  SciPy is imported only above that, so a cold
``aidl check`` of an ordinary part does not pay for its import.
"""
from __future__ import annotations

import numpy as np

SMALL_BOXES = 64
SMALL_VERTS = 4000


def _median(a) -> float:
    """The median of ``a`` (np.median imports numpy.ma, which a cold check avoids)."""
    a = np.sort(np.asarray(a, dtype=float))
    k = len(a) // 2
    return float(a[k]) if len(a) % 2 else float((a[k - 1] + a[k]) / 2)


def _kdtree(points):
    from scipy.spatial import cKDTree      # imported only for large inputs (see above)
    return cKDTree(points)


def box_pairs(boxes, pad: float = 0.0) -> np.ndarray:
    """The pairs ``(i, j)``, ``i < j``, of ``boxes`` (n x 4: x0, y0, x1, y1) that overlap or
    touch once each is grown by ``pad`` on every side; a k x 2 integer array, rows sorted."""
    b = np.asarray(boxes, dtype=float).reshape(-1, 4)
    n = len(b)
    if n < 2:
        return np.zeros((0, 2), dtype=np.intp)
    c = (b[:, :2] + b[:, 2:]) / 2
    h = np.abs(b[:, 2:] - b[:, :2]) / 2 + pad
    if n <= SMALL_BOXES:
        ii, jj = np.triu_indices(n, 1)
        cand = np.column_stack([ii, jj]).astype(np.intp)
    else:
        # radii a little large: the candidates must include every pair the exact test accepts
        cand = _candidates(c, np.hypot(h[:, 0], h[:, 1]) * (1 + 1e-6) + 1e-9, np.arange(n))
    if not len(cand):
        return np.zeros((0, 2), dtype=np.intp)
    if n > SMALL_BOXES:                   # the tree's pairs, each once, in order
        cand = np.sort(cand, axis=1)
        key = np.sort(cand[:, 0] * n + cand[:, 1])
        key = key[np.r_[True, key[1:] != key[:-1]]]
        cand = np.column_stack([key // n, key % n]).astype(np.intp)
    i, j = cand[:, 0], cand[:, 1]
    lo, hi = np.minimum(b[:, :2], b[:, 2:]) - pad, np.maximum(b[:, :2], b[:, 2:]) + pad
    ok = np.all((lo[i] <= hi[j]) & (lo[j] <= hi[i]), axis=1)
    return cand[ok]


def _candidates(c, R, idx) -> np.ndarray:
    """Index pairs (into the full arrays) of the boxes ``idx`` whose centres are within the sum
    of their radii ``R``: small boxes by one k-d tree, the large ones recursively."""
    if len(idx) < 2:
        return np.zeros((0, 2), dtype=np.intp)
    r = R[idx]
    cut = 4 * _median(r)
    small, big = idx[r <= cut], idx[r > cut]
    out = []
    if len(small) > 1:
        tree = _kdtree(c[small])
        p = tree.query_pairs(2 * float(R[small].max()), output_type="ndarray")
        if len(p):
            out.append(small[p])
    if len(big):
        if len(small):
            tree = _kdtree(c[small])
            rs = float(R[small].max())
            for i in big:                 # few: the recursion halves them at least
                js = tree.query_ball_point(c[i], float(R[i]) + rs, return_sorted=False)
                if js:
                    out.append(np.column_stack([np.full(len(js), i), small[np.asarray(js)]]))
        if len(big) == len(idx):          # all alike in size but spread: no smaller set
            ii, jj = np.triu_indices(len(big), 1)
            out.append(np.column_stack([big[ii], big[jj]]))
        else:
            out.append(_candidates(c, R, big))
    out = [o for o in out if len(o)]
    return np.concatenate(out).astype(np.intp) if out else np.zeros((0, 2), dtype=np.intp)


def close_pairs(vertices, vfeat, seg_a, seg_b, sfeat, dist: float):
    """The (vertex, segment) pairs of different features closer than ``dist``.

    ``vertices`` (N x 2) with their feature ids ``vfeat``; segments from ``seg_a`` to
    ``seg_b`` (M x 2 each) with ``sfeat``.  Returns ``(v, s, d, foot)``: vertex indices,
    segment indices, the exact distances and the nearest points on the segments (K x 2)."""
    V = np.asarray(vertices, dtype=float).reshape(-1, 2)
    A = np.asarray(seg_a, dtype=float).reshape(-1, 2)
    B = np.asarray(seg_b, dtype=float).reshape(-1, 2)
    empty = (np.zeros(0, np.intp), np.zeros(0, np.intp), np.zeros(0), np.zeros((0, 2)))
    if not len(V) or not len(A):
        return empty
    vfeat, sfeat = np.asarray(vfeat), np.asarray(sfeat)
    if len(V) <= SMALL_VERTS and len(A) <= SMALL_VERTS:
        s, v = _band_pairs(V, A, B, dist)
    else:
        s, v = _tree_pairs(V, A, B, dist)
    if not len(s):
        return empty
    keep = vfeat[v] != sfeat[s]
    s, v = s[keep], v[keep]
    a, ab = A[s], B[s] - A[s]
    ap = V[v] - a
    l2 = np.einsum("ij,ij->i", ab, ab)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(l2 > 0, np.einsum("ij,ij->i", ap, ab) / l2, 0.0), 0.0, 1.0)
    foot = a + t[:, None] * ab
    d = np.hypot(*(V[v] - foot).T)
    keep = d < dist
    return v[keep], s[keep], d[keep], foot[keep]


def _band_pairs(V, A, B, dist):
    """Candidate (segment, vertex) pairs: the vertices within ``dist`` of each segment's box
    (y by binary search in the vertices sorted by y, then x)."""
    order = np.argsort(V[:, 1], kind="stable")
    ys = V[order, 1]
    lo = np.searchsorted(ys, np.minimum(A[:, 1], B[:, 1]) - dist, side="left")
    hi = np.searchsorted(ys, np.maximum(A[:, 1], B[:, 1]) + dist, side="right")
    cnt = np.maximum(hi - lo, 0)
    total = int(cnt.sum())
    if not total:
        return np.zeros(0, np.intp), np.zeros(0, np.intp)
    s = np.repeat(np.arange(len(A)), cnt)
    start = np.cumsum(cnt) - cnt
    v = order[lo[s] + (np.arange(total) - start[s])]
    x = V[v, 0]
    ok = (x >= np.minimum(A[s, 0], B[s, 0]) - dist) & (x <= np.maximum(A[s, 0], B[s, 0]) + dist)
    return s[ok], v[ok]


def _tree_pairs(V, A, B, dist):
    """Candidate (segment, vertex) pairs from a k-d tree over the vertices, searched around
    each segment's midpoint within half its length plus ``dist``."""
    mid = (A + B) / 2
    L = np.hypot(*(B - A).T)
    cut = max(4 * _median(L), 1e-9)
    short, long_ = np.flatnonzero(L <= cut), np.flatnonzero(L > cut)
    tree = _kdtree(V)
    si, vi = [], []
    if len(short):
        m = _kdtree(mid[short]).sparse_distance_matrix(
            tree, dist + float(L[short].max()) / 2, output_type="ndarray")
        si.append(short[m["i"]])
        vi.append(m["j"].astype(np.intp))
    for s in long_:                       # long edges (an outline's sides): one query each
        js = tree.query_ball_point(mid[s], dist + float(L[s]) / 2, return_sorted=False)
        if js:
            si.append(np.full(len(js), s, dtype=np.intp))
            vi.append(np.asarray(js, dtype=np.intp))
    if not si:
        return np.zeros(0, np.intp), np.zeros(0, np.intp)
    return np.concatenate(si), np.concatenate(vi)


def boundary(loops, fid: int):
    """The vertices and segments of closed ``loops`` (each M x 2), tagged with feature ``fid``:
    ``(V, vfeat, A, B, sfeat)``."""
    polys = [np.asarray(p, dtype=float).reshape(-1, 2) for p in loops]
    polys = [p for p in polys if len(p) >= 2]
    if not polys:
        z = np.zeros((0, 2))
        return z, np.zeros(0, np.intp), z, z, np.zeros(0, np.intp)
    V = np.concatenate(polys)
    B = np.concatenate([np.concatenate([p[1:], p[:1]]) for p in polys])
    f = np.full(len(V), fid, dtype=np.intp)
    return V, f, V, B, f
