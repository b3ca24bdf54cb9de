"""Why a solve failed, and what is still free: conflict sets, redundancy, degrees of freedom.

All three read the Jacobian ``J`` (rows: residuals, columns: unknowns) at a point:

* **Conflicts.**  Rows are taken in a fixed order (constructor-held dimensions first, then the
  user's constraints in source order) and added to a basis one by one (a rank-revealing
  Gram-Schmidt, the greedy form of a column-pivoted QR of ``J^T``).  A row that adds no rank is a
  combination of earlier rows; the least-squares coefficients of that combination name the
  rows it depends on.  If any row of that dependent set is unsatisfied, the set is a *conflict*
  (an over-constrained, inconsistent system): those constraints cannot all hold, and no smaller
  subset of the basis explains the dependency.  If all are satisfied, the later row is merely
  *redundant* (consistent, a warning).
* **Degrees of freedom.**  For each structure, its own unknowns plus its children's frames,
  against its own constraints and those of its ancestors that use these unknowns (a parent's
  ``CenterInside(bore, self)`` places the hole's geometry), everything else held at the
  solution: ``dof = unknowns - rank(J)``; a parameter whose column has a
  component in the null space of ``J`` is not determined, and its geometry (or child) *floats*.

Dense linear algebra: used for one structure's system, or for the connected component of a
failed system that holds the unsatisfied rows (capped at :data:`MAX_DENSE` rows).  SciPy (sparse
matrices, connected components) is imported only for systems larger than
:data:`DENSE_CELLS`: the freedom count on ``aidl check``'s ok line stays in numpy, so a cold
check does not pay SciPy's import.
"""
from __future__ import annotations

import time

import numpy as np

from ..records import Compared
from .arrays import unique

from ..geometry.model import Constraint
from .system import user_residuals

DEP_TOL = 1e-7
MAX_DENSE = 5000
# a dense SVD of m x n costs about m n min(m, n) flops: past this (5-10 s on the test machine;
# 2 500 chained points, 2 499 x 5 000, took 80 s and 1 GB) the count is "not counted"
MAX_SVD_FLOPS = 1e10
# what a dense SVD is assumed to cost per second (a low figure for a busy machine): one that
# would end past the run's deadline is not started (the structure is "not counted")
SVD_FLOPS_PER_SECOND = 1e9
DENSE_CELLS = 250_000    # a structure's Jacobian up to this many cells is ranked densely
MAX_CONFLICTS = 10       # conflict sets collected per failed system (the report shows 3)


class Conflict(Compared):
    """Constraints that cannot all hold together: ``[(Constraint, residual)]``."""
    __slots__ = ("items",)

    def __init__(self, items: list | None = None):
        self.items = [] if items is None else items

    @property
    def constraints(self) -> list[Constraint]:
        return [c for c, _ in self.items]


class Redundant(Compared):
    """``constraint`` is implied by ``by`` (consistent: a warning, not an error)."""
    __slots__ = ("constraint", "by", "partly")

    def __init__(self, constraint: Constraint, by: list, partly: bool = False):
        self.constraint = constraint
        self.by = by
        self.partly = partly  # only some of the constraint's equations are implied


def _order_key(c: Constraint, r: int):
    sp_ = c.span
    pos = (sp_.line, sp_.col) if sp_ is not None else (0, 0)
    return (0 if c.implicit else 1, pos, r)


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
    Jacobian (benchmarks/bench_diagnose.py).  Past ``deadline`` (``time.monotonic()``,
    looked at before every row) it stops early: one row costs at most ``3 rank n`` flops, so
    the pass needs no estimate before it starts.

    ``basis``: a dict that receives ``"Q"`` (the orthonormal basis, one row per independent
    row, growing) and ``"indep"`` (those rows, in ``order``): after the pass,
    ``Q[:len(indep)]`` spans the rows taken, and its first ``j`` rows span the first ``j``
    independent rows of ``order`` (what :func:`redundancies` measures the constructors'
    span with)."""
    m, n = J.shape
    cap = min(m, n)
    Q = np.zeros((cap, n))
    L = np.zeros((cap, cap))
    indep: list[int] = []
    if basis is not None:
        basis["Q"], basis["indep"] = Q, indep
    k = 0
    for step, r in enumerate(order):
        if deadline is not None and time.monotonic() > deadline:
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


def _pin_closure(solver, rows: np.ndarray, x: np.ndarray):
    """The pinning rows that ``rows`` (solver rows) reach: ``(vars, pin_rows)``, the pinned
    parameters the rows read and every pinned parameter those are computed from (increasing),
    and, per parameter, the row of :attr:`~.hierarchy.Solver.rows_built` that pins it.

    Pinned geometry (:func:`~.system.pinned`) is held at values its own rows fix, and those
    rows are dropped from the solve; other rows may still read it (a bounding box of a gear,
    a ``Distance`` to a fixed point).  With ``P`` the pinning rows (square and triangular on
    the pinned columns, zero elsewhere) and ``O`` the solve's rows, every dependency
    ``y^T J = 0`` of the whole system is one of ``O``'s over the free columns (``y_O``) with
    ``y_P^T = -y_O^T O_P P^-1``: its pinning rows are those of the parameters ``O`` reads and
    of the parameters these are computed from, no others.  So a conflict or a dependency found
    on ``rows`` plus this closure is the one the unpinned system has, with every constraint
    it involves named.  Empty arrays when nothing pinned is read."""
    pins = solver.pins
    none = np.zeros(0, dtype=np.int64)
    if not len(pins) or not len(rows):
        return none, none
    pv = pins.var
    order = np.argsort(pv)
    pv_sorted = pv[order]
    if len(rows) * len(pv) <= DENSE_CELLS:          # numpy only (no SciPy on a cold check)
        Jr = solver.tape(rows).jacobian(x, pv_sorted, dense=True)
        read = np.flatnonzero(np.any(Jr != 0, axis=0))
    else:
        Jr = solver.tape(rows).jacobian(x, pv_sorted).tocoo()
        read = unique(np.asarray(Jr.col[Jr.data != 0], dtype=np.int64))
    if not len(read):
        return none, none
    row_of = {int(v): int(r) for v, r in zip(pv_sorted, pins.row[order])}
    todo = pv_sorted[read].tolist()
    seen = set(todo)
    while todo:
        v = todo.pop()
        r = row_of[v]
        for u in pins.cols[pins.indptr[r]:pins.indptr[r + 1]].tolist():
            if u != v and u in row_of and u not in seen:
                seen.add(u)
                todo.append(u)
    vs = np.array(sorted(seen), dtype=np.int64)
    return vs, np.array([row_of[v] for v in vs.tolist()], dtype=np.int64)


def _with_pins(solver, t, rows: np.ndarray, cols: np.ndarray, x: np.ndarray,
               dense: bool | None = None):
    """``(J, cols_all, pin_rows)``: the Jacobian of the solver rows ``rows`` (tape ``t``)
    over ``cols`` and the pinned parameters they reach, with the pinning rows that reach
    them (:func:`_pin_closure`, rows of :attr:`~.hierarchy.Solver.rows_built`) appended
    below, over ``cols_all`` (increasing).  Dense (NumPy only) when ``dense``, or when
    ``dense`` is None and it has at most :data:`DENSE_CELLS` cells; else CSR."""
    pvars, prows = _pin_closure(solver, rows, x)
    cols_all = unique(np.concatenate([np.asarray(cols, dtype=np.int64), pvars])) \
        if len(pvars) else np.asarray(cols, dtype=np.int64)
    m = len(rows) + len(prows)
    if dense is None:
        dense = m * len(cols_all) <= DENSE_CELLS
    if dense and not len(cols_all):
        return np.zeros((m, 0)), cols_all, prows
    J = t.jacobian(x, cols_all, dense=dense)
    if not len(prows):
        return J, cols_all, prows
    pins = solver.pins
    lo, hi = pins.indptr[prows], pins.indptr[prows + 1]
    n = hi - lo
    at = np.repeat(lo - np.cumsum(n) + n, n) + np.arange(int(n.sum()))
    r = np.repeat(np.arange(len(prows)), n)
    c = np.searchsorted(cols_all, pins.cols[at])
    if dense:
        P = np.zeros((len(prows), len(cols_all)))
        np.add.at(P, (r, c), pins.vals[at])
        return np.vstack([J, P]), cols_all, prows
    import scipy.sparse as sp
    P = sp.csr_matrix((pins.vals[at], (r, c)), shape=(len(prows), len(cols_all)))
    return sp.vstack([J, P]).tocsr(), cols_all, prows


def conflicts(solver, rows: np.ndarray, cols: np.ndarray, x: np.ndarray,
              tol: float = 1e-6) -> list[Conflict]:
    """The conflicting constraint sets of the system ``rows`` x ``cols`` at ``x``, together
    with the pinning rows it reaches (:func:`_pin_closure`): a ``Distance`` between two
    ``Fixed`` points conflicts with both ``Fixed``, pinned or not."""
    t = solver.tape(rows)
    F = t.evaluate(x)
    user = user_residuals(solver, rows, F, x)
    bad = np.abs(F) > tol
    if not bad.any():
        return []
    J, _, prows = _with_pins(solver, t, rows, cols, x, dense=False)
    cons = [solver.rows.constraint[r] for r in rows]
    keys = rows.tolist()
    if len(prows):
        F = np.concatenate([F, np.zeros(len(prows))])       # a pinned value holds its row
        user = np.concatenate([user, np.zeros(len(prows))])
        bad = np.concatenate([bad, np.zeros(len(prows), dtype=bool)])
        built = solver.rows_built.constraint
        cons += [built[r] for r in prows.tolist()]
        keys += (len(solver.rows.exprs) + prows).tolist()
    lab = _components(J)
    local = np.flatnonzero(np.isin(lab, unique(lab[bad])))
    if len(local) > MAX_DENSE:
        return []
    Jd = J[local].toarray()
    Jd = Jd[:, np.any(Jd != 0, axis=0)]
    cons = [cons[i] for i in local]
    order = sorted(range(len(local)), key=lambda i: _order_key(cons[i], keys[local[i]]))
    out: list[Conflict] = []
    seen: set = set()
    Fl = F[local]
    deadline = getattr(solver, "deadline", None)
    # the greedy pass looks at the deadline before every row: no estimate needed
    for r, support, coef in dependencies(Jd, order, deadline):
        if len(out) >= MAX_CONFLICTS or (deadline is not None and time.monotonic() > deadline):
            break                        # the best sets found so far
        members = [r] + support
        # a dependency J_r = sum c_i J_i is consistent when the residuals obey it too
        # (F_r = sum c_i F_i: the error is merely spread over the set); otherwise the rows
        # demand different things: a conflict
        gap = abs(Fl[r] - float(coef @ Fl[support])) if len(support) else abs(Fl[r])
        if gap <= tol:
            continue
        per: dict[int, list] = {}
        for i in members:
            c = cons[i]
            e = per.setdefault(id(c), [c, 0.0])
            e[1] = max(e[1], float(user[local[i]]))
        key = frozenset(per)
        if key in seen or len(per) < 2:
            continue
        seen.add(key)
        items = sorted(per.values(), key=lambda cv: _order_key(cv[0], 0))
        out.append(Conflict([(c, v) for c, v in items]))
    # the smallest sets first
    out.sort(key=lambda k: len(k.items))
    return out


class StructureDof(Compared):
    """Remaining freedom of one structure's own sketch (its unknowns and children's frames)."""
    __slots__ = ("structure", "unknowns", "rank", "floating", "why")

    def __init__(self, structure: object, unknowns: int, rank: int, floating: list | None = None,
                 why: str = ""):
        self.structure = structure
        self.unknowns = unknowns
        self.rank = rank  # -1: not counted (``why`` says why)
        self.floating = [] if floating is None else floating  # labels of undetermined entities
        self.why = why  # "too large" or "out of time"

    @property
    def dof(self) -> int:
        return self.unknowns - self.rank


def degrees_of_freedom(solver, floating: bool = True,
                       deadline: float | None = None) -> list[StructureDof]:
    """Per-structure degrees of freedom and floating entities, at the solver's current point
    (call after solving).  ``floating=False`` counts only (singular values, no null space:
    what the summary line of ``aidl check`` needs).  Past ``deadline`` (``time.monotonic()``,
    the run's end), or where a dense SVD would end past it (at
    :data:`SVD_FLOPS_PER_SECOND`), a structure is not counted: rank -1, ``why`` "out of
    time" (or "too large" past :data:`MAX_SVD_FLOPS`).

    For the count, the model's whole Jacobian is formed once (:attr:`~.hierarchy.Solver.whole`,
    every row against every structure's columns; dense up to :data:`DENSE_CELLS` cells, else
    sparse) and each structure's block is cut out of it: the same entries, bit for bit, as
    the structure's own tape gives (each entry sums the same terms in the same order),
    without compiling or evaluating a tape per structure."""
    model = solver.model
    x = solver.x
    out = []
    label_of = {}
    if floating:
        for g in model.all_geometry():
            for p in g.points.values():
                label_of[p.ix] = label_of[p.iy] = g.label
            for s in g.scalars.values():
                label_of[s.index] = g.label
            # a drawing's circles are the drawing (one rigid body, issue 49): named as it
            for c in _drawing_circles(g):
                for p in c.points.values():
                    label_of[p.ix] = label_of[p.iy] = g.label
    axis = [-1] * len(solver.x)           # per parameter: a point's x 0, its y 1, else -1
    for g in model.all_geometry():
        for c in _drawing_circles(g):
            for p in c.points.values():
                axis[p.ix], axis[p.iy] = 0, 1
        for p in g.points.values():
            axis[p.ix], axis[p.iy] = 0, 1
    systems = []                       # (structure, params, rows, cols)
    touching = _ancestor_rows(solver, x)
    for s in model.structures:
        params = list(solver.own.get(id(s), ()))
        for c in s.children.values():
            params += [i for i in solver.frame.get(id(c), ())]
            if floating:
                for i in solver.frame.get(id(c), ()):
                    label_of[i] = f"{c.path} (position)"
        rows = solver.rows_of([s])
        if touching is not None and s.parent is not None and params:
            rows = touching(s, rows, params)
        sl = solver.slack[rows] if len(rows) else np.zeros(0, dtype=np.int64)
        cols = unique(np.concatenate([np.asarray(params, dtype=np.int64), sl[sl >= 0]]))
        systems.append((s, params, rows, cols))
    whole = None
    if not floating:
        whole = _whole_jacobian(solver, x, [c for s, _, r, c in systems if len(r) and len(c)])
    held = _held_by_rigid(model)
    pinned = solver.pinned_by
    pinned_axes: dict[int, set] = {}      # id(structure) -> axes of its pinned points
    owner = model.param_owner
    for v, _ in solver.pins:
        if axis[v] >= 0:
            pinned_axes.setdefault(id(owner[v]), set()).add(axis[v])
    for s, params, rows, cols in systems:
        if deadline is not None and time.monotonic() > deadline and len(rows) and len(cols) \
                and id(s) not in held:
            d = StructureDof(s, len(params), -1, why="out of time")
        else:
            d = _dof_of(solver, model, s, params, rows, cols, whole, held, label_of, floating,
                        axis, pinned_axes.get(id(s), ()), deadline)
        k = pinned.get(id(s), 0)
        if k:
            # geometry pinned in s's frame (system.pinned) is held by the solver, but it is
            # still s's geometry: k unknowns that s's own rows fix (a square invertible block
            # that no other row touches): k more unknowns, k more rank, nothing floats
            d.unknowns += k
            if d.rank >= 0:
                d.rank += k
        out.append(d)
    return out


def _drawing_circles(g) -> list:
    """The construction Circles of a ``Drawing2D`` (its ``circles[i]``; not in its
    structure's geometry list), else none."""
    return g.data.get("circles", ()) if g.kind == "Drawing2D" else ()


def _dof_of(solver, model, s, params, rows, cols, whole, held, label_of, floating,
            axis, pinned_axes, deadline) -> StructureDof:
    """One structure's :class:`StructureDof` (see :func:`degrees_of_freedom`); ``axis`` and
    ``pinned_axes`` as :func:`_gauge_shifts` takes them, ``deadline`` as
    :func:`degrees_of_freedom`."""
    x = solver.x
    n_unknowns = len(params)
    if id(s) in held:
        # ``Rigid(s)`` (or a rigid ancestor): its shapes keep their placement to each
        # other and to its frame, which alone moves (the parent counts it): nothing inside
        # floats
        return StructureDof(s, n_unknowns, n_unknowns)
    if not len(cols):
        return StructureDof(s, 0, 0)
    if not len(rows):
        gauge = _gauge_shifts(solver, s, np.zeros((0, len(cols))), cols, axis, pinned_axes)
        if not gauge:
            free = (sorted({label_of.get(i, model.param_label[i]) for i in params})
                    if floating else [])
            return StructureDof(s, n_unknowns, 0, free)
        rows_t = np.array(gauge)          # no row: only the frame's shift to leave out
        if not floating:
            return StructureDof(s, n_unknowns, len(gauge))
        rank, moving = null_support(rows_t)
        pos = {int(c): k for k, c in enumerate(cols)}
        free = sorted({label_of.get(i, model.param_label[i]) for i in params
                       if moving[pos[i]]})
        return StructureDof(s, n_unknowns, rank - (len(cols) - n_unknowns), free)
    if not floating:
        if len(rows) * len(cols) <= DENSE_CELLS:
            if whole is not None:
                J = _dense_cut(*whole, rows, cols)
            else:
                J = solver.tape(rows).jacobian(x, cols, dense=True)
            rank = _dense_block_rank(J)
        else:
            J = solver.tape(rows).jacobian(x, cols)
            rank = _block_rank(J, deadline)
        if rank < 0:
            return StructureDof(s, n_unknowns, -1, why=_why_not(rank))
        rank += len(_gauge_shifts(solver, s, J, cols, axis, pinned_axes))
        return StructureDof(s, n_unknowns, rank - (len(cols) - n_unknowns))
    J = solver.tape(rows).jacobian(x, cols)
    gauge = _gauge_shifts(solver, s, J, cols, axis, pinned_axes)
    if gauge:
        import scipy.sparse as sp
        J = sp.vstack([sp.csr_matrix(J), sp.csr_matrix(np.array(gauge))])
    rank, moving = null_support(J, deadline)
    if rank < 0:
        return StructureDof(s, n_unknowns, -1, why=_why_not(rank))
    # slack columns each come with a LINK row of full rank: they neither add nor remove
    n_slack = len(cols) - n_unknowns
    free = []
    if moving.any():
        pos = {int(c): k for k, c in enumerate(cols)}
        free = sorted({label_of.get(i, model.param_label[i])
                       for i in params if moving[pos[i]]})
    return StructureDof(s, n_unknowns, rank - n_slack, free)


def _gauge_shifts(solver, s, J, cols, axis: list, pinned_axes=()) -> list:
    """The shifts of all of structure ``s``'s content (its own points and its children's
    frames) along x and along y, as vectors over ``cols`` (sorted), that change no row of
    ``J``: each is the move of ``s``'s frame, which its parent counts (a frame shifted one way
    and its contents the other change nothing drawn), so ``s``'s own count leaves it out
    (issue 38: a part of 3 structures in an assembly of 1 counted its one placement 3 times,
    6 freedoms for 2).  Only for a structure whose frame is an unknown (not the root's).
    ``axis``: per parameter, 0 for a point's x, 1 for its y, -1 otherwise.  ``pinned_axes``:
    the axes of ``s``'s points pinned in its frame (:func:`~.system.pinned`): their dropped rows
    fix them in the frame, so they see a shift along that axis, and it is no frame move."""
    if s.parent is None or not (0 <= s.fx < len(solver.free) and solver.free[s.fx]):
        return []
    pos = {c: k for k, c in enumerate(cols.tolist())}
    own = solver.own.get(id(s), ())
    children = s.children.values()
    scale = None
    out = []
    for a in (0, 1):
        if a in pinned_axes:
            continue
        k = [pos[i] for i in own if axis[i] == a and i in pos]
        k += [pos[i] for i in ((c.fx, c.fy)[a] for c in children) if i in pos]
        if not k:
            continue
        if J.shape[0]:
            if scale is None:
                scale = max(1.0, float(abs(J).max()))
            if np.abs(np.asarray(J[:, k].sum(axis=1), dtype=float)).max() > 1e-9 * scale:
                continue                # some row sees the shift: not the frame's move
        t = np.zeros(len(cols))
        t[k] = 1.0
        out.append(t)
    return out


def _held_by_rigid(model) -> set:
    """The ids of the structures whose inside ``Rigid`` holds: each rigid structure and every
    structure below it (the solver moves them only by the rigid structure's frame,
    :func:`aidl_lang.solver.hierarchy._rigid_below`)."""
    out: set = set()
    todo = [s for s in model.structures if getattr(s, "rigid", False)]
    while todo:
        t = todo.pop()
        if id(t) in out:
            continue
        out.add(id(t))
        todo += t.children.values()
    return out


NOT_COUNTED_SIZE, NOT_COUNTED_TIME = -1, -2     # the ranks that say why a count was not made


def _why_not(rank: int) -> str:
    return "out of time" if rank == NOT_COUNTED_TIME else "too large"


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
        if deadline is not None and time.monotonic() > deadline:
            return NOT_COUNTED_TIME, np.zeros(n, dtype=bool)
        norm = np.linalg.norm(Ad, axis=1)         # rows the greedy pass skips: nothing to add
        independent = [i for i in range(len(core))
                       if i not in dependent and norm[i] > 0 and np.isfinite(norm[i])]
        keep = np.sort(np.concatenate([keep, core[independent]]))
    B = A[keep]
    r = B.shape[0]
    if r >= n:
        return r, np.zeros(n, dtype=bool)
    if deadline is not None and time.monotonic() > deadline:
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
    if deadline is not None and time.monotonic() + flops / SVD_FLOPS_PER_SECOND > deadline:
        return "out of time"
    return ""


def _svd_too_large(m: int, n: int) -> bool:
    """Whether a dense SVD of ``m`` x ``n`` would cost more than :data:`MAX_SVD_FLOPS`."""
    return float(m) * float(n) * float(min(m, n)) > MAX_SVD_FLOPS


def _svd_too_late(m: int, n: int, deadline: float | None) -> bool:
    """Whether a dense SVD of ``m`` x ``n`` would end past ``deadline`` (``time.monotonic()``;
    None: never), at :data:`SVD_FLOPS_PER_SECOND`."""
    if deadline is None:
        return False
    flops = float(m) * float(n) * float(min(m, n))
    return time.monotonic() + flops / SVD_FLOPS_PER_SECOND > deadline


def _ancestor_rows(solver, x: np.ndarray):
    """``touching(s, rows, params)``: structure ``s``'s own ``rows`` and the rows of its
    ancestors that use one of ``params`` (its own unknowns and its children's frames), in
    increasing order; ``None`` when no structure has a parent.

    A parent may constrain its descendants' geometry (``CenterInside(bore, self)`` reads the
    hole's circle; validity rule 2): at the solution those rows pin the child's unknowns as
    much as the child's own constraints do, so the count holds them too (issue 23: a hole
    placed by its parent was counted, and listed by ``--dof``, as floating).  The rows are
    found from the sparsity of the whole model's Jacobian (one evaluation over every free
    column)."""
    model = solver.model
    if not any(s.parent is not None for s in model.structures):
        return None
    cols = np.flatnonzero(solver.free)
    if not len(cols):
        return None
    whole = solver.whole
    if whole.n_rows * len(cols) <= DENSE_CELLS:       # numpy only (no SciPy on a cold check)
        nz_r, nz_c = np.nonzero(whole.jacobian(x, cols, dense=True).T)
        indices, indptr = nz_c, np.searchsorted(nz_r, np.arange(len(cols) + 1))
    else:
        C = whole.jacobian(x, cols).tocsc()
        indices, indptr = C.indices, C.indptr
    n_rows = whole.n_rows
    where = np.full(len(solver.free), -1, dtype=np.int64)
    where[cols] = np.arange(len(cols))
    # the structure each row belongs to (its index in model.structures), so that "is this
    # row an ancestor's?" costs the depth of the tree, not the ancestors' rows (a sorted list
    # of them per structure was quadratic: a 10 000-copy pattern took 31 s and 2.6 GB)
    number = {id(a): i for i, a in enumerate(model.structures)}
    owner = np.full(n_rows, -1, dtype=np.int64)
    for a in model.structures:
        if a.children:
            owner[np.asarray(solver.rows_of([a]), dtype=np.int64)] = number[id(a)]

    def touching(s, rows: np.ndarray, params: list) -> np.ndarray:
        chain = []
        a = s.parent
        while a is not None:
            chain.append(number[id(a)])
            a = a.parent
        if not chain:
            return rows
        k = where[np.asarray(params, dtype=np.int64)]
        k = k[k >= 0]
        if not len(k):
            return rows
        # the rows that use one of the unknowns (a few per unknown), kept where an ancestor's
        used = np.concatenate([indices[indptr[j]:indptr[j + 1]] for j in k]).astype(np.int64)
        of = owner[used]
        hit = np.zeros(len(used), dtype=bool)
        for a in chain:
            hit |= of == a
        extra = used[hit]
        if not len(extra):
            return rows
        both = np.sort(np.concatenate([np.asarray(rows, dtype=np.int64), extra]))
        return both[np.concatenate([[True], both[1:] != both[:-1]])]

    return touching


def _whole_jacobian(solver, x: np.ndarray, col_sets: list):
    """``(J, cols)``: the Jacobian of every row of the model against the union ``cols``
    (increasing) of ``col_sets``: dense up to :data:`DENSE_CELLS` cells, else sparse (CSR;
    :func:`_dense_cut` reads a structure's block out of it).  One tape for the whole model,
    not one per structure: a model of 1,000 parts compiled 1,000 tapes (0.6 s)."""
    if not col_sets:
        return None
    whole = solver.whole
    cols = unique(np.concatenate(col_sets))
    return whole.jacobian(x, cols, dense=whole.n_rows * len(cols) <= DENSE_CELLS), cols


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


def freedom_text(dofs: list[StructureDof], slide: "Sliding | None" = None) -> str:
    """``fully constrained`` or ``N degrees of freedom left, see --dof`` for a whole model
    (structures too large for the dense rank count are reported as unknown); with ``slide``
    (:func:`sliding`) it says what is free: ``N degrees of freedom left (free: hole `bore`
    can slide along x), see --dof`` or ``(free: only where the whole part sits
    (harmless))``."""
    if any(d.rank < 0 for d in dofs):
        why = ("model too large" if any(d.why == "too large" for d in dofs if d.rank < 0)
               else "out of time")
        return f"degrees of freedom not counted ({why}), see --dof"
    n = sum(max(0, d.dof) for d in dofs)
    if n == 0:
        return "fully constrained"
    said = sliding_text(slide) if slide is not None else ""
    if said.startswith("free: only") and n != sum(len(a.split(", ")) for _, a in slide.placement):
        said = "no hole, drawing or solid child slides against its part"   # shapes inside may
    return (f"{n} degree{'s' if n != 1 else ''} of freedom left"
            + (f" ({said})" if said else "") + ", see --dof")


def redundancies(solver, deadline: float | None = None,
                 max_rows: int = MAX_DENSE, skipped: list | None = None,
                 why: set | None = None) -> list[Redundant]:
    """User constraints that other constraints already imply, over the whole model's
    unknowns: what W0401 reports.

    What it measures (issue 23): for a constraint ``C`` with rows ``J_C`` (its equations'
    gradients; rows with no unknown left out) among all rows ``J``,

    * ``C`` is **redundant** when removing it keeps the rank, ``rank(J without C) ==
      rank(J)``: every equation of ``C`` follows from the others, so dropping it frees
      nothing;
    * ``C`` is **partly redundant** when it still pins something but some of what it says
      also follows from the others: ``rank(J_C) + rank(J without C) > rank(J)`` (its row space
      meets theirs), with ``J_C`` taken modulo the constructors' rows (the held shapes).  So
      ``Fixed(body)`` of a rectangle, which fixes every corner while the corners follow from
      the center through the rectangle's own shape, is not "partly redundant": beyond the
      shape it says two things (the center), and both count.

    Both come from one basis of the left null space of ``J`` (a vector ``y`` with
    ``y^T J = 0`` per dependent row of the greedy rank-revealing pass, :func:`dependencies`):
    with ``N_C`` that basis restricted to ``C``'s rows, ``rank(J) - rank(J without C) =
    |C| - rank(N_C)``.  ``by`` names the other constraints in the dependencies that touch
    ``C``.  A constraint whose every equation involves no unknown and holds (``r.width == 30``
    with the width held by the constructor) follows from the held values (``by`` empty).

    The flat system is split into connected components (rows sharing unknowns); each, up to
    :data:`MAX_DENSE` rows, is ranked densely.  Only consistent systems are looked at (a
    failed solve reports conflicts instead).  Past ``deadline`` (``time.monotonic()``) the
    blocks not yet ranked are left out, and so are blocks of more than ``max_rows`` rows
    (after the rows independent of all others by structure are peeled off,
    :func:`_peeled_rows`); the user constraints so left out are appended to ``skipped``, and
    the reasons (``"out of time"``, ``"too large"``) added to ``why``.  No dense
    factorisation is started without its cost estimated first (:func:`_dense_refused`): one
    that would pass :data:`MAX_SVD_FLOPS` or end past ``deadline`` leaves its constraint out
    ("too large" / "out of time") instead of running past the budget (issue 48: a gear pair
    under a ``Below`` spent 99 s in one SVD of 6,264 columns).  The constructors' span that
    "partly redundant" is measured against is the greedy pass's own basis (its first rows:
    the constructors' rows come first in its order), not a separate SVD.  NumPy only while the
    Jacobian has at most :data:`DENSE_CELLS` cells, so plain ``aidl check`` does not import
    SciPy for it."""
    rows = np.arange(len(solver.rows.exprs), dtype=np.int64)
    rows = rows[solver.kind[rows] == 0]
    if not len(rows):
        return []
    cols = np.flatnonzero(solver.free)
    t = solver.tape(rows)
    x = solver.x
    F = t.evaluate(x)
    # the pinning rows the solve's rows reach take part (see _pin_closure): a dependency
    # through pinned geometry names its pinning constraints, as without pinning
    J, cols, prows = _with_pins(solver, t, rows, cols, x)
    cons = [solver.rows.constraint[r] for r in rows]
    keys = rows
    in_closure: dict[int, int] = {}         # id(constraint) -> its pinning rows taken here
    if len(prows):
        built = solver.rows_built.constraint
        extra = [built[r] for r in prows.tolist()]
        for c in extra:
            in_closure[id(c)] = in_closure.get(id(c), 0) + 1
        cons += extra
        keys = np.concatenate([rows, len(solver.rows.exprs) + prows])
        F = np.concatenate([F, np.zeros(len(prows))])       # a pinned value holds its row
        rows = np.arange(len(keys), dtype=np.int64)         # positions in J from here on
    dense = isinstance(J, np.ndarray)
    if dense:
        lab = _dense_components(J) if J.shape[1] else np.arange(J.shape[0])
        norms = np.sqrt((J * J).sum(axis=1))
    else:
        lab = _components(J)
        norms = np.sqrt(np.asarray(J.multiply(J).sum(axis=1)).ravel())
    live = norms > 0.0                      # a row with no unknown left: held values only
    if not dense:
        # rows independent of all others by structure take no part in any dependency (a
        # chain of 2 500 Distances peels to nothing): peeled once, every block at a time
        peeled = np.zeros(len(rows), dtype=bool)
        peeled[live] = _peeled_rows(J[live], lab[live])
        position = np.arange(J.shape[1])        # J's columns are positions in ``cols``
    by_c: dict[int, list[int]] = {}
    for i, c in enumerate(cons):
        by_c.setdefault(id(c), []).append(i)
    contribution: dict[int, int] = {}       # rank(J) - rank(J without C), summed over blocks
    rank_c: dict[int, int] = {}             # rank(J_C)
    by: dict[int, list] = {}
    unknown: dict = {}                      # id(constraint) -> why it was not searched

    def leave_out(ids, reason: str) -> None:
        for k_ in ids:
            unknown.setdefault(k_, reason)
    for comp in unique(lab[live]):
        local = np.flatnonzero((lab == comp) & live)
        if deadline is not None and time.monotonic() > deadline:
            leave_out((id(cons[i]) for i in local), "out of time")
            continue
        if len(local) == 1:                 # one row, independent of all others
            k = id(cons[local[0]])
            contribution[k] = contribution.get(k, 0) + 1
            rank_c[k] = rank_c.get(k, 0) + 1
            continue
        lc = [cons[i] for i in local]
        if dense:
            Jd = J[local]
            Jd = Jd[:, np.any(Jd != 0, axis=0)]
            core = np.arange(len(local))
        else:
            core = np.flatnonzero(~peeled[local])     # only these are decomposed
            Jd = None
            block = unique(J.indices[_row_entries(J, local)[0]])    # the block's columns
        if len(core) > min(max_rows, MAX_DENSE):
            leave_out((id(cons[i]) for i in local), "too large")
            continue
        null = []
        gs: dict = {}                       # the greedy pass's basis
        colmask = None
        if len(core):
            Jk = Jd[core] if Jd is not None else _dense_cut(J, position, local[core], block)
            colmask = np.any(Jk != 0, axis=0)
            Jk = Jk[:, colmask]
            order = sorted(range(len(core)),
                           key=lambda i: _order_key(lc[core[i]], int(keys[local[core[i]]])))
            null = [(int(core[r]), [int(core[i]) for i in support], coef)
                    for r, support, coef in dependencies(Jk, order, deadline, gs)]
        if deadline is not None and time.monotonic() > deadline:
            leave_out((id(cons[i]) for i in local), "out of time")  # the basis may be incomplete
            continue
        # the constructors' rows lead the greedy order, so the first basis rows span them (the
        # peeled ones are independent of every other row and change no rank: left out)
        in_core = np.zeros(len(local), dtype=bool)
        in_core[core] = True
        n_imp = 0
        for i in gs.get("indep", ()):
            if not lc[core[i]].implicit:
                break
            n_imp += 1
        Qi = gs["Q"][:n_imp] if n_imp else None

        def dense_rows(ii: list[int]) -> np.ndarray:
            return Jd[ii] if Jd is not None else _dense_cut(J, position, local[ii], block)
        mine: dict[int, list[int]] = {}
        for i, c in enumerate(lc):
            mine.setdefault(id(c), []).append(i)
        touched: dict[int, list[int]] = {}          # constraint -> the dependencies it is in
        for n_, (r, support, _) in enumerate(null):
            for k in {id(lc[i]) for i in [r, *support]}:
                touched.setdefault(k, []).append(n_)
        # the constructors' rows: what a constraint says beyond them is measured modulo
        # their span (the greedy pass's first basis rows ``Qi``), see rank_c
        for k, idx in mine.items():
            if deadline is not None and time.monotonic() > deadline:
                leave_out((id(c) for c in lc), "out of time")  # a block is reported whole or not
                break
            pos = {i: j for j, i in enumerate(idx)}
            M = []
            others: list = []
            named = {k}                     # ids in ``others`` (and k): linear, not a scan
            for n_ in touched.get(k, ()):
                r, support, coef = null[n_]
                v = np.zeros(len(idx))
                if r in pos:
                    v[pos[r]] += 1.0
                for i, cf in zip(support, coef):
                    if i in pos:
                        v[pos[i]] -= cf
                M.append(v)
                for i in [r, *support]:
                    if id(lc[i]) not in named:
                        named.add(id(lc[i]))
                        others.append(lc[i])
            if M:
                refused = _dense_refused(len(M), len(idx), deadline)
                if refused:
                    leave_out([k], refused)
                    continue
            rM = _rank(np.array(M)) if M else 0
            gain = len(idx) - rM
            contribution[k] = contribution.get(k, 0) + gain
            if rM:
                lst = by.setdefault(k, [])
                have = {id(o) for o in lst}
                lst += [o for o in others if id(o) not in have]
            if rM == 0 or gain == 0 or lc[idx[0]].implicit:
                # independent of every other row (no overlap: rank beyond the shapes = gain),
                # or fully implied (reported as such whatever its own rank)
                rank_c[k] = rank_c.get(k, 0) + gain
                continue
            # rank of C's rows modulo the constructors' span: each peeled row is independent
            # of every other row (1 each); the core rows, projected off ``Qi``
            mine_core = [i for i in idx if in_core[i]]
            peeled_c = len(idx) - len(mine_core)
            r_core = 0
            if mine_core:
                n_cols = int(colmask.sum())
                refused = _dense_refused(len(mine_core), n_cols, deadline, n_imp)
                if refused:
                    leave_out([k], refused)
                    continue
                Jc = dense_rows(mine_core)[:, colmask]
                if Qi is not None:
                    for _ in range(2):          # twice, as the greedy pass does
                        Jc = Jc - (Jc @ Qi.T) @ Qi
                r_core = _rank(Jc)
            rank_c[k] = rank_c.get(k, 0) + peeled_c + r_core
    out: list[Redundant] = []
    seen: set = set()
    # a row that pins geometry (system.pinned; dropped from the solve) is one independent
    # row of its own: it counts as the rows of a one-row block above do
    pinned = solver.pinned_rows
    for i, c in enumerate(cons):
        k = id(c)
        if c.implicit or k in seen:
            continue
        if k in unknown:
            seen.add(k)
            if skipped is not None:
                skipped.append(c)
            if why is not None:
                why.add(unknown[k])
            continue
        seen.add(k)
        mine_rows = by_c[k]
        p = pinned.get(k, 0) - in_closure.get(k, 0)
        if not p and not any(live[j] for j in mine_rows):
            if all(abs(F[j]) <= 1e-9 for j in mine_rows):
                out.append(Redundant(c, []))        # follows from held values alone
            continue
        gain, rk = contribution.get(k, 0) + p, rank_c.get(k, 0) + p
        if gain == 0:
            out.append(Redundant(c, _explicit_first(by.get(k, []))))
        elif rk > gain:
            out.append(Redundant(c, _explicit_first(by.get(k, [])), partly=True))
    return out


def _explicit_first(cs: list) -> list:
    return sorted(cs, key=lambda c: (c.implicit, _order_key(c, 0)))


def _rank(A: np.ndarray) -> int:
    """Numerical rank of a small dense matrix (singular values above ``1e-9`` of the
    largest, or above ``1e-6`` for the combination coefficients' matrices, see callers)."""
    if A.size == 0:
        return 0
    sv = np.linalg.svd(A, compute_uv=False)
    return int(np.sum(sv > 1e-7 * max(1.0, float(sv[0]))))


class Sliding(Compared):
    """What the freedom left means (issue 35): ``placement`` the parts whose whole body can
    still move (``[(part, "x"|"y"|"x, y")]``: where the part sits, harmless), ``features``
    the structures inside a part that can move relative to it (``[(structure, axes)]``)."""
    __slots__ = ("placement", "features", "constrained", "bounded")

    def __init__(self, placement: list | None = None, features: list | None = None,
                 constrained: set | None = None, bounded: set | None = None):
        self.placement = [] if placement is None else placement
        self.features = [] if features is None else features
        # ids of features some row places; ids of features that slide only within
        self.constrained = set() if constrained is None else constrained
        self.bounded = set() if bounded is None else bounded
        #                                                 inequalities not reached (Inside, ...)


def _parts(model) -> list:
    """The parts: the root when it is a solid (or drawing), else the solids of its
    assemblies."""
    root = model.root
    if root is None:
        return []
    if root.kind != "assembly":
        return [root]
    out, todo = [], list(root.children.values())
    while todo:
        t = todo.pop(0)
        if t.kind == "assembly":
            todo += t.children.values()
        elif t.kind in ("solid", "drawing"):
            out.append(t)
    return out


def sliding(solver) -> Sliding:
    """Which whole parts and which features can translate, at the solution: structure ``t``
    slides along x when the move ``t.frame.x += 1`` (for a root without a frame: each of its
    own points and children's frames) changes no row, except rows of an inactive inequality
    (its slack is positive: the bound is not reached).  One product of the whole model's
    Jacobian with each candidate move: linear in the model's size.  A feature is reported
    only where its parent does not slide the same way with it."""
    model = solver.model
    out = Sliding()
    parts = _parts(model)
    # only the columns a move touches: every frame, and the points of a part without one
    # (the rows' other unknowns stay put); a few columns, so the Jacobian is dense and small
    need = np.zeros(len(solver.free), dtype=bool)
    need[:len(solver.is_frame)] |= solver.is_frame
    for g in model.all_geometry():
        if g.owner in parts and g.owner.parent is None:
            for pt in g.points.values():
                need[pt.ix] = need[pt.iy] = True
    cols = np.flatnonzero(need & solver.free)
    if not parts or not len(cols):
        return out
    x = solver.x
    whole = solver.whole
    if whole.n_rows * len(cols) <= DENSE_CELLS:
        J = whole.jacobian(x, cols, dense=True)
        scale = np.abs(J).max(axis=1) if J.shape[1] else np.zeros(J.shape[0])
    else:       # by columns: each move and each part reads a few of them
        J = whole.jacobian(x, cols).tocsc()
        scale = np.asarray(abs(J).max(axis=1).todense()).ravel()
    slack = solver.slack[:J.shape[0]] if len(solver.slack) >= J.shape[0] else None
    loose = np.zeros(J.shape[0], dtype=bool)
    if slack is not None:
        has = slack >= 0
        loose[has] = x[slack[has]] > 1e-9           # an inequality whose bound is not reached
    where = np.full(len(solver.free), -1, dtype=np.int64)
    where[cols] = np.arange(len(cols))
    px: dict = {}
    for g in model.all_geometry():
        for p in g.points.values():
            px.setdefault(id(p.owner), []).append((p.ix, p.iy))

    def move(t, axis: int):
        v = np.zeros(len(cols))
        f = (t.fx, t.fy)[axis]
        if t.parent is not None and 0 <= f < len(where) and where[f] >= 0:
            v[where[f]] = 1.0
            return v
        if t.parent is not None:
            return None                             # a held frame: it does not slide
        for pt in px.get(id(t), ()):
            k = where[pt[axis]]
            if k < 0:
                return None                         # a held point: the whole cannot move
            v[k] = 1.0
        for c in t.children.values():
            k = where[(c.fx, c.fy)[axis]] if 0 <= (c.fx, c.fy)[axis] < len(where) else -1
            if k < 0:
                return None
            v[k] = 1.0
        return v

    def slides(t, axis: int) -> bool:
        v = move(t, axis)
        if v is None or not v.any():
            return False
        rows, B = _block(J, np.flatnonzero(v))       # J @ v on the rows the move touches
        r = np.abs(B.sum(axis=1))
        return not np.any((r > 1e-9 * np.maximum(1.0, scale[rows])) & ~loose[rows])

    def axes(t) -> str:
        return ", ".join(a for a, k in (("x", 0), ("y", 1)) if slides(t, k))
    for p in parts:
        a = axes(p)
        if a:
            out.placement.append((p, a))
        found = _features(p, J, loose, scale, where, px, model)
        out.features += found
        if found and loose.any():
            strict = {id(t) for t, _ in _features(p, J, np.zeros_like(loose), scale, where,
                                                   px, model)}
            out.bounded |= {id(t) for t, _ in found if id(t) not in strict}
        for t, _ in found:
            if _block(J, [where[t.fx], where[t.fy]])[1].any():
                out.constrained.add(id(t))
    asm = [t for t in model.structures if t.kind == "assembly"]
    if not out.placement and not out.features:
        for t in asm:                       # a group of parts placed only as a whole
            a = axes(t)
            if a:
                out.placement.append((t, a))
                break
    return out


MAX_CANDIDATES = 400     # features of one part whose joint motions are searched (2 per axis)


def _block(J, cols) -> tuple[np.ndarray, np.ndarray]:
    """Columns ``cols`` of the Jacobian ``J`` (a dense array, or sparse by columns) on the rows
    where any of them is non-zero: ``(rows, dense block of len(rows) x len(cols))``.  A part's
    moves read a few columns of the whole model's Jacobian; taking only those rows keeps the
    sliding check linear in the number of parts (1,000 parts: each product was over every row)."""
    if isinstance(J, np.ndarray):
        sub = J[:, cols]
        rows = np.flatnonzero(np.any(sub != 0, axis=1))
        return rows, sub[rows]
    # read the compressed columns directly (SciPy's indexing costs ~0.5 ms a call)
    spans = [slice(J.indptr[c], J.indptr[c + 1]) for c in cols]
    rows = np.unique(np.concatenate([J.indices[s] for s in spans])) if spans else \
        np.zeros(0, dtype=np.int64)
    B = np.zeros((len(rows), len(spans)))
    for j, s in enumerate(spans):
        np.add.at(B[:, j], np.searchsorted(rows, J.indices[s]), J.data[s])
    return rows, B


def _features(p, J, loose, scale, where, px, model) -> list:
    """``[(structure, axes)]``: the structures inside part ``p`` that can move relative to it.
    Candidates are the frames of its structures; their joint moves that change no row
    (beyond inactive inequalities) are the null space of ``J V`` (``V``: one column per
    candidate and axis; by its Gram matrix).  A candidate slides along an axis when some such
    move changes its absolute position there (its frame and those above it, inside ``p``)
    against ``p``'s own shapes, or, when ``p`` has none, against its first child: a move of
    the whole part is not a slide.  Only the outermost sliding structure is named."""
    desc, todo = [], list(p.children.values())
    while todo:
        t = todo.pop(0)
        desc.append(t)
        todo += t.children.values()
    cands = [t for t in desc
             if all(0 <= f < len(where) and where[f] >= 0 for f in (t.fx, t.fy))]
    if not cands or len(cands) > MAX_CANDIDATES:
        return []
    n = len(cands)
    # J V (V: a unit column per candidate frame and axis) on the rows those columns touch;
    # the other rows are zero in J V and add nothing to its Gram matrix
    rows, M = _block(J, [where[f] for t in cands for f in (t.fx, t.fy)])
    keep = ~loose[rows]
    M = M[keep] / np.maximum(1.0, scale[rows][keep])[:, None]
    w, Q = np.linalg.eigh(M.T @ M)
    null = Q[:, w <= 1e-12 * max(1.0, float(w.max(initial=0.0)))]
    if not null.shape[1]:
        return []
    index = {id(t): i for i, t in enumerate(cands)}
    A = np.zeros((2 * n, 2 * n))          # absolute motion: a frame and the frames above it
    for i, t in enumerate(cands):
        s_ = t
        while s_ is not None and s_ is not p:
            if id(s_) in index:
                A[2 * i, 2 * index[id(s_)]] = A[2 * i + 1, 2 * index[id(s_)] + 1] = 1.0
            s_ = s_.parent
    motion = A @ null
    anchor = None
    if not any(not g.construction for g in p.geometry):
        anchor = next((i for i, t in enumerate(cands) if t.parent is p), None)
    out, reported = [], set()
    for i, t in enumerate(cands):
        if i == anchor:
            continue
        ax = []
        for k, name in ((0, "x"), (1, "y")):
            m = motion[2 * i + k] - (motion[2 * anchor + k] if anchor is not None else 0.0)
            if np.any(np.abs(m) > 1e-6):
                ax.append(name)
        up, hidden = t.parent, False
        while up is not None and up is not p:
            hidden = hidden or id(up) in reported
            up = up.parent
        if ax and not hidden:
            reported.add(id(t))
            out.append((t, ", ".join(ax)))
    return out


def sliding_text(sl: Sliding) -> str:
    """``free: hole `bore` can slide along x`` or ``free: only where the whole part sits
    (harmless)``; "" when nothing slides."""
    if sl.features:
        said = [f"{_name(t)} can slide along {a}"
                + (" within its bounds" if id(t) in sl.bounded else "")
                for t, a in sl.features[:3]]
        more = f" and {len(sl.features) - 3} more" if len(sl.features) > 3 else ""
        return "free: " + "; ".join(said) + more
    if sl.placement:
        return "free: only where the whole part sits (harmless)"
    return ""


def _name(o) -> str:
    """``hole `plate.bore``` for a structure, ```plate.pin.c``` for a shape."""
    if hasattr(o, "path"):
        return f"{o.kind} `{o.path}`"
    return f"`{o.label}`"
