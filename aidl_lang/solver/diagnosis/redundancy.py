"""Which user constraints other constraints already imply: the redundancy search (W0401).

In: a solved, consistent :class:`~.hierarchy.Solver`, a deadline and a size bound.  Out: a
:class:`Redundant` per user constraint that the others imply, wholly or partly (``by``: the
constraints it follows from), and the constraints left unsearched with the reason
("too large", "out of time").  The measure (issue 23: a constraint is redundant when removing
it keeps the rank, partly redundant when its row space meets the others' beyond the
constructors' shapes), read off the left null space that the greedy rank-revealing pass of
:func:`~..core.rank.dependencies` finds block by block, and the budget rules (issues 37, 48)
are in :func:`redundancies`'s docstring; docs/solver.md.
"""
from __future__ import annotations

import numpy as np

from ...base.limits import now
from ...base.records import Compared
from ..core.arrays import unique

from ...geometry.core.expr import Lin
from ...geometry.core.model import Constraint
from ..core.rank import (MAX_DENSE, _components, _dense_components, _dense_cut, _dense_refused,
                         _peeled_rows, _row_entries, dependencies)
from .diagnose import _order_key, _with_pins, built_keys, used_free_columns


class Redundant(Compared):
    """``constraint`` is implied by ``by`` (consistent: a warning, not an error).  ``beyond``:
    0 when all it says is implied; when only part is (:attr:`partly`), the rank of its
    searched rows beyond the constructors' span (what it would pin were nothing of it
    implied, pinning rows left out, as :meth:`Search.rank_lost` counts)."""
    __slots__ = ("constraint", "by", "beyond")

    def __init__(self, constraint: Constraint, by: list, beyond: int = 0):
        self.constraint = constraint
        self.by = by
        self.beyond = beyond

    @property
    def partly(self) -> bool:
        """Only some of the constraint's equations are implied."""
        return self.beyond > 0


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
    failed solve reports conflicts instead).  Past ``deadline`` (:func:`aidl_lang.base.limits.now`: CPU seconds) the
    blocks not yet ranked are left out, and so are blocks of more than ``max_rows`` rows
    (after the rows independent of all others by structure are peeled off,
    :func:`_peeled_rows`); the user constraints so left out are appended to ``skipped``, and
    the reasons (``"out of time"``, ``"too large"``) added to ``why``.  No dense
    factorisation is started without its cost estimated first (:func:`_dense_refused`): one
    that would pass :data:`~.diagnose.MAX_SVD_FLOPS` or end past ``deadline`` leaves its
    constraint out ("too large" / "out of time") instead of running past the budget (issue
    48: a gear pair under a ``Below`` spent 99 s in one SVD of 6,264 columns).  The constructors' span that
    "partly redundant" is measured against is the greedy pass's own basis (its first rows:
    the constructors' rows come first in its order), not a separate SVD.  NumPy only while the
    Jacobian has at most :data:`~..core.rank.DENSE_CELLS` cells, so plain ``aidl check`` does
    not import SciPy for it.

    The steps: :func:`_flat_system` (the rows and their Jacobian, pinning rows included),
    :func:`_row_blocks` (the blocks of rows sharing unknowns, rows peeled), per block
    :func:`_search_block` (its dependencies, :class:`_Block`, then :func:`_measure` per
    constraint), and :func:`_report` (what each user constraint is said to be)."""
    return search(solver, deadline, max_rows, skipped, why).found


class Search(Compared):
    """The redundancy search's findings (``found``: a :class:`Redundant` per implied user
    constraint) and what :meth:`rank_lost` needs to judge a set of them dropped together:
    each searched block's dependencies (``blocks``, by the ids of the constraints in it), the
    constraints of one-row blocks and their pinning rows outside the closure (``alone``), and
    the constraints the solved point does not meet, left out (``overridden``,
    :func:`_held_rows`)."""
    __slots__ = ("found", "blocks", "alone", "unknown", "overridden")

    def __init__(self, found: list | None = None, blocks: dict | None = None,
                 alone: dict | None = None, unknown: dict | None = None,
                 overridden: set | None = None):
        self.found = [] if found is None else found
        self.blocks = {} if blocks is None else blocks
        self.alone = {} if alone is None else alone
        self.unknown = {} if unknown is None else unknown
        self.overridden = set() if overridden is None else overridden

    def rank_lost(self, drop) -> int | None:
        """``rank(J) - rank(J without drop)``: how many degrees of freedom dropping the user
        constraints ``drop`` together would free (0: the others still hold every unknown
        they held; the same measure as a single constraint's, ``|D| - rank(N_D)`` with
        ``N_D`` the dependencies restricted to ``D``'s rows, block by block).  None when
        one of them was not searched, or does not hold at the solved point."""
        ids = {id(c) for c in drop}
        if any(k in self.unknown or k in self.overridden for k in ids):
            return None
        lost = sum(self.alone.get(k, 0) for k in ids)
        seen: set = set()
        for k in ids:
            for b in self.blocks.get(k, ()):
                if id(b) in seen:
                    continue
                seen.add(id(b))
                idx = [i for i, c in enumerate(b.lc) if id(c) in ids]
                deps = [n_ for n_, (r, support, _) in enumerate(b.null)
                        if any(id(b.lc[i]) in ids for i in [r, *support])]
                M = _restricted(b.null, deps, idx)
                lost += len(idx) - (_rank(np.array(M)) if M else 0)
        return lost


def _restricted(null: list, deps, idx: list) -> list:
    """The dependencies ``deps`` of ``null`` (``(row, support, coef)``) restricted to the
    rows ``idx``: one vector over ``idx`` each (``N_C`` of :func:`redundancies`)."""
    pos = {i: j for j, i in enumerate(idx)}
    M = []
    for n_ in deps:
        r, support, coef = null[n_]
        v = np.zeros(len(idx))
        if r in pos:
            v[pos[r]] += 1.0
        for i, cf in zip(support, coef):
            if i in pos:
                v[pos[i]] -= cf
        M.append(v)
    return M


def search(solver, deadline: float | None = None, max_rows: int = MAX_DENSE,
           skipped: list | None = None, why: set | None = None,
           flops: float | None = None) -> Search:
    """:func:`redundancies` (the same arguments), with what judging a drop set needs kept
    (:class:`Search`, :meth:`Search.rank_lost`: W0401's hint drops only a set that frees
    nothing, issue 84).  ``flops``: the search's work, in floating-point operations of its
    factorisations (a block's core of ``m`` rows costs ``m`` cubed, paid before it is ranked):
    a block past it is left out, ``"out of budget"``, the same on every machine; the CPU
    ``deadline`` is the backstop."""
    system = _flat_system(solver)
    if system is None:
        return Search()
    J, F, cons, keys, in_closure, overridden = system
    lab, live, peeled, position = _row_blocks(J)
    by_c: dict[int, list[int]] = {}
    for i, c in enumerate(cons):
        by_c.setdefault(id(c), []).append(i)
    found = _Found(flops)
    for comp in unique(lab[live]):
        local = np.flatnonzero((lab == comp) & live)
        if deadline is not None and now() > deadline:
            found.leave_out((id(cons[i]) for i in local), "out of time")
            continue
        if len(local) == 1:                 # one row, independent of all others
            k = id(cons[local[0]])
            found.contribution[k] = found.contribution.get(k, 0) + 1
            found.rank_c[k] = found.rank_c.get(k, 0) + 1
            found.alone[k] = found.alone.get(k, 0) + 1
            continue
        _search_block(J, local, [cons[i] for i in local], keys, peeled, position, found,
                      deadline, max_rows)
    reds = _report(solver, cons, by_c, F, live, in_closure, found, skipped, why)
    pinned = solver.pinned_rows
    for k in by_c:              # a pinning row outside the closure: one independent row
        p = pinned.get(k, 0) - in_closure.get(k, 0)
        if p:
            found.alone[k] = found.alone.get(k, 0) + p
    return Search(reds, found.blocks, found.alone, found.unknown, overridden)


def _flat_system(solver):
    """``(J, F, cons, keys, in_closure, overridden)`` of the solve's rows (the user's and the
    constructors', not the links or slacks' own) of the constraints the solved point meets
    (``overridden``: the ids of those it does not, :func:`_held_rows`), or None when there
    are none: their Jacobian over the free
    unknowns and residuals, with the pinning rows they reach appended (see
    :func:`~.diagnose._pin_closure`: a dependency through pinned geometry names its pinning
    constraints, as without pinning; a pinned value holds its row), the constraint and the
    order key (its row of the whole system) of each row, and per pinning constraint
    (``id``) how many of its rows were taken so."""
    rows = np.arange(len(solver.rows.exprs), dtype=np.int64)
    rows = rows[solver.kind[rows] == 0]
    if not len(rows):
        return None
    x = solver.x
    rows, overridden = _held_rows(solver, rows, x)
    if not len(rows):
        return None
    cols = used_free_columns(solver)      # the others' columns of J are all zero
    t = solver.tape(rows)
    F = t.evaluate(x)
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
        keys = built_keys(solver, rows, prows)
        F = np.concatenate([F, np.zeros(len(prows))])       # a pinned value holds its row
    return J, F, cons, keys, in_closure, overridden


def _held_rows(solver, rows: np.ndarray, x: np.ndarray) -> tuple:
    """``(rows, overridden)``: the equation rows ``rows`` less those of every constraint that
    does not hold the solved design where it is, and the ids of those constraints:

    * a structure's hold of its own place in its parent (a row of a constraint of ``S`` that
      reads ``S``'s frame: ``Fixed(self)``, as every joint of std/joints.aidl "holds itself
      where `cx`, `cy` put it").  The hierarchical solve meets it at ``S``'s level, where the
      frame is held, and the parent's constraints then move the frame without asking it
      again (docs/solver.md): it is where the instance starts, which whatever places the
      instance overrides, and the freedom count does not count it either (:mod:`.freedom`:
      a structure's frame against its parent's rows).  Counted, it made the parent's
      placement look implied: W0401 said to drop `AlignRight(right_tail, panel)` and
      `AlignCenterY(right_tail, panel)` of a lid, "the template holds it already"; dropped,
      the tail went back to where the template started it, 79 mm off, and a divider's second
      `cross_halving` 40 mm (issue 109, law 4);
    * a row the solved point does not meet (its residual above
      :data:`~..core.hierarchy.CHECK_TOL`): it holds nothing in the solved design.

    The whole constraint is left out, its other rows too (met by chance: the hold's y where
    the placement kept it)."""
    from ..core.hierarchy import CHECK_TOL
    F = solver.tape(rows).evaluate(x)
    con, exprs = solver.rows.constraint, solver.rows.exprs
    overridden = {id(con[r]) for r in rows[np.abs(F) > CHECK_TOL].tolist()}
    for r in rows.tolist():
        c = con[r]
        e = exprs[r]
        s = c.owner
        if type(e) is Lin and s is not None and s.parent is not None \
                and (s.fx in e.terms or s.fy in e.terms):
            overridden.add(id(c))       # reads its own structure's frame: a self-hold
    if not overridden:
        return rows, overridden
    keep = np.array([id(con[r]) not in overridden for r in rows.tolist()], dtype=bool)
    return rows[keep], overridden


def _row_blocks(J):
    """``(lab, live, peeled, position)``: a block label per row of ``J`` (rows sharing an
    unknown share a block), whether the row has an unknown left (else it reads held values
    only), and for a sparse ``J`` the rows independent of all others by structure
    (:func:`~..core.rank._peeled_rows`: they take part in no dependency; a chain of 2 500
    ``Distance``s peels to nothing), peeled once, every block at a time, and the positions
    of ``J``'s columns (None, None for a dense ``J``)."""
    if isinstance(J, np.ndarray):
        lab = _dense_components(J) if J.shape[1] else np.arange(J.shape[0])
        norms = np.sqrt((J * J).sum(axis=1))
        return lab, norms > 0.0, None, None
    lab = _components(J)
    norms = np.sqrt(np.asarray(J.multiply(J).sum(axis=1)).ravel())
    live = norms > 0.0                      # a row with no unknown left: held values only
    peeled = np.zeros(J.shape[0], dtype=bool)
    peeled[live] = _peeled_rows(J[live], lab[live])
    return lab, live, peeled, np.arange(J.shape[1])    # J's columns are positions in ``cols``


class _Found:
    """What the search has found, per constraint (its ``id``): ``contribution``, ``rank(J) -
    rank(J without C)`` summed over blocks; ``rank_c``, ``rank(J_C)`` beyond the constructors'
    span; ``by``, the other constraints in its dependencies; ``unknown``, why it was not
    searched (the first reason given)."""
    __slots__ = ("contribution", "rank_c", "by", "unknown", "blocks", "alone", "flops_left")

    def __init__(self, flops: float | None = None):
        # the search's budget in floating-point operations of its factorisations (estimated
        # from each block's core, before it is ranked): the same blocks searched on every
        # machine (issue 101); None: no bound but the deadline
        self.flops_left = float("inf") if flops is None else float(flops)
        self.contribution: dict[int, int] = {}
        self.rank_c: dict[int, int] = {}
        self.by: dict[int, list] = {}
        self.unknown: dict = {}
        self.blocks: dict[int, list] = {}       # id(constraint) -> the searched blocks it is in
        self.alone: dict[int, int] = {}         # id(constraint) -> its rows independent of all

    def leave_out(self, ids, reason: str) -> None:
        for k_ in ids:
            self.unknown.setdefault(k_, reason)


class _Block:
    """One block of rows sharing unknowns, under search: its rows ``local`` (positions in
    ``J``) and their constraints ``lc``; ``core`` the rows decomposed (all of a dense ``J``'s,
    the unpeeled ones of a sparse one); after :meth:`find_dependencies`, ``null`` the
    dependencies among the core rows (``(row, support, coef)``, block positions), and
    ``colmask`` the columns the core uses; after :meth:`constructors_span`, ``Qi`` the
    orthonormal basis of the constructors' rows (``n_imp`` of them) and ``in_core``."""
    __slots__ = ("J", "local", "lc", "position", "Jd", "core", "block", "null", "gs",
                 "colmask", "in_core", "n_imp", "Qi")

    def __init__(self, J, local: np.ndarray, lc: list, peeled, position):
        self.J, self.local, self.lc, self.position = J, local, lc, position
        if isinstance(J, np.ndarray):
            Jd = J[local]
            self.Jd = Jd[:, np.any(Jd != 0, axis=0)]
            self.core = np.arange(len(local))
            self.block = None
        else:
            self.core = np.flatnonzero(~peeled[local])     # only these are decomposed
            self.Jd = None
            self.block = unique(J.indices[_row_entries(J, local)[0]])    # the block's columns
        self.null: list = []
        self.gs: dict = {}                  # the greedy pass's basis
        self.colmask = None

    def dense_rows(self, ii) -> np.ndarray:
        """The block's rows ``ii`` (block positions) as a dense array over its columns."""
        if self.Jd is not None:
            return self.Jd[ii]
        return _dense_cut(self.J, self.position, self.local[ii], self.block)

    def find_dependencies(self, keys: np.ndarray, deadline: float | None) -> None:
        """The greedy pass (:func:`~..core.rank.dependencies`) over the core rows, in the
        order constructors first, then source order."""
        core, lc, local = self.core, self.lc, self.local
        if len(core):
            Jk = self.dense_rows(core)
            self.colmask = np.any(Jk != 0, axis=0)
            Jk = Jk[:, self.colmask]
            order = sorted(range(len(core)),
                           key=lambda i: _order_key(lc[core[i]], int(keys[local[core[i]]])))
            self.null = [(int(core[r]), [int(core[i]) for i in support], coef)
                         for r, support, coef in dependencies(Jk, order, deadline, self.gs)]

    def constructors_span(self) -> None:
        """The constructors' rows lead the greedy order, so the first basis rows span them
        (the peeled ones are independent of every other row and change no rank: left out)."""
        self.in_core = np.zeros(len(self.local), dtype=bool)
        self.in_core[self.core] = True
        n_imp = 0
        for i in self.gs.get("indep", ()):
            if not self.lc[self.core[i]].implicit:
                break
            n_imp += 1
        self.n_imp = n_imp
        self.Qi = self.gs["Q"][:n_imp] if n_imp else None


def _search_block(J, local: np.ndarray, lc: list, keys: np.ndarray, peeled, position,
                  found: _Found, deadline: float | None, max_rows: int) -> None:
    """Search one block of rows sharing unknowns (``local``, their constraints ``lc``): left
    out whole when its core has more than ``max_rows`` rows or the deadline passes (a block
    is reported whole or not), else its dependencies are found and each constraint in it
    measured (:func:`_measure`), into ``found``."""
    b = _Block(J, local, lc, peeled, position)
    if len(b.core) > min(max_rows, MAX_DENSE):
        found.leave_out((id(c) for c in lc), "too large")
        return
    cost = float(len(b.core)) ** 3
    if cost > found.flops_left:
        found.leave_out((id(c) for c in lc), "out of budget")
        return
    found.flops_left -= cost
    b.find_dependencies(keys, deadline)
    if deadline is not None and now() > deadline:
        found.leave_out((id(c) for c in lc), "out of time")  # the basis may be incomplete
        return
    b.constructors_span()
    mine: dict[int, list[int]] = {}
    for i, c in enumerate(lc):
        mine.setdefault(id(c), []).append(i)
    touched: dict[int, list[int]] = {}          # constraint -> the dependencies it is in
    for n_, (r, support, _) in enumerate(b.null):
        for k in {id(lc[i]) for i in [r, *support]}:
            touched.setdefault(k, []).append(n_)
    # the constructors' rows: what a constraint says beyond them is measured modulo
    # their span (the greedy pass's first basis rows ``Qi``), see rank_c
    for k in mine:
        found.blocks.setdefault(k, []).append(b)
    for k, idx in mine.items():
        if deadline is not None and now() > deadline:
            found.leave_out((id(c) for c in lc), "out of time")  # a block is reported whole or not
            break
        _measure(b, k, idx, touched.get(k, ()), found, deadline)


def _measure(b: _Block, k: int, idx: list, deps, found: _Found, deadline: float | None) -> None:
    """Constraint ``k`` (its rows ``idx`` in block ``b``, in the dependencies ``deps``): its
    share of the rank, ``|C| - rank(N_C)`` with ``N_C`` the dependencies restricted to its
    rows, the constraints it depends with, and the rank of its rows beyond the constructors'
    span (:func:`_rank_beyond_constructors`), into ``found``; left out when a factorisation
    is refused (:func:`~..core.rank._dense_refused`)."""
    lc, null = b.lc, b.null
    M = _restricted(null, deps, idx)
    others: list = []
    named = {k}                     # ids in ``others`` (and k): linear, not a scan
    for n_ in deps:
        r, support, _ = null[n_]
        for i in [r, *support]:
            if id(lc[i]) not in named:
                named.add(id(lc[i]))
                others.append(lc[i])
    if M:
        refused = _dense_refused(len(M), len(idx), deadline)
        if refused:
            found.leave_out([k], refused)
            return
    rM = _rank(np.array(M)) if M else 0
    gain = len(idx) - rM
    found.contribution[k] = found.contribution.get(k, 0) + gain
    if rM:
        lst = found.by.setdefault(k, [])
        have = {id(o) for o in lst}
        lst += [o for o in others if id(o) not in have]
    if rM == 0 or gain == 0 or lc[idx[0]].implicit:
        # independent of every other row (no overlap: rank beyond the shapes = gain),
        # or fully implied (reported as such whatever its own rank)
        found.rank_c[k] = found.rank_c.get(k, 0) + gain
        return
    rank = _rank_beyond_constructors(b, idx, deadline)
    if isinstance(rank, str):
        found.leave_out([k], rank)
        return
    found.rank_c[k] = found.rank_c.get(k, 0) + rank


def _rank_beyond_constructors(b: _Block, idx: list, deadline: float | None) -> int | str:
    """The rank of a constraint's rows ``idx`` modulo the constructors' span: each peeled row
    is independent of every other row (1 each); the core rows, projected off ``Qi``, are
    ranked densely.  The reason (a string) when that factorisation is refused."""
    mine_core = [i for i in idx if b.in_core[i]]
    peeled_c = len(idx) - len(mine_core)
    r_core = 0
    if mine_core:
        n_cols = int(b.colmask.sum())
        refused = _dense_refused(len(mine_core), n_cols, deadline, b.n_imp)
        if refused:
            return refused
        Jc = b.dense_rows(mine_core)[:, b.colmask]
        if b.Qi is not None:
            for _ in range(2):          # twice, as the greedy pass does
                Jc = Jc - (Jc @ b.Qi.T) @ b.Qi
        r_core = _rank(Jc)
    return peeled_c + r_core


def _report(solver, cons: list, by_c: dict, F: np.ndarray, live: np.ndarray, in_closure: dict,
            found: _Found, skipped: list | None, why: set | None) -> list[Redundant]:
    """What each user constraint is said to be, from ``found``: redundant (its rank share is
    0), partly redundant (its rank beyond the shapes exceeds its share), implied by held
    values alone (no unknown left in any of its rows, and they hold), or left out (appended
    to ``skipped``, the reason added to ``why``)."""
    out: list[Redundant] = []
    seen: set = set()
    # a row that pins geometry (system.pinned; dropped from the solve) is one independent
    # row of its own: it counts as the rows of a one-row block above do
    pinned = solver.pinned_rows
    unknown, contribution, rank_c, by = found.unknown, found.contribution, found.rank_c, found.by
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
            out.append(Redundant(c, _explicit_first(by.get(k, [])), beyond=rk - p))
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
