"""Damped minimum-norm Newton on a compiled tape (SolveSpace's step, Levenberg–Marquardt damping).

Solves ``F(x) = 0`` for the unknown columns ``cols`` of ``x``.  The step is the minimum-norm
Newton step in scaled coordinates::

    J_D = J D,   dx = -D J_D^T (J_D J_D^T + mu I)^-1 F

through ``scipy.sparse.linalg.splu`` (a dense solve for small systems).  The minimum-norm step
moves the starting guesses as little as the constraints require; the column scaling ``D`` makes
some unknowns cheaper to move (translation frames: a part moves rigidly before it deforms;
slacks: an inactive inequality does not resist motion).  ``mu`` starts negligible (a pure Newton
step) and grows only when a step fails to reduce ``|F|`` (Levenberg–Marquardt), which also keeps
the step defined for redundant, rank-deficient systems.
"""
from __future__ import annotations

import math

import numpy as np

from ...base.records import Record
from .tape import Tape

TOL = 1e-10
DENSE_MAX = 48          # up to this many rows a system is always solved densely
DENSE_WORK = 1_000_000  # ... and up to this many multiplications for J J^T (rows^2 x unknowns)


def dense_enough(rows: int, unknowns: int) -> bool:
    """Whether a system of ``rows`` residuals and ``unknowns`` is solved with NumPy's dense
    solve: up to DENSE_MAX rows and 4 DENSE_MAX unknowns, or ``J J^T`` costing at most
    DENSE_WORK multiplications (where ``splu``'s fixed overhead, and importing SciPy, would
    cost more than the dense work: the bracket example's 59 x 8 systems)."""
    return (rows <= DENSE_MAX and unknowns <= 4 * DENSE_MAX) or \
        rows * rows * max(unknowns, 1) <= DENSE_WORK


def unreachable(Js, F: np.ndarray) -> bool:
    """Whether every row that is off (``F_i != 0``) has an all-zero Jacobian row (dense or
    SciPy CSR ``Js``): no unknown reaches those rows, the others are already 0, so ``J J^T`` is
    block-diagonal between them and the damped step is exactly 0 for every damping ``mu``
    (``y = -(G + mu I)^-1 F`` is 0 on the rows with entries, ``J^T y`` adds only exact zeros).
    Newton then stops at once, with the result the 14 rejected tries would give.  Typical: a
    structure's own attempt whose violated rows need its children's frames to move (the next,
    translation, attempt frees them): 25 such attempts on the 500-structure model."""
    off = F != 0.0
    if not off.any():
        return False
    if isinstance(Js, np.ndarray):
        return not bool(np.any(Js[off] != 0.0))
    rows = np.repeat(np.arange(Js.shape[0]), np.diff(Js.indptr))
    return not bool(np.any(off[rows] & (Js.data != 0.0)))


try:                                  # the LAPACK solve behind np.linalg.solve
    from numpy.linalg import _umath_linalg
except ImportError:                   # pragma: no cover - a NumPy without it
    _umath_linalg = None


def _singular(err, flag):
    raise np.linalg.LinAlgError("Singular matrix")


def solve_dense(M: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``np.linalg.solve(M, b)`` for a float64 ``M`` (m, m) and ``b`` (m,): the same LAPACK
    call (``gesv`` through NumPy's ``solve1``) and the same ``LinAlgError`` on a singular
    ``M``, without the wrapper's argument checks (most of its cost on a tiny system)."""
    if _umath_linalg is None:         # pragma: no cover
        return np.linalg.solve(M, b)
    with np.errstate(call=_singular, invalid="call", over="ignore", divide="ignore",
                     under="ignore"):
        return _umath_linalg.solve1(M, b, signature="dd->d")


class NewtonResult(Record):
    """A Newton solve's end point, whether it converged, its iterations and residual."""
    __slots__ = ("x", "converged", "iterations", "residual")

    def __init__(self, x: np.ndarray, converged: bool, iterations: int, residual: float):
        self.x = x
        self.converged = converged
        self.iterations = iterations
        self.residual = residual  # max |F| at x


class _Step:
    """The damped minimum-norm step for one Jacobian: ``J J^T`` is formed once and only the
    damping ``mu`` changes between tries (a rejected step used to rebuild it).  A sparse
    ``Js`` (SciPy CSR) is solved with ``splu``, SciPy being imported only then."""

    def __init__(self, Js, dense: bool):
        if not dense and dense_enough(*Js.shape):
            Js, dense = Js.toarray(), True
        self.Js, self.dense = Js, dense
        if dense:
            with np.errstate(over="ignore"):     # entries near 1e300 (a quotient's derivative
                self.G = Js @ Js.T               # at an exact 0): inf, solve_dense's singular
        else:
            # G + diag(d) in CSC, laid out once per step: G's entries and the diagonal are
            # summed by np.bincount into a fixed pattern (0 + G_ii + d_i: the same sum, bit for
            # bit, as scipy's G + diags(d), without its per-try matrix constructions)
            G = (Js @ Js.T).tocoo()
            m = G.shape[0]
            diag = np.arange(m, dtype=np.int64)
            r = np.concatenate([G.row.astype(np.int64), diag])
            c = np.concatenate([G.col.astype(np.int64), diag])
            keys, self.inv = np.unique(c * m + r, return_inverse=True)
            self.inv = self.inv.ravel()
            self.gdata = G.data
            self.indices = (keys % m).astype(np.int32)
            self.indptr = np.searchsorted(keys // m, np.arange(m + 1)).astype(np.int32)
            isdiag = np.zeros(m, dtype=bool)
            isdiag[G.row[(G.row == G.col) & (G.data != 0.0)]] = True
            self.zero = ~isdiag
            self.m = m

    def __call__(self, F: np.ndarray, mu: float) -> np.ndarray:
        if self.dense:
            M = self.G.copy()
            diag = M.reshape(-1)[::M.shape[0] + 1]       # a view of M's diagonal
            diag += mu + (diag == 0.0)
            return self.Js.T @ solve_dense(M, -F)
        import scipy.sparse as sp
        from scipy.sparse.linalg import splu
        data = np.bincount(self.inv, weights=np.concatenate([self.gdata, mu + self.zero]),
                           minlength=len(self.indices))
        M = sp.csc_matrix((data, self.indices, self.indptr), shape=(self.m, self.m))
        return self.Js.T @ splu(M).solve(-F)


def newton(tape: Tape, x0: np.ndarray, cols: np.ndarray, scale: np.ndarray | None = None,
           choices: np.ndarray | None = None, max_iter: int = 100,
           tol: float = TOL, reduction=None) -> NewtonResult:
    """Solve ``tape``'s rows for ``x[cols]`` from ``x0`` (not modified).

    ``scale`` (len(cols)) weights the unknowns (default 1); ``choices`` freezes min/max branches;
    ``reduction`` (:class:`~.reduce.Reduction`) substitutes ``x[cols] = S z + t`` and drops the
    rows it solved.  Stops at ``max |F| <= tol`` (rows kept), after ``max_iter`` steps, or when
    no damping reduces ``|F|``.  A :class:`~.small.SmallTape` runs the same steps in Python
    floats (``solve_newton``: the same iterates, bit for bit).
    """
    small = getattr(tape, "solve_newton", None)
    if small is not None:
        return small(x0, cols, scale, choices, max_iter, tol, reduction)
    x = x0.copy()
    if reduction is not None:
        red = reduction
        x[cols] = red.expand(red.z0) + red.t
        keep = red.keep
        d = red.scale
        u = red.z0.copy()
    else:
        keep = None
        d = np.ones(len(cols)) if scale is None else scale
        u = x[cols].copy()

    def place(u):
        xn = x.copy()
        xn[cols] = (red.expand(u) + red.t) if reduction is not None else u
        return xn

    def residual(xx):
        F, v = tape.evaluate(xx, choices, nodes=True)
        return (F if keep is None else F[keep]), v

    F, v = residual(x)
    res = float(np.max(np.abs(F))) if len(F) else 0.0
    if res <= tol or not len(u) or not np.isfinite(res):
        return NewtonResult(x, res <= tol, 0, res)
    norm = math.sqrt(F.dot(F))       # np.linalg.norm of a 1-D array: these very steps
    mu = 1e-12
    it = 0
    small = dense_enough(len(F), len(u))
    while it < max_iter:
        it += 1
        # the reduced Jacobian J[keep] @ S comes straight from the tape (Tape.jacobian)
        if small:                    # dense all the way: no sparse-matrix overhead
            Js = tape.jacobian(x, cols, choices, v, dense=True, reduction=reduction) * d
        else:
            J = tape.jacobian(x, cols, choices, v, reduction=reduction)
            Js = type(J)((J.data * d[J.indices], J.indices, J.indptr), shape=J.shape)
        accepted = False
        if unreachable(Js, F):
            break                    # every damping gives the step 0: none can be accepted
        step = _Step(Js, dense=small)
        for _ in range(14):
            try:
                du = d * step(F, mu)
            except (RuntimeError, np.linalg.LinAlgError):
                mu = max(mu * 100, 1e-8)
                continue
            un = u + du
            xn = place(un)
            Fn, vn = residual(xn)
            nn = math.sqrt(Fn.dot(Fn))
            if math.isfinite(nn) and nn < norm:
                u, x, F, v, norm = un, xn, Fn, vn, nn
                mu = max(mu / 10, 1e-12)
                accepted = True
                break
            mu = max(mu * 10, 1e-8)
        res = float(np.max(np.abs(F)))
        if res <= tol or not accepted:
            break
    return NewtonResult(x, res <= tol, it, res)
