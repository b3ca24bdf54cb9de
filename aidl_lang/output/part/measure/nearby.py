"""Which features are near each other, without comparing every pair: the spatial index that
keeps the geometry checks (:mod:`.checks`) O(n log n) in the number of holes.

* :func:`box_pairs`: the pairs of axis-aligned boxes that overlap (each grown by a pad), from a
  uniform grid over the box centres (:class:`_Grid`): two boxes can overlap only when
  their centres are within the sum of their half diagonals, so the boxes up to four times
  the median half diagonal are paired by one grid query at twice the largest of them, and
  the larger ones (the outline of a plate, a few long slots) are treated the same way among
  themselves and queried against the small ones' grid; the candidates are then tested exactly.
* :func:`close_pairs`: the (vertex, segment) pairs of different features closer than a
  distance, with the exact point-segment distance and the foot of the perpendicular: the
  minimum distance between two non-crossing polygon boundaries is the least of these (it is
  reached at a vertex of one of them).  A grid over the vertices is searched in each
  segment's bounding box grown by the distance.
* :func:`close_pairs_facing`: the same pairs within closed loops where only a vertex whose
  tangent runs against the segment matters (W0519's slits): the segments by direction
  class, each against the vertices that can face it (no neighbours along a curve).

Small inputs (at most :data:`SMALL_BOXES` boxes, :data:`SMALL_VERTS` vertices) are measured
more simply: every pair of boxes, and each segment against the vertices in its y band (found
by binary search in the vertices sorted by y).  Neither path imports SciPy (its k-d tree cost
a cold ``aidl check`` of a 400-hole plate +1,229 M instructions to import, issue 38).
"""
from __future__ import annotations

import numpy as np

SMALL_BOXES = 64
SMALL_PAIRS = 20_000    # box_pairs tests every pair at once up to this many (n <= 200):
                        # cheaper than the grid's sorts (the telephone's 9 calls: 5.3 -> ? ms)
MAX_PAIRS = 3_000_000   # pairs (or candidates) one query may list: ~250 MB while they are
                        # measured; past it :class:`TooManyPairs` (the check says it did not
                        # look, W0521) instead of a quadratic list of a dense cluster
PAIRS_PER_POINT = 32    # pairs a point or query may have on average past MAX_PAIRS in all
CHUNK = 500_000         # candidates measured at once by :func:`close_pairs`


class TooManyPairs(Exception):
    """More than ``limit`` pairs (or candidate pairs) lie within the distance asked: a
    dense cluster (a drawing of thousands of edges all within the distance of one another),
    refused before they are listed.  ``count``: how many candidates there were."""

    def __init__(self, count: int, limit: int):
        super().__init__(f"{count:,} pairs, more than {limit:,}")
        self.count, self.limit = count, limit
SMALL_VERTS = 4000
BAND_PER_ITEM = 16      # candidates per vertex and segment above which the grid finds them


def _median(a) -> float:
    """The median of ``a`` (np.median imports numpy.ma, which a cold check avoids)."""
    a = np.sort(np.asarray(a, dtype=float))
    k = len(a) // 2
    return float(a[k]) if len(a) % 2 else float((a[k - 1] + a[k]) / 2)


class _Grid:
    """Points (n x 2) in a uniform grid of square cells of side ``cell``, sorted row by row
    (key ``row * columns + column``), so that the points whose cells meet a box are one slice
    of the sorted points per row of cells: a box query costs a binary search per row it
    spans and the points it finds, whatever the spread of the points (NumPy only)."""

    def __init__(self, P, cell: float):
        self.P = P = np.asarray(P, dtype=float).reshape(-1, 2)
        lo, hi = P.min(axis=0), P.max(axis=0)
        # at most 2**20 cells a side: the keys fit int64 and a query spans few rows
        self.h = h = max(float(cell), float((hi - lo).max()) / 2 ** 20, 1e-9)
        self.lo = lo
        ij = np.floor((P - lo) / h).astype(np.int64)
        self.nx, self.ny = int(ij[:, 0].max()) + 1, int(ij[:, 1].max()) + 1
        key = ij[:, 1] * self.nx + ij[:, 0]
        self.order = np.argsort(key, kind="stable")
        self.keys = key[self.order]

    def in_boxes(self, qlo, qhi, limit: int | None = None) -> tuple[np.ndarray, np.ndarray]:
        """``(q, p)``: every point ``p`` inside box ``q`` (``qlo[q]`` to ``qhi[q]``, edges
        included), in the order of the queries; :class:`TooManyPairs` when the cells searched
        hold more than ``limit`` (default :data:`MAX_PAIRS`) points in all."""
        limit = MAX_PAIRS if limit is None else limit
        qlo = np.asarray(qlo, dtype=float).reshape(-1, 2)
        qhi = np.asarray(qhi, dtype=float).reshape(-1, 2)
        with np.errstate(invalid="ignore", over="ignore"):
            a = np.floor((qlo - self.lo) / self.h)
            b = np.floor((qhi - self.lo) / self.h)
        lim = np.array([self.nx - 1, self.ny - 1], dtype=float)
        hit = np.all((b >= 0) & (a <= lim), axis=1)
        qs = np.flatnonzero(hit)
        a = np.clip(a[qs], 0, lim).astype(np.int64)
        b = np.clip(b[qs], 0, lim).astype(np.int64)
        rows = b[:, 1] - a[:, 1] + 1
        total = int(rows.sum())
        none = (np.zeros(0, np.intp), np.zeros(0, np.intp))
        if not total:
            return none
        k = np.repeat(np.arange(len(qs)), rows)
        row = a[k, 1] + (np.arange(total) - np.repeat(np.cumsum(rows) - rows, rows))
        first = np.searchsorted(self.keys, row * self.nx + a[k, 0], "left")
        cnt = np.searchsorted(self.keys, row * self.nx + b[k, 0], "right") - first
        n = int(cnt.sum())
        if not n:
            return none
        if n > limit:
            raise TooManyPairs(n, limit)
        q = qs[np.repeat(k, cnt)]
        p = self.order[np.repeat(first, cnt) + (np.arange(n) - np.repeat(np.cumsum(cnt) - cnt, cnt))]
        x, y = self.P[p, 0], self.P[p, 1]
        ok = (x >= qlo[q, 0]) & (x <= qhi[q, 0]) & (y >= qlo[q, 1]) & (y <= qhi[q, 1])
        return q[ok].astype(np.intp), p[ok].astype(np.intp)

    def within(self, C, r) -> tuple[np.ndarray, np.ndarray]:
        """``(q, p)``: every point ``p`` within distance ``r[q]`` (or ``r``) of ``C[q]``, in
        the order of the queries.  The queries go in blocks whose candidates number at most
        :data:`MAX_PAIRS` (halved past it), so a large but sparse set (a plate cut into
        90,601 squares: 6.3 million candidates, about 18 an item) is measured in bounded
        memory; :class:`TooManyPairs` when one query alone has more candidates, or when the
        pairs found pass :data:`MAX_PAIRS` and :data:`PAIRS_PER_POINT` a point and query (a
        dense cluster: a quadratic list)."""
        C = np.asarray(C, dtype=float).reshape(-1, 2)
        r = np.broadcast_to(np.asarray(r, dtype=float), (len(C),))[:, None]
        most = max(MAX_PAIRS, PAIRS_PER_POINT * (len(self.P) + len(C)))
        qs, ps, found = [], [], 0
        todo = [(0, len(C))]
        while todo:
            lo, hi = todo.pop()
            try:
                q, p = self.in_boxes(C[lo:hi] - r[lo:hi], C[lo:hi] + r[lo:hi])
            except TooManyPairs:
                if hi - lo == 1:
                    raise
                mid = (lo + hi) // 2
                todo += [(mid, hi), (lo, mid)]          # the first half first: in order
                continue
            q = q + lo
            d = self.P.take(p, axis=0) - C.take(q, axis=0)     # = P[p] - C[q] (faster)
            ok = np.hypot(d[:, 0], d[:, 1]) <= r[q, 0]
            found += int(ok.sum())
            if found > most:
                raise TooManyPairs(found, most)
            qs.append(q[ok])
            ps.append(p[ok])
        if not qs:
            return np.zeros(0, np.intp), np.zeros(0, np.intp)
        return np.concatenate(qs), np.concatenate(ps)


def box_pairs(boxes, pad: float = 0.0) -> np.ndarray:
    """The pairs ``(i, j)``, ``i < j``, of ``boxes`` (n x 4: x0, y0, x1, y1) that overlap or
    touch once each is grown by ``pad`` on every side; a k x 2 integer array, rows sorted."""
    b = np.asarray(boxes, dtype=float).reshape(-1, 4)
    n = len(b)
    if n < 2:
        return np.zeros((0, 2), dtype=np.intp)
    c = (b[:, :2] + b[:, 2:]) / 2
    h = np.abs(b[:, 2:] - b[:, :2]) / 2 + pad
    if n <= SMALL_BOXES or n * (n - 1) // 2 <= SMALL_PAIRS:
        ii, jj = np.triu_indices(n, 1)
        cand = np.column_stack([ii, jj]).astype(np.intp)
    else:
        # radii a little large: the candidates must include every pair the exact test accepts
        cand = _candidates(c, np.hypot(h[:, 0], h[:, 1]) * (1 + 1e-6) + 1e-9, np.arange(n))
    if not len(cand):
        return np.zeros((0, 2), dtype=np.intp)
    if n > SMALL_BOXES and n * (n - 1) // 2 > SMALL_PAIRS:   # the grid's, once each, in order
        cand = np.sort(cand, axis=1)
        key = np.sort(cand[:, 0] * n + cand[:, 1])
        key = key[np.r_[True, key[1:] != key[:-1]]]
        cand = np.column_stack([key // n, key % n]).astype(np.intp)
    i, j = cand[:, 0], cand[:, 1]
    lo, hi = np.minimum(b[:, :2], b[:, 2:]) - pad, np.maximum(b[:, :2], b[:, 2:]) + pad
    ok = np.all((lo[i] <= hi[j]) & (lo[j] <= hi[i]), axis=1)
    return cand[ok]


def box_pairs_between(a, b, pad: float = 0.0) -> np.ndarray:
    """The pairs ``(i, j)`` of a box ``a[i]`` and a box ``b[j]`` (n x 4 and m x 4: x0, y0,
    x1, y1) that overlap or touch once each is grown by ``pad``: what :func:`box_pairs` of
    both sets gives between them, rows sorted, without the pairs within one set (a part's
    outline: every edge meets the next).  Up to :data:`SMALL_PAIRS` ``n x m`` every pair at
    once; else :func:`box_pairs` of both, the pairs within a set dropped."""
    A = np.asarray(a, dtype=float).reshape(-1, 4)
    B = np.asarray(b, dtype=float).reshape(-1, 4)
    if not len(A) or not len(B):
        return np.zeros((0, 2), dtype=np.intp)
    if len(A) * len(B) > 10 * SMALL_PAIRS:
        pairs = box_pairs(np.vstack([A, B]), pad)
        pairs = pairs[(pairs[:, 0] < len(A)) & (pairs[:, 1] >= len(A))]
        return np.column_stack([pairs[:, 0], pairs[:, 1] - len(A)]).astype(np.intp)
    alo, ahi = np.minimum(A[:, :2], A[:, 2:]) - pad, np.maximum(A[:, :2], A[:, 2:]) + pad
    blo, bhi = np.minimum(B[:, :2], B[:, 2:]) - pad, np.maximum(B[:, :2], B[:, 2:]) + pad
    ok = ((alo[:, None, 0] <= bhi[None, :, 0]) & (blo[None, :, 0] <= ahi[:, None, 0])
          & (alo[:, None, 1] <= bhi[None, :, 1]) & (blo[None, :, 1] <= ahi[:, None, 1]))
    i, j = np.nonzero(ok)
    return np.column_stack([i, j]).astype(np.intp)


def _candidates(c, R, idx) -> np.ndarray:
    """Index pairs (into the full arrays) of the boxes ``idx`` whose centres are within the sum
    of their radii ``R``: small boxes by one grid, the large ones recursively."""
    if len(idx) < 2:
        return np.zeros((0, 2), dtype=np.intp)
    r = R[idx]
    cut = 4 * _median(r)
    small, big = idx[r <= cut], idx[r > cut]
    out = []
    if len(small) > 1:
        rs2 = 2 * float(R[small].max())
        q, p = _Grid(c[small], rs2).within(c[small], rs2)
        keep = q < p                      # each pair once, as (i, j) with i before j
        if keep.any():
            out.append(np.column_stack([small[q[keep]], small[p[keep]]]))
    if len(big):
        if len(small):
            rs = float(R[small].max())
            q, p = _Grid(c[small], 2 * rs).within(c[big], R[big] + rs)
            if len(q):
                out.append(np.column_stack([big[q], small[p]]))
        if len(big) == len(idx):          # all alike in size but spread: no smaller set
            if len(big) * (len(big) - 1) // 2 > MAX_PAIRS:
                raise TooManyPairs(len(big) * (len(big) - 1) // 2, MAX_PAIRS)
            ii, jj = np.triu_indices(len(big), 1)
            out.append(np.column_stack([big[ii], big[jj]]))
        else:
            out.append(_candidates(c, R, big))
    out = [o for o in out if len(o)]
    return np.concatenate(out).astype(np.intp) if out else np.zeros((0, 2), dtype=np.intp)


def close_pairs(vertices, vfeat, seg_a, seg_b, sfeat, dist: float, others: bool = True,
                skip=None):
    """The (vertex, segment) pairs of different features closer than ``dist``.

    ``vertices`` (N x 2) with their feature ids ``vfeat``; segments from ``seg_a`` to
    ``seg_b`` (M x 2 each) with ``sfeat``.  Returns ``(v, s, d, foot)``: vertex indices,
    segment indices, the exact distances and the nearest points on the segments (K x 2).
    ``others=False`` skips the first cut of small inputs (each feature's vertices against
    the box of the other features' segments), which only pays when features are few.
    ``skip``: pairs of feature ids (K x 2, non-negative, either order) whose pairs are
    neither measured nor returned (holes already known to overlap, :func:`..checks.openings.
    _analyse`: a row of 5,000 overlapping circles measured 460,000 such pairs); the other
    pairs come as without it, in the same order.
    :class:`TooManyPairs` past :data:`MAX_PAIRS` pairs (the candidates of a large input are
    measured :data:`CHUNK` at a time, so memory stays bounded)."""
    V = np.asarray(vertices, dtype=float).reshape(-1, 2)
    A = np.asarray(seg_a, dtype=float).reshape(-1, 2)
    B = np.asarray(seg_b, dtype=float).reshape(-1, 2)
    empty = (np.zeros(0, np.intp), np.zeros(0, np.intp), np.zeros(0), np.zeros((0, 2)))
    if not len(V) or not len(A):
        return empty
    vfeat, sfeat = np.asarray(vfeat), np.asarray(sfeat)
    keep = _Skip(skip) if skip is not None and len(skip) else None
    if len(V) <= SMALL_VERTS and len(A) <= SMALL_VERTS:
        if others:
            vk, sk = _within_others(V, vfeat, np.minimum(A, B) - dist,
                                    np.maximum(A, B) + dist, sfeat)
        else:                   # a feature per vertex (W0519): no other feature's box to cut
            vk, sk = np.arange(len(V)), np.arange(len(A))
        s, v = _band_pairs(V.take(vk, axis=0), A.take(sk, axis=0), B.take(sk, axis=0),
                           dist)                       # in the same order as all of them
        s, v = sk[s], vk[v]
        if keep is not None and len(s):
            ok = keep(vfeat[v], sfeat[s])
            s, v = s[ok], v[ok]
        return _measure(V, A, B, vfeat, sfeat, v, s, dist) if len(s) else empty
    # large: features of whole loops (a plate's holes) are paired run by run (:func:`_run_pairs`,
    # no candidate within one feature is listed); a feature per vertex (the slit check) by the
    # grid over the vertices.  Either way the same pairs, in the grid's order (segment, then
    # the vertex's cell, then the vertex)
    L = np.hypot(*(B - A).T)
    h = max(_median(L), dist, 1e-9)
    lo, hi = np.minimum(A, B) - dist, np.maximum(A, B) + dist
    out = None
    if _changes(vfeat) * 8 < len(V) and _changes(sfeat) * 8 < len(A):
        out = _run_pairs(V, vfeat, A, B, sfeat, lo, hi, dist, h, keep)
    if out is None:
        out = _grid_chunks(V, vfeat, A, B, sfeat, lo, hi, dist, h, keep)
    if not out:
        return empty
    v, s, d, foot = (np.concatenate([o[k] for o in out]) for k in range(4))
    return _in_grid_order(V, h, v, s, d, foot)


def _in_grid_order(V, h: float, v, s, d, foot):
    """``(v, s, d, foot)`` sorted as :func:`close_pairs` answers a large input: by segment,
    then the vertex's cell in :class:`_Grid` ``(V, h)``, then the vertex."""
    key = _cell_keys(V, h)
    order = np.lexsort((v, key[v], s))
    return v[order], s[order], d[order], foot[order]


FACING_BINS = 6     # direction classes of :func:`close_pairs_facing` (60 degrees each)


def close_pairs_facing(V, nxt, prv, dist: float, cos_max: float):
    """What ``close_pairs(V, idx, V, V[nxt], idx, dist, others=False)`` answers (``idx``:
    every vertex its own feature), with at least every pair whose vertex has a tangent
    (``V[nxt[v]] - V[v]`` or ``V[v] - V[prv[v]]``) running against the segment (``V[s]`` to
    ``V[nxt[s]]``, the cosine of their angle below ``-cos_max``, ``0 <= cos_max < 1``), in the
    same order; pairs that do not face each other may be left out.

    ``V`` (n x 2, mm) the vertices of closed loops, ``nxt``/``prv`` the index of the next and
    previous vertex of each one's loop.  A large input (over :data:`SMALL_VERTS` vertices) is
    searched by direction: the segments in :data:`FACING_BINS` classes of their direction,
    each class against only the vertices with a tangent within the facing angle (and 2 degrees
    more) of its opposite.  The neighbours along a curve (a perforated plate's 900,000 chords:
    each within ``dist`` of the next three, 2.7 million pairs, every one then dropped as not
    facing) are never listed: 20,000 holes 3.8 -> 0.9 s.  :class:`TooManyPairs` as
    :func:`close_pairs`: past :data:`MAX_PAIRS` in one class or in all together."""
    V = np.asarray(V, dtype=float).reshape(-1, 2)
    B = V[nxt]
    idx = np.arange(len(V))
    if len(V) <= SMALL_VERTS:
        return close_pairs(V, idx, V, B, idx, dist, others=False)
    D = B - V
    ang = np.arctan2(D[:, 1], D[:, 0])                  # each segment's direction, -pi..pi
    width = 2 * np.pi / FACING_BINS
    cls = np.minimum((ang + np.pi) // width, FACING_BINS - 1).astype(np.intp)
    # facing: the tangent within arccos(cos_max) of the segment's opposite direction; so
    # within half a class, that angle and a margin of the class's middle, turned round
    reach = width / 2 + float(np.arccos(cos_max)) + np.radians(2)
    tang = (ang, ang[prv])                              # a vertex's two tangents' directions
    out, kept = [], 0
    for k in range(FACING_BINS):
        segs = np.flatnonzero(cls == k)
        if not len(segs):
            continue
        back = (k + 0.5) * width                        # the class's middle (-pi + ...) + pi
        near = np.zeros(len(V), dtype=bool)
        for a in tang:
            near |= np.abs((a - back + np.pi) % (2 * np.pi) - np.pi) <= reach
        verts = np.flatnonzero(near)
        if not len(verts):
            continue
        v, s, d, foot = close_pairs(V.take(verts, axis=0), verts, V.take(segs, axis=0),
                                    B.take(segs, axis=0), segs, dist, others=False)
        if len(v):
            out.append((verts[v], segs[s], d, foot))
            kept += len(v)
            if kept > MAX_PAIRS:            # the classes' pairs together, as one search's
                raise TooManyPairs(kept, MAX_PAIRS)
    if not out:
        return (np.zeros(0, np.intp), np.zeros(0, np.intp), np.zeros(0), np.zeros((0, 2)))
    v, s, d, foot = (np.concatenate([o[k] for o in out]) for k in range(4))
    h = max(_median(np.hypot(*D.T)), dist, 1e-9)
    return _in_grid_order(V, h, v, s, d, foot)


def _changes(feat) -> int:
    """How many times the feature id changes along ``feat``."""
    return int(np.count_nonzero(feat[1:] != feat[:-1])) if len(feat) > 1 else 0


def _cell_keys(P, cell: float) -> np.ndarray:
    """The cell key of each point of ``P`` in :class:`_Grid` ``(P, cell)`` (the order of its
    answers)."""
    lo, hi = P.min(axis=0), P.max(axis=0)
    h = max(float(cell), float((hi - lo).max()) / 2 ** 20, 1e-9)
    ij = np.floor((P - lo) / h).astype(np.int64)
    return ij[:, 1] * (int(ij[:, 0].max()) + 1) + ij[:, 0]


class _Skip:
    """``close_pairs``'s ``skip``: called with two arrays of feature ids, True where the pair
    is not skipped."""

    def __init__(self, skip):
        sk = np.asarray(skip, dtype=np.int64).reshape(-1, 2)
        self.keys = np.unique(np.minimum(sk[:, 0], sk[:, 1]) * (1 << 32)
                              + np.maximum(sk[:, 0], sk[:, 1]))

    def __call__(self, fa, fb) -> np.ndarray:
        fa, fb = np.asarray(fa, dtype=np.int64), np.asarray(fb, dtype=np.int64)
        key = np.minimum(fa, fb) * (1 << 32) + np.maximum(fa, fb)
        at = np.minimum(np.searchsorted(self.keys, key), len(self.keys) - 1)
        return self.keys[at] != key


def _grid_chunks(V, vfeat, A, B, sfeat, lo, hi, dist, h, keep=None) -> list:
    """The close pairs by the grid over the vertices: each segment's grown box (``lo``-``hi``)
    searched, :data:`CHUNK` candidates measured at a time (runs of segments from the counts
    taken once), the kept pairs at most :data:`MAX_PAIRS` in all."""
    grid = _Grid(V, h)
    out, kept, todo = [], 0, [(0, len(A))]
    while todo:
        i, j = todo.pop()
        try:
            q, p = grid.in_boxes(lo[i:j], hi[i:j], limit=CHUNK if j - i > 1 else MAX_PAIRS)
        except TooManyPairs:
            if j - i == 1:      # one segment's box alone holds too many: halving cannot help
                raise           # (it pushed the same segment again, forever)
            m = (i + j) // 2
            todo += [(m, j), (i, m)]
            continue
        if len(q) and keep is not None:
            ok = keep(vfeat[p], sfeat[q + i])
            q, p = q[ok], p[ok]
        if len(q):
            got = _measure(V, A, B, vfeat, sfeat, p, q + i, dist)
            kept += len(got[0])
            if kept > MAX_PAIRS:
                raise TooManyPairs(kept, MAX_PAIRS)
            out.append(got)
    return out


RUN = 16            # items per run of :func:`_runs_of` at most


def _runs_of(P, feat, step, reach: float):
    """Runs of consecutive items of one feature (at most :data:`RUN`, of length at most
    ``4 * reach`` along ``step``, the distance from each item to the next; an item whose step
    is longer than ``reach`` alone): ``(starts, stops, feature)``."""
    n = len(P)
    cut = np.r_[True, feat[1:] != feat[:-1]]
    long_ = step > reach                  # a long item alone (an outline's side)
    cut |= long_
    cut[1:] |= long_[:-1]
    starts = np.flatnonzero(cut)
    # within each piece, a new run every RUN items or when the length passes 4 * reach
    pos = np.arange(n) - np.repeat(starts, np.diff(np.r_[starts, n]))
    csum = np.cumsum(step) - step
    base = np.repeat(csum[starts], np.diff(np.r_[starts, n]))
    piece = np.floor((csum - base) / (4 * reach)).astype(np.int64)
    cut2 = cut.copy()
    cut2[1:] |= (pos[1:] % RUN == 0) | (piece[1:] != piece[:-1])
    starts = np.flatnonzero(cut2)
    return starts, np.r_[starts[1:], n], feat[starts]


def _run_pairs(V, vfeat, A, B, sfeat, lo, hi, dist, h, keep=None) -> list | None:
    """The close pairs of features of whole loops: the vertices and the segments in runs
    (:func:`_runs_of`), each segment run's box (its segments' boxes grown by the distance)
    searched for the vertex runs' boxes it meets in a grid over their centres (the vertex
    runs are short: their half size pads the query), the pairs of runs of different
    features kept, then every vertex of one run against every segment of the other inside
    the segment's grown box, :data:`CHUNK` candidates listed and measured at a time.  A
    vertex within ``dist`` of a segment's box lies in its run's box, which then meets the
    segment's run's: every pair is found once.  None when one segment run meets more than
    :data:`MAX_PAIRS` vertex runs (the caller's grid then)."""
    reach = 4 * h
    vstep = np.r_[np.hypot(*(V[1:] - V[:-1]).T), 0.0] if len(V) > 1 else np.zeros(len(V))
    vs, ve, vf = _runs_of(V, vfeat, vstep, reach)
    ss, se, sf = _runs_of(A, sfeat, np.hypot(*(B - A).T), reach)
    vlo, vhi = np.minimum.reduceat(V, vs), np.maximum.reduceat(V, vs)
    slo, shi = np.minimum.reduceat(lo, ss), np.maximum.reduceat(hi, ss)
    pad = dist * 1e-6 + 1e-9
    half = (vhi - vlo).max(axis=0) / 2 + pad          # the largest vertex run's half size
    grid = _Grid((vlo + vhi) / 2, max(2 * float(half.max()), 1e-9))
    nv, ns = ve - vs, se - ss
    out: list = []
    kept = [0]
    todo = [(0, len(ss))]
    while todo:
        i, j = todo.pop()
        try:
            q, p = grid.in_boxes(slo[i:j] - half, shi[i:j] + half,
                                 limit=CHUNK if j - i > 1 else MAX_PAIRS)
        except TooManyPairs:
            if j - i == 1:
                return None
            m = (i + j) // 2
            todo += [(m, j), (i, m)]
            continue
        q = q + i
        ok = ((vlo[p] <= shi[q] + pad).all(axis=1) & (vhi[p] >= slo[q] - pad).all(axis=1)
              & (vf[p] != sf[q]))
        if keep is not None:            # runs of features whose pairs are skipped
            ok &= keep(vf[p], sf[q])
        _expand(V, vfeat, A, B, sfeat, lo, hi, dist, vs[p[ok]], nv[p[ok]], ss[q[ok]],
                ns[q[ok]], out, kept)
    return out


def _expand(V, vfeat, A, B, sfeat, lo, hi, dist, v0, nv, s0, ns, out: list, kept: list):
    """Every vertex ``v0[k]`` ... ``v0[k] + nv[k] - 1`` against every segment ``s0[k]`` ...
    ``s0[k] + ns[k] - 1`` (pairs of runs), the vertex inside the segment's grown box,
    measured (:func:`_measure`) :data:`CHUNK` candidates at a time into ``out``;
    ``kept[0]``: the pairs kept so far (:class:`TooManyPairs` past :data:`MAX_PAIRS`)."""
    cnt = nv * ns
    ends = np.cumsum(cnt)
    at = 0
    while at < len(cnt):
        base = ends[at - 1] if at else 0
        stop = max(at + 1, int(np.searchsorted(ends, base + CHUNK, "right")))
        c = cnt[at:stop]
        tot = int(c.sum())
        k = np.repeat(np.arange(at, stop), c)
        off = np.arange(tot) - np.repeat(np.cumsum(c) - c, c)
        nsk = ns[k]
        v = v0[k] + off // nsk
        s = s0[k] + off % nsk
        x, y = V[v, 0], V[v, 1]
        ok = (x >= lo[s, 0]) & (x <= hi[s, 0]) & (y >= lo[s, 1]) & (y <= hi[s, 1])
        if ok.any():
            got = _measure(V, A, B, vfeat, sfeat, v[ok], s[ok], dist)
            kept[0] += len(got[0])
            if kept[0] > MAX_PAIRS:
                raise TooManyPairs(kept[0], MAX_PAIRS)
            out.append(got)
        at = stop


def _measure(V, A, B, vfeat, sfeat, v, s, dist):
    """The candidate pairs (vertex ``v``, segment ``s``) of different features whose exact
    distance is below ``dist``: ``(v, s, d, foot)`` as :func:`close_pairs` returns them."""
    keep = vfeat[v] != sfeat[s]
    s, v = s[keep], v[keep]
    # (rows gathered with take: indexing a 2-column array by an index array costs 15 times as
    # much in NumPy 2.4)
    a = A.take(s, axis=0)
    ab = B.take(s, axis=0) - a
    Vv = V.take(v, axis=0)
    ap = Vv - a
    l2 = np.einsum("ij,ij->i", ab, ab)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(l2 > 0, np.einsum("ij,ij->i", ap, ab) / l2, 0.0), 0.0, 1.0)
    foot = a + t[:, None] * ab
    d = np.hypot(*(Vv - foot).T)
    keep = d < dist
    return v[keep], s[keep], d[keep], foot.compress(keep, axis=0)


def _others_box(lo, hi, feat):
    """For each item's feature ``f``: the box (x0, y0, x1, y1) of the items (boxes ``lo``-``hi``,
    n x 2 each, features ``feat``) of every other feature, and that feature list: ``(fs,
    box)``, box[i] for feature fs[i] (empty where no other feature has items: x0 = inf)."""
    order = np.argsort(feat, kind="stable")
    f = feat[order]
    start = np.flatnonzero(np.r_[True, f[1:] != f[:-1]])
    fs = f[start]
    per = np.hstack([np.minimum.reduceat(lo[order], start), -np.maximum.reduceat(hi[order],
                                                                                start)])
    # the least of the others' minima (and greatest maxima, negated): the least of all, or
    # the second least for the feature that holds the least
    box = np.full(per.shape, np.inf)
    if len(fs) > 1:
        k = np.argsort(per, axis=0, kind="stable")
        first, second = per[k[0], np.arange(4)], per[k[1], np.arange(4)]
        box[:] = first
        box[k[0], np.arange(4)] = second
    box[:, 2:] *= -1
    return fs, box


def _within_others(V, vfeat, lo, hi, sfeat):
    """The vertices (of features ``vfeat``) inside the box of the grown segment boxes
    ``lo``-``hi`` of the other features, and the segments (of features ``sfeat``) whose grown
    box meets the box of the other features' vertices, as index arrays: every (vertex,
    segment) pair of different features within the distance is among them (two features
    side by side keep their facing sides; a bore far inside a gear keeps nothing of the
    gear's 2,500 vertices)."""
    b = _box_of_others(lo, hi, sfeat, vfeat)
    vk = np.flatnonzero((V[:, 0] >= b[:, 0]) & (V[:, 1] >= b[:, 1]) & (V[:, 0] <= b[:, 2])
                        & (V[:, 1] <= b[:, 3]))
    b = _box_of_others(V, V, vfeat, sfeat)
    sk = np.flatnonzero((hi[:, 0] >= b[:, 0]) & (hi[:, 1] >= b[:, 1]) & (lo[:, 0] <= b[:, 2])
                        & (lo[:, 1] <= b[:, 3]))
    return vk, sk


def _box_of_others(lo, hi, feat, want):
    """For each feature of ``want``: the box of the items (boxes ``lo``-``hi``, features
    ``feat``) of every other feature (n x 4: x0, y0, x1, y1)."""
    fs, box = _others_box(lo, hi, feat)
    i = np.minimum(np.searchsorted(fs, want), len(fs) - 1)
    every = [lo[:, 0].min(), lo[:, 1].min(), hi[:, 0].max(), hi[:, 1].max()]
    return np.where((fs[i] == want)[:, None], box[i], [every])   # no items of its own: all


def _band_pairs(V, A, B, dist):
    """Candidate (segment, vertex) pairs: the vertices within ``dist`` of each segment's box
    (y by binary search in the vertices sorted by y, then x), by segment, then by the
    vertices' order in y.  When the bands hold more than :data:`BAND_PER_ITEM` vertices per
    vertex and segment (a round part: each band crosses it from side to side; a gear's
    2,500 vertices, 170,000 candidates), the pairs are found in :func:`_grid_pairs`'s grid
    instead (the same pairs: both keep the vertices inside the grown box, edges included)
    and put in this order, so that every result is the same."""
    order = np.argsort(V[:, 1], kind="stable")
    ys = V[order, 1]
    lo = np.searchsorted(ys, np.minimum(A[:, 1], B[:, 1]) - dist, side="left")
    hi = np.searchsorted(ys, np.maximum(A[:, 1], B[:, 1]) + dist, side="right")
    cnt = np.maximum(hi - lo, 0)
    total = int(cnt.sum())
    if not total:
        return np.zeros(0, np.intp), np.zeros(0, np.intp)
    if total > BAND_PER_ITEM * (len(V) + len(A)):
        s, v = _grid_pairs(V, A, B, dist)
        rank = np.empty(len(V), dtype=np.intp)
        rank[order] = np.arange(len(V))
        k = np.lexsort((rank[v], s))
        return s[k], v[k]
    s = np.repeat(np.arange(len(A)), cnt)
    start = np.cumsum(cnt) - cnt
    v = order[lo[s] + (np.arange(total) - start[s])]
    x = V[v, 0]
    ok = (x >= np.minimum(A[s, 0], B[s, 0]) - dist) & (x <= np.maximum(A[s, 0], B[s, 0]) + dist)
    return s[ok], v[ok]


def _grid_pairs(V, A, B, dist):
    """Candidate (segment, vertex) pairs from a grid over the vertices: the vertices in each
    segment's bounding box grown by ``dist`` (cells of the median segment's length, at least
    ``dist``)."""
    L = np.hypot(*(B - A).T)
    q, p = _Grid(V, max(_median(L), dist, 1e-9)).in_boxes(
        np.minimum(A, B) - dist, np.maximum(A, B) + dist)
    return q, p


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


def boundaries(groups: list, first: int):
    """What :func:`boundary` gives for each group of closed loops ``groups[k]`` with feature
    ``first + k``, concatenated in that order, in a few array operations (not a dozen per
    group: 20,000 holes' regions).  ``(V, vfeat, A, B, sfeat)``."""
    polys, fids = [], []
    for k, loops in enumerate(groups):
        for p in loops:
            p = np.asarray(p, dtype=float).reshape(-1, 2)
            if len(p) >= 2:
                polys.append(p)
                fids.append(first + k)
    if not polys:
        z = np.zeros((0, 2))
        return z, np.zeros(0, np.intp), z, z, np.zeros(0, np.intp)
    V = np.concatenate(polys)
    sizes = np.array([len(p) for p in polys], dtype=np.intp)
    start = np.repeat(np.cumsum(sizes) - sizes, sizes)
    idx = np.arange(len(V))
    B = V[start + (idx - start + 1) % np.repeat(sizes, sizes)]
    f = np.repeat(np.array(fids, dtype=np.intp), sizes)
    return V, f, V, B, f


def faces_apart(faces: list) -> bool:
    """True when no two of ``faces`` (non-empty ``CrossSection`` s) have boxes that meet
    (touching counts as meeting): their union is every face as it is, so it is the same
    however they are grouped.  False for an empty face or too many pairs to list."""
    if any(f.is_empty() for f in faces):
        return False
    b = np.array([f.bounds() for f in faces], float).reshape(-1, 4)
    # first the neighbours in x and in y (O(n log n)): nested boxes (1,000 concentric
    # circles, 500,000 pairs to list) meet their neighbour in either order
    for axis in (0, 1):
        o = np.argsort(b[:, axis], kind="stable")
        lo, hi = b[o, :2], b[o, 2:]
        if len(o) > 1 and np.all((lo[1:] <= hi[:-1]) & (lo[:-1] <= hi[1:]), axis=1).any():
            return False
    try:
        return not len(box_pairs(b))
    except TooManyPairs:
        return False


def meeting(a: list, b: list) -> list:
    """For each shape of ``a`` (CrossSections), the indices (ascending) of the shapes of ``b``
    whose bounding boxes meet its own (touching counts): the only ones it can share area
    with.  By :func:`box_pairs_between` (a grid past a few thousand pairs)."""
    out: list = [[] for _ in a]
    if not a or not b:
        return out
    boxes = [np.array([c.bounds() for c in shapes], dtype=float).reshape(-1, 4)
             for shapes in (a, b)]
    for i, j in box_pairs_between(*boxes):
        out[i].append(int(j))
    for js in out:
        js.sort()
    return out


def components(m: int, a: list, b: list) -> np.ndarray:
    """The connected components of ``m`` nodes joined by the edges ``a[k][i] - b[k][i]``
    (lists of index arrays): for each node the least node of its component.  Union-find by
    rounds, vectorised: every edge whose ends have different roots hooks the greater root to
    the least root it meets, then the roots are compressed by pointer jumping."""
    parent = np.arange(m)
    if not a:
        return parent
    a, b = np.concatenate(a), np.concatenate(b)
    while len(a):
        ra, rb = parent[a], parent[b]
        diff = ra != rb
        if not diff.any():
            break
        a, b, ra, rb = a[diff], b[diff], ra[diff], rb[diff]
        np.minimum.at(parent, np.maximum(ra, rb), np.minimum(ra, rb))
        while True:
            nxt = parent[parent]
            if np.array_equal(nxt, parent):
                break
            parent = nxt
    return parent


def _ranks(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``lo`` and ``hi`` as ranks among their distinct values together (equal values, equal
    ranks): two closed intervals meet exactly when their ranks' do."""
    v = np.sort(np.concatenate([lo, hi]))
    v = v[np.r_[True, v[1:] != v[:-1]]]
    return np.searchsorted(v, lo), np.searchsorted(v, hi)


def box_groups(boxes, pad: float = 0.0) -> np.ndarray:
    """For each of ``boxes`` (n x 4: x0, y0, x1, y1) the least index of the boxes it is
    connected to by boxes that overlap or touch once grown by ``pad`` (the connected
    components of :func:`box_pairs`'s pairs, the same answer), without listing the pairs:
    1,000 nested boxes (concentric circles) are 500,000 pairs, 4,000 more than
    :data:`MAX_PAIRS`.

    A segment tree over the boxes' distinct x values (ranks): each box covers O(log n) nodes
    whole (its canonical nodes) and has its two ends in O(log n) nodes.  Two boxes whose x
    ranges meet have a node that one covers whole and that holds an end of the other (the
    canonical node of the first over the greater of their left ends), where they meet iff
    their y ranges do.  So in each node, the y intervals of the boxes covering it are merged
    into disjoint runs (boxes of one run are connected), and each box with an end in it joins
    every run its y interval meets (the runs between the first and the last it meets are
    joined too): O(n log n) edges in all, by sorts, then :func:`components`."""
    b = np.asarray(boxes, dtype=float).reshape(-1, 4)
    n = len(b)
    if n < 2:
        return np.arange(n)
    lo = np.minimum(b[:, :2], b[:, 2:]) - pad
    hi = np.maximum(b[:, :2], b[:, 2:]) + pad
    x0, x1 = _ranks(lo[:, 0], hi[:, 0])
    y0, y1 = _ranks(lo[:, 1], hi[:, 1])
    size = 1
    while size < int(x1.max()) + 1:
        size *= 2
    # canonical nodes of [x0, x1] (half open [x0, x1 + 1)), bottom up, all boxes at once
    cn, cb = [], []
    left, right, box = x0 + size, x1 + 1 + size, np.arange(n)
    while len(box):
        odd = (left & 1).astype(bool) & (left < right)
        cn.append(left[odd])
        cb.append(box[odd])
        left = left + odd
        odd = (right & 1).astype(bool) & (left < right)
        right = right - odd
        cn.append(right[odd])
        cb.append(box[odd])
        left, right = left >> 1, right >> 1
        keep = left < right
        left, right, box = left[keep], right[keep], box[keep]
    cover_node, cover_box = np.concatenate(cn), np.concatenate(cb)
    # the nodes above each end (both ends of a box: a node holding both counts once)
    en, eb = [], []
    ends = np.concatenate([x0, x1]) + size
    owner = np.concatenate([np.arange(n), np.arange(n)])
    while size >= 1:
        en.append(ends)
        eb.append(owner)
        ends = ends >> 1
        size >>= 1
    end_node, end_box = np.concatenate(en), np.concatenate(eb)
    R = int(max(y1.max(), 0)) + 2            # a node's y keys: node * R + rank, exact
    # the runs of the covering boxes' y intervals in each node
    o = np.lexsort((y0[cover_box], cover_node))
    cnode, cbox = cover_node[o], cover_box[o]
    k0 = cnode * R + y0[cbox]
    k1 = cnode * R + y1[cbox]
    reach = np.maximum.accumulate(k1)        # keys of earlier nodes are all smaller
    new = np.r_[True, k0[1:] > reach[:-1]]
    run = np.cumsum(new) - 1
    first = np.flatnonzero(new)
    run_lo, run_hi = k0[first], np.maximum.reduceat(k1, first)
    rep = cbox[first]                        # a box of each run
    ea, eb_ = [cbox[~new]], [cbox[np.flatnonzero(~new) - 1]]   # within a run: to the one before
    # each end's box against the runs of its nodes
    q0 = end_node * R + y0[end_box]
    q1 = end_node * R + y1[end_box]
    a = np.searchsorted(run_hi, q0, "left")            # the first run reaching up to it
    z = np.searchsorted(run_lo, q1, "right") - 1       # the last run starting below its top
    hit = a <= z
    ea.append(end_box[hit])
    eb_.append(rep[a[hit]])
    joined = np.zeros(len(first) + 1, dtype=np.int64)   # runs a..z joined through the box
    np.add.at(joined, a[hit], 1)
    np.add.at(joined, z[hit], -1)
    chain = np.flatnonzero(np.cumsum(joined)[:-1] > 0)
    ea.append(rep[chain])
    eb_.append(rep[chain + 1])
    del run
    return components(n, ea, eb_)
