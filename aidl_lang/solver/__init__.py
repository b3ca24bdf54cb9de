"""Solve a model's constraints: the paper's hierarchical solver (appendix "Solver Details").

Pipeline of this package, one module per step:

* :mod:`.system`: the model's residual rows, with deferred bounding boxes expanded and
  inequalities written with slacks (non-inversion included);
* :mod:`.tape`: rows compiled into a vectorised tape (values and reverse-mode Jacobian);
* :mod:`.newton`: damped minimum-norm Newton steps on a tape;
* :mod:`.hierarchy`: the post-order recursive solve with iterative deepening and min/max
  branch iteration;
* :mod:`.diagnose`: after a failure, the smallest conflicting constraint sets (rank-revealing
  QR of the Jacobian); on demand, :mod:`.freedom` (degrees of freedom per structure),
  :mod:`.redundancy` (redundant constraints) and :mod:`.sliding` (what can still move).

:func:`solve` is the entry point; a failure lists the constraints still unsatisfied and the
conflict sets found, with their structure and source span.
"""
from __future__ import annotations

import numpy as np

from ..base.records import Compared
from ..geometry.core.model import Constraint, Model
from ..geometry.relations.bbox import drawn_box_misses
from .core.hierarchy import CHECK_TOL, ITER_BUDGET, Solver
from .core.holds import build_rows
from .core.system import LINK, SIGN, user_residuals
from .core.tape import Tape


class SolveResult(Compared):
    """Outcome of :func:`solve`.

    ``n_unknowns``/``n_equations``: what Newton solved for (the free unknowns, the rows);
    ``n_settled``: unknowns settled directly before Newton, each by one affine constraint row
    of its own (:func:`.system.pinned`; a ``Fixed`` point, a held distance), not counted in
    ``n_unknowns``.  ``unsatisfied``: ``[(Constraint, residual)]`` worst first; ``conflicts``: list of
    :class:`~.diagnose.Conflict`; ``budget_exceeded``: the iteration budget ran out.
    """
    __slots__ = ("converged", "iterations", "rounds", "unsatisfied", "max_residual", "n_unknowns",
                 "n_equations", "n_settled", "conflicts", "budget_exceeded", "out_of_time",
                 "attempts", "solver")

    def __init__(self, converged: bool, iterations: int, rounds: int,
                 unsatisfied: list | None = None, max_residual: float = 0.0, n_unknowns: int = 0,
                 n_equations: int = 0, n_settled: int = 0, conflicts: list | None = None,
                 budget_exceeded: bool = False, out_of_time: bool = False, attempts: int = 0,
                 solver: Solver | None = None):
        self.converged = converged
        self.iterations = iterations
        self.rounds = rounds
        self.unsatisfied = [] if unsatisfied is None else unsatisfied
        self.max_residual = max_residual
        self.n_unknowns = n_unknowns
        self.n_equations = n_equations
        self.n_settled = n_settled
        self.conflicts = [] if conflicts is None else conflicts
        self.budget_exceeded = budget_exceeded
        self.out_of_time = out_of_time
        self.attempts = attempts
        self.solver = solver


def solve_text(res: SolveResult) -> str:
    """The solve in words for ``aidl check``'s summary line: ``"20 unknowns, 20 equations,
    solved in 2 Newton steps"``; with unknowns settled directly (:attr:`SolveResult.n_settled`)
    it says so, so that a model whose constraints were all honoured before Newton does not
    read "0 unknowns" as "nothing was solved": ``"4 unknowns, all 4 settled directly by
    their constraints (0 Newton steps)"`` or ``"30 unknowns: 4 settled directly by their
    constraints, 26 solved by Newton from 26 equations in 3 steps"``."""
    n, k, e, it = res.n_unknowns, res.n_settled, res.n_equations, res.iterations
    if not k:
        return f"{n} unknowns, {e} equations, solved in {it} Newton steps"
    if not n:
        return (f"{k} unknowns, all {k} settled directly by their constraints "
                f"({e} further equation{'s' if e != 1 else ''} checked, 0 Newton steps)" if e else
                f"{k} unknowns, all {k} settled directly by their constraints (0 Newton steps)")
    return (f"{n + k} unknowns: {k} settled directly by their constraints, {n} solved by "
            f"Newton from {e} equations in {it} steps")


def solve(model: Model, flat: bool = False, diagnose: bool = True,
          deadline: float | None = None) -> SolveResult:
    """Solve ``model`` in place (``model.x`` is updated even on failure, for diagnostics).

    ``flat=True`` solves everything at once instead of hierarchically (for benchmarks);
    ``deadline`` (a :func:`aidl_lang.base.limits.now` value: CPU seconds) stops the solve and the conflict search when
    passed (``SolveResult.out_of_time``)."""
    solver = Solver(model)
    solver.deadline = deadline
    return run(solver, flat=flat, diagnose=diagnose)


# solves again at most, for relations on drawn boxes (run): each takes the box where the
# last one ended, so the miss shrinks by the error of its first-order model (a flexible
# triangle's inset, stretched: 0.17 mm, then 10 times less each time)
RESOLVES = 10


def run(solver: Solver, flat: bool = False, diagnose: bool = True) -> SolveResult:
    """(Re-)run a compiled :class:`Solver` from its current point and report.

    A failed solve of a model whose drawings are held where their files put them, next to an
    inequality (:attr:`.system.Rows.bounded_holds`), is run once more from the start with
    those holds released: a bound the held drawing breaks moves it, as it did before holds
    (``Inside(logo, body)`` over a logo drawn off the plate).  The result is then the new
    solver's (``SolveResult.solver``).

    A converged solve whose solution misses a relation on a box read from a drawn outline (an
    ``Inset``, an ``Intersect``: :func:`~aidl_lang.geometry.relations.bbox.drawn_box_misses`,
    its sides taken as its source's extreme points plus constants where the solve began) is
    solved again from the solution by a new solver, the boxes taken there, while the miss
    shrinks (:data:`RESOLVES` times at most; what is left is W0405); the result and its
    ``solver`` are the last one's, its ``iterations`` all of them (issue 109)."""
    res = _run_held(solver, flat, diagnose)
    steps, last = res.iterations, float("inf")
    for _ in range(RESOLVES):
        if not res.converged or res.out_of_time:
            break
        miss = max((v for _c, v in drawn_box_misses(res.solver.model if res.solver is not None
                                                    else solver.model)), default=0.0)
        if miss == 0.0 or miss >= last:     # met (to 1e-9 mm), or no nearer: W0405 says it
            break
        last = miss
        again = Solver(solver.model)
        again.deadline = solver.deadline
        res = _run_held(again, flat, diagnose)
        steps += res.iterations
        res.iterations = steps
    return res


def _run_held(solver: Solver, flat: bool, diagnose: bool) -> SolveResult:
    """:func:`run` but the solves again for drawn boxes: the holds released after a failure."""
    x_start = list(solver.model.x)
    res = _run(solver, flat, diagnose)
    bounded = solver.rows_built.bounded_holds
    if res.converged or not bounded or res.budget_exceeded or res.out_of_time:
        return res
    model = solver.model
    for c in bounded:
        c.released = True
    model.x = x_start
    again = Solver(model)
    again.deadline = solver.deadline
    return _run(again, flat, diagnose)


def _run(solver: Solver, flat: bool = False, diagnose: bool = True) -> SolveResult:
    model = solver.model
    solver.failed.clear()
    solver.trace.__init__()
    ok = solver.solve_flat() if flat else solver.solve_hierarchical()
    tr = solver.trace
    model.x = solver.x[:solver.n_model].tolist()
    res = SolveResult(ok and not tr.budget_exceeded, tr.iterations,
                      max((a.rounds for a in tr.attempts), default=0),
                      n_unknowns=int(solver.free.sum()), n_equations=len(solver.rows.exprs),
                      n_settled=len(solver.pins),
                      budget_exceeded=tr.budget_exceeded, attempts=len(tr.attempts),
                      solver=solver, out_of_time=tr.out_of_time)
    if not res.converged:
        per: dict[int, list] = {}
        worst = 0.0
        for f in tr.failures:
            vals = _row_residuals(solver, f.attempt.rows, solver.x)
            for r, v in zip(f.attempt.rows, vals):
                worst = max(worst, v)
                if v > CHECK_TOL:
                    c = solver.rows.constraint[r]
                    e = per.setdefault(id(c), [c, 0.0])
                    e[1] = max(e[1], v)
        res.unsatisfied = sorted(((c, v) for c, v in per.values()), key=lambda cv: -cv[1])
        res.max_residual = worst
        if diagnose and tr.failures:
            from .diagnosis.diagnose import conflicts
            for f in tr.failures:
                res.conflicts += conflicts(solver, f.attempt.rows, f.attempt.cols, solver.x)
    return res


def _row_residuals(solver: Solver, rows: np.ndarray, x: np.ndarray) -> np.ndarray:
    if not len(rows):
        return np.zeros(0)
    return user_residuals(solver, rows, solver.tape(rows).evaluate(x), x)


def constraint_residuals(model: Model) -> list[tuple[Constraint, float]]:
    """Largest residual of each constraint at the model's current values (true min/max)."""
    x = model.xs()
    rows = build_rows(model, x)
    xe = np.concatenate([x, np.zeros(rows.n_params - len(x))])
    F = Tape(rows.exprs, rows.n_params).evaluate(xe) if rows.exprs else np.zeros(0)
    out: dict[int, list] = {}
    for r, c in enumerate(rows.constraint):
        k = rows.kind[r]
        v = max(0.0, -F[r]) if k == LINK else 0.0 if k == SIGN else abs(F[r])
        e = out.setdefault(id(c), [c, 0.0])
        e[1] = max(e[1], v)
    return [(c, v) for c, v in out.values()]


__all__ = ["SolveResult", "Solver", "solve", "run", "constraint_residuals", "ITER_BUDGET"]
