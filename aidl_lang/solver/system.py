"""The residual rows of a model, ready for solving.

Built once the interpreter has finished, so that everything deferred can be resolved (paper,
appendix "Solver Details", *Deferred expressions*):

* bounding-box terms are expanded into ``min``/``max`` over the extreme points of their target,
  each constraint leaving out descendants whose own box it also uses (:mod:`aidl_lang.bbox`);
* every inequality ``g >= 0`` becomes two equations over a slack ``s`` (a new unknown owned by
  the constraint): ``g - s == 0`` and ``s - |s| == 0`` (computed as ``2 min(s, 0)``, so the
  branch iteration of :mod:`.hierarchy` decides whether the bound is active);
* every box a constraint uses also gets width >= 0 and height >= 0 written the same way
  (non-inversion: a solve never turns a box inside out).

Parameters: the model's ``x`` (``n_model`` entries) followed by one slack per inequality.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..memory import gc_paused
from ..geometry.bbox import collect, exclusions, expand, side_expr
from ..geometry.expr import Lin, add, func, mul, var
from ..geometry.model import Constraint, Model

EQ, LINK, SIGN = 0, 1, 2


@dataclass
class Rows:
    """All residual rows of a model (see module doc).

    ``exprs[r]``: residual expression over the extended parameter vector; ``constraint[r]``:
    the constraint it comes from; ``kind[r]``: EQ, LINK (``g - s``) or SIGN (``s - |s|``);
    ``slack[r]``: the slack's parameter index for LINK/SIGN rows, else -1.
    """

    exprs: list = field(default_factory=list)
    constraint: list = field(default_factory=list)
    kind: list = field(default_factory=list)
    slack: list = field(default_factory=list)
    n_model: int = 0
    n_params: int = 0
    by_owner: dict = field(default_factory=dict)      # id(Structure) -> [row]

    def add(self, c: Constraint, e, kind=EQ, slack=-1) -> None:
        r = len(self.exprs)
        self.exprs.append(e)
        self.constraint.append(c)
        self.kind.append(kind)
        self.slack.append(slack)
        self.by_owner.setdefault(id(c.owner), []).append(r)

    def add_inequality(self, c: Constraint, g) -> None:
        s = self.n_params
        self.n_params += 1
        sv = var(s)
        self.add(c, add(g, mul(-1.0, sv)), LINK, s)
        # s - |s| == 0, written 2 min(s, 0): its branch (active: 2s, inactive: 0) is a min/max
        # choice that the branch iteration freezes and re-checks like any other
        self.add(c, func("min", mul(2.0, sv), 0.0), SIGN, s)


def build_rows(model: Model, x: np.ndarray) -> Rows:
    """The rows of every constraint of ``model`` at parameter values ``x`` (model part)."""
    with gc_paused():          # many small acyclic objects: no cyclic collections meanwhile
        return _build_rows(model, x)


def _build_rows(model: Model, x: np.ndarray) -> Rows:
    rows = Rows(n_model=len(x), n_params=len(x))
    cache: dict = {}
    for c in model.constraints:
        if c.deferred is not None:
            terms: list = []
            for eq in c.deferred:
                collect(eq.expr, terms)
            excl = exclusions(terms)
            boxes: dict = {}
            for eq in c.deferred:
                e = expand(eq.expr, x, excl, cache, boxes)
                if eq.ineq:
                    rows.add_inequality(c, e)
                else:
                    rows.add(c, e)
            for target, frame, axes in boxes.values():
                _non_inversion(rows, c, target, frame, axes, x, excl, cache)
        for eq in c.equations:
            if eq.ineq:
                rows.add_inequality(c, eq.expr)
            else:
                rows.add(c, eq.expr)
    return rows


def _non_inversion(rows: Rows, c, target, frame, axes, x, excl, cache) -> None:
    for axis in sorted(axes):
        lo, hi = ("left", "right") if axis == "x" else ("bottom", "top")
        a = side_expr(target, lo, frame, x, excl, cache)
        b = side_expr(target, hi, frame, x, excl, cache)
        if isinstance(a, Lin) and isinstance(b, Lin):
            continue            # a single point: width 0 by construction
        rows.add_inequality(c, add(b, mul(-1.0, a)))


def user_residuals(solver, rows: np.ndarray, F: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Each row's residual as the user sees it, from the tape's ``F`` over ``rows``: ``|F|``
    for an equation; for an inequality its violation ``max(0, -g)`` (``g = F + s``) on the
    LINK row and 0 on the SIGN row."""
    kind = solver.kind[rows]
    out = np.abs(F)
    link = kind == LINK
    if link.any():
        out[link] = np.maximum(0.0, -(F[link] + x[solver.slack[rows[link]]]))
    out[kind == SIGN] = 0.0
    return out
