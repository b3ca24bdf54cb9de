"""The linear algebra the solver's diagnostics read a Jacobian with: the greedy rank-revealing
pass (:func:`dependencies`), ranks and null spaces by blocks of rows that share unknowns
(:func:`null_support`, :func:`_block_rank`, :func:`_dense_block_rank`, :func:`_peeled_rows`,
:func:`_dense_cut`), and the cost check before a dense factorisation (:func:`_dense_refused`).

Read by :mod:`..diagnosis` (conflicts, freedom, redundancy, sliding) and by :mod:`.holds` (which
held values a hold may keep).  Dense up to :data:`DENSE_CELLS` cells (numpy only: a cold
``aidl check`` does not import SciPy); SciPy's sparse matrices past it.  Imports the base and
:mod:`.arrays` only.
"""
from __future__ import annotations

import numpy as np

from ...base.limits import now
from .arrays import unique


MAX_DENSE = 5000


# a dense SVD of m x n costs about m n min(m, n) flops: past this (5-10 s on the test machine;
# 2 500 chained points, 2 499 x 5 000, took 80 s and 1 GB) the count is "not counted"
MAX_SVD_FLOPS = 1e10


# what a dense SVD is assumed to cost per second (a low figure for a busy machine): one that
# would end past the run's deadline is not started (the structure is "not counted")
SVD_FLOPS_PER_SECOND = 1e9


DENSE_CELLS = 250_000    # a structure's Jacobian up to this many cells is ranked densely


def _components(J) -> np.ndarray:
    """A component label per row of the sparse ``J``: rows sharing an unknown are connected."""
    import scipy.sparse as sp
    from scipy.sparse.csgraph import connected_components
    m = J.shape[0]
    B = sp.bmat([[None, J], [J.T, None]]).tocsr()
    _, lab = connected_components(B, directed=False)
    return lab[:m]


def _dense_components(J: np.ndarray) -> np.ndarray:
    """The same labels as :func:`_components` for a dense ``J`` (union-find over its nonzeros,
    no SciPy)."""
    m, n = J.shape
    parent = list(range(m + n))

    def find(a: int) -> int:
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    for r, c in zip(*np.nonzero(J)):
        a, b = find(int(r)), find(m + int(c))
        if a != b:
            parent[a] = b
    return np.array([find(i) for i in range(m)], dtype=np.int64)


def _dense_block_rank(J: np.ndarray) -> int:
    """:func:`_block_rank` for a dense ``J`` (one SVD per block of rows sharing unknowns).

    A block of one row (most blocks of a sketch: a held dimension, a coordinate) is ranked
    without an SVD: its one singular value is the row's 2-norm, and the rank is 1 when that
    exceeds ``1e-9 max(1, norm)``.  Only a finite norm at least twice or at most half the
    threshold is decided so (LAPACK's value and NumPy's differ by a few ulps at most); a
    row near it, or not finite, takes the SVD as before."""
    if J.shape[0] == 0:
        return 0
    lab = _dense_components(J)
    single = np.flatnonzero(np.bincount(lab)[lab] == 1)
    rank = 0
    if len(single):
        R = J[single]
        norms = np.sqrt((R * R).sum(axis=1))
        sure = np.isfinite(norms) & ((norms >= 2e-9) | (norms <= 0.5e-9))
        rank += int(np.count_nonzero(sure & (norms >= 2e-9)))
        lab[single[sure]] = -1                          # counted: no SVD for these
    for k in unique(lab):
        if k < 0:
            continue
        sub = J[lab == k]
        sub = sub[:, np.any(sub != 0, axis=0)]
        if sub.shape[1] == 0:
            continue
        sv = np.linalg.svd(sub, compute_uv=False)
        rank += int(np.sum(sv > 1e-9 * max(1.0, float(sv[0]))))
    return rank


NOT_COUNTED_SIZE, NOT_COUNTED_TIME = -1, -2     # the ranks that say why a count was not made


def null_support(J, deadline: float | None = None) -> tuple[int, np.ndarray]:
    """``(rank, moving)`` of a sparse Jacobian ``J`` (rows x columns): its numerical rank and,
    per column, whether some direction of its null space moves that unknown (the entities
    ``--dof`` lists as floating); rank -1 when what is left for the SVD is larger than
    :data:`MAX_DENSE` or :data:`MAX_SVD_FLOPS`, -2 when it would end past ``deadline``.

    First the columns every null vector leaves at 0 are found by propagation, in
    O(non-zeros): a row whose only non-negligible entry outside the already *determined*
    columns is in column ``c`` forces ``v_c = 0`` for any null vector ``v`` (its other terms
    vanish), so ``c`` is determined too — a fixed anchor determines the points chained to
    it, one constraint after another.  Only the rest ``U`` needs the SVD:
    ``null(J) = {v : v_D = 0, J[:, U] v_U = 0}``, so ``rank(J) = |D| + rank(J[:, U])``.  A
    pivot must be at least 1e-6 of its row's largest entry and entries below 1e-12 of it
    count as zero, so what propagation neglects moves an unknown by at most 1e-6 of a unit
    step, the threshold below which the SVD's null space counts it as still.  A gear pair
    of 6 000 unknowns was one 3 000-column SVD per gear (38 s); propagated, its blocks are
    small."""
    import scipy.sparse as sp
    J = sp.csr_matrix(J)
    n_rows, n_cols = J.shape
    moving = np.zeros(n_cols, dtype=bool)
    if n_cols == 0:
        return 0, moving
    absd = np.abs(J.data)
    row_of = np.repeat(np.arange(n_rows), np.diff(J.indptr))
    row_max = np.zeros(n_rows)
    np.maximum.at(row_max, row_of, absd)
    live = absd > 1e-12 * row_max[row_of]          # entries that count
    R = sp.csr_matrix((np.where(live, J.data, 0.0), J.indices.copy(), J.indptr.copy()),
                      shape=J.shape)                # its own arrays: eliminate_zeros edits them
    R.eliminate_zeros()
    C = R.tocsc()
    count = np.diff(R.indptr).astype(np.int64)      # live entries in undetermined columns
    determined = np.zeros(n_cols, dtype=bool)
    todo = list(np.flatnonzero(count == 1))
    while todo:
        r = todo.pop()
        if count[r] != 1:
            continue
        lo, hi = R.indptr[r], R.indptr[r + 1]
        k = next(k for k in range(lo, hi) if not determined[R.indices[k]])
        c = R.indices[k]
        if abs(R.data[k]) < 1e-6 * row_max[r]:
            continue                                # too small to pivot on: left to the SVD
        determined[c] = True
        for rr in C.indices[C.indptr[c]:C.indptr[c + 1]]:
            count[rr] -= 1
            if count[rr] == 1:
                todo.append(rr)
    U = np.flatnonzero(~determined)
    if not len(U):
        return n_cols, moving
    sub = C[:, U].tocsr()
    sub = sub[np.flatnonzero(np.diff(sub.indptr))]
    if sub.shape[0] > MAX_DENSE or len(U) > MAX_DENSE or _svd_too_large(*sub.shape) \
            or _svd_too_late(*sub.shape, deadline):
        rank_u, moves = _sparse_null_support(sub, deadline)
        if rank_u < 0:
            return rank_u, moving
        moving[U] = moves
        return n_cols - len(U) + rank_u, moving
    if sub.shape[0] == 0:
        moving[U] = True
        return n_cols - len(U), moving
    # the thin SVD (Vt: min(rows, columns) x columns): its first rank_u rows span the row
    # space, and a column moves when e_c is not in it, when the rest of its unit length,
    # 1 - |Vt[:rank_u, c]|^2, is the null space's share (the full SVD's n x n Vt, for 2 500
    # points 5 000 x 5 000, took 80 s and 1 GB)
    _, sv, Vt = np.linalg.svd(sub.toarray(), full_matrices=False)
    rank_u = int(np.sum(sv > 1e-9 * max(1.0, float(sv[0]) if len(sv) else 1.0)))
    if len(U) > rank_u:
        rest = 1.0 - np.einsum("ij,ij->j", Vt[:rank_u], Vt[:rank_u])
        moving[U] = rest > 1e-12
    return n_cols - len(U) + rank_u, moving


PROBES = 16        # random vectors projected on the null space by _sparse_null_support


def _sparse_null_support(A, deadline: float | None = None) -> tuple[int, np.ndarray]:
    """:func:`null_support`'s ``(rank, moving)`` of a sparse ``A`` too large for one dense
    SVD (issue 37: 2 500 chained points, a 2 499 x 5 000 SVD).

    The rank: the rows independent of all others by structure are peeled off
    (:func:`_peeled_rows`; a chain peels to nothing) and the rest, the *core*, is ranked by
    the greedy pass (:func:`dependencies`), which also names the core's dependent rows.
    Without those, ``B`` (``r`` x ``n``) has full row rank, and the projection of a vector
    ``z`` on the null space is the ``v`` of the saddle-point system
    ``[[I, B^T], [B, 0]] [v; y] = [z; 0]`` (one sparse LU, SuperLU).  A column moves when
    the null space has a share of it, ``|P e_c|^2 > 1e-12`` as for the SVD; that share is
    the mean of ``v_c^2`` over random Gaussian ``z`` (:data:`PROBES` of them, a fixed seed:
    the same answer every run), which for a share 100 times the threshold falls below it
    with a probability under ``1e-20``.  Rank -1 when the core is too large for the greedy
    pass or the system is too ill-conditioned to trust (``B v`` not ~0), -2 past
    ``deadline``."""
    import scipy.sparse as sp
    from scipy.sparse.linalg import splu
    A = sp.csr_matrix(A, copy=True)
    A.eliminate_zeros()
    A = A[np.flatnonzero(np.diff(A.indptr))]        # rows of explicit zeros say nothing
    m, n = A.shape
    if m == 0:
        return 0, np.ones(n, dtype=bool)
    peeled = _peeled_rows(A)
    keep = np.flatnonzero(peeled)
    core = np.flatnonzero(~peeled)
    if len(core):
        Ac = A[core]
        cc = unique(Ac.indices)
        if len(core) > MAX_DENSE or len(cc) > MAX_DENSE or _svd_too_large(len(core), len(cc)):
            return NOT_COUNTED_SIZE, np.zeros(n, dtype=bool)
        Ad = Ac[:, cc].toarray()
        dependent = {r for r, _, _ in dependencies(Ad, list(range(len(core))), deadline)}
        if deadline is not None and now() > deadline:
            return NOT_COUNTED_TIME, np.zeros(n, dtype=bool)
        norm = np.linalg.norm(Ad, axis=1)         # rows the greedy pass skips: nothing to add
        independent = [i for i in range(len(core))
                       if i not in dependent and norm[i] > 0 and np.isfinite(norm[i])]
        keep = np.sort(np.concatenate([keep, core[independent]]))
    B = A[keep]
    r = B.shape[0]
    if r >= n:
        return r, np.zeros(n, dtype=bool)
    if deadline is not None and now() > deadline:
        return NOT_COUNTED_TIME, np.zeros(n, dtype=bool)
    K = sp.bmat([[sp.identity(n), B.T], [B, None]], format="csc")
    try:
        lu = splu(K)
        Z = np.random.default_rng(0).standard_normal((n, PROBES))
        V = lu.solve(np.vstack([Z, np.zeros((r, PROBES))]))[:n]
    except RuntimeError:                             # singular: the rank was misjudged
        return NOT_COUNTED_SIZE, np.zeros(n, dtype=bool)
    scale = max(1.0, float(abs(B).max())) * max(1.0, float(np.abs(V).max(initial=0.0)))
    if not np.all(np.isfinite(V)) or float(np.abs(B @ V).max(initial=0.0)) > 1e-8 * scale:
        return NOT_COUNTED_SIZE, np.zeros(n, dtype=bool)
    return r, (V * V).mean(axis=1) > 1e-12


def _dense_refused(m: int, n: int, deadline: float | None, k: int = 0) -> str:
    """Why a dense factorisation of an ``m`` x ``n`` matrix (after a projection on ``k``
    basis rows, ``2 m n k`` flops more) must not start: ``"too large"`` past
    :data:`MAX_SVD_FLOPS`, ``"out of time"`` when it would end past ``deadline`` at
    :data:`SVD_FLOPS_PER_SECOND`; ``""`` when it may.  LAPACK cannot be interrupted, so every
    SVD of the diagnostics asks first (issue 48)."""
    flops = float(m) * float(n) * float(min(m, n)) + 2.0 * m * n * k
    if flops > MAX_SVD_FLOPS:
        return "too large"
    if deadline is not None and now() + flops / SVD_FLOPS_PER_SECOND > deadline:
        return "out of time"
    return ""


def _svd_too_large(m: int, n: int) -> bool:
    """Whether a dense SVD of ``m`` x ``n`` would cost more than :data:`MAX_SVD_FLOPS`."""
    return float(m) * float(n) * float(min(m, n)) > MAX_SVD_FLOPS


def _svd_too_late(m: int, n: int, deadline: float | None) -> bool:
    """Whether a dense SVD of ``m`` x ``n`` would end past ``deadline`` (:func:`aidl_lang.base.limits.now`: CPU seconds;
    None: never), at :data:`SVD_FLOPS_PER_SECOND`."""
    if deadline is None:
        return False
    flops = float(m) * float(n) * float(min(m, n))
    return now() + flops / SVD_FLOPS_PER_SECOND > deadline


def _row_entries(W, rows) -> tuple[np.ndarray, np.ndarray]:
    """The stored entries of rows ``rows`` of the CSR ``W``: each one's position in
    ``W.data``/``W.indices``, and the index in ``rows`` of its row."""
    rows = np.asarray(rows, dtype=np.int64)
    starts, counts = W.indptr[rows], W.indptr[rows + 1] - W.indptr[rows]
    at = np.repeat(starts - np.cumsum(counts) + counts, counts) + np.arange(counts.sum())
    return at, np.repeat(np.arange(len(rows)), counts)


def _dense_cut(W, wcols: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Rows ``rows`` and columns ``cols`` (parameters, increasing, all in ``wcols``) of the
    Jacobian ``W`` (dense, or CSR over the parameters ``wcols``) as a dense array, read
    straight from the compressed rows (SciPy's indexing costs ~0.5 ms a call)."""
    if isinstance(W, np.ndarray):
        return W[rows][:, np.searchsorted(wcols, cols)]
    at, row = _row_entries(W, rows)
    param = wcols[W.indices[at]]
    col = np.minimum(np.searchsorted(cols, param), max(len(cols) - 1, 0))
    mine = cols[col] == param if len(cols) else np.zeros(len(param), dtype=bool)
    J = np.zeros((len(rows), len(cols)))
    J[row[mine], col[mine]] = W.data[at[mine]]
    return J


def _block_rank(J, deadline: float | None = None) -> int:
    """Numerical rank of a sparse Jacobian, block by block (rows that share no unknown are
    independent), so a large sketch of small independent pieces needs only small SVDs;
    -1 if one block is too large for a dense SVD, -2 if one would end past ``deadline``."""
    import scipy.sparse as sp
    J = sp.csr_matrix(J)
    if J.shape[0] == 0:
        return 0
    J, rank = _peel(J)
    if J.shape[0] == 0:
        return rank
    lab = _components(J)
    for k in unique(lab):
        r = np.flatnonzero(lab == k)
        sub = J[r]
        c = unique(sub.indices)
        if len(r) > MAX_DENSE or len(c) > MAX_DENSE or _svd_too_large(len(r), len(c)):
            return NOT_COUNTED_SIZE
        if _svd_too_late(len(r), len(c), deadline):
            return NOT_COUNTED_TIME
        sv = np.linalg.svd(sub[:, c].toarray(), compute_uv=False)
        if len(sv):
            rank += int(np.sum(sv > 1e-9 * max(1.0, float(sv[0]))))
    return rank


def _peel(J):
    """``(core, k)``: the rows of the sparse ``J`` (CSR) that the rank needs an SVD for, and
    the number ``k`` of rows peeled off, each independent of all the others
    (:func:`_peeled_rows`).  A pattern of 5 000 copies was one 15 000-row block (an SVD of
    minutes); peeled, nothing is left to decompose."""
    import scipy.sparse as sp
    J = sp.csr_matrix(J)
    peeled = _peeled_rows(J)
    if not peeled.any():
        return J, 0
    return sp.csr_matrix(J[np.flatnonzero(~peeled)]), int(peeled.sum())


def _peeled_rows(J, lab: np.ndarray | None = None) -> np.ndarray:
    """Per row of the sparse ``J``, whether it is independent of all the other rows by
    structure alone: a row holding the only non-zero of some column (a pattern copy's
    ``x_k - x_0 - k dx``, a point that only one constraint places, the last link of a
    chain) is in no combination of rows that vanishes (``y^T J = 0`` forces ``y_r = 0`` at
    that column), so ``rank(J) = 1 + rank(J without it)``; peeling repeats while such
    columns appear, in O(non-zeros).  A chain of 2 500 ``Distance``s peels to nothing.  A
    pivot must be more than ``1e-9`` of its row's largest entry (entries below ``1e-12``
    of the matrix's largest count as zero); a smaller one is left to the dense rank.

    ``lab``: a component label per row (rows of different components share no column): the
    rows of every component are peeled at once, each entry compared with its own
    component's largest, as if each component were peeled on its own."""
    import scipy.sparse as sp
    J = sp.csr_matrix(J, copy=True)
    size = np.abs(J.data)
    if lab is None:
        J.data[size <= 1e-12 * max(1.0, float(size.max(initial=0.0)))] = 0.0
    else:
        of = lab[np.repeat(np.arange(J.shape[0]), np.diff(J.indptr))]
        largest = np.zeros(int(lab.max(initial=-1)) + 1)
        np.maximum.at(largest, of, size)
        J.data[size <= 1e-12 * np.maximum(1.0, largest[of])] = 0.0
    J.eliminate_zeros()
    C = J.tocsc()
    n_rows, n_cols = J.shape
    row_alive = np.ones(n_rows, dtype=bool)
    count = np.diff(C.indptr).astype(np.int64)
    row_max = np.zeros(n_rows)
    np.maximum.at(row_max, np.repeat(np.arange(n_rows), np.diff(J.indptr)), np.abs(J.data))
    todo = list(np.flatnonzero(count == 1))
    indptr, indices = J.indptr, J.indices
    cptr, crow, cval = C.indptr, C.indices, C.data
    while todo:
        c = todo.pop()
        if count[c] != 1:
            continue
        for k in range(cptr[c], cptr[c + 1]):
            r = crow[k]
            if row_alive[r]:
                break
        else:
            continue
        if abs(cval[k]) <= 1e-9 * row_max[r]:
            continue                    # too small to pivot on: leave it to the SVD
        row_alive[r] = False
        for j in indices[indptr[r]:indptr[r + 1]]:
            count[j] -= 1
            if count[j] == 1:
                todo.append(j)
    return ~row_alive


DEP_TOL = 1e-7


def dependencies(J: np.ndarray, order: list[int], deadline: float | None = None,
                 basis: dict | None = None):
    """Greedy rank-revealing pass over the rows of dense ``J`` in ``order``.

    Yields ``(row, support, coef)`` for each row that is a combination of earlier independent
    rows, ``support`` being those rows (their coefficient is not negligible) and ``coef`` their
    coefficients.

    Classical Gram-Schmidt with re-orthogonalisation, vectorised: the orthonormal basis ``Q``
    and the lower-triangular ``L`` with ``J[indep] = L Q`` grow one row at a time, so a
    dependent row's coefficients come from one triangular solve ``L^T c = Q v`` instead of a
    least-squares problem; a row's projection only touches the basis vectors that overlap it.
    Cost O(rows x rank x overlap): well under a second for a few thousand rows of a sparse
    Jacobian (benchmarks/solver/bench_diagnose.py).  Past ``deadline`` (:func:`aidl_lang.base.limits.now`: CPU seconds,
    looked at before every row) it stops early: one row costs at most ``3 rank n`` flops, so
    the pass needs no estimate before it starts.

    ``basis``: a dict that receives ``"Q"`` (the orthonormal basis, one row per independent
    row, growing) and ``"indep"`` (those rows, in ``order``): after the pass,
    ``Q[:len(indep)]`` spans the rows taken, and its first ``j`` rows span the first ``j``
    independent rows of ``order`` (what :func:`~.redundancy.redundancies` measures the
    constructors' span with)."""
    m, n = J.shape
    cap = min(m, n)
    Q = np.zeros((cap, n))
    L = np.zeros((cap, cap))
    indep: list[int] = []
    if basis is not None:
        basis["Q"], basis["indep"] = Q, indep
    k = 0
    for step, r in enumerate(order):
        if deadline is not None and now() > deadline:
            return
        v = np.asarray(J[r], dtype=float)
        nv = float(np.linalg.norm(v))
        if nv == 0.0 or not np.isfinite(nv):
            continue
        a = np.zeros(k)
        w = v.copy()
        for _ in range(2):              # twice for stability
            if not k:
                break
            nz = np.flatnonzero(w)
            if len(nz) * 4 < n:
                d = Q[:k, nz] @ w[nz]
            else:
                d = Q[:k] @ w
            hit = np.flatnonzero(d)
            if len(hit):
                w -= Q[hit].T @ d[hit]
                a[hit] += d[hit]
        nw = float(np.linalg.norm(w))
        if nw > DEP_TOL * nv and k < cap:
            Q[k] = w / nw
            L[k, :k] = a
            L[k, k] = nw
            indep.append(r)
            k += 1
            continue
        if not k:
            continue
        c = _solve_upper(L[:k, :k].T, a)
        big = np.abs(c) > 1e-6 * max(1.0, float(np.max(np.abs(c))))
        yield r, [indep[i] for i in np.flatnonzero(big)], c[big]


def _solve_upper(U: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``U^-1 b`` for an upper-triangular ``U``: SciPy's triangular solve for a large basis,
    NumPy's general solve for a small one (no SciPy import on a plain ``aidl check``)."""
    if len(b) <= 200:
        return np.linalg.solve(U, b)
    from scipy.linalg import solve_triangular
    return solve_triangular(U, b, lower=False, check_finite=False)
