"""Compile residual expressions into a vectorised evaluation tape.

A constraint system is a list of residual rows ``F_r(x)`` (mm / radians), each an :mod:`expr`
tree.  Walking those trees in Python for every Newton step is what makes naive solvers slow, so
they are compiled once into a :class:`Tape`:

* affine rows (most CAD constraints: coincident, horizontal, offsets) become one sparse matrix
  ``A`` over the whole parameter vector, ``F_aff = A x + b``;
* nonlinear rows are flattened into nodes; their affine leaves are one sparse matrix ``L``; the
  interior nodes are grouped by (depth level, operator), so one numpy call evaluates e.g. every
  ``sqrt`` at level 3 of every row at once (no Python loop per equation);
* the Jacobian is reverse-mode: one backward sweep over the same groups gives each leaf's
  adjoint, and ``J = A + R diag(adjoint) L`` is refilled into a sparsity pattern that is built
  once per choice of unknown columns (:meth:`Tape.pattern`).

``min``/``max`` become binary selection nodes whose branch is *frozen* for a Newton solve
(paper, appendix "Solver Details", *Iterated Newton solve for branching expressions*):
:meth:`Tape.choose` picks the active branches at a point, :meth:`Tape.evaluate` with those
choices evaluates the pruned system, and with ``choices=None`` the true min/max.

Held parameters are read from ``x`` at evaluation time, never folded into constants, so a tape
stays valid when a held dimension is edited: re-solving after an edit only reruns Newton.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .arrays import unique

from ..geometry.expr import Lin, Nl

LEAF, ADD, MUL, DIV, POW, ATAN2, MIN, MAX = range(8)
_UNARY_OPS = ["sin", "cos", "tan", "asin", "acos", "atan", "sqrt", "abs", "exp", "log"]
_UNARY = {name: 8 + i for i, name in enumerate(_UNARY_OPS)}
SIN, COS, TAN, ASIN, ACOS, ATAN, SQRT, ABS, EXP, LOG = range(8, 18)
_BINARY = {"add": ADD, "mul": MUL, "div": DIV, "pow": POW, "atan2": ATAN2,
           "min": MIN, "max": MAX}
_TINY = 1e-300


def _distinct(a: np.ndarray) -> bool:
    """No value of ``a`` repeats (a Python set for short arrays: np.unique's overhead
    dominated small tapes)."""
    if len(a) <= 64:
        return len(set(a.tolist())) == len(a)
    return len(unique(a)) == len(a)


class TapeError(ValueError):
    """An expression the tape cannot compile (an unknown operator or an unexpanded term)."""


@dataclass
class _Group:
    op: int
    idx: np.ndarray       # node indices computed by this group
    a0: np.ndarray        # first argument node of each
    a1: np.ndarray        # second argument node (== a0 for unary ops)
    uniq0: bool           # a0 has no repeated node (plain fancy-index accumulation is exact)
    uniq1: bool
    sel: np.ndarray | None = None   # for MIN/MAX: position of each node in the choices array


class Tape:
    """Residual rows ``F(x)`` of one system, compiled for vectorised evaluation.

    Shapes: ``x`` has ``n_params`` entries; :meth:`evaluate` returns ``F`` with ``n_rows``
    entries; :meth:`jacobian` returns a ``(n_rows, len(cols))`` CSR matrix ``dF/dx[cols]``.
    Source: SolveSpace-style sparse Newton (``System::SolveLinearSystem``), with the per-kind
    vectorisation of the issue-3 measurements.
    """

    def __init__(self, exprs: list, n_params: int):
        self.n_rows = len(exprs)
        self.n_params = n_params
        ar, ac, av, ab, arows = [], [], [], [], []          # affine rows
        lr, lc, lv, lconst = [], [], [], []                 # leaves of nonlinear rows
        op, a0, a1, level, root_of = [], [], [], [], []
        leaf_node = []                                       # node index of each leaf
        nl_rows, nl_roots = [], []

        def node(code: int, p: int, q: int, lev: int, row: int) -> int:
            op.append(code)
            a0.append(p)
            a1.append(q)
            level.append(lev)
            root_of.append(row)
            return len(op) - 1

        op_add, a0_add, a1_add, lev_add, root_add = (op.append, a0.append, a1.append,
                                                      level.append, root_of.append)
        binary_or_unary = {**_UNARY, **_BINARY}
        for r, e in enumerate(exprs):
            if type(e) is Lin or isinstance(e, Lin):
                k = len(arows)
                terms = e.terms
                ar.extend([k] * len(terms))
                ac.extend(terms.keys())
                av.extend(terms.values())
                ab.append(e.const)
                arows.append(r)
                continue
            memo: dict[int, int] = {}
            stack = [(e, False)]
            push, pop = stack.append, stack.pop
            while stack:                       # iterative post-order: deep trees are fine
                item, ready = pop()
                key = id(item)
                if key in memo:
                    continue
                if type(item) is Lin or isinstance(item, Lin):
                    leaf = len(lconst)
                    terms = item.terms
                    lr.extend([leaf] * len(terms))
                    lc.extend(terms.keys())
                    lv.extend(terms.values())
                    lconst.append(item.const)
                    memo[key] = n = len(op)          # node(LEAF, leaf, leaf, 0, r)
                    op_add(LEAF)
                    a0_add(leaf)
                    a1_add(leaf)
                    lev_add(0)
                    root_add(r)
                    leaf_node.append(n)
                    continue
                if not isinstance(item, Nl):
                    raise TapeError(f"cannot compile {type(item).__name__} into a residual")
                if not ready:
                    push((item, True))
                    for arg in item.args:
                        if id(arg) not in memo:
                            push((arg, False))
                    continue
                args = [memo[id(a)] for a in item.args]
                code = binary_or_unary.get(item.op)
                if code is None:
                    raise TapeError(f"unknown operator `{item.op}`")
                if code in (MIN, MAX) and len(args) > 2:
                    # n-ary min/max: a balanced tree of binary selections
                    while len(args) > 1:
                        nxt = []
                        for j in range(0, len(args) - 1, 2):
                            p, q = args[j], args[j + 1]
                            nxt.append(node(code, p, q, max(level[p], level[q]) + 1, r))
                        if len(args) % 2:
                            nxt.append(args[-1])
                        args = nxt
                    memo[key] = args[0]
                    continue
                if len(args) == 1:
                    p = q = args[0]
                elif len(args) == 2:
                    p, q = args
                else:
                    raise TapeError(f"operator `{item.op}` with {len(args)} arguments")
                memo[key] = len(op)                  # node(code, p, q, ..., r)
                op_add(code)
                a0_add(p)
                a1_add(q)
                lp_, lq_ = level[p], level[q]
                lev_add((lp_ if lp_ > lq_ else lq_) + 1)
                root_add(r)
            nl_rows.append(r)
            nl_roots.append(memo[id(e)])

        self.aff_rows = np.asarray(arows, dtype=np.int64)
        # sparse rows kept as COO arrays: products are np.bincount (no scipy overhead)
        self.a_row = np.asarray(ar, dtype=np.int64)
        self.a_col = np.asarray(ac, dtype=np.int64)
        self.a_val = np.asarray(av, dtype=float)
        self.b = np.asarray(ab, dtype=float)
        self.l_row = np.asarray(lr, dtype=np.int64)
        self.l_col = np.asarray(lc, dtype=np.int64)
        self.l_val = np.asarray(lv, dtype=float)
        self.lconst = np.asarray(lconst, dtype=float)
        self.leaf_node = np.asarray(leaf_node, dtype=np.int64)
        self.n_nodes = len(op)
        self.nl_rows = np.asarray(nl_rows, dtype=np.int64)
        self.nl_roots = np.asarray(nl_roots, dtype=np.int64)
        op_a = np.asarray(op, dtype=np.int64)
        a0_a = np.asarray(a0, dtype=np.int64)
        a1_a = np.asarray(a1, dtype=np.int64)
        lev = np.asarray(level, dtype=np.int64)
        self.root_of = np.asarray(root_of, dtype=np.int64)
        # group interior nodes by (level, op)
        self.groups: list[_Group] = []
        inner = np.flatnonzero(op_a != LEAF)
        self.n_choices = 0
        if len(inner):
            order = np.lexsort((op_a[inner], lev[inner]))
            inner = inner[order]
            keys = lev[inner] * 64 + op_a[inner]
            cuts = np.flatnonzero(np.diff(keys)) + 1
            for chunk in np.split(inner, cuts):
                g0, g1 = a0_a[chunk], a1_a[chunk]
                g = _Group(int(op_a[chunk[0]]), chunk, g0, g1, _distinct(g0), _distinct(g1))
                if g.op in (MIN, MAX):
                    g.sel = np.arange(self.n_choices, self.n_choices + len(chunk))
                    self.n_choices += len(chunk)
                self.groups.append(g)
        # the choice index of each row whose top node is a min/max (-1 otherwise)
        self.root_choice = -np.ones(self.n_rows, dtype=np.int64)
        node_choice = -np.ones(self.n_nodes, dtype=np.int64)
        for g in self.groups:
            if g.sel is not None:
                node_choice[g.idx] = g.sel
        if len(self.nl_rows):
            self.root_choice[self.nl_rows] = node_choice[self.nl_roots]
        self._patterns: dict = {}

    # ------------------------------------------------------------------ evaluation
    def _forward(self, x: np.ndarray, choices: np.ndarray | None):
        v = np.empty(self.n_nodes)
        if len(self.leaf_node):
            v[self.leaf_node] = np.bincount(self.l_row, weights=self.l_val * x[self.l_col],
                                            minlength=len(self.lconst)) + self.lconst
        for g in self.groups:
            p, q = v[g.a0], v[g.a1]
            o = g.op
            if o == ADD:
                r = p + q
            elif o == MUL:
                r = p * q
            elif o == DIV:
                r = p / np.where(q == 0.0, _TINY, q)
            elif o == POW:
                with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                    r = np.power(p, q)
            elif o == ATAN2:
                r = np.arctan2(p, q)
            elif o in (MIN, MAX):
                pick = choices[g.sel] if choices is not None else (
                    (q < p) if o == MIN else (q > p))
                r = np.where(pick, q, p)
            elif o == SIN:
                r = np.sin(p)
            elif o == COS:
                r = np.cos(p)
            elif o == TAN:
                r = np.tan(p)
            elif o == ASIN:
                r = np.arcsin(np.clip(p, -1.0, 1.0))
            elif o == ACOS:
                r = np.arccos(np.clip(p, -1.0, 1.0))
            elif o == ATAN:
                r = np.arctan(p)
            elif o == SQRT:
                r = np.sqrt(np.maximum(p, 0.0))
            elif o == ABS:
                r = np.abs(p)
            elif o == EXP:
                with np.errstate(over="ignore"):
                    r = np.exp(p)
            elif o == LOG:
                with np.errstate(invalid="ignore", divide="ignore"):
                    r = np.log(p)
            else:  # pragma: no cover - compile rejects unknown ops
                raise TapeError(f"bad op {o}")
            v[g.idx] = r
        return v

    def evaluate(self, x: np.ndarray, choices: np.ndarray | None = None,
                 nodes: bool = False):
        """Residuals ``F`` (n_rows,) at ``x``; with ``nodes=True`` also the node values.

        ``choices`` freezes every min/max at a branch (see :meth:`choose`); ``None`` evaluates
        the true min/max."""
        F = np.empty(self.n_rows)
        if len(self.aff_rows):
            F[self.aff_rows] = np.bincount(self.a_row, weights=self.a_val * x[self.a_col],
                                           minlength=len(self.b)) + self.b
        v = self._forward(x, choices) if self.n_nodes else np.empty(0)
        if len(self.nl_rows):
            F[self.nl_rows] = v[self.nl_roots]
        return (F, v) if nodes else F

    def choose(self, x: np.ndarray) -> np.ndarray:
        """The active branch of every min/max at ``x`` (True = second argument)."""
        ch = np.zeros(self.n_choices, dtype=bool)
        if not self.n_choices:
            return ch
        v = self._forward(x, None)
        for g in self.groups:
            if g.sel is not None:
                p, q = v[g.a0], v[g.a1]
                ch[g.sel] = (q < p) if g.op == MIN else (q > p)
        return ch

    def _adjoints(self, v: np.ndarray, choices) -> np.ndarray:
        adj = np.zeros(self.n_nodes)
        adj[self.nl_roots] = 1.0
        for g in reversed(self.groups):
            w = adj[g.idx]
            p, q = v[g.a0], v[g.a1]
            o = g.op
            d1 = None
            if o == ADD:
                d0, d1 = w, w
            elif o == MUL:
                d0, d1 = w * q, w * p
            elif o == DIV:
                qq = np.where(q == 0.0, _TINY, q)
                d0, d1 = w / qq, -w * p / (qq * qq)
            elif o == POW:
                with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                    d0 = w * np.where((p != 0) | (q >= 1), q * np.power(p, q - 1), 0.0)
                    d1 = w * np.where(p > 0, np.power(p, q) * np.log(np.where(p > 0, p, 1.0)),
                                      0.0)
            elif o == ATAN2:
                r2 = p * p + q * q
                r2 = np.where(r2 == 0.0, _TINY, r2)
                d0, d1 = w * q / r2, -w * p / r2
            elif o in (MIN, MAX):
                pick = choices[g.sel] if choices is not None else (
                    (q < p) if o == MIN else (q > p))
                d0, d1 = np.where(pick, 0.0, w), np.where(pick, w, 0.0)
            else:
                if o == SIN:
                    d = np.cos(p)
                elif o == COS:
                    d = -np.sin(p)
                elif o == TAN:
                    d = 1.0 / np.cos(p) ** 2
                elif o in (ASIN, ACOS):
                    d = 1.0 / np.sqrt(np.maximum(1e-300, 1.0 - np.clip(p, -1, 1) ** 2))
                    if o == ACOS:
                        d = -d
                elif o == ATAN:
                    d = 1.0 / (1.0 + p * p)
                elif o == SQRT:
                    s = np.sqrt(np.maximum(p, 0.0))
                    d = np.where(s > 1e-150, 0.5 / np.where(s > 1e-150, s, 1.0), 1e150)
                elif o == ABS:
                    d = np.where(p >= 0, 1.0, -1.0)
                elif o == EXP:
                    with np.errstate(over="ignore"):
                        d = np.exp(p)
                else:  # LOG
                    d = 1.0 / np.where(p == 0.0, _TINY, p)
                d0 = w * d
            if g.uniq0:
                adj[g.a0] += d0
            else:
                np.add.at(adj, g.a0, d0)
            if d1 is not None:
                if g.uniq1:
                    adj[g.a1] += d1
                else:
                    np.add.at(adj, g.a1, d1)
        return adj

    # ------------------------------------------------------------------ Jacobian
    def pattern(self, cols: np.ndarray) -> "_Pattern":
        """The Jacobian's sparsity pattern for unknown columns ``cols`` (parameter indices),
        built once and cached: later Jacobians only refill values."""
        key = cols.tobytes()
        pat = self._patterns.get(key)
        if pat is None:
            pat = _Pattern(self, cols)
            self._patterns[key] = pat
        return pat

    def jacobian(self, x: np.ndarray, cols: np.ndarray, choices=None, v=None,
                 dense: bool = False):
        """``dF/dx[cols]`` at ``x``, shape (n_rows, len(cols)): CSR, or an ndarray if ``dense``."""
        pat = self.pattern(cols)
        if v is None:
            _, v = self.evaluate(x, choices, nodes=True)
        w = pat.aff_vals
        if len(pat.nl_leaf):
            adj = self._adjoints(v, choices)
            w = np.concatenate([w, adj[self.leaf_node[pat.nl_leaf]] * pat.nl_vals])
        data = np.bincount(pat.inv, weights=w, minlength=pat.nnz) if len(w) else np.zeros(0)
        if dense:
            J = np.zeros((self.n_rows, len(cols)))
            J[pat.urows, pat.indices] = data
            return J
        import scipy.sparse as sp           # only sparse (large) systems need SciPy
        return sp.csr_matrix((data, pat.indices, pat.indptr), shape=(self.n_rows, len(cols)))


class _Pattern:
    """Positions of every Jacobian entry in a fixed CSR layout, for one set of unknowns."""

    def __init__(self, tape: Tape, cols: np.ndarray):
        n = tape.n_params
        colmap = -np.ones(n, dtype=np.int64)
        colmap[cols] = np.arange(len(cols))
        keep = colmap[tape.a_col] >= 0
        a_rows = tape.aff_rows[tape.a_row[keep]]
        a_cols = colmap[tape.a_col[keep]]
        self.aff_vals = tape.a_val[keep]
        keep = colmap[tape.l_col] >= 0
        self.nl_leaf = tape.l_row[keep]
        self.nl_vals = tape.l_val[keep]
        l_cols = colmap[tape.l_col[keep]]
        n_rows = tape.root_of[tape.leaf_node[self.nl_leaf]] if len(self.nl_leaf) else \
            np.zeros(0, dtype=np.int64)
        rows = np.concatenate([a_rows, n_rows]).astype(np.int64)
        cc = np.concatenate([a_cols, l_cols]).astype(np.int64)
        m = max(len(cols), 1)
        keys = rows * m + cc
        uniq, inv = np.unique(keys, return_inverse=True)
        self.inv = inv.ravel()
        self.nnz = len(uniq)
        self.indices = (uniq % m).astype(np.int32)
        urows = uniq // m
        self.urows = urows
        self.indptr = np.searchsorted(urows, np.arange(tape.n_rows + 1)).astype(np.int32)
