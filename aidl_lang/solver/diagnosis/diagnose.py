"""Why a solve failed: conflict sets (the linear algebra they are found with, and which the
other diagnostics share, is :mod:`..core.rank`).

All read the Jacobian ``J`` (rows: residuals, columns: unknowns) at a point:

* **Conflicts** (:func:`conflicts`; in: a failed system's rows and unknowns at its last point,
  out: :class:`Conflict` sets).  Rows are taken in a fixed order (constructor-held dimensions
  first, then the user's constraints in source order) and added to a basis one by one (a
  rank-revealing Gram-Schmidt, the greedy form of a column-pivoted QR of ``J^T``,
  :func:`dependencies`).  A row that adds no rank is a combination of earlier rows; the
  least-squares coefficients of that combination name the rows it depends on.  If any row of
  that dependent set is unsatisfied, the set is a *conflict* (an over-constrained,
  inconsistent system): those constraints cannot all hold, and no smaller subset of the basis
  explains the dependency.  If all are satisfied, the later row is merely *redundant*
  (consistent, a warning: :mod:`.redundancy`).
* **Ranks and null spaces** (:func:`dependencies`, :func:`null_support`,
  :func:`_block_rank`, :func:`_dense_block_rank`, :func:`_peeled_rows`, :func:`_dense_cut`,
  :func:`_dense_refused`), which the other diagnostics use: :mod:`.freedom` (degrees of
  freedom per structure, what floats), :mod:`.redundancy` (which constraints others imply,
  W0401) and :mod:`.sliding` (what the freedom left means).

Dense linear algebra: used for one structure's system, or for the connected component of a
failed system that holds the unsatisfied rows (capped at :data:`MAX_DENSE` rows).  SciPy (sparse
matrices, connected components) is imported only for systems larger than
:data:`DENSE_CELLS`: the freedom count on ``aidl check``'s ok line stays in numpy, so a cold
check does not pay SciPy's import.
"""
from __future__ import annotations

import numpy as np

from ...base.limits import now
from ...base.records import Compared
from ..core.arrays import unique

from ...geometry.core.model import Constraint
from ..core.rank import DENSE_CELLS, MAX_DENSE, _components, dependencies
from ..core.system import user_residuals

MAX_CONFLICTS = 10       # conflict sets collected per failed system (the report shows 3)


class Conflict(Compared):
    """Constraints that cannot all hold together: ``[(Constraint, residual)]``."""
    __slots__ = ("items",)

    def __init__(self, items: list | None = None):
        self.items = [] if items is None else items

    @property
    def constraints(self) -> list[Constraint]:
        return [c for c, _ in self.items]


def built_keys(solver, rows: np.ndarray, prows: np.ndarray) -> np.ndarray:
    """The order keys of solver rows ``rows`` and pinning rows ``prows``: each row's index
    among the rows built (:attr:`~..core.hierarchy.Solver.built_index`), so that the rows of
    one constraint are taken in the same order pinned or not.  Before (issue 105), the pinning
    rows came after every solver row: `Fixed(c.center)` with its y row pinned by a later
    `c.center.y == 2` took y before x, and the conflict sets named differed (2 and 3
    constraints pinned, 3 and 4 unpinned)."""
    bi = getattr(solver, "built_index", None)
    rows = np.asarray(rows, dtype=np.int64)
    own = bi[rows] if bi is not None else rows
    return np.concatenate([own, np.asarray(prows, dtype=np.int64)])


LEAST_ROWS = 64          # rows of a conflict set made minimal by deletion (at most)


def _inconsistent(A: np.ndarray, f: np.ndarray, tol: float) -> bool:
    """True when the linearised rows ``A dx = -f`` have no solution: the least-squares
    residual is above ``tol`` (the rows demand different things)."""
    dx = np.linalg.lstsq(A, -f, rcond=None)[0]
    return float(np.max(np.abs(A @ dx + f), initial=0.0)) > tol


def _least_conflict(members: list, cons: list, rows_of: dict, J: np.ndarray, F: np.ndarray,
                    tol: float) -> list:
    """The rows of a conflict made minimal by deletion, constraint by constraint, the
    first-written tried first: a constraint is left out when the others' rows (all the rows
    of each, ``rows_of``) still conflict (:func:`_inconsistent`), and at least two
    constraints stay.  The greedy basis names the rows a dependent row combines, and a row
    that was itself dependent is never among them: `c.center.y == 2` after `Fixed(c.center)`
    (whose y row was dependent) was named with `Fixed(arc.center)` and a `Distance`, four
    constraints where two conflict (issue 105).  Sets of more than :data:`LEAST_ROWS` rows
    are kept as found."""
    first = {}
    for i in members:
        first.setdefault(id(cons[i]), cons[i])
    ids = sorted(first, key=lambda k: _order_key(first[k], 0))
    if len(ids) <= 2 or sum(len(rows_of[k]) for k in ids) > LEAST_ROWS:
        return members
    rows = {k: rows_of[k] for k in ids}
    keep = list(ids)
    for k in ids:
        rest = [j for j in keep if j != k]
        if len(rest) < 2:
            break
        sel = [i for j in rest for i in rows[j]]
        if _inconsistent(J[sel], F[sel], tol):
            keep = rest
    if keep == ids:
        return members
    return [i for j in keep for i in rows[j]]


def _order_key(c: Constraint, r: int):
    sp_ = c.span
    pos = (sp_.line, sp_.col) if sp_ is not None else (0, 0)
    return (0 if c.implicit else 1, pos, r)


def used_free_columns(solver) -> np.ndarray:
    """The free unknowns (increasing indices, ``int64``) that some row of the solve uses: the
    only columns of its Jacobian that can hold a non-zero.  A pattern of 20,000 holes placed
    by their coordinates has 80,000 free unknowns and a handful of rows over a few of them;
    a Jacobian over the few stays dense and small (NumPy only, no SciPy import) where one
    over all of them held 6 x 80,000 cells, nearly all zero."""
    t = solver.whole
    used = np.zeros(len(solver.free), dtype=bool)
    used[np.asarray(t.a_col, dtype=np.int64)] = True
    used[np.asarray(t.l_col, dtype=np.int64)] = True
    return np.flatnonzero(used & np.asarray(solver.free, dtype=bool))


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
    keys = built_keys(solver, rows, prows).tolist()
    if len(prows):
        F = np.concatenate([F, np.zeros(len(prows))])       # a pinned value holds its row
        user = np.concatenate([user, np.zeros(len(prows))])
        bad = np.concatenate([bad, np.zeros(len(prows), dtype=bool)])
        built = solver.rows_built.constraint
        cons += [built[r] for r in prows.tolist()]
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
    rows_of: dict[int, list] = {}           # id(constraint) -> its rows among ``local``
    for i, c in enumerate(cons):
        rows_of.setdefault(id(c), []).append(i)
    deadline = getattr(solver, "deadline", None)
    # the greedy pass looks at the deadline before every row: no estimate needed
    for r, support, coef in dependencies(Jd, order, deadline):
        if len(out) >= MAX_CONFLICTS or (deadline is not None and now() > deadline):
            break                        # the best sets found so far
        members = [r] + support
        # a dependency J_r = sum c_i J_i is consistent when the residuals obey it too
        # (F_r = sum c_i F_i: the error is merely spread over the set); otherwise the rows
        # demand different things: a conflict
        gap = abs(Fl[r] - float(coef @ Fl[support])) if len(support) else abs(Fl[r])
        if gap <= tol:
            continue
        members = _least_conflict(members, cons, rows_of, Jd, Fl, tol)
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


