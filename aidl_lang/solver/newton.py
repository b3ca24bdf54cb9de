"""Damped minimum-norm Newton (Levenberg–Marquardt) on a sparse system, SolveSpace style.

Solves ``F(x) = 0`` for the free parameters.  Affine equations are one sparse matrix (all
evaluated in one product); nonlinear equations are evaluated with their analytic gradients.
The step is ``dx = -D J_D^T (J_D J_D^T + mu I)^-1 F`` with ``J_D = J D`` through ``scipy.sparse.linalg.splu``: the
minimum-norm step moves the starting guesses as little as the constraints require, and
the column scaling ``D`` (frames x100) makes moving a whole structure cheaper than deforming it;
``mu > 0`` keeps it defined for redundant (rank-deficient) systems.  ``mu`` grows when a step
does not reduce ``|F|`` and shrinks when it does (Levenberg–Marquardt damping).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from ..expr import Lin, value_and_grad

TOL = 1e-10


@dataclass
class System:
    """The equations of one solve, laid out for fast evaluation.

    ``cols`` maps a full parameter index to its unknown column (-1 for held parameters).
    """

    n_rows: int
    cols: np.ndarray
    free_idx: np.ndarray
    A: sp.csr_matrix                 # affine rows (row order: lin_rows)
    b: np.ndarray
    lin_rows: np.ndarray
    nl: list                         # [(row, expr)]

    def residual_and_jacobian(self, x: np.ndarray, want_j: bool = True):
        F = np.empty(self.n_rows)
        xf = x[self.free_idx]
        if len(self.lin_rows):
            F[self.lin_rows] = self.A @ xf + self.b
        rows, cols, vals = [], [], []
        for r, e in self.nl:
            v, g = value_and_grad(e, x)
            F[r] = v
            if want_j:
                for k, d in g.items():
                    c = self.cols[k]
                    if c >= 0 and d != 0.0:
                        rows.append(r)
                        cols.append(c)
                        vals.append(d)
        if not want_j:
            return F, None
        Jn = sp.csr_matrix((vals, (rows, cols)), shape=(self.n_rows, len(self.free_idx)))
        J = self.A_full + Jn
        return F, J


def build_system(exprs: list, free: np.ndarray, x: np.ndarray,
                 scale: np.ndarray | None = None) -> System:
    """``scale[i]`` > 1 makes parameter ``i`` cheaper to move in the minimum-norm step
    (translation frames: a part moves rigidly before it deforms)."""
    n = len(x)
    free_idx = np.flatnonzero(free)
    cols = -np.ones(n, dtype=np.int64)
    cols[free_idx] = np.arange(len(free_idx))
    lr, lc, lv, lb, lin_rows, nl = [], [], [], [], [], []
    for r, e in enumerate(exprs):
        if isinstance(e, Lin):
            c0 = e.const
            for k, v in e.terms.items():
                if cols[k] >= 0:
                    lr.append(len(lin_rows))
                    lc.append(cols[k])
                    lv.append(v)
                else:
                    c0 += v * x[k]
            lb.append(c0)
            lin_rows.append(r)
        else:
            nl.append((r, e))
    m = len(free_idx)
    A = sp.csr_matrix((lv, (lr, lc)), shape=(len(lin_rows), m))
    sys_ = System(len(exprs), cols, free_idx, A, np.asarray(lb, dtype=float),
                  np.asarray(lin_rows, dtype=np.int64), nl)
    # the affine rows placed at their row numbers, reused every iteration
    P = sp.csr_matrix((np.ones(len(lin_rows)), (np.asarray(lin_rows, dtype=np.int64),
                                                  np.arange(len(lin_rows)))),
                      shape=(len(exprs), len(lin_rows)))
    sys_.A_full = (P @ A).tocsr()
    d = np.ones(len(free_idx)) if scale is None else np.asarray(scale, dtype=float)[free_idx]
    sys_.D = sp.diags(d)
    sys_.d = d
    return sys_


@dataclass
class NewtonResult:
    x: np.ndarray
    converged: bool
    iterations: int
    residual: float


def newton(system: System, x0: np.ndarray, max_iter: int = 100, tol: float = TOL) -> NewtonResult:
    x = x0.copy()
    if system.n_rows == 0 or len(system.free_idx) == 0:
        F, _ = system.residual_and_jacobian(x, want_j=False)
        res = float(np.max(np.abs(F))) if len(F) else 0.0
        return NewtonResult(x, res <= tol, 0, res)
    F, J = system.residual_and_jacobian(x)
    norm = float(np.linalg.norm(F))
    mu = 1e-9
    it = 0
    for it in range(1, max_iter + 1):
        if np.max(np.abs(F)) <= tol:
            return NewtonResult(x, True, it - 1, float(np.max(np.abs(F))))
        Js = (J @ system.D).tocsr()
        JJt = (Js @ Js.T).tocsc()
        accepted = False
        for _ in range(12):
            try:
                M = JJt + sp.identity(JJt.shape[0], format="csc") * mu
                y = splu(M).solve(-F)
            except RuntimeError:
                mu = max(mu * 100, 1e-8)
                continue
            dx = system.d * (Js.T @ y)
            xn = x.copy()
            xn[system.free_idx] += dx
            Fn, _ = system.residual_and_jacobian(xn, want_j=False)
            nn = float(np.linalg.norm(Fn))
            if np.isfinite(nn) and nn < norm:
                x, norm = xn, nn
                mu = max(mu / 10, 1e-12)
                accepted = True
                break
            mu = max(mu * 10, 1e-8)
        if not accepted:
            break
        F, J = system.residual_and_jacobian(x)
    res = float(np.max(np.abs(F))) if len(F) else 0.0
    return NewtonResult(x, res <= tol, it, res)
