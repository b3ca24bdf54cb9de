"""Damped Newton on several independent small systems at once, step for step as if alone.

The hierarchical solve (:mod:`.hierarchy`) solves structures children first; structures whose
subtrees are disjoint share no unknown and no row (validity rule 2, ``E0202``: a constraint
only refers to its own structure's subtree), so the order in which they are solved does not
change any of their results (paper, appendix "Solver Details", *Iterative Deepening Recursive
Solve*: the post-order only requires a structure's subtree to be solved before it).  The
500-structure generated model has 238 parts of 16 rows and 12 unknowns: solved one by one,
each attempt paid ~1 ms of fixed NumPy cost (cutting its tape, substitution, Jacobian layout,
a dozen evaluations) for ~20 us of arithmetic.

:func:`newton_batch` takes one tape holding the rows of several such systems (*blocks*) and
runs :func:`.newton.newton`'s loop for every block at once: one tape evaluation and one
Jacobian for all blocks per step or try, and per block exactly the operations
:func:`~.newton.newton` performs alone: its own substitution classes (or none), its own
damping ``mu``, acceptance test, iteration count and stop.  Every evaluation is row by row,
so a block's residuals, node values and Jacobian entries are the same bits in the batch as in
its own tape, and its dense step (``_Step``, NumPy's ``solve``) is computed on the same
contiguous arrays: each block ends at exactly the point, after exactly the steps, of a solve
on its own (``tests/test_solver_batch.py``).  Only dense-sized blocks are batched
(:func:`~.newton.dense_enough`).
"""
from __future__ import annotations

import numpy as np

from ...base.records import Record
from .arrays import unique
from .tape import Tape


class BlockResult(Record):
    """One block's Newton outcome in a batched solve."""
    __slots__ = ("converged", "iterations", "residual")

    def __init__(self, converged: bool, iterations: int, residual: float):
        self.converged = converged
        self.iterations = iterations
        self.residual = residual  # max |F| of the block's (kept) rows at its end point


def _norms(Fk: np.ndarray) -> np.ndarray:
    """The 2-norm of each row of ``Fk`` (K, m), each as ``np.linalg.norm`` of that row alone
    (``sqrt(f.dot(f))``: a stacked (1, m) @ (m, 1) product is that dot product per slice)."""
    if not Fk.shape[1]:
        return np.zeros(len(Fk))
    return np.sqrt((Fk[:, None, :] @ Fk[:, :, None])[:, 0, 0])


def newton_batch(tape: Tape, x0: np.ndarray, cols: np.ndarray, scale: np.ndarray,
                 blocks: list, choices: np.ndarray | None, max_iter: int = 100,
                 tol: float = 1e-10, reduction=None, budget: int | None = None):
    """Solve the independent blocks of ``tape`` for their unknowns, each as
    :func:`~.newton.newton` would alone.

    ``cols`` (increasing) are the unknowns of all blocks, ``scale`` their weights;
    ``blocks``: per block ``(rows, colpos)``, its rows (tape positions) and its unknowns
    (positions in ``cols``), disjoint, each block's rows using only its own unknowns (and held
    values), each small enough for a dense step (:func:`~.newton.dense_enough`);
    ``reduction`` is :func:`~.reduce.reduce` of the whole tape over ``cols`` (its classes never
    span two blocks).  ``budget``: the most Newton steps all blocks together may take (each
    step of each block counts one); when the next step would pass it, every block stops there
    and ``out_of_budget`` is True.

    Blocks of one shape (rows x unknowns after substitution) are stacked: ``J J^T``, the
    damped solve and ``J^T y`` are one stacked NumPy call per shape and try, which computes
    each slice exactly as the 2-D call does alone (LAPACK ``gesv`` and BLAS per slice).

    The steps: :class:`_Layout` (each block's rows and unknowns, where its values go back in
    ``x``), :func:`_stacks` (blocks by shape), :func:`_first_residuals`, then per Newton step
    :func:`_linearise` (the scaled Jacobian of every block still stepping) and
    :func:`_damped_steps` (newton's tries with growing damping, until each block's residual
    norm falls), then the convergence test.

    Returns ``(x, results, out_of_budget)``: ``x`` with every block's unknowns at its end
    point, and a :class:`BlockResult` per block."""
    x = x0.copy()
    red = reduction
    nb = len(blocks)
    lay = _Layout(tape.n_rows, x, cols, scale, blocks, red)
    lay.place(x, lay.reduced, lay.u)    # newton starts a reduced system at its class means
    stacks = _stacks(lay.frs, lay.zbs)
    F, v = tape.evaluate(x, choices, nodes=True)
    it = np.zeros(nb, dtype=np.int64)
    res, done, norm = _first_residuals(F, stacks, nb, tol)
    mu = np.full(nb, 1e-12)
    used = 0
    out_of_budget = False
    while True:
        active = ~done & (it < max_iter)
        n_active = int(active.sum())
        if not n_active:
            break
        if budget is not None and used + n_active > budget:
            out_of_budget = True
            break
        used += n_active
        it[active] += 1
        stepping, mats = _linearise(tape, x, cols, choices, v, red, lay, F, active, done, stacks)
        accepted = _damped_steps(tape, x, choices, lay, F, mats, stepping, mu, norm)
        for ks, R, Z, J, G in mats:
            res[ks] = np.max(np.abs(F[R]), axis=1)
        done |= stepping & ((res <= tol) | ~accepted)
        if (~done & (it < max_iter)).any():
            _, v = tape.evaluate(x, choices, nodes=True)
    return x, [BlockResult(bool(res[k] <= tol), int(it[k]), float(res[k])) for k in range(nb)], \
        out_of_budget


class _Layout:
    """The set-up of a batch: per tape row its block and its row in the block, per unknown
    (a class of the reduction, or a column) its position in its block; ``u`` every block's
    unknowns at the start (its class means, or its columns' values) and ``dz`` their scaling;
    ``frs``/``zbs`` each block's kept rows and unknowns; and the placement back into ``x``
    (:meth:`place`).  A block none of whose rows was substituted is solved unreduced, as
    :func:`~.newton.newton` solves it alone."""
    __slots__ = ("rowblock", "rowlocal", "zlocal", "u", "dz", "frs", "zbs", "reduced",
                 "px", "pz", "pt", "pb", "unred", "pzc", "fixed")

    def __init__(self, n_rows: int, x: np.ndarray, cols: np.ndarray, scale: np.ndarray,
                 blocks: list, red):
        nb = len(blocks)
        if red is not None:
            kept = np.zeros(n_rows, dtype=bool)
            kept[red.keep] = True
            nz = len(red.z0)
        else:
            kept = np.ones(n_rows, dtype=bool)
            nz = len(cols)
        rowblock = -np.ones(n_rows, dtype=np.int64)
        rowlocal = np.zeros(n_rows, dtype=np.int64)
        zlocal = np.zeros(nz, dtype=np.int64)
        u = np.zeros(nz)                  # every block's unknowns (its classes, or its columns)
        dz = np.ones(nz)                  # their scaling
        frs, zbs = [], []
        reduced = np.zeros(nb, dtype=bool)
        px, pz, pt, pb = [], [], [], []   # placement: x column, z source, offset, block
        for k, (rows, cp) in enumerate(blocks):
            if red is not None and not bool(kept[rows].all()):
                reduced[k] = True
                fr = rows[kept[rows]]
                zc = red.zc[cp]
                zb = unique(zc[zc >= 0])
                u[zb] = red.z0[zb]
                dz[zb] = red.scale[zb]
                px.append(cols[cp])
                pz.append(zc)
                pt.append(red.t[cp])
            else:
                # no row of this block was substituted: alone it is solved unreduced
                fr = rows
                zb = red.zc[cp] if red is not None else cp
                u[zb] = x[cols[cp]]
                dz[zb] = scale[cp]
                px.append(cols[cp])
                pz.append(zb)
                pt.append(np.full(len(cp), np.nan))      # NaN: place the value itself
            pb.append(np.full(len(cp), k, dtype=np.int64))
            rowblock[fr] = k
            rowlocal[fr] = np.arange(len(fr))
            zlocal[zb] = np.arange(len(zb))
            frs.append(fr)
            zbs.append(zb)
        px, pz, pt, pb = (np.concatenate(a) for a in (px, pz, pt, pb))
        self.rowblock, self.rowlocal, self.zlocal, self.u, self.dz = \
            rowblock, rowlocal, zlocal, u, dz
        self.frs, self.zbs, self.reduced = frs, zbs, reduced
        self.px, self.pz, self.pt, self.pb = px, pz, pt, pb
        self.unred = np.isnan(pt)
        self.pzc = np.maximum(pz, 0)
        self.fixed = pz < 0

    def place(self, xx: np.ndarray, which: np.ndarray, uu: np.ndarray) -> None:
        """``newton``'s ``place`` for the blocks ``which`` (bool per block): ``0 + z`` (0 when
        the class is fixed) plus the offset, or the value itself when unreduced."""
        pzc, unred = self.pzc, self.unred
        sel = which[self.pb]
        z = uu[pzc] if len(uu) else np.zeros(len(pzc))    # every class fixed: nothing to read
        val = np.where(self.fixed, 0.0, 0.0 + z)
        val = np.where(unred, z, val + np.where(unred, 0.0, self.pt))
        xx[self.px[sel]] = val[sel]


def _stacks(frs: list, zbs: list) -> list:
    """The blocks by shape: one ``(blocks, rows, unknowns)`` stack per (rows, unknowns), the
    blocks' kept rows (K, m) and unknowns (K, n) as stacked arrays."""
    shapes: dict = {}
    for k in range(len(frs)):
        shapes.setdefault((len(frs[k]), len(zbs[k])), []).append(k)
    return [(np.asarray(ks, dtype=np.int64), np.asarray([frs[k] for k in ks]).reshape(len(ks), m),
             np.asarray([zbs[k] for k in ks]).reshape(len(ks), n))
            for (m, n), ks in shapes.items()]


def _first_residuals(F: np.ndarray, stacks: list, nb: int, tol: float):
    """``(res, done, norm)`` per block at the start point: its max ``|F|``, whether it is
    already done (within ``tol``, no unknown, or not finite: newton's first test), and the
    2-norm of its residuals that a step must lower."""
    done = np.zeros(nb, dtype=bool)
    res = np.zeros(nb)
    norm = np.zeros(nb)
    for ks, R, Z in stacks:
        Fk = F[R]
        r = np.max(np.abs(Fk), axis=1) if R.shape[1] else np.zeros(len(ks))
        res[ks] = r
        done[ks] = (r <= tol) | (Z.shape[1] == 0) | ~np.isfinite(r)
        norm[ks] = _norms(Fk)
    return res, done, norm


def _linearise(tape: Tape, x: np.ndarray, cols: np.ndarray, choices, v, red, lay: _Layout,
               F: np.ndarray, active: np.ndarray, done: np.ndarray, stacks: list):
    """``(stepping, mats)``: the blocks that step now, and per stack of them
    ``(blocks, rows, unknowns, J, J J^T)`` with ``J`` the Jacobian times the scaling (``J D``)
    of each block, from one :meth:`~.tape.Tape.jacobian_entries` of the whole tape.  A
    block that cannot move its residuals (``newton.unreachable``: every row that is off has
    no nonzero entry) is marked in ``done`` (updated in place) and does not step."""
    nb = len(done)
    rowblock, dz = lay.rowblock, lay.dz
    r, z, data = tape.jacobian_entries(x, cols, choices, v, reduction=red)
    blk = rowblock[r]
    mine = blk >= 0                            # rows of the blocks solved here
    r, z, data, blk = r[mine], z[mine], data[mine], blk[mine]
    js = data * dz[z]                          # the entries of J D
    # newton.unreachable per block: every row that is off has no nonzero entry
    off = F != 0.0
    has_off = np.bincount(rowblock[rowblock >= 0], weights=off[rowblock >= 0],
                          minlength=nb) > 0
    has_reach = np.bincount(blk, weights=off[r] & (js != 0.0), minlength=nb) > 0
    done |= active & has_off & ~has_reach     # newton's `break`: every step would be 0
    stepping = active & ~done
    live = stepping[blk]
    blk, lr, lc, js = blk[live], lay.rowlocal[r[live]], lay.zlocal[z[live]], js[live]
    mats = []
    for ks, R, Z in stacks:
        on = stepping[ks]
        if not on.any():
            continue
        ks, R, Z = ks[on], R[on], Z[on]
        slot = -np.ones(nb, dtype=np.int64)
        slot[ks] = np.arange(len(ks))
        mine = slot[blk] >= 0
        J = np.zeros((len(ks), R.shape[1], Z.shape[1]))
        J[slot[blk[mine]], lr[mine], lc[mine]] = js[mine]
        mats.append((ks, R, Z, J, J @ J.transpose(0, 2, 1)))
    return stepping, mats


def _damped_steps(tape: Tape, x: np.ndarray, choices, lay: _Layout, F: np.ndarray,
                  mats: list, stepping: np.ndarray, mu: np.ndarray,
                  norm: np.ndarray) -> np.ndarray:
    """One Newton step of every block in ``stepping``: newton's (at most 14) tries, each the
    damped step (:func:`_try_steps`) of the blocks not yet accepted, kept by a block when its
    residuals' 2-norm falls (:func:`_lowered`).  The damping ``mu`` falls tenfold on an
    accepted try and grows tenfold on a rejected one.  ``x``, ``F``, ``mu``, ``norm`` and the
    layout's unknowns ``u`` are updated in place for the blocks that accepted; returns which
    blocks did."""
    nb = len(mu)
    u = lay.u
    accepted = np.zeros(nb, dtype=bool)
    for _ in range(14):
        trying = stepping & ~accepted
        if not trying.any():
            break
        un, tried = _try_steps(mats, trying, u, lay.dz, F, mu)
        if not tried.any():
            continue
        xn = x.copy()
        lay.place(xn, tried, un)
        Fn = tape.evaluate(xn, choices)
        acc = _lowered(mats, tried, Fn, norm)
        rej = tried & ~acc
        mu[acc] = np.maximum(mu[acc] / 10, 1e-12)
        mu[rej] = np.maximum(mu[rej] * 10, 1e-8)
        if acc.any():
            pb, pz, px, rowblock = lay.pb, lay.pz, lay.px, lay.rowblock
            zs = acc[pb] & ~lay.fixed
            u[pz[zs]] = un[pz[zs]]
            xs = acc[pb]
            x[px[xs]] = xn[px[xs]]
            rs = rowblock >= 0
            rs[rs] = acc[rowblock[rs]]
            F[rs] = Fn[rs]
            accepted |= acc
    return accepted


def _try_steps(mats: list, trying: np.ndarray, u: np.ndarray, dz: np.ndarray, F: np.ndarray,
               mu: np.ndarray):
    """``(un, tried)``: the unknowns after one damped step ``dz * J^T (J J^T + mu I)^-1 (-F)``
    of each block in ``trying`` (a zero diagonal counts as 1, as in newton), stacked per
    shape, and which blocks have one.  Where the stacked solve fails, each block is solved
    alone, as newton does; a block whose system is singular grows its ``mu`` (in place)
    and is not tried."""
    nb = len(mu)
    un = u.copy()
    tried = np.zeros(nb, dtype=bool)
    for ks, R, Z, J, G in mats:
        sel = np.flatnonzero(trying[ks])
        if not len(sel):
            continue
        kk = ks[sel]
        M = G[sel]
        diag = np.einsum("kii->ki", M)
        diag += mu[kk][:, None] + (diag == 0.0)
        Fk = F[R[sel]]
        try:
            y = np.linalg.solve(M, -Fk[..., None])[..., 0]
            ok = np.ones(len(sel), dtype=bool)
        except (RuntimeError, np.linalg.LinAlgError):  # which: each alone, as newton
            y = np.zeros(Fk.shape)
            ok = np.zeros(len(sel), dtype=bool)
            for i in range(len(sel)):
                try:
                    y[i] = np.linalg.solve(M[i], -Fk[i])
                    ok[i] = True
                except (RuntimeError, np.linalg.LinAlgError):
                    pass
        bad = kk[~ok]
        mu[bad] = np.maximum(mu[bad] * 100, 1e-8)
        Jt = J[sel].transpose(0, 2, 1)
        step = (Jt @ y[..., None])[..., 0]
        zz = Z[sel][ok]
        un[zz] = u[zz] + dz[zz] * step[ok]
        tried[kk[ok]] = True
    return un, tried


def _lowered(mats: list, tried: np.ndarray, Fn: np.ndarray, norm: np.ndarray) -> np.ndarray:
    """Which blocks of ``tried`` lower their residuals' 2-norm at the tried point ``Fn``
    (finite and strictly below ``norm``, newton's acceptance test); their ``norm`` is set
    to the new one in place."""
    acc = np.zeros(len(tried), dtype=bool)
    for ks, R, Z, J, G in mats:
        sel = np.flatnonzero(tried[ks])
        if len(sel):
            kk = ks[sel]
            nn = _norms(Fn[R[sel]])
            a = np.isfinite(nn) & (nn < norm[kk])
            norm[kk[a]] = nn[a]
            acc[kk[a]] = True
    return acc
