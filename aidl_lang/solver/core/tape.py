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

``min``/``max`` (any number of arguments) become one selection node each, whose branch (the
position of the chosen argument) is *frozen* for a Newton solve
(paper, appendix "Solver Details", *Iterated Newton solve for branching expressions*):
:meth:`Tape.choose` picks the active branches at a point, :meth:`Tape.evaluate` with those
choices evaluates the pruned system, and with ``choices=None`` the true min/max.

Held parameters are read from ``x`` at evaluation time, never folded into constants, so a tape
stays valid when a held dimension is edited: re-solving after an edit only reruns Newton.
"""
from __future__ import annotations

from itertools import chain

import numpy as np

from ...base.records import Record
from ...base.memory import gc_paused
from .arrays import unique

from ...geometry.core.expr import Lin, Nl

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


def _lin_arrays(lins: list):
    """COO arrays of affine expressions: ``(row, col, value)`` of every term, row by row in
    each ``terms`` dict's order, and each expression's constant."""
    terms = [e.terms for e in lins]
    lens = np.fromiter(map(len, terms), np.int64, len(terms))
    total = int(lens.sum())
    rows = np.repeat(np.arange(len(terms), dtype=np.int64), lens)
    cols = np.fromiter(chain.from_iterable(terms), np.int64, total)
    vals = np.fromiter(chain.from_iterable(t.values() for t in terms), float, total)
    const = np.fromiter((e.const for e in lins), float, len(lins))
    return rows, cols, vals, const


def _take(start: np.ndarray, rows: np.ndarray):
    """Indices of the blocks ``start[r]:start[r + 1]`` for ``r`` in ``rows``, concatenated;
    with each block's shift (new position - old) and length."""
    s = start[rows]
    n = start[rows + 1] - s
    d = np.cumsum(n) - n - s
    return np.arange(int(n.sum()), dtype=np.int64) - np.repeat(d, n), d, n


def _levels(op: np.ndarray, a0: np.ndarray, a1: np.ndarray, marg: np.ndarray) -> np.ndarray:
    """Each node's depth: 0 for a leaf, else 1 + the deepest argument's.  Relaxed with array
    passes (one per level: most rows are a few levels deep); for a small tape, or past
    ``_LEVEL_PASSES`` levels, one pass in node order (every argument precedes its node:
    post-order)."""
    lev = np.zeros(len(op), dtype=np.int64)
    inner = np.flatnonzero(op != LEAF)
    if not len(inner):
        return lev
    if len(inner) > _LEVEL_SMALL:
        mm = (op[inner] == MIN) | (op[inner] == MAX)
        bi, mi = inner[~mm], inner[mm]
        p, q = a0[bi], a1[bi]
        cnt = a1[mi]                          # min/max: their runs of ``marg``
        starts = np.cumsum(cnt) - cnt
        flat = marg[np.arange(int(cnt.sum()), dtype=np.int64) + np.repeat(a0[mi] - starts, cnt)]
        for _ in range(_LEVEL_PASSES):
            nb = np.maximum(lev[p], lev[q]) + 1
            nm = np.maximum.reduceat(lev[flat], starts) + 1 if len(mi) else nb[:0]
            if np.array_equal(nb, lev[bi]) and np.array_equal(nm, lev[mi]):
                return lev
            lev[bi], lev[mi] = nb, nm
    out = lev.tolist()
    opl, a0l, a1l, margl = op.tolist(), a0.tolist(), a1.tolist(), marg.tolist()
    for i in inner.tolist():
        if opl[i] == MIN or opl[i] == MAX:
            out[i] = max([out[a] for a in margl[a0l[i]:a0l[i] + a1l[i]]]) + 1
        else:
            u, w = out[a0l[i]], out[a1l[i]]
            out[i] = (u if u > w else w) + 1
    return np.asarray(out, dtype=np.int64)


_LEVEL_PASSES = 64
_SHARED_MIN_ROWS = 256    # from this many rows the compile walks shared subexpressions once
_SHARED_BLOWUP = 4        # ... unless the rows' trees are this much larger than the DAG
_LEVEL_SMALL = 512        # up to this many interior nodes the ordered pass is cheaper


class TapeError(ValueError):
    """An expression the tape cannot compile (an unknown operator or an unexpanded term)."""


class _Group(Record):
    """The nodes of one operation, evaluated together by fancy indexing."""
    __slots__ = ("op", "idx", "a0", "a1", "uniq0", "uniq1", "sel", "args", "starts", "seg")

    def __init__(self, op: int, idx: np.ndarray, a0: np.ndarray, a1: np.ndarray, uniq0: bool,
                 uniq1: bool, sel: np.ndarray | None = None, args: np.ndarray | None = None,
                 starts: np.ndarray | None = None, seg: np.ndarray | None = None):
        self.op = op
        self.idx = idx  # node indices computed by this group
        self.a0 = a0  # first argument node of each (MIN/MAX: start of its run of marg)
        self.a1 = a1  # second argument node (== a0 for unary ops; MIN/MAX: arity)
        self.uniq0 = uniq0  # a0 has no repeated node (plain fancy-index accumulation is exact)
        self.uniq1 = uniq1
        self.sel = sel  # for MIN/MAX: position of each node in the choices array
        self.args = args  # for MIN/MAX: argument nodes of all its nodes, flattened
        self.starts = starts  # for MIN/MAX: where each node's arguments start in args
        self.seg = seg  # for MIN/MAX: the node (0..len(idx)) of each argument


def _pick(g: _Group, vals: np.ndarray) -> np.ndarray:
    """The position (0-based, per node) of the first smallest (MIN) or largest (MAX) of each
    node's arguments ``vals`` (flattened like ``g.args``): the branch a chain of binary
    selections ``q if q < p else p`` picks (ties go to the earlier argument).  A node with a
    NaN argument picks its first argument."""
    red = np.minimum if g.op == MIN else np.maximum
    m = red.reduceat(vals, g.starts)
    n = len(vals)
    pos = np.where(vals == m[g.seg], np.arange(n), n)
    first = np.minimum.reduceat(pos, g.starts)
    first = np.where(first == n, g.starts, first)
    return first - g.starts


class Tape:
    """Residual rows ``F(x)`` of one system, compiled for vectorised evaluation.

    Shapes: ``x`` has ``n_params`` entries; :meth:`evaluate` returns ``F`` with ``n_rows``
    entries; :meth:`jacobian` returns a ``(n_rows, len(cols))`` CSR matrix ``dF/dx[cols]``.
    Source: SolveSpace-style sparse Newton (``System::SolveLinearSystem``), with the per-kind
    vectorisation of the issue-3 measurements.
    """

    def __init__(self, exprs: list, n_params: int, shared: bool | None = None):
        """Compile ``exprs`` (rows over ``n_params`` parameters).  ``shared``: walk every
        shared subexpression once (:meth:`_compile_shared`, the same arrays); ``None``
        chooses it for tapes of ``_SHARED_MIN_ROWS`` rows or more."""
        with gc_paused():      # one tuple per node, none cyclic: no cyclic collections meanwhile
            if shared is None:
                shared = len(exprs) >= _SHARED_MIN_ROWS
            if not (shared and self._compile_shared(exprs, n_params)):
                self._compile(exprs, n_params)

    def _compile_shared(self, exprs: list, n_params: int) -> bool:
        """The arrays of :meth:`_compile`, equal one for one, from one walk over the *distinct*
        expression nodes of all rows (memoised by identity across rows: a bounding-box side
        shared by many rows is walked once) and array passes that lay each row's nodes out
        as the per-row walk would.

        The per-row walk emits a row's nodes in post-order, last argument first, each node
        once (memoised within the row): that is the expansion of the row's expression DAG
        into a tree, in that post-order, keeping the first occurrence of each node.  Here the
        distinct nodes' subtree sizes give every tree occurrence its position directly
        (breadth-first, one array pass per depth, work proportional to the trees), the first
        occurrence of each (row, node) is kept, and arguments are renumbered by lookup.  Leaf
        entries are gathered from each distinct affine leaf's terms.  Returns False (nothing
        set) for an expression nested deeper than the recursion limit or DAGs whose trees
        would be much larger than their nodes; :meth:`_compile` then does it row by row."""
        walked = _distinct_nodes(exprs)
        if walked is None:
            return False
        gnodes, gmarg, glin, aff, arows, nl_rows, roots = walked
        occ = _occurrences(gnodes, gmarg, roots)
        if occ is None:
            return False
        G, gop, ga0, nargs, child, cstart, roots, pos_node, pos_row = occ
        # the first occurrence of each (row, node), in position order
        key = pos_row * G + pos_node
        srt = np.argsort(key, kind="stable")
        ks = key[srt]
        first = np.ones(len(ks), dtype=bool)
        first[1:] = ks[1:] != ks[:-1]
        keep = np.sort(srt[first])
        ukeys = ks[first]                          # sorted distinct keys
        newid = np.empty(len(ukeys), dtype=np.int64)
        newid[np.argsort(srt[first], kind="stable")] = np.arange(len(ukeys), dtype=np.int64)
        # newid[i]: node index of ukeys[i]; keep: positions of the nodes in node order
        node = pos_node[keep]
        row = pos_row[keep]
        N = len(node)

        def new(rows_, nodes_):
            return newid[np.searchsorted(ukeys, rows_ * G + nodes_)]

        op = gop[node]
        a0 = np.empty(N, dtype=np.int64)
        a1 = np.empty(N, dtype=np.int64)
        is_leaf = op == LEAF
        leaf_nodes = np.flatnonzero(is_leaf)
        a0[leaf_nodes] = a1[leaf_nodes] = np.arange(len(leaf_nodes), dtype=np.int64)
        nn_ = nargs[node]
        mmn = np.flatnonzero((op == MIN) | (op == MAX))
        one = np.flatnonzero(~is_leaf & (nn_ == 1) & ~((op == MIN) | (op == MAX)))
        two = np.flatnonzero(~is_leaf & (nn_ == 2) & ~((op == MIN) | (op == MAX)))
        a0[one] = a1[one] = new(row[one], child[cstart[node[one]]])
        a0[two] = new(row[two], child[cstart[node[two]]])
        a1[two] = new(row[two], child[cstart[node[two]] + 1])
        cm = nn_[mmn]
        mstart = np.cumsum(cm) - cm
        a0[mmn] = mstart
        a1[mmn] = cm
        rel = np.arange(int(cm.sum()), dtype=np.int64) - np.repeat(mstart, cm)
        marg = new(np.repeat(row[mmn], cm), child[np.repeat(cstart[node[mmn]], cm) + rel])
        nl_rows = np.asarray(nl_rows, dtype=np.int64)
        nl_roots = new(np.arange(len(roots), dtype=np.int64), roots)
        root_of = nl_rows[row]
        # leaves: each distinct leaf's terms, gathered in leaf order
        u_row, u_col, u_val, u_const = _lin_arrays(glin)
        lid = ga0[node[leaf_nodes]]
        start = np.searchsorted(u_row, np.arange(len(glin) + 1))
        eidx, _, en = _take(start, lid)
        l_row = np.repeat(np.arange(len(lid), dtype=np.int64), en)
        a_row, a_col, a_val, b = _lin_arrays(aff)
        self.n_rows = len(exprs)
        self.n_params = n_params
        self._setup(np.asarray(arows, dtype=np.int64), a_row, a_col, a_val, b,
                    l_row, u_col[eidx], u_val[eidx], u_const[lid], leaf_nodes,
                    nl_rows, nl_roots, op, a0, a1, _levels(op, a0, a1, marg), root_of, marg)
        return True

    def _compile(self, exprs: list, n_params: int) -> None:
        self.n_rows = len(exprs)
        self.n_params = n_params
        aff, arows = [], []                   # affine rows: their Lin and row
        leaves = []                           # the Lin of every leaf node, in order
        nodes = []                            # (op, arg0, arg1, row) of every node
        marg = []                             # argument nodes of every min/max, in order
        nl_rows, nl_roots = [], []
        node_add, leaf_add = nodes.append, leaves.append
        binary_or_unary = {**_UNARY, **_BINARY}

        def leaf_of(item, r: int, memo: dict) -> int:
            leaf = len(leaves)
            leaf_add(item)
            memo[id(item)] = n = len(nodes)
            node_add((LEAF, leaf, leaf, r))
            return n

        def interior(item, args: list, r: int, memo: dict) -> int:
            code = binary_or_unary.get(item.op)
            if code is None:
                raise TapeError(f"unknown operator `{item.op}`")
            if code in (MIN, MAX):
                # n-ary min/max: one node whose arguments are a run of ``marg``
                if not args:
                    raise TapeError(f"operator `{item.op}` with no arguments")
                memo[id(item)] = n = len(nodes)
                node_add((code, len(marg), len(args), r))
                marg.extend(args)
                return n
            if len(args) == 1:
                p = q = args[0]
            elif len(args) == 2:
                p, q = args
            else:
                raise TapeError(f"operator `{item.op}` with {len(args)} arguments")
            memo[id(item)] = n = len(nodes)
            node_add((code, p, q, r))
            return n

        def visit(item, r: int, memo: dict) -> int:
            """Post-order, last argument first (the order of the explicit stack in walk)."""
            n = memo.get(id(item))
            if n is not None:
                return n
            if type(item) is Lin or isinstance(item, Lin):
                return leaf_of(item, r, memo)
            if not isinstance(item, Nl):
                raise TapeError(f"cannot compile {type(item).__name__} into a residual")
            args = item.args
            k = len(args)
            out = [0] * k
            for j in range(k - 1, -1, -1):
                arg = args[j]
                n = memo.get(id(arg))
                if n is None:
                    if type(arg) is Lin:       # a leaf, inline (most arguments of min/max)
                        memo[id(arg)] = n = len(nodes)
                        leaf = len(leaves)
                        node_add((LEAF, leaf, leaf, r))
                        leaf_add(arg)
                    else:
                        n = visit(arg, r, memo)
                out[j] = n
            return interior(item, out, r, memo)

        def walk(e, r: int, memo: dict) -> None:
            stack = [(e, False)]
            push, pop = stack.append, stack.pop
            while stack:                       # iterative post-order: deep trees are fine
                item, ready = pop()
                if id(item) in memo:
                    continue
                if type(item) is Lin or isinstance(item, Lin):
                    leaf_of(item, r, memo)
                    continue
                if not isinstance(item, Nl):
                    raise TapeError(f"cannot compile {type(item).__name__} into a residual")
                if not ready:
                    push((item, True))
                    for arg in item.args:
                        if id(arg) not in memo:
                            push((arg, False))
                    continue
                interior(item, [memo[id(a)] for a in item.args], r, memo)

        for r, e in enumerate(exprs):
            if type(e) is Lin or isinstance(e, Lin):
                aff.append(e)
                arows.append(r)
                continue
            memo: dict[int, int] = {}
            n0, f0, m0 = len(nodes), len(leaves), len(marg)
            try:
                visit(e, r, memo)
            except RecursionError:             # a very deep tree: start the row again with
                memo.clear()                   # an explicit stack
                del nodes[n0:], leaves[f0:], marg[m0:]
                walk(e, r, memo)
            nl_rows.append(r)
            nl_roots.append(memo[id(e)])
        a_row, a_col, a_val, b = _lin_arrays(aff)
        l_row, l_col, l_val, lconst = _lin_arrays(leaves)
        nn = len(nodes)
        na = np.fromiter(chain.from_iterable(nodes), np.int64, 4 * nn).reshape(nn, 4)
        op, a0, a1 = na[:, 0].copy(), na[:, 1].copy(), na[:, 2].copy()
        marg = np.asarray(marg, dtype=np.int64)
        # `visit` refers to itself through its closure cell: a reference cycle that would keep
        # the node tuples and leaf lists alive until the next cyclic collection (which then
        # had ~80k objects to traverse on the 500-structure model); free them now
        visit = None
        nodes.clear()
        leaves.clear()
        self._setup(np.asarray(arows, dtype=np.int64), a_row, a_col, a_val, b,
                    l_row, l_col, l_val, lconst, np.flatnonzero(op == LEAF),
                    np.asarray(nl_rows, dtype=np.int64), np.asarray(nl_roots, dtype=np.int64),
                    op, a0, a1, _levels(op, a0, a1, marg), na[:, 3].copy(), marg)

    def _setup(self, aff_rows, a_row, a_col, a_val, b, l_row, l_col, l_val, lconst, leaf_node,
               nl_rows, nl_roots, op_a, a0_a, a1_a, lev, root_of, marg,
               uniq_hint: dict | None = None) -> None:
        """Store the flattened arrays and group the interior nodes by (level, operator).
        ``uniq_hint``: the whole tape's :attr:`uniq`, when this is a cut of it."""
        self.aff_rows = aff_rows
        # sparse rows kept as COO arrays: products are np.bincount (no scipy overhead)
        self.a_row, self.a_col, self.a_val, self.b = a_row, a_col, a_val, b
        self.l_row, self.l_col, self.l_val, self.lconst = l_row, l_col, l_val, lconst
        self.leaf_node = leaf_node
        self.n_nodes = len(op_a)
        self.nl_rows, self.nl_roots = nl_rows, nl_roots
        self.op, self.a0, self.a1, self.level = op_a, a0_a, a1_a, lev
        self.root_of = root_of
        self.marg = marg
        # group interior nodes by (level, op)
        self.groups: list[_Group] = []
        self.uniq: dict = {}          # level * 64 + op -> the group's (uniq0, uniq1)
        inner = np.flatnonzero(op_a != LEAF)
        self.n_choices = 0
        if len(inner):
            order = np.lexsort((op_a[inner], lev[inner]))
            inner = inner[order]
            keys = lev[inner] * 64 + op_a[inner]
            cuts = (np.flatnonzero(np.diff(keys)) + 1).tolist()
            bounds = [0, *cuts, len(inner)]
            gkeys = keys[bounds[:-1]].tolist()
            for b0, b1, key in zip(bounds, bounds[1:], gkeys):
                chunk = inner[b0:b1]
                op = key % 64
                g0, g1 = a0_a[chunk], a1_a[chunk]
                # a group of a cut is part of the whole tape's group of the same key, its
                # arguments shifted one to one: "no repeats" holds in it if it held there
                hint = uniq_hint.get(key, (False, False)) if uniq_hint else (False, False)
                if op in (MIN, MAX):
                    g = _Group(op, chunk, g0, g1, False, True)
                    # the group's arguments, flattened: each node's run of ``marg``
                    start = np.cumsum(g1) - g1
                    g.starts = start
                    g.args = marg[np.arange(int(g1.sum()), dtype=np.int64)
                                  + np.repeat(g0 - start, g1)]
                    g.seg = np.repeat(np.arange(len(chunk), dtype=np.int64), g1)
                    g.uniq0 = hint[0] or _distinct(g.args)
                    g.sel = np.arange(self.n_choices, self.n_choices + len(chunk))
                    self.n_choices += len(chunk)
                else:
                    g = _Group(op, chunk, g0, g1, hint[0] or _distinct(g0),
                               hint[1] or _distinct(g1))
                self.uniq[key] = (g.uniq0, g.uniq1)
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

    def subset(self, rows: np.ndarray) -> "Tape":
        """The tape of rows ``rows`` (increasing positions in this tape) by array selection,
        without walking any expression again.

        Equal, array for array, to ``Tape([exprs[r] for r in rows], n_params)``: every node
        belongs to one row (the compile memoises within a row only), nodes keep their order,
        and the (level, operator) grouping is stable, so evaluation and Jacobians are the same
        bit for bit (``tests/test_solver_subset.py``)."""
        rows = np.asarray(rows, dtype=np.int64)
        t = Tape.__new__(Tape)
        t.n_rows = len(rows)
        t.n_params = self.n_params
        st = self._starts()
        # every array is a run of blocks, one per row, in row order (see _starts): gather the
        # blocks of ``rows`` and shift the indices that point into other blocks
        nidx, nd, nn = _take(st["node"], rows)
        lidx, ld, ln = _take(st["leaf"], rows)
        eidx, _, en = _take(st["lent"], rows)
        kidx, kd, kn = _take(st["aff"], rows)
        aidx, _, an = _take(st["aent"], rows)
        ridx, _, rn = _take(st["nl"], rows)
        midx, md, mn = _take(st["marg"], rows)
        pos = np.arange(len(rows), dtype=np.int64)
        op = self.op[nidx]
        shift = np.repeat(nd, nn)
        mm = (op == MIN) | (op == MAX)
        shift0 = np.where(op == LEAF, np.repeat(ld, nn), np.where(mm, np.repeat(md, nn), shift))
        shift1 = np.where(op == LEAF, shift0, np.where(mm, 0, shift))
        t._setup(np.repeat(pos, kn), self.a_row[aidx] + np.repeat(kd, an), self.a_col[aidx],
                 self.a_val[aidx], self.b[kidx], self.l_row[eidx] + np.repeat(ld, en),
                 self.l_col[eidx], self.l_val[eidx], self.lconst[lidx],
                 self.leaf_node[lidx] + np.repeat(nd, ln), np.repeat(pos, rn),
                 self.nl_roots[ridx] + np.repeat(nd, rn), op, self.a0[nidx] + shift0,
                 self.a1[nidx] + shift1, self.level[nidx], np.repeat(pos, nn),
                 self.marg[midx] + np.repeat(nd, mn), self.uniq)
        return t

    def _starts(self) -> dict:
        """Where each row's block starts in every per-row array (length ``n_rows + 1``):
        nodes, leaves, leaf entries, affine rows, affine entries, nonlinear roots, min/max
        arguments.  A compile
        appends each row's items together and in row order, so each array is sorted by row."""
        st = self.__dict__.get("_row_starts")
        if st is None:
            r = np.arange(self.n_rows + 1)
            leaf = np.searchsorted(self.root_of[self.leaf_node], r)
            aff = np.searchsorted(self.aff_rows, r)
            mm = np.flatnonzero((self.op == MIN) | (self.op == MAX))
            marg_row = np.repeat(self.root_of[mm], self.a1[mm])
            st = self._row_starts = {
                "node": np.searchsorted(self.root_of, r), "leaf": leaf,
                "lent": np.searchsorted(self.l_row, leaf), "aff": aff,
                "aent": np.searchsorted(self.a_row, aff), "nl": np.searchsorted(self.nl_rows, r),
                "marg": np.searchsorted(marg_row, r)}
        return st

    # ------------------------------------------------------------------ evaluation
    def _forward(self, x: np.ndarray, choices: np.ndarray | None,
                 record: np.ndarray | None = None):
        """Node values at ``x``; min/max at the branches ``choices``, or the true min/max
        (then, if ``record`` is given, each one's branch is written into it)."""
        v = np.empty(self.n_nodes)
        if len(self.leaf_node):
            v[self.leaf_node] = np.bincount(self.l_row, weights=self.l_val * x[self.l_col],
                                            minlength=len(self.lconst)) + self.lconst
        for g in self.groups:
            o = g.op
            if o == MIN or o == MAX:
                vals = v[g.args]
                if choices is not None:
                    pick = choices[g.sel]
                else:
                    pick = _pick(g, vals)
                    if record is not None:
                        record[g.sel] = pick
                v[g.idx] = vals[g.starts + pick]
                continue
            p, q = v[g.a0], v[g.a1]
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
                 nodes: bool = False, record: np.ndarray | None = None):
        """Residuals ``F`` (n_rows,) at ``x``; with ``nodes=True`` also the node values.

        ``choices`` freezes every min/max at a branch (see :meth:`choose`); ``None`` evaluates
        the true min/max, and then ``record`` (int64, ``n_choices``), if given, receives the
        branches :meth:`choose` would return (one pass for both)."""
        F = np.empty(self.n_rows)
        if len(self.aff_rows):
            F[self.aff_rows] = np.bincount(self.a_row, weights=self.a_val * x[self.a_col],
                                           minlength=len(self.b)) + self.b
        v = self._forward(x, choices, record) if self.n_nodes else np.empty(0)
        if len(self.nl_rows):
            F[self.nl_rows] = v[self.nl_roots]
        return (F, v) if nodes else F

    def choose(self, x: np.ndarray) -> np.ndarray:
        """The active branch of every min/max at ``x``: the position of its chosen argument
        (0 = first; the first smallest for min, the first largest for max), int64."""
        ch = np.zeros(self.n_choices, dtype=np.int64)
        if self.n_choices:
            self._forward(x, None, record=ch)
        return ch

    def _adjoints(self, v: np.ndarray, choices) -> np.ndarray:
        adj = np.zeros(self.n_nodes)
        adj[self.nl_roots] = 1.0
        for g in reversed(self.groups):
            w = adj[g.idx]
            o = g.op
            if o == MIN or o == MAX:
                pick = choices[g.sel] if choices is not None else _pick(g, v[g.args])
                chosen = g.args[g.starts + pick]
                if g.uniq0:
                    adj[chosen] += w
                else:
                    np.add.at(adj, chosen, w)
                continue
            p, q = v[g.a0], v[g.a1]
            d1 = None
            if o == ADD:
                d0, d1 = w, w
            elif o == MUL:
                d0, d1 = w * q, w * p
            elif o == DIV:
                qq = np.where(q == 0.0, _TINY, q)
                # -w p / q^2 as two quotients (q^2 underflows to 0 at q = _TINY: 0/0 where
                # w p = 0); past 1e308 it is inf, as in small.py's Python floats
                with np.errstate(over="ignore"):
                    d0 = w / qq
                    d1 = -d0 * (p / qq)
            elif o == POW:
                with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                    d0 = w * np.where((p != 0) | (q >= 1), q * np.power(p, q - 1), 0.0)
                    d1 = w * np.where(p > 0, np.power(p, q) * np.log(np.where(p > 0, p, 1.0)),
                                      0.0)
            elif o == ATAN2:
                r2 = p * p + q * q
                r2 = np.where(r2 == 0.0, _TINY, r2)
                d0, d1 = w * q / r2, -w * p / r2
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
                 dense: bool = False, reduction=None):
        """``dF/dx[cols]`` at ``x``, shape (n_rows, len(cols)): CSR, or an ndarray if ``dense``.

        With a ``reduction`` (:class:`~.reduce.Reduction`, ``x[cols] = S z + t``) it is the
        reduced Jacobian ``(dF/dx[cols])[keep] @ S``, shape (len(keep), len(z)), summed
        straight from the entries into a layout kept per reduction (in column order, as
        SciPy's CSR product sums them), without forming the full matrix or ``S``."""
        pat = self.pattern(cols)
        data = self._entries(pat, x, choices, v)
        if reduction is not None:
            lay = pat.reduced(self, reduction)
            data = np.bincount(lay.inv, weights=data[lay.valid], minlength=lay.nnz)
            shape = lay.shape
            if dense:
                J = np.zeros(shape)
                J[lay.urows, lay.indices] = data
                return J
        else:
            shape = (self.n_rows, len(cols))
            if dense:
                J = np.zeros(shape)
                J[pat.urows, pat.indices] = data
                return J
            lay = pat
        import scipy.sparse as sp           # only sparse (large) systems need SciPy
        return sp.csr_matrix((data, lay.indices, lay.indptr), shape=shape)


    def _entries(self, pat: "_Pattern", x, choices, v) -> np.ndarray:
        """The Jacobian's entries in ``pat``'s CSR layout (one value per stored entry)."""
        if v is None:
            _, v = self.evaluate(x, choices, nodes=True)
        w = pat.aff_vals
        if len(pat.nl_leaf):
            adj = self._adjoints(v, choices)
            w = np.concatenate([w, adj[self.leaf_node[pat.nl_leaf]] * pat.nl_vals])
        return np.bincount(pat.inv, weights=w, minlength=pat.nnz) if len(w) else np.zeros(0)

    def jacobian_entries(self, x: np.ndarray, cols: np.ndarray, choices=None, v=None,
                         reduction=None):
        """The stored entries of :meth:`jacobian` as COO arrays ``(row, col, value)``: the
        same values, bit for bit, without building a matrix (for a batch of independent
        systems, each taking its own block: :mod:`.batch`).  ``row`` indexes the tape's rows
        (with a ``reduction``, ``reduction.keep``'s rows), ``col`` the positions in ``cols``
        (with a ``reduction``, its class columns ``z``), both int64."""
        pat = self.pattern(cols)
        data = self._entries(pat, x, choices, v)
        if reduction is not None:
            lay = pat.reduced(self, reduction)
            data = np.bincount(lay.inv, weights=data[lay.valid], minlength=lay.nnz)
            return reduction.keep[lay.urows], lay.indices.astype(np.int64), data
        return pat.urows, pat.indices.astype(np.int64), data


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
        self._reduced: dict = {}

    def reduced(self, tape: Tape, red) -> "_Reduced":
        """The layout of the reduced Jacobian for substitution ``red`` (cached)."""
        key = (red.keep.tobytes(), red.zc.tobytes())
        lay = self._reduced.get(key)
        if lay is None:
            if len(self._reduced) >= 8:
                self._reduced.clear()
            lay = self._reduced[key] = _Reduced(self, tape, red)
        return lay


class _Reduced:
    """Where each Jacobian entry goes in the reduced CSR layout ``J[keep] @ S``: kept rows
    renumbered, columns merged into their class ``zc`` (entries of fixed unknowns and dropped
    rows left out)."""

    def __init__(self, pat: _Pattern, tape: Tape, red):
        nz = max(len(red.z0), 1)
        rowpos = -np.ones(tape.n_rows, dtype=np.int64)
        rowpos[red.keep] = np.arange(len(red.keep))
        r = rowpos[pat.urows]
        c = red.zc[pat.indices]
        self.valid = np.flatnonzero((r >= 0) & (c >= 0))
        keys = r[self.valid] * nz + c[self.valid]
        uniq, inv = np.unique(keys, return_inverse=True)
        self.inv = inv.ravel()
        self.nnz = len(uniq)
        self.indices = (uniq % nz).astype(np.int32)
        self.urows = uniq // nz
        self.indptr = np.searchsorted(self.urows, np.arange(len(red.keep) + 1)).astype(np.int32)
        self.shape = (len(red.keep), len(red.z0))


def _distinct_nodes(exprs: list):
    """One walk over the distinct expression nodes of all rows ``exprs`` (memoised by
    identity across rows), for :meth:`Tape._compile_shared`: ``(gnodes, gmarg, glin, aff,
    arows, nl_rows, roots)``, the distinct nodes as ``(operator, p, q, arity)``, the argument
    runs of min/max, the distinct affine leaves, the affine rows and their indices, the
    nonlinear rows' indices and root nodes; None for an expression nested deeper than the
    recursion limit."""
    gnodes = []                           # distinct nodes: (operator, p, q, arity)
    gmarg = []                            # argument runs of min/max (node ids)
    glin = []                             # distinct leaves (Lin), in order
    memo: dict[int, int] = {}
    node_add, lin_add = gnodes.append, glin.append
    codes = {**_UNARY, **_BINARY}

    def visit(item) -> int:
        args = item.args
        k = len(args)
        out = [0] * k
        for j in range(k - 1, -1, -1):
            arg = args[j]
            n = memo.get(id(arg))
            if n is None:
                if type(arg) is Lin or isinstance(arg, Lin):
                    memo[id(arg)] = n = len(gnodes)
                    node_add((LEAF, len(glin), 0, 0))
                    lin_add(arg)
                elif isinstance(arg, Nl):
                    n = visit(arg)
                else:
                    raise TapeError(f"cannot compile {type(arg).__name__} into a residual")
            out[j] = n
        code = codes.get(item.op)
        if code is None:
            raise TapeError(f"unknown operator `{item.op}`")
        if code == MIN or code == MAX:
            if not k:
                raise TapeError(f"operator `{item.op}` with no arguments")
            memo[id(item)] = n = len(gnodes)
            node_add((code, len(gmarg), 0, k))
            gmarg.extend(out)
        elif k == 1:
            memo[id(item)] = n = len(gnodes)
            node_add((code, out[0], out[0], 1))
        elif k == 2:
            memo[id(item)] = n = len(gnodes)
            node_add((code, out[0], out[1], 2))
        else:
            raise TapeError(f"operator `{item.op}` with {k} arguments")
        return n

    aff, arows, nl_rows, roots = [], [], [], []
    try:
        for r, e in enumerate(exprs):
            if type(e) is Lin or isinstance(e, Lin):
                aff.append(e)
                arows.append(r)
                continue
            if not isinstance(e, Nl):
                raise TapeError(f"cannot compile {type(e).__name__} into a residual")
            n = memo.get(id(e))
            nl_rows.append(r)
            roots.append(visit(e) if n is None else n)
    except RecursionError:
        return None
    finally:
        visit = None                      # break the closure's self-reference
    return gnodes, gmarg, glin, aff, arows, nl_rows, roots


def _occurrences(gnodes: list, gmarg: list, roots: list):
    """Every occurrence of the distinct nodes ``gnodes`` in the rows' trees (their DAGs
    expanded), for :meth:`Tape._compile_shared`: its node and row by position (breadth-first,
    one array pass per depth; post-order within each row, last argument first), with the
    nodes' arrays ``(G, gop, ga0, nargs, child, cstart, roots, pos_node, pos_row)``; None when
    the trees would be much larger than their nodes (:data:`_SHARED_BLOWUP`)."""
    G = len(gnodes)
    ga = np.fromiter(chain.from_iterable(gnodes), np.int64, 4 * G).reshape(G, 4)
    gnodes.clear()
    gop, ga0, ga1, nargs = ga[:, 0].copy(), ga[:, 1].copy(), ga[:, 2].copy(), ga[:, 3].copy()
    gmarg = np.asarray(gmarg, dtype=np.int64)
    # each node's arguments in order, as a CSR run: a min/max its run of gmarg, a
    # two-argument node (p, q), a one-argument node (p)
    mm = (gop == MIN) | (gop == MAX)
    cstart = np.concatenate([[0], np.cumsum(nargs)])
    child = np.empty(int(cstart[-1]), dtype=np.int64)
    mm_nodes = np.flatnonzero(mm)
    if len(mm_nodes):
        cnt = nargs[mm_nodes]
        rel = np.arange(int(cnt.sum()), dtype=np.int64) - np.repeat(np.cumsum(cnt) - cnt, cnt)
        child[np.repeat(cstart[mm_nodes], cnt) + rel] = gmarg[np.repeat(ga0[mm_nodes], cnt)
                                                              + rel]
    bi = np.flatnonzero(~mm & (nargs >= 1))
    child[cstart[bi]] = ga0[bi]
    b2 = bi[nargs[bi] == 2]
    child[cstart[b2] + 1] = ga1[b2]
    # subtree sizes of the tree expansions, by depth (a node's depth: 1 + its deepest
    # argument's; the walk emitted every argument before its node)
    depth = _levels(gop, ga0, np.where(mm, nargs, ga1), gmarg)
    size = np.ones(G, dtype=np.int64)
    order = np.argsort(depth, kind="stable")
    bounds = np.searchsorted(depth[order], np.arange(int(depth.max(initial=0)) + 2))
    for lv in range(1, len(bounds) - 1):
        nodes = order[bounds[lv]:bounds[lv + 1]]
        na_ = nargs[nodes]
        grp = np.cumsum(na_) - na_
        idx = np.repeat(cstart[nodes], na_) + (np.arange(int(na_.sum()), dtype=np.int64)
                                               - np.repeat(grp, na_))
        size[nodes] = np.minimum(1 + np.add.reduceat(size[child[idx]], grp), 1 << 40)
    roots = np.asarray(roots, dtype=np.int64)
    total = int(size[roots].sum()) if len(roots) else 0
    if total > _SHARED_BLOWUP * (G + len(roots)) + 1024:
        return None
    # every tree occurrence: its node, row and position (breadth-first by depth)
    pos_node = np.empty(total, dtype=np.int64)
    pos_row = np.empty(total, dtype=np.int64)
    fn = roots
    fr = np.arange(len(roots), dtype=np.int64)
    fo = np.cumsum(size[roots]) - size[roots]
    while len(fn):
        at = fo + size[fn] - 1                 # post-order: a node ends its subtree
        pos_node[at] = fn
        pos_row[at] = fr
        na_ = nargs[fn]
        has = na_ > 0
        fn, fr, fo, na_ = fn[has], fr[has], fo[has], na_[has]
        if not len(fn):
            break
        k = int(na_.sum())
        grp = np.cumsum(na_) - na_
        rel = np.arange(k, dtype=np.int64) - np.repeat(grp, na_)
        ch = child[np.repeat(cstart[fn], na_) + rel]
        cs = size[ch]
        # last argument first: argument j starts after the subtrees of arguments > j
        incl = np.cumsum(cs)
        gend = np.repeat(incl[grp + na_ - 1], na_)
        fo = np.repeat(fo, na_) + (gend - incl)
        fn, fr = ch, np.repeat(fr, na_)
    return G, gop, ga0, nargs, child, cstart, roots, pos_node, pos_row
