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
from ..geometry.expr import Expr, Lin, Nl, add, func, mul, var
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

    def subset(self, keep: list) -> "Rows":
        """The rows ``keep`` (increasing row indices) as a new :class:`Rows`, renumbered;
        parameters (and slacks) keep their indices."""
        out = Rows(n_model=self.n_model, n_params=self.n_params)
        exprs, cons, kind, slack = self.exprs, self.constraint, self.kind, self.slack
        out.exprs = [exprs[r] for r in keep]
        out.constraint = [cons[r] for r in keep]
        out.kind = [kind[r] for r in keep]
        out.slack = [slack[r] for r in keep]
        by = out.by_owner
        for r, c in enumerate(out.constraint):
            by.setdefault(id(c.owner), []).append(r)
        return out


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


PIVOT = 1e-6      # a pinning row's coefficient on the unknown it pins, against its largest


def pinned(rows: Rows, free, is_frame, owner: list) -> list[tuple[int, int]]:
    """The unknowns fixed in their structure's frame by affine rows alone, and those rows:
    ``[(parameter, row)]`` in an order where each row pins its parameter from constants and
    parameters pinned before it (issue 38: rigid geometry adds no unknowns).

    A set is taken only as a whole connected component of the rows' unknowns: every row of
    it is an affine equation (``Fixed``, a constructor's offsets such as an ``Arc``'s ends
    from its center, ``p.x == 5``), it reads no held value (an edit of one would move it) and
    no frame (a frame stays an unknown: the geometry moves with it), all its unknowns and
    rows belong to one structure, no other row (nonlinear, inequality, box) reads its
    unknowns, and the rows pin the unknowns one at a time, each row pinning one unknown with
    a coefficient of at least :data:`PIVOT` times its largest.  Its Jacobian is then
    square, triangular and invertible, and no other row touches its columns: taking the
    unknowns out as held values and dropping the rows leaves every other unknown's solve,
    the rank deficiency (degrees of freedom), the redundancy of every other constraint and
    every conflict as they were (``docs/solver.md`` §1).  ``spur_gear``'s teeth (each arc's
    center ``Fixed``, its ends offsets from it) are such components: the gear pair's 6,658
    unknowns go down to a few dozen."""
    exprs, kind, cons = rows.exprs, rows.kind, rows.constraint
    n = rows.n_model
    ok_var = (np.asarray(free[:n], dtype=bool) & ~np.asarray(is_frame[:n], dtype=bool)).tolist()
    # each parameter's structure when it may be pinned, else None (held, a frame, a slack)
    home = [o if ok else None for o, ok in zip(owner, ok_var)] + [None] * (rows.n_params - n)
    cand: list[int] = []                   # rows that may pin
    var_rows: dict[int, list[int]] = {}
    seeds: set = set()                     # unknowns that cannot be pinned, nor their component
    other: list[int] = []                  # nonlinear rows, inequalities: walked only if needed
    left = [0] * len(exprs)                # a candidate's unknowns not yet pinned
    for r, e in enumerate(exprs):
        if kind[r] != EQ or type(e) is not Lin:
            other.append(r)
            continue
        terms = e.terms
        if not terms:
            continue
        o = cons[r].owner
        if o is not None:
            for i in terms:
                if home[i] is not o:
                    break
            else:                          # every unknown of the row is of its structure
                cand.append(r)
                left[r] = len(terms)
                for i in terms:
                    vr = var_rows.get(i)
                    if vr is None:
                        var_rows[i] = [r]
                    else:
                        vr.append(r)
                continue
        seeds.update(i for i in terms if i < n)
    if not cand:
        return []
    # propagation: a row with one unknown not yet pinned pins it
    pin_of: dict[int, int] = {}            # parameter -> the row that pins it
    order: list[tuple[int, int]] = []
    todo = [r for r in cand if left[r] == 1]
    while todo:
        r = todo.pop()
        if left[r] != 1:
            continue
        terms = exprs[r].terms
        for v in terms:
            if v not in pin_of:
                break
        c = abs(terms[v])
        if len(terms) > 1 and not c >= PIVOT * max(map(abs, terms.values())):
            seeds.add(v)
            continue
        left[r] = -1                       # used
        pin_of[v] = r
        order.append((v, r))
        for r2 in var_rows[v]:
            if r2 != r and left[r2] > 0:
                left[r2] -= 1
                if left[r2] == 1:
                    todo.append(r2)
    if not order:
        return []
    # a candidate row left unused (it pins nothing new: a dependent row, or one of a cycle)
    # spoils its component, and so does an unknown not pinned
    for r in cand:
        if left[r] >= 0:
            seeds.update(exprs[r].terms)
    # nor may a nonlinear row, an inequality or a box read a pinned unknown
    seen: set = set()
    for r in other:
        stack = [exprs[r]]
        while stack:
            e = stack.pop()
            if type(e) is Lin:
                for i in e.terms:
                    if i in pin_of:
                        seeds.add(i)
                continue
            if id(e) in seen:
                continue
            seen.add(id(e))
            if type(e) is not Nl:
                return []                  # not an expression the solver knows: pin nothing
            stack.extend(a for a in e.args if isinstance(a, Expr))
    # spoil the whole component of every seed (through the candidate rows)
    spoilt = set(seeds)
    stack = list(seeds)
    done_rows: set = set()
    while stack:
        v = stack.pop()
        for r in var_rows.get(v, ()):
            if r in done_rows:
                continue
            done_rows.add(r)
            for u in exprs[r].terms:
                if u not in spoilt:
                    spoilt.add(u)
                    stack.append(u)
    return [(v, r) for v, r in order if v not in spoilt]


def pin_values(rows: Rows, pins: list, x: np.ndarray) -> None:
    """Set each pinned parameter of :func:`pinned`'s ``pins`` so that its row holds
    (``x_v = -(const + sum of the row's other terms) / coef_v``, in ``pins``' order)."""
    exprs = rows.exprs
    xl = x.tolist()            # Python floats: the same arithmetic without NumPy scalars
    for v, r in pins:
        e = exprs[r]
        terms = e.terms
        s = e.const
        if len(terms) > 1:                 # (a Fixed row has its own unknown only)
            for i, c in terms.items():
                if i != v:
                    s += c * xl[i]
        xl[v] = -s / terms[v]
    vs = [v for v, _ in pins]
    x[vs] = [xl[v] for v in vs]


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
