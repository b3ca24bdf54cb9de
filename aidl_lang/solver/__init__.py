"""Solve a model's constraints (flat solve of the whole tree).

1. Deferred expressions: bounding boxes are expanded now that the tree is final, each
   constraint leaving out descendants whose own box it also uses (:mod:`aidl_lang.bbox`).
2. Branch pruning: ``min``/``max`` are replaced by the branch active at the current point
   (paper, appendix "Solver Details"); after a solve the original expressions are re-checked and
   the solve repeats from the new point until they hold.
3. Inequalities (``<=``, ``>=``, Inside, Taller, ...) use an active set: an inequality violated at
   the current point is solved as an equality, then everything is re-checked.
4. Each round is one damped minimum-norm Newton solve (:mod:`.newton`).

A failure lists the constraints still unsatisfied, with their structure and source span.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..bbox import collect, expand, exclusions
from ..expr import evaluate, has_branches, prune
from ..model import Constraint, Model
from .newton import TOL, build_system, newton

MAX_ROUNDS = 12
MAX_ITER = 100
CHECK_TOL = 1e-6
FRAME_SCALE = 100.0     # frames move 1e4x cheaper (in the squared step norm) than geometry


@dataclass
class Row:
    constraint: Constraint
    expr: object          # original (branches intact)
    ineq: bool


@dataclass
class SolveResult:
    converged: bool
    iterations: int
    rounds: int
    unsatisfied: list = field(default_factory=list)   # [(Constraint, residual)]
    max_residual: float = 0.0
    n_unknowns: int = 0
    n_equations: int = 0


def equations(model: Model, x: np.ndarray) -> list[Row]:
    """All equations of the model with deferred bounding boxes expanded."""
    rows = []
    for c in model.constraints:
        if c.deferred is not None:
            terms = []
            for eq in c.deferred:
                collect(eq.expr, terms)
            excl = exclusions(terms)
            for eq in c.deferred:
                rows.append(Row(c, expand(eq.expr, x, excl), eq.ineq))
        for eq in c.equations:
            rows.append(Row(c, eq.expr, eq.ineq))
    return rows


def row_residual(r: Row, x) -> float:
    v = evaluate(r.expr, x)
    if r.ineq:
        return max(0.0, -v)
    return abs(v)


def solve(model: Model, max_iter: int = MAX_ITER) -> SolveResult:
    x = model.xs()
    free = np.asarray(model.free, dtype=bool)
    rows = equations(model, x)
    scale = np.array([FRAME_SCALE if lab.endswith((".frame.x", ".frame.y")) else 1.0
                      for lab in model.param_label])
    active = [not r.ineq or evaluate(r.expr, x) < -TOL for r in rows]
    total_it = 0
    res = None
    rounds = 0
    for rounds in range(1, MAX_ROUNDS + 1):
        sel = [i for i, r in enumerate(rows) if active[i]]
        exprs = [prune(rows[i].expr, x) if has_branches(rows[i].expr) else rows[i].expr
                 for i in sel]
        system = build_system(exprs, free, x, scale)
        res = newton(system, x, max_iter=max_iter)
        total_it += res.iterations
        x = res.x
        changed = False
        for i, r in enumerate(rows):
            if r.ineq and not active[i] and evaluate(r.expr, x) < -1e-9:
                active[i] = True
                changed = True
        bad_branch = any(active[i] and has_branches(r.expr) and row_residual(r, x) > CHECK_TOL
                         for i, r in enumerate(rows))
        if not changed and not bad_branch:
            break
        if not res.converged and not changed:
            break
    model.x = list(map(float, x))
    per: dict[int, tuple[Constraint, float]] = {}
    worst = 0.0
    for r in rows:
        v = row_residual(r, x)
        worst = max(worst, v)
        if v > CHECK_TOL:
            prev = per.get(id(r.constraint))
            if prev is None or prev[1] < v:
                per[id(r.constraint)] = (r.constraint, v)
    unsat = sorted(per.values(), key=lambda cv: -cv[1])
    return SolveResult(not unsat, total_it, rounds, unsat, worst,
                       int(free.sum()), len(rows))


def constraint_residuals(model: Model) -> list[tuple[Constraint, float]]:
    """Largest residual of each constraint at the model's current values."""
    x = model.xs()
    out: dict[int, list] = {}
    for r in equations(model, x):
        v = row_residual(r, x)
        e = out.setdefault(id(r.constraint), [r.constraint, 0.0])
        e[1] = max(e[1], v)
    return [(c, v) for c, v in out.values()]
