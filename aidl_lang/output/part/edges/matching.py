"""Step 1 of the exact recovery (:mod:`.exact`): each result edge of a boolean matched to the
input chord that contains it, over a uniform grid of the chords' samples (:class:`_Grid`), so
a part costs O(n) for n edges; in blocks that bound the memory (:data:`PAIRS_PER_BLOCK`,
:data:`CHORDS_PER_BLOCK`, :data:`EDGES_PER_BLOCK`) and a cap on the candidate pairs that
refuses curves drawn on top of each other (:data:`MAX_CANDIDATES`, :data:`STACKED_HINT`).
"""
from __future__ import annotations


import numpy as np

from ....base.limits import OutOfBudget


PAIRS_PER_BLOCK = 100_000     # candidate (edge, chord) pairs matched at once (~10 MB)


CHORDS_PER_BLOCK = 20_000     # chords sampled into the grid at once (~10 MB)


MAX_SAMPLES = 1_000_000       # chord samples the grid may hold past 16 a chord (~16 MB)


EDGES_PER_BLOCK = 10_000      # result edges looked up in the grid at once (~2 MB)


CARRIERS_PER_EDGE = 8         # chords kept per result edge (the nearest)


STACKED_HINT = ("draw each curve once: copies at the same place (a pattern or template "
                "repeated without moving it) add nothing to the part; this bound is the same "
                "at every `--budget`")


MAX_CANDIDATES = 10_000_000   # candidate pairs in all (OutOfBudget beyond: a few seconds)...


# ... or this many per edge matched, when more: the 2,250,000 edges of 50,000 holes have ~4.5
# each; curves stacked on top of each other give hundreds or thousands
CANDIDATES_PER_EDGE = 16


class _Grid:
    """Chords (A[i] -> B[i], carrier C[i]) sampled into a uniform grid: every chord has a
    sample within half a cell of each of its points, so a query point's chords are among the
    samples of its cell and the eight around it."""

    def __init__(self, A, B, C):
        self.A, self.B, self.C = A, B, C
        m = len(A)
        if not m:
            self.cell = 1.0
            self.keys = np.zeros(0, dtype=np.int64)
            self.chord = np.zeros(0, dtype=np.int64)
            return
        D = B - A
        L = np.hypot(D[:, 0], D[:, 1])
        total = float(L.sum())
        med = float(np.sort(L)[m // 2])
        span = float(max(np.abs(A).max(), np.abs(B).max()))
        lo, hi = np.minimum(A.min(axis=0), B.min(axis=0)), np.maximum(A.max(axis=0), B.max(axis=0))
        # the area of the chords' box per mm of chord: the mean gap between long chords (a
        # grid of n slits across a plate: its pitch).  Cells of the median chord alone were
        # the plate's size there, so every result edge met every slit: a 100 x 100 grid of
        # slits, 40,804 edges x 200 slits, was refused as curves drawn on top of each other
        gap = float(np.prod(np.maximum(hi - lo, 1e-9))) / max(total, 1e-300)
        # cells small enough to hold few chords, few enough that a cell's key fits int64 and
        # the samples number at most about MAX_SAMPLES (or 16 a chord)
        self.cell = h = max(min(med, gap), total / max(16 * m + 1024, MAX_SAMPLES), 1e-6,
                            span / 2 ** 30)
        ns = np.maximum(1, np.ceil(L / h).astype(np.int64))           # pieces per chord
        # the samples' cells, CHORDS_PER_BLOCK chords at a time: the sample points of all
        # chords at once were the largest temporaries of a compile (issue 26)
        keys, chord = [], []
        for b in range(0, m, CHORDS_PER_BLOCK):
            k, c = self._samples(A, D, ns, b, min(m, b + CHORDS_PER_BLOCK))
            keys.append(k)
            chord.append(c)
        keys, chord = np.concatenate(keys), np.concatenate(chord)
        order = np.argsort(keys, kind="stable")
        self.keys = keys[order]
        self.chord = chord[order]

    def _samples(self, A, D, ns, first: int, stop: int) -> tuple[np.ndarray, np.ndarray]:
        """``(cell keys, chord)`` of the samples of chords ``first:stop``: ``ns[i] + 1``
        points evenly along chord ``i`` (both ends included)."""
        n = ns[first:stop]
        chord = np.repeat(np.arange(first, stop), n + 1)
        start = np.cumsum(n + 1) - (n + 1)
        t = (np.arange(len(chord)) - np.repeat(start, n + 1)) / np.repeat(n, n + 1)
        # (rows gathered with take: indexing a 2-column array by an index array costs 15
        # times as much in NumPy 2.4)
        return self._key(A.take(chord, axis=0) + D.take(chord, axis=0) * t[:, None]), chord

    def _key(self, S, dx=0, dy=0):
        ix = np.floor(S[:, 0] / self.cell).astype(np.int64) + dx
        iy = np.floor(S[:, 1] / self.cell).astype(np.int64) + dy
        return ix * 4_294_967_311 + iy

    def _candidates(self, P, Q, tol, lo, cnt, first: int):
        """``(q, k)``: the query edges ``first + i`` (``P[q] -> Q[q]``) and the carriers of the
        chords that hold them within ``tol`` (either way round), among the candidates
        ``lo``/``cnt`` of these edges."""
        qs, cs = [], []
        for j in range(len(cnt)):
            c_ = cnt[j]
            tot = int(c_.sum())
            if not tot:
                continue
            qs.append(first + np.repeat(np.arange(len(c_)), c_))
            off = np.arange(tot) - np.repeat(np.cumsum(c_) - c_, c_)
            cs.append(self.chord[np.repeat(lo[j], c_) + off])
        if not qs:
            return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
        q = np.concatenate(qs)
        c = np.concatenate(cs)
        # np.unique without importing numpy.ma; sorted stably: the pairs come in three runs of
        # ascending edges (one per column of cells), which a merge sort takes 3 times faster
        pair = np.sort(q * len(self.A) + c, kind="stable")
        pair = pair[np.r_[True, pair[1:] != pair[:-1]]]
        q, c = pair // len(self.A), pair % len(self.A)
        a, b = self.A.take(c, axis=0), self.B.take(c, axis=0)      # = A[c], B[c] (faster)
        d = b - a
        L = np.hypot(d[:, 0], d[:, 1])
        ok = L > 0
        u = d / np.where(ok, L, 1.0)[:, None]
        p, e = P.take(q, axis=0) - a, Q.take(q, axis=0) - a
        dp = np.abs(u[:, 0] * p[:, 1] - u[:, 1] * p[:, 0])
        de = np.abs(u[:, 0] * e[:, 1] - u[:, 1] * e[:, 0])
        tp = u[:, 0] * p[:, 0] + u[:, 1] * p[:, 1]
        te = u[:, 0] * e[:, 0] + u[:, 1] * e[:, 1]
        ok &= (dp <= tol) & (de <= tol) & (tp >= -tol) & (te >= -tol) & (tp <= L + tol) & \
            (te <= L + tol)                    # either way round: a hole runs backwards
        q, k, off = q[ok], self.C[c[ok]], (dp + de)[ok]
        # keep the CARRIERS_PER_EDGE nearest chords of an edge: more are curves within
        # MATCH_TOL of each other (5 000 circles 1e-9 mm apart), and each would be kept
        order = np.lexsort((off, q))
        q, k = q[order], k[order]
        group = np.flatnonzero(np.r_[True, q[1:] != q[:-1]])
        rank = np.arange(len(q)) - np.repeat(group, np.diff(np.r_[group, len(q)]))
        keep = rank < CARRIERS_PER_EDGE
        return q[keep], k[keep]

    def _cells(self, M) -> tuple[np.ndarray, np.ndarray]:
        """``(lo, cnt)``, each 3 x len(M): the samples in the cell of point ``M[i]`` and in the
        eight around it are ``self.chord[lo[j, i]:lo[j, i] + cnt[j, i]]``, j = 0..2: one
        column of three cells each (a cell's key is its column times a number larger than any
        row's, plus its row, so the three rows of a column are one slice of the sorted
        keys)."""
        lo = np.empty((3, len(M)), dtype=np.int64)
        cnt = np.empty((3, len(M)), dtype=np.int64)
        for j, dx in enumerate((-1, 0, 1)):
            lo[j] = np.searchsorted(self.keys, self._key(M, dx, -1), "left")
            cnt[j] = np.searchsorted(self.keys, self._key(M, dx, 1), "right") - lo[j]
        return lo, cnt

    def match(self, P, Q, tol) -> np.ndarray:
        """The carrier of each query edge ``P[i] -> Q[i]`` (N x 2 each, mm): that of a chord
        holding it within ``tol`` (mm) either way round, -1 for none (see the module
        docstring); raises :class:`~aidl_lang.base.limits.OutOfBudget` past
        :data:`MAX_CANDIDATES` candidate pairs (or :data:`CANDIDATES_PER_EDGE` per edge).
        The edges are looked up in the order of their midpoints' cells (a search of the
        sorted cell keys in sorted order walks the table once: ten times faster than in the
        polygons' order at 900,000 edges); the answer is the same in any order."""
        n = len(P)
        if not len(self.keys):
            return np.full(n, -1, dtype=np.int64)
        order = np.argsort(self._key((P + Q) / 2), kind="stable")
        cid, multi = self._match_sorted(P.take(order, axis=0), Q.take(order, axis=0), tol)
        out = np.empty(n, dtype=np.int64)
        out[order] = cid
        if multi:
            _settle(out, {int(order[qi]): ks for qi, ks in multi.items()})
        return out

    def _match_sorted(self, P, Q, tol) -> tuple[np.ndarray, dict]:
        """:meth:`match` of edges in the order of their cells: each edge's first carrier
        (the least index) and ``{edge: [carriers, ascending]}`` of the edges several
        carriers hold (edges numbered as given), for :func:`_settle`."""
        n = len(P)
        cid = np.full(n, -1, dtype=np.int64)
        # each query edge's candidate chords: the samples of its midpoint's cell and the eight
        # around it (_cells); first only how many, to refuse before any work is done.  The
        # cells found are kept for the matching (int32 where the table allows: 24 bytes an
        # edge, less than the midpoints kept before; looked up again there, 20,000 holes'
        # 900,000 edges: 0.42 -> 0.21 s)
        wide = np.int64 if len(self.keys) >= 2 ** 31 else np.int32
        LO = np.empty((3, n), dtype=wide)
        CNT = np.empty((3, n), dtype=wide)
        for b in range(0, n, EDGES_PER_BLOCK):
            LO[:, b:b + EDGES_PER_BLOCK], CNT[:, b:b + EDGES_PER_BLOCK] = \
                self._cells((P[b:b + EDGES_PER_BLOCK] + Q[b:b + EDGES_PER_BLOCK]) / 2)
        ends = np.cumsum(CNT.sum(axis=0, dtype=np.int64))
        most = max(MAX_CANDIDATES, CANDIDATES_PER_EDGE * n)
        if ends[-1] > most:
            raise OutOfBudget(f"more than {most:,} (edge, chord) pairs to match "
                              "(thousands of curves drawn on top of each other)",
                              "the exact outlines", hint=STACKED_HINT)
        # the queries in blocks of at most PAIRS_PER_BLOCK candidate pairs, so that memory
        # stays bounded however many chords lie on top of each other
        qs, ks = [], []
        at = 0
        while at < n:
            base = ends[at - 1] if at else 0
            stop = max(at + 1, int(np.searchsorted(ends, base + PAIRS_PER_BLOCK, "right")))
            stop = min(stop, at + EDGES_PER_BLOCK)
            q, k = self._candidates(P, Q, tol, LO[:, at:stop], CNT[:, at:stop], at)
            qs.append(q)
            ks.append(k)
            at = stop
        q = np.concatenate(qs)
        k = np.concatenate(ks)
        if not len(q):
            return cid, {}
        # several chords may hold one (short) edge, where curves meet: keep them all for now
        first = np.full(n, -1, dtype=np.int64)
        order = np.lexsort((k, q))
        q, k = q[order], k[order]
        starts = np.flatnonzero(np.r_[True, q[1:] != q[:-1]])
        first[q[starts]] = k[starts]
        multi = np.r_[q[1:] == q[:-1], False] | np.r_[False, q[1:] == q[:-1]]
        cand: dict = {}
        for qi, ki in zip(q[multi].tolist(), k[multi].tolist()):
            cand.setdefault(qi, []).append(ki)
        return first, cand


def _settle(cid: np.ndarray, cand: dict) -> None:
    """An edge several chords hold (a short edge where curves meet: ``cand`` ``{edge:
    [carriers]}``) takes the carrier it shares with a neighbouring edge of ``cid`` (the edges
    in order, each after the ones before it settled), else its first."""
    n = len(cid)
    for qi in sorted(cand):
        ks = cand[qi]
        for nb in (int(cid[qi - 1]), int(cid[(qi + 1) % n])):
            if nb in ks:
                cid[qi] = nb
                break
