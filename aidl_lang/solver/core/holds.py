"""Holds: a ``Drawing2D`` stays where its file (or ``at=``) puts it, along the directions no
other constraint places it (issue 49; docs/solver.md, "Holds").  :func:`build_rows` is
:func:`.system.build_rows` less the hold rows the other rows already determine
(:func:`settle_holds`); the solver, its hierarchy and the live preview build their rows
through it.  Its own module because it ranks Jacobians with :mod:`.diagnose`, which reads
:mod:`.system`."""
from __future__ import annotations

import numpy as np

from ...geometry.core.expr import Lin, Nl
from ...geometry.core.model import Model
from .system import EQ, SIGN, Rows
from .system import build_rows as _all_rows


def build_rows(model: Model, x: np.ndarray) -> Rows:
    """The rows of every constraint of ``model`` at parameter values ``x`` (model part),
    less the rows of holds that the other rows already determine (:func:`settle_holds`)."""
    rows = _all_rows(model, x)
    if getattr(model, "holds", 0):
        rows = settle_holds(rows, model, x)
    return rows


HOLD_MOVES = 1e-6   # a held unknown's share of the null space (norm) above which it moves


def row_vars(e, out: set) -> None:
    """Add to ``out`` the parameter indices that the residual expression ``e`` reads."""
    stack = [e]
    while stack:
        a = stack.pop()
        t = type(a)
        if t is Lin:
            out.update(a.terms)
        elif t is Nl:
            stack.extend(a.args)


def settle_holds(rows: Rows, model: Model, x: np.ndarray) -> Rows:
    """``rows`` less each hold row that is not needed (issue 49).

    A hold (:attr:`~aidl_lang.geometry.core.model.Constraint.hold`: a ``Drawing2D``'s origin at
    its ``at``, ``origin.x - a == 0`` and ``origin.y - b == 0``) keeps a placement only
    along the directions the other constraints leave free: a hold row is kept when its
    unknown still moves in the null space of the Jacobian of the other equations (and the
    hold rows kept before it), at ``x``; else those equations already place it there and
    the row is dropped.  So a drawing no constraint places stays exactly where its file puts
    it (its rows then pin it as one rigid body, :func:`pinned`), ``d.bb.left == 30`` moves it
    along x only, and ``Fixed(d.origin)`` is not redundant with the hold.  Inequalities (and
    their slacks) are left out of the Jacobian: an inactive bound places nothing; but a bound
    the held drawing breaks must move it, so the holds kept in a component with an
    inequality are listed in ``bounded_holds``, and a failed solve is run again with them
    released (:attr:`~aidl_lang.geometry.core.model.Constraint.released`; :func:`..run`).  A
    released hold's rows are dropped.

    Only the rows connected to the holds' unknowns (through free unknowns) are looked at:
    densely up to ``rank.DENSE_CELLS`` cells (the null space's basis, cut down by each
    hold kept), else by :func:`~.rank.null_support` per hold; a system too large even
    for that keeps no hold (the drawing is placed by its constraints alone, as before)."""
    cons, kind, exprs = rows.constraint, rows.kind, rows.exprs
    hold = [r for r, c in enumerate(cons) if c.hold]
    if not hold:
        return rows
    released = {r for r in hold if cons[r].released}
    hold = [r for r in hold if r not in released]
    n_model = rows.n_model
    free = np.zeros(rows.n_params, dtype=bool)
    free[:n_model] = np.asarray(model.free, dtype=bool)[:n_model]
    # the unknowns of every row but the holds, by row and unknown
    is_hold = np.zeros(len(exprs), dtype=bool)
    is_hold[hold] = True
    is_hold[list(released)] = True
    by_var: dict[int, list] = {}
    vars_of: dict[int, list] = {}
    for r, e in enumerate(exprs):
        if kind[r] == SIGN or is_hold[r]:
            continue
        vs: set = set()
        row_vars(e, vs)
        vs = [v for v in vs if v < len(free) and free[v]]
        if vs:
            vars_of[r] = vs
            for v in vs:
                by_var.setdefault(v, []).append(r)
    hold_var = []                      # each hold row's unknown (-1: none, a held origin)
    for r in hold:
        vs: set = set()
        row_vars(exprs[r], vs)
        vs = [v for v in vs if v < len(free) and free[v]]
        hold_var.append(vs[0] if len(vs) == 1 else -1)
    # the rows connected to each hold's unknown
    seen_v: set = set()
    comp: set = set()
    bounded = []                       # per hold: an inequality among its connected rows
    for v0 in hold_var:
        if v0 < 0:
            bounded.append(False)
            continue
        seen, rs = {v0}, set()
        stack = [v0]
        while stack:
            v = stack.pop()
            for r in by_var.get(v, ()):
                if r in rs:
                    continue
                rs.add(r)
                for u in vars_of[r]:
                    if u not in seen:
                        seen.add(u)
                        stack.append(u)
        bounded.append(any(kind[r] != EQ for r in rs))
        seen_v |= seen
        comp |= rs
    cols = np.array(sorted(seen_v), dtype=np.int64)
    pos = {int(c): k for k, c in enumerate(cols.tolist())}
    # inequalities place nothing (their slack absorbs any move): equations alone are ranked
    comp_rows = sorted(r for r in comp if kind[r] == EQ)
    keep_hold = _needed_holds(exprs, rows.n_params, x, comp_rows, cols,
                              [pos.get(v, -1) for v in hold_var]) if hold else []
    drop = {r for r, k in zip(hold, keep_hold) if not k} | released
    out = rows.subset([r for r in range(len(exprs)) if r not in drop]) if drop else rows
    out.bounded_holds = [cons[r] for r, k, b in zip(hold, keep_hold, bounded) if k and b]
    return out


def _needed_holds(exprs, n_params, x, comp_rows, cols, hold_cols) -> list:
    """Per hold (its unknown's column in ``cols``, -1: none), whether it is kept
    (:func:`settle_holds`)."""
    from .rank import DENSE_CELLS
    from .tape import Tape
    out = []
    n = len(cols)
    xe = np.concatenate([x, np.zeros(n_params - len(x))])
    if comp_rows:
        J = Tape([exprs[r] for r in comp_rows], n_params).jacobian(
            xe, cols, dense=len(comp_rows) * n <= DENSE_CELLS)
    else:
        J = np.zeros((0, n))
    if isinstance(J, np.ndarray):
        if J.shape[0]:
            # Vt whole (n x n) either way; U only as wide as needed (a tall J of thousands
            # of rows would make a full U of millions of cells)
            _, sv, Vt = np.linalg.svd(J, full_matrices=J.shape[0] < J.shape[1])
            rank = int(np.sum(sv > 1e-9 * max(1.0, float(sv[0]) if len(sv) else 1.0)))
            N = Vt[rank:].T                      # the null space's basis, n x k
        else:
            N = np.eye(n)
        for c in hold_cols:
            a = N[c] if c >= 0 and N.shape[1] else None
            if a is None or float(np.linalg.norm(a)) <= HOLD_MOVES:
                out.append(False)
                continue
            out.append(True)
            # the null space of the rows with this hold: the vectors of N with a @ z == 0
            _, _, Zt = np.linalg.svd(a[None, :], full_matrices=True)
            N = N @ Zt[1:].T
        return out
    import scipy.sparse as sp
    from .rank import null_support
    J = sp.csr_matrix(J)
    for c in hold_cols:
        if c < 0:
            out.append(False)
            continue
        rank, moving = null_support(J)
        if rank < 0 or not moving[c]:
            out.append(False)
            continue
        out.append(True)
        J = sp.vstack([J, sp.csr_matrix(([1.0], ([0], [c])), shape=(1, n))]).tocsr()
    return out


def reuse(old, model: Model, keys: list[str] | None) -> tuple[bool, list[str] | None]:
    """Whether the compiled solver ``old`` (a :class:`~aidl_lang.solver.Solver`, or None)
    solves ``model`` too: the same unknowns and the same rows, compared expression by
    expression (held values and starting positions may differ; constants baked into rows
    may not).  When it does, every value of ``model`` that differs is written into it with
    :meth:`~aidl_lang.solver.Solver.set_value` (Newton then re-runs on its compiled tapes:
    the sliders of ``aidl serve``, ``aidl check --sweep``).  ``keys``: the ``repr`` of
    ``old``'s rows from an earlier call, each made when first compared (None: none yet).
    Returns ``(reused, keys)``.

    The rows are compared in order and the first that differs ends it: a planetary's
    `module` moved (its rows differ from the first) wrote the ``repr`` of all its 15,836
    rows, old and new, 75 ms of CPU before the cold solve; now 6 ms (issue 113)."""
    x = model.xs()
    if old is None or old.n_model != len(x) or list(old.model.free) != list(model.free):
        return False, None
    rows = build_rows(model, x)
    built = old.rows_built          # every row, those of pinned geometry included
    if keys is None or len(keys) != len(built.exprs):
        keys = [None] * len(built.exprs)     # made when first compared, then kept
    if rows.n_params != built.n_params or rows.kind != built.kind \
            or rows.slack != built.slack or len(rows.exprs) != len(built.exprs):
        return False, keys
    for i, e in enumerate(rows.exprs):
        k = keys[i]
        if k is None:
            k = keys[i] = repr(built.exprs[i])
        if repr(e) != k:
            return False, keys
    for i in range(len(x)):
        if old.x[i] != x[i]:
            old.set_value(i, x[i])
    return True, keys
