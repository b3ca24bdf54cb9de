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

from ..records import dataclass

import numpy as np

from .arrays import unique
from .newton import _Step, unreachable
from .tape import Tape


@dataclass
class BlockResult:
    converged: bool
    iterations: int
    residual: float          # max |F| of the block's (kept) rows at its end point


class _Block:
    """One system's state: its rows ``fr`` (tape positions, kept rows only), unknown
    positions ``cp`` (in ``cols``), class columns ``zb`` (in the reduction's ``z``, or in
    ``cols`` unreduced) and the Newton variables of :func:`~.newton.newton`."""

    __slots__ = ("fr", "cp", "zb", "reduced", "zloc", "t", "u", "d", "F", "norm", "mu",
                 "it", "done", "res", "accepted", "step", "un")

    def place(self, x: np.ndarray, cols: np.ndarray, u: np.ndarray) -> None:
        """Write ``x[cols]`` of this block for ``u`` (as ``newton``'s ``place``)."""
        if self.reduced:
            out = np.zeros(len(self.cp))
            r = self.zloc >= 0
            out[r] += u[self.zloc[r]]
            x[cols[self.cp]] = out + self.t
        else:
            x[cols[self.cp]] = u


def newton_batch(tape: Tape, x0: np.ndarray, cols: np.ndarray, scale: np.ndarray,
                 blocks: list, choices: np.ndarray | None, max_iter: int = 100,
                 tol: float = 1e-10, reduction=None, budget: int | None = None):
    """Solve the independent blocks of ``tape`` for their unknowns, each as
    :func:`~.newton.newton` would alone.

    ``cols`` (increasing) are the unknowns of all blocks, ``scale`` their weights;
    ``blocks``: per block ``(rows, colpos)``, its rows (tape positions) and its unknowns
    (positions in ``cols``), disjoint, each block's rows using only its own unknowns (and held
    values); ``reduction`` is :func:`~.reduce.reduce` of the whole tape over ``cols`` (its
    classes never span two blocks).  ``budget``: the most Newton steps all blocks together
    may take (each step of each block counts one); when the next step would pass it, every
    block stops there and ``out_of_budget`` is True.

    Returns ``(x, results, out_of_budget)``: ``x`` with every block's unknowns at its end
    point, and a :class:`BlockResult` per block."""
    x = x0.copy()
    red = reduction
    n_rows = tape.n_rows
    if red is not None:
        kept = np.zeros(n_rows, dtype=bool)
        kept[red.keep] = True
        nz = len(red.z0)
    else:
        kept = np.ones(n_rows, dtype=bool)
        nz = len(cols)
    rowblock = -np.ones(n_rows, dtype=np.int64)
    rowlocal = np.zeros(n_rows, dtype=np.int64)
    zblock = -np.ones(nz, dtype=np.int64)
    zlocal = np.zeros(nz, dtype=np.int64)
    bs: list[_Block] = []
    for k, (rows, cp) in enumerate(blocks):
        b = _Block()
        b.cp = cp
        b.reduced = red is not None and not bool(kept[rows].all())
        if b.reduced:
            b.fr = rows[kept[rows]]
            zc = red.zc[cp]
            b.zb = unique(zc[zc >= 0])
            b.zloc = np.where(zc >= 0, np.searchsorted(b.zb, zc), -1)
            b.t = red.t[cp]
            b.u = red.z0[b.zb].copy()
            b.d = red.scale[b.zb]
            b.place(x, cols, b.u)
        else:
            # no row of this block was substituted: alone it is solved unreduced
            b.fr = rows
            b.zb = red.zc[cp] if red is not None else cp
            b.u = x[cols[cp]].copy()
            b.d = scale[cp]
        rowblock[b.fr] = k
        rowlocal[b.fr] = np.arange(len(b.fr))
        zblock[b.zb] = k
        zlocal[b.zb] = np.arange(len(b.zb))
        b.it = 0
        b.done = False
        bs.append(b)
    F, v = tape.evaluate(x, choices, nodes=True)
    for b in bs:
        b.F = F[b.fr]
        b.res = float(np.max(np.abs(b.F))) if len(b.F) else 0.0
        if b.res <= tol or not len(b.u) or not np.isfinite(b.res):
            b.done = True
            continue
        b.norm = float(np.linalg.norm(b.F))
        b.mu = 1e-12
    used = 0
    out_of_budget = False
    while True:
        active = [k for k, b in enumerate(bs) if not b.done and b.it < max_iter]
        if not active:
            break
        if budget is not None and used + len(active) > budget:
            out_of_budget = True
            break
        used += len(active)
        r, z, data = tape.jacobian_entries(x, cols, choices, v, reduction=red)
        blk = rowblock[r]
        order = np.argsort(blk, kind="stable")
        bounds = np.searchsorted(blk[order], np.arange(len(bs) + 1)).tolist()
        lr, lc = rowlocal[r], zlocal[z]
        trying = []
        for k in active:
            b = bs[k]
            b.it += 1
            b.accepted = False
            sel = order[bounds[k]:bounds[k + 1]]
            J = np.zeros((len(b.fr), len(b.zb)))
            J[lr[sel], lc[sel]] = data[sel]
            Js = J * b.d
            if unreachable(Js, b.F):
                b.done = True             # newton's `break`: the step is 0 for every mu
                continue
            b.step = _Step(Js, dense=True)
            trying.append(b)
        stepped = list(trying)
        for _ in range(14):
            if not trying:
                break
            xn = x.copy()
            evals = []
            for b in trying:
                try:
                    du = b.d * b.step(b.F, b.mu)
                except (RuntimeError, np.linalg.LinAlgError):
                    b.mu = max(b.mu * 100, 1e-8)
                    continue
                b.un = b.u + du
                b.place(xn, cols, b.un)
                evals.append(b)
            if evals:
                Fn, vn = tape.evaluate(xn, choices, nodes=True)
            for b in evals:
                Fb = Fn[b.fr]
                nn = float(np.linalg.norm(Fb))
                if np.isfinite(nn) and nn < b.norm:
                    b.u, b.F, b.norm = b.un, Fb, nn
                    idx = cols[b.cp]
                    x[idx] = xn[idx]
                    b.mu = max(b.mu / 10, 1e-12)
                    b.accepted = True
                else:
                    b.mu = max(b.mu * 10, 1e-8)
            trying = [b for b in trying if not b.accepted]
        for b in stepped:
            b.res = float(np.max(np.abs(b.F)))
            if b.res <= tol or not b.accepted:
                b.done = True
        if any(not b.done and b.it < max_iter for b in bs):
            _, v = tape.evaluate(x, choices, nodes=True)
    return x, [BlockResult(b.res <= tol, b.it, b.res) for b in bs], out_of_budget
