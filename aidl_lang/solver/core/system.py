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

from itertools import chain

import numpy as np

from ...base.records import Compared, Record
from ...base.memory import gc_paused
from ...geometry.relations.bbox import collect, defer_boxes, exclusions, expand, side_expr
from ...geometry.core.expr import Lin, add, func, mul, var
from ...geometry.core.model import Constraint, Model

EQ, LINK, SIGN = 0, 1, 2


class Rows(Compared):
    """All residual rows of a model (see module doc).

    ``exprs[r]``: residual expression over the extended parameter vector; ``constraint[r]``:
    the constraint it comes from; ``kind[r]``: EQ, LINK (``g - s``) or SIGN (``s - |s|``);
    ``slack[r]``: the slack's parameter index for LINK/SIGN rows, else -1.
    """
    __slots__ = ("exprs", "constraint", "kind", "slack", "n_model", "n_params", "by_owner",
                 "bounded_holds")

    def __init__(self, exprs: list | None = None, constraint: list | None = None,
                 kind: list | None = None, slack: list | None = None, n_model: int = 0,
                 n_params: int = 0, by_owner: dict | None = None,
                 bounded_holds: list | None = None):
        self.exprs = [] if exprs is None else exprs
        self.constraint = [] if constraint is None else constraint
        self.kind = [] if kind is None else kind
        self.slack = [] if slack is None else slack
        self.n_model = n_model
        self.n_params = n_params
        self.by_owner = {} if by_owner is None else by_owner  # id(Structure) -> [row]
        # holds kept (holds.settle_holds) whose rows share unknowns with an inequality: released and
        # solved again when the solve fails (an inequality may need to move the drawing)
        self.bounded_holds = [] if bounded_holds is None else bounded_holds

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
    """The rows of every constraint of ``model`` at parameter values ``x`` (model part),
    holds included (:func:`.holds.build_rows` drops those the other rows determine)."""
    with gc_paused():          # many small acyclic objects: no cyclic collections meanwhile
        return _build_rows(model, x)


def _build_rows(model: Model, x: np.ndarray) -> Rows:
    rows = Rows(n_model=len(x), n_params=len(x))
    cache: dict = {}
    for c in model.constraints:
        if c.deferred is None:      # a box read where no interpreter path deferred it: the
            defer_boxes(c)          # same as one that did (was "cannot compile BBTerm")
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
SMALL_LEVEL = 16  # a level of fewer pins is done in Python (a NumPy level costs ~20 calls)


class Pins(Record):
    """What :func:`pinned` found: ``var[k]`` (a parameter index) is pinned by row ``row[k]``,
    through that row's term at ``entry[k]`` (an index into ``cols``/``vals``).  ``level[k]``
    (non-decreasing) orders them: a row of level ``L`` reads constants and parameters pinned
    at levels below ``L`` only.  ``indptr``, ``cols``, ``vals`` are the terms of every row
    that is an affine equation (other rows have none) in compressed sparse rows: row ``r``'s
    parameters and coefficients at ``indptr[r]:indptr[r + 1]``, in its ``terms`` dict's
    order.  Iterating gives the ``(parameter, row)`` pairs in order."""
    __slots__ = ("var", "row", "entry", "level", "indptr", "cols", "vals")

    def __init__(self, var: np.ndarray, row: np.ndarray, entry: np.ndarray, level: np.ndarray,
                 indptr: np.ndarray, cols: np.ndarray, vals: np.ndarray):
        self.var = var
        self.row = row
        self.entry = entry
        self.level = level
        self.indptr = indptr
        self.cols = cols
        self.vals = vals

    def __len__(self) -> int:
        return len(self.var)

    def __iter__(self):
        return zip(self.var.tolist(), self.row.tolist())


_NO_TERMS: dict = {}


def pinned_none() -> Pins:
    """No pins (what :func:`pinned` finds in a model without pinned geometry)."""
    z = np.zeros(0, dtype=np.int64)
    return Pins(z, z, z, z, np.zeros(1, dtype=np.int64), z, np.zeros(0))


def pinned(rows: Rows, free, is_frame, owner: list) -> Pins:
    """The unknowns fixed in their structure's frame by affine rows alone, and those rows
    (:class:`Pins`: ``(parameter, row)`` pairs in an order where each row pins its parameter
    from constants and parameters pinned before it; issue 38: rigid geometry adds no
    unknowns).

    A set is taken only as a whole connected component of the rows' unknowns: every row of
    it is an affine equation (``Fixed``, a constructor's offsets such as an ``Arc``'s ends
    from its center, ``p.x == 5``), it reads no held value (an edit of one would move it) and
    no frame (a frame stays an unknown: the geometry moves with it), all its unknowns and
    rows belong to one structure, and the rows pin the unknowns one at a time, each row
    pinning one unknown with a nonzero coefficient of at least :data:`PIVOT` times its
    largest.  Its Jacobian block is then square, triangular and invertible and zero outside
    its columns: taking the unknowns out as held values and dropping the rows leaves every
    other unknown's solve, the rank deficiency (degrees of freedom) and the redundancy of
    every other constraint as they were, whatever other rows read the pinned unknowns (a
    box, a ``Distance``: issue 48; before, any such reader spoilt the component, and a
    ``Below`` over a gear kept its 6,264 unknowns).  A conflict or a dependency through
    pinned geometry involves exactly the pinning rows its rows reach, which the diagnostics
    take back (:func:`~..diagnosis.diagnose._pin_closure`; ``docs/solver.md`` §1).  ``spur_gear``'s teeth (each arc's
    center ``Fixed``, its ends offsets from it, the pattern's copies affine in those) are
    such components: the gear pair's 6,658 unknowns go down to a few dozen.

    The rows' terms are taken once into arrays (compressed sparse rows and columns); the
    pinning peels them a level at a time: every candidate row with one unknown left pins it,
    all of a level in one array operation, and each pinned unknown takes one off the count
    of every row reading it (a row's last unknown is read off the sum of its unpinned
    terms' positions).  A triangular component's pinning is unique (each row pins the one
    unknown left to it in any order), so the pairs do not depend on the order of the peel."""
    exprs, kind = rows.exprs, rows.kind
    n, n_all, m = rows.n_model, rows.n_params, len(exprs)
    # every affine equation's terms (other rows: none), as compressed sparse rows
    aff = [e.terms if k == EQ and type(e) is Lin else _NO_TERMS for e, k in zip(exprs, kind)]
    lens = np.fromiter(map(len, aff), dtype=np.int64, count=m)
    nnz = int(lens.sum())
    cols = np.fromiter(chain.from_iterable(aff), dtype=np.int64, count=nnz)
    vals = np.fromiter(chain.from_iterable(map(dict.values, aff)), dtype=np.float64, count=nnz)
    indptr = np.zeros(m + 1, dtype=np.int64)
    np.cumsum(lens, out=indptr[1:])
    erow = np.repeat(np.arange(m, dtype=np.int64), lens)        # each term's row
    # each parameter's structure (its id) when it may be pinned, else 0 (held, a frame, a
    # slack); each row's structure
    home = np.zeros(n_all, dtype=np.int64)
    home[:len(owner)] = np.fromiter(map(id, owner), dtype=np.int64, count=len(owner))
    home[:n][~(np.asarray(free[:n], dtype=bool) & ~np.asarray(is_frame[:n], dtype=bool))] = 0
    row_home = np.zeros(m, dtype=np.int64)
    for k, rs in rows.by_owner.items():
        row_home[rs] = k
    # a candidate: an affine equation of a structure all of whose unknowns are of it
    foreign = np.bincount(erow[home[cols] != row_home[erow]], minlength=m)
    cand = (lens > 0) & (foreign == 0) & (row_home != id(None))
    if not cand.any():
        return pinned_none()
    ecand = cand[erow]
    seed = np.zeros(n_all, dtype=bool)     # unknowns that cannot be pinned, nor their component
    absv = np.abs(vals)
    row_max = np.zeros(m)
    row_max[lens > 0] = np.maximum.reduceat(absv, indptr[:-1][lens > 0])
    pivot_ok = (absv > 0) & (absv >= PIVOT * row_max[erow])
    # the candidates' terms by unknown (compressed sparse columns)
    ce = np.flatnonzero(ecand)
    by_col = ce[np.argsort(cols[ce], kind="stable")]
    colptr = np.zeros(n_all + 1, dtype=np.int64)
    np.cumsum(np.bincount(cols[ce], minlength=n_all), out=colptr[1:])
    left = np.where(cand, lens, -2)        # a candidate's unknowns not yet pinned (-1: used)
    unpinned = np.bincount(erow[ce], weights=ce, minlength=m).astype(np.int64)  # their terms
    # the peel, a level at a time
    out_var, out_row, out_entry, out_level = [], [], [], []
    front = np.flatnonzero(left == 1)
    level = 0
    while len(front):
        if len(front) < SMALL_LEVEL:
            v, rs, ent, lv, front, level = _levels_small(front, level, cols, erow, by_col,
                                                         colptr, pivot_ok, left, unpinned, seed)
        else:
            level += 1
            v, rs, ent, front = _level(front, cols, erow, by_col, colptr, pivot_ok, left,
                                       unpinned, seed)
            lv = np.full(len(v), level, dtype=np.int64)
        out_var.append(v)
        out_row.append(rs)
        out_entry.append(ent)
        out_level.append(lv)
    if not out_var:
        return pinned_none()
    var, row = np.concatenate(out_var), np.concatenate(out_row)
    entry, lev = np.concatenate(out_entry), np.concatenate(out_level)
    # a candidate row left unused (it pins nothing new: a dependent row, or one of a cycle)
    # spoils its component, and so does an unknown not pinned
    seed[cols[(left >= 0)[erow]]] = True
    # spoil the whole component of every seed (through the candidate rows)
    stack = np.flatnonzero(seed & (colptr[1:] > colptr[:-1])).tolist()
    if stack:
        spoilt = seed
        done_rows = np.zeros(m, dtype=bool)
        while stack:
            v = stack.pop()
            for r in erow[by_col[colptr.item(v):colptr.item(v + 1)]].tolist():
                if done_rows[r]:
                    continue
                done_rows[r] = True
                for u in cols[indptr.item(r):indptr.item(r + 1)].tolist():
                    if not spoilt[u]:
                        spoilt[u] = True
                        stack.append(u)
        keep = ~spoilt[var]
        var, row, entry, lev = var[keep], row[keep], entry[keep], lev[keep]
    return Pins(var, row, entry, lev, indptr, cols, vals)


def _level(front, cols, erow, by_col, colptr, pivot_ok, left, unpinned, seed):
    """One level of :func:`pinned`'s peel in array operations: the rows ``front`` (one
    unknown left each, ``left``) pin their unknowns; ``(unknowns, rows, terms, next
    front)``.  Of two rows left with one unknown, the first pins it; the other is left
    with none, unused (it spoils its component)."""
    front = front[left[front] == 1]
    ent = unpinned[front]                  # the one unknown left: its term
    ok = pivot_ok[ent]
    if not ok.all():
        seed[cols[ent[~ok]]] = True
        front, ent = front[ok], ent[ok]
    v, first = np.unique(cols[ent], return_index=True)
    front, ent = front[first], ent[first]
    left[front] = -1
    # every candidate row reading a pinned unknown has one unknown fewer
    start, count = colptr[v], colptr[v + 1] - colptr[v]
    ends = np.cumsum(count)
    reads = by_col[np.repeat(start - ends + count, count) + np.arange(ends[-1] if len(v) else 0)]
    rr = erow[reads]
    live = left[rr] > 0
    reads, rr = reads[live], rr[live]
    np.subtract.at(left, rr, 1)
    np.subtract.at(unpinned, rr, reads)
    return v, front, ent, np.unique(rr[left[rr] == 1])


def _levels_small(front, level, cols, erow, by_col, colptr, pivot_ok, left, unpinned, seed):
    """:func:`_level` one row at a time in Python, level after level while the levels stay
    small (a chain of offsets is a level per row); ``(unknowns, rows, terms, levels, next
    front, last level)``."""
    vs: list = []
    rows: list = []
    ents: list = []
    levels: list = []
    front = front.tolist()
    cols, erow, by_col, colptr = cols.tolist(), erow.tolist(), by_col.tolist(), colptr.tolist()
    left_a, unpinned_a = left, unpinned
    left, unpinned, pivot_ok = left.tolist(), unpinned.tolist(), pivot_ok.tolist()
    while front and len(front) < SMALL_LEVEL:
        level += 1
        nxt = []
        for r in front:
            if left[r] != 1:               # a second row left with the same unknown
                continue
            e = unpinned[r]
            v = cols[e]
            if not pivot_ok[e]:
                seed[v] = True
                continue
            left[r] = -1
            vs.append(v)
            rows.append(r)
            ents.append(e)
            levels.append(level)
            for e2 in by_col[colptr[v]:colptr[v + 1]]:
                r2 = erow[e2]
                if left[r2] > 0:
                    left[r2] -= 1
                    unpinned[r2] -= e2
                    if left[r2] == 1:
                        nxt.append(r2)
        front = nxt
    left_a[:] = left
    unpinned_a[:] = unpinned
    as_array = lambda a: np.asarray(a, dtype=np.int64)
    return (as_array(vs), as_array(rows), as_array(ents), as_array(levels), as_array(front),
            level)


def pin_values(rows: Rows, pins: Pins, x: np.ndarray) -> None:
    """Set each pinned parameter of :func:`pinned`'s ``pins`` so that its row holds
    (``x_v = -(const + sum of the row's other terms) / coef_v``), a level at a time (a
    small level in Python); each row's sum is taken in its terms' order, so the floats are
    those of the sum written out in Python."""
    if not len(pins):
        return
    exprs = rows.exprs
    var, row, ent, lev, indptr, cols, vals = (pins.var, pins.row, pins.entry, pins.level,
                                              pins.indptr, pins.cols, pins.vals)
    const = np.fromiter((exprs[r].const for r in row.tolist()), dtype=np.float64,
                        count=len(row))
    coef = vals[ent]
    start, stop = indptr[row], indptr[row + 1]
    cuts = (np.flatnonzero(np.diff(lev)) + 1).tolist()
    lists = None
    for a, b in zip([0, *cuts], [*cuts, len(lev)]):
        if b - a < SMALL_LEVEL:
            if lists is None:
                lists = [arr.tolist() for arr in (const, ent, start, stop, vals, cols, var, coef)]
            cn, en, st, sp, vl, cl, vr, cf = lists
            for k in range(a, b):
                s, e_k = cn[k], en[k]
                for e in range(st[k], sp[k]):
                    if e != e_k:
                        s += vl[e] * x.item(cl[e])
                x[vr[k]] = -s / cf[k]
            continue
        s = const[a:b]
        st, sp, en = start[a:b], stop[a:b], ent[a:b]
        for j in range(int((sp - st).max())):
            k = st + j
            use = (k < sp) & (k != en)     # the row's j-th term, unless the pinned one
            if use.any():
                kk = k[use]
                s[use] = s[use] + vals[kk] * x[cols[kk]]
        x[var[a:b]] = -s / coef[a:b]


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
