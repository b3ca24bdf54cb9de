"""Which user constraints other constraints already imply: the redundancy search (W0401).

In: a solved, consistent :class:`~.hierarchy.Solver`, a deadline and a size bound.  Out: a
:class:`Redundant` per user constraint that the others imply, wholly or partly (``by``: the
constraints it follows from), and the constraints left unsearched with the reason
("too large", "out of time").  The measure (issue 23: a constraint is redundant when removing
it keeps the rank, partly redundant when its row space meets the others' beyond the
constructors' shapes), read off the left null space that the greedy rank-revealing pass of
:func:`~.diagnose.dependencies` finds block by block, and the budget rules (issues 37, 48)
are in :func:`redundancies`'s docstring; docs/solver.md.
"""
from __future__ import annotations

import time

import numpy as np

from ..records import Compared
from .arrays import unique

from ..geometry.model import Constraint
from .diagnose import (MAX_DENSE, _components, _dense_components, _dense_cut, _dense_refused,
                       _order_key, _peeled_rows, _row_entries, _with_pins, dependencies)


class Redundant(Compared):
    """``constraint`` is implied by ``by`` (consistent: a warning, not an error)."""
    __slots__ = ("constraint", "by", "partly")

    def __init__(self, constraint: Constraint, by: list, partly: bool = False):
        self.constraint = constraint
        self.by = by
        self.partly = partly  # only some of the constraint's equations are implied


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
