"""Small systems in plain Python floats: the same numbers as the tape, without NumPy's per-call cost.

A system of a few dozen rows costs far more in fixed overhead than in arithmetic: compiling it
into a :class:`~.tape.Tape` (node arrays, groups, sparsity patterns) and running the
substitution and Newton's bookkeeping on arrays of a few dozen entries is hundreds of small
NumPy calls of a microsecond or more each (issue 12: a 6-rectangle sketch took 0.8 ms to solve
cold, SolveSpace 0.05 ms).  :class:`SmallTape` compiles such a row set into Python lists and
evaluates residuals and the reduced Jacobian with Python floats; :func:`reduce_small` is the
substitution of :mod:`.reduce` on those lists; :func:`newton_small` is :func:`.newton.newton`
with NumPy kept only for the dense linear algebra (``J J^T``, the solve, the norm).

**Bit for bit the general path.**  Every floating-point operation is the one the tape performs,
in the same order: an affine expression is ``(0.0 + sum of coef * x in term order) + const``
(``np.bincount`` sums in entry order from 0), a node's adjoint receives its contributions in
the tape's group order (depth, then operator, descending; first arguments, then second ones),
Jacobian entries of one row and unknown are summed in leaf order and merged into their
substitution class in column order (the CSR order of ``Tape.jacobian(reduction=...)``), and
``J J^T``, the damped solve and ``|F|`` are the same NumPy calls on equal arrays.  Only
operators whose NumPy and Python results are both correctly rounded are compiled here (``+``,
``*``, ``/``, ``sqrt``, ``abs``); a row with any other operator, a ``min``/``max`` or an
inequality leaves the row set to the tape.  ``tests/test_solver_small.py`` checks residuals,
substitutions, reduced Jacobians and whole solves against the general path with hypothesis.

Anything else asked of a :class:`SmallTape` (a sparse Jacobian for the conflict search, a
subset) is delegated to a :class:`~.tape.Tape` of the same rows, compiled on first use.
"""
from __future__ import annotations

import math

import numpy as np

from ...geometry.core.expr import Lin, Nl
from .newton import NewtonResult, _Step, dense_enough
from .reduce import _KEEP, Reduction, classes

SMALL_ROWS = 20      # row sets up to this size are solved in Python floats (measured crossover)

# operator codes: the tape's (tape.py), for the group order of the adjoint sweep
_LEAF, _ADD, _MUL, _DIV, _SQRT, _ABS = 0, 1, 2, 3, 14, 15
_CODES = {"add": _ADD, "mul": _MUL, "div": _DIV, "sqrt": _SQRT, "abs": _ABS}
_TINY = 1e-300


def _div(a: float, b: float) -> float:
    """``a / b`` as NumPy divides: IEEE infinities and NaN for a zero ``b`` (Python raises)."""
    try:
        return a / b
    except ZeroDivisionError:
        if a != a or a == 0.0:
            return math.nan
        return math.copysign(math.inf, a) * math.copysign(1.0, b)


class Unsupported(Exception):
    """The row set has an operator, a ``min``/``max`` or a shape this module does not compile."""


class SmallTape:
    """Rows ``F(x)`` of a small system as Python lists (see module doc).

    Shapes as :class:`~.tape.Tape`: ``x`` has ``n_params`` entries, :meth:`evaluate` returns
    ``F`` (``n_rows``,).  Raises :class:`Unsupported` for a row set it does not compile.
    """

    n_choices = 0

    def __init__(self, exprs: list, n_params: int):
        self.exprs = exprs
        self.n_rows = len(exprs)
        self.n_params = n_params
        self.root_choice = -np.ones(self.n_rows, dtype=np.int64)
        # per row: ("a", terms, const) for an affine row, else ("n", leaves, inner, back, root)
        #   leaves: [(node, terms, const)] in leaf order; inner: [(node, op, a0, a1)] in node
        #   order (arguments first); back: the adjoint sweep, [(op, [(node, a0, a1)])] per
        #   (depth, op) group, deepest group first
        self.rows: list = []
        self.aff: list = []            # (row, terms, const) of the affine rows, in row order
        for r, e in enumerate(exprs):
            if type(e) is Lin or isinstance(e, Lin):
                terms = list(e.terms.items())
                self.rows.append(("a", terms, e.const))
                self.aff.append((r, terms, e.const))
            else:
                try:
                    self.rows.append(_compile_row(e))
                except Unsupported as err:
                    raise Unsupported(*err.args, r) from None
        self._memo: dict = {}
        self._full = None

    # ------------------------------------------------------------------ the tape's interface
    def evaluate(self, x: np.ndarray, choices=None, nodes: bool = False, record=None):
        """Residuals ``F`` (n_rows,) at ``x``, equal to :meth:`.Tape.evaluate`'s."""
        F = self.values(x.tolist(), range(self.n_rows))[0]
        F = np.array(F, dtype=float)
        return (F, None) if nodes else F

    def choose(self, x: np.ndarray) -> np.ndarray:
        return np.zeros(0, dtype=np.int64)

    def substitute(self, x: np.ndarray, cols: np.ndarray, scale: np.ndarray):
        """:func:`.reduce.reduce` of these rows (:func:`reduce_small`)."""
        return reduce_small(self, x, cols, scale)

    def solve_newton(self, x0, cols, scale=None, choices=None, max_iter=100, tol=1e-10,
                     reduction=None) -> NewtonResult:
        """:func:`.newton.newton` on these rows (:func:`newton_small`)."""
        return newton_small(self, x0, cols, scale, choices, max_iter, tol, reduction)

    @property
    def tape(self):
        """The :class:`~.tape.Tape` of the same rows (compiled on first use)."""
        if self._full is None:
            from .tape import Tape
            self._full = Tape(self.exprs, self.n_params)
        return self._full

    def __getattr__(self, name):        # jacobian, subset, pattern, aff_rows... of the Tape
        if name.startswith("__") or name in ("_full", "exprs", "n_params"):
            raise AttributeError(name)
        return getattr(self.tape, name)

    # ------------------------------------------------------------------ Python evaluation
    def values(self, x: list, which) -> tuple[list, list]:
        """Residuals of rows ``which`` at ``x`` (a list) and each row's node values."""
        F, V = [], []
        for r in which:
            row = self.rows[r]
            if row[0] == "a":
                s = 0.0
                for c, w in row[1]:
                    s += w * x[c]
                F.append(s + row[2])
                V.append(None)
                continue
            v = [0.0] * row[5]
            for n, terms, const in row[1]:
                s = 0.0
                for c, w in terms:
                    s += w * x[c]
                v[n] = s + const
            for n, op, a, b in row[2]:
                p = v[a]
                if op == _ADD:
                    v[n] = p + v[b]
                elif op == _MUL:
                    v[n] = p * v[b]
                elif op == _SQRT:
                    v[n] = math.sqrt(p) if p >= 0.0 or p != p else 0.0
                elif op == _DIV:
                    q = v[b]
                    v[n] = p / (q if q != 0.0 else _TINY)
                else:                                   # _ABS
                    v[n] = abs(p)
            F.append(v[row[4]])
            V.append(v)
        return F, V

    def adjoints(self, r: int, v: list) -> list:
        """``dF_r/d node`` for every node of nonlinear row ``r`` (node values ``v``), each
        node's contributions added in the tape's group order."""
        row = self.rows[r]
        adj = [0.0] * row[5]
        adj[row[4]] = 1.0
        for op, nodes in row[3]:
            if op == _ADD:
                for n, a, b in nodes:
                    adj[a] += adj[n]
                for n, a, b in nodes:
                    adj[b] += adj[n]
            elif op == _MUL:
                for n, a, b in nodes:
                    adj[a] += adj[n] * v[b]
                for n, a, b in nodes:
                    adj[b] += adj[n] * v[a]
            elif op == _DIV:
                d1 = []
                for n, a, b in nodes:
                    q = v[b]
                    q = q if q != 0.0 else _TINY
                    d0 = adj[n] / q                 # as Tape: -(w / q) * (p / q), no q * q
                    adj[a] += d0
                    d1.append(-d0 * (v[a] / q))
                for (n, a, b), d in zip(nodes, d1):
                    adj[b] += d
            elif op == _SQRT:
                for n, a, b in nodes:
                    p = v[a]
                    s = math.sqrt(p) if p >= 0.0 or p != p else 0.0
                    adj[a] += adj[n] * (0.5 / s if s > 1e-150 else 1e150)
            else:                                       # _ABS
                for n, a, b in nodes:
                    adj[a] += adj[n] * (1.0 if v[a] >= 0 else -1.0)
        return adj

    def plan(self, r: int, colpos: dict, zc: list | None):
        """How row ``r``'s reduced Jacobian row is summed: ``[(z, [[(node, coef)]])]``, per
        class ``z`` its unknowns in column order, per unknown its leaf terms in leaf order
        (``Tape.jacobian``'s sums: an entry from 0 in leaf order, a class from 0 in column
        order); for an affine row the constant ``[(z, value)]``."""
        row = self.rows[r]
        if row[0] == "a":
            ent = {k: 0.0 + w for c, w in row[1] if (k := colpos.get(c)) is not None}
        else:
            ent = {}
            for n, terms, const in row[1]:
                for c, a in terms:
                    k = colpos.get(c)
                    if k is not None:
                        ent.setdefault(k, []).append((n, a))
        byz: dict = {}
        for k in sorted(ent):
            z = k if zc is None else zc[k]
            if z >= 0:
                byz.setdefault(z, []).append(ent[k])
        if row[0] == "a":
            out = []
            for z, vals in byz.items():
                acc = 0.0
                for val in vals:
                    acc += val
                out.append((z, acc))
            return ("a", out)
        return ("n", list(byz.items()))

    def jacobian_rows(self, which, V: list, plans: list, nz: int) -> list:
        """The reduced Jacobian rows (lists of ``nz``) of rows ``which``, node values ``V``."""
        J = []
        for r, v, (kind, plan) in zip(which, V, plans):
            row = [0.0] * nz
            if kind == "a":
                for z, val in plan:
                    row[z] = val
            else:
                adj = self.adjoints(r, v)
                for z, cs in plan:
                    acc = 0.0
                    for terms in cs:
                        jc = 0.0
                        for n, a in terms:
                            jc += adj[n] * a
                        acc += jc
                    row[z] = acc
            J.append(row)
        return J


def _compile_row(e) -> tuple:
    """One nonlinear row, walked in the tape's order (post-order, last argument first, each
    object once), so that leaves and nodes are numbered as :class:`~.tape.Tape` numbers them."""
    memo: dict = {}
    leaves: list = []
    inner: list = []
    level: list = []
    count = [0]

    def visit(item) -> int:
        n = memo.get(id(item))
        if n is not None:
            return n
        if type(item) is Lin or isinstance(item, Lin):
            n = memo[id(item)] = count[0]
            count[0] += 1
            leaves.append((n, list(item.terms.items()), item.const))
            level.append(0)
            return n
        if not isinstance(item, Nl):
            raise Unsupported(type(item).__name__)
        code = _CODES.get(item.op)
        args = item.args
        if code is None or not 1 <= len(args) <= 2 or (len(args) == 2) != (code <= _DIV):
            raise Unsupported(item.op)
        out = [0] * len(args)
        for j in range(len(args) - 1, -1, -1):
            out[j] = visit(args[j])
        p, q = (out[0], out[0]) if len(out) == 1 else out
        n = memo[id(item)] = count[0]
        count[0] += 1
        inner.append((n, code, p, q))
        level.append(max(level[p], level[q]) + 1)
        return n

    try:
        root = visit(e)
    except RecursionError:
        raise Unsupported("deep") from None
    groups: dict = {}
    for n, code, p, q in inner:
        groups.setdefault((level[n], code), []).append((n, p, q))
    back = [(key[1], groups[key]) for key in sorted(groups, reverse=True)]
    return ("n", leaves, inner, back, root, count[0])


def small_tape(exprs: list, n_params: int, rows=None, bad: set | None = None, whole=None):
    """A :class:`SmallTape` of ``exprs`` (or of ``exprs[r]`` for ``r`` in ``rows``), or None
    when the general tape should take them: more than ``SMALL_ROWS`` rows, or an operator not
    compiled here.

    ``bad``: rows known not to compile here, skipped at once (a row found so is added);
    ``whole``: the :class:`~.tape.Tape` of every row, if compiled: its operators mark every
    such row at once (a model with bounding boxes has a ``min``/``max`` in most structures'
    rows, and each would otherwise be walked up to it)."""
    if rows is None:
        rows = range(len(exprs))
    if len(rows) > SMALL_ROWS:
        return None
    if bad is not None and whole is not None and -1 not in bad:
        ok = np.zeros(64, dtype=bool)
        ok[[_LEAF, *_CODES.values()]] = True
        bad.update(set(whole.root_of[~ok[whole.op]].tolist()))
        bad.add(-1)                             # the whole tape's rows are marked
    rows = rows.tolist() if isinstance(rows, np.ndarray) else list(rows)
    if bad and any(r in bad for r in rows):
        return None
    try:
        return SmallTape([exprs[r] for r in rows], n_params)
    except Unsupported as e:
        if bad is not None and e.args and isinstance(e.args[-1], int):
            bad.add(rows[e.args[-1]])
        return None


# ---------------------------------------------------------------------- substitution
class SmallReduction(Reduction):
    """A :class:`~.reduce.Reduction` with its parts also as Python lists (for
    :func:`newton_small`)."""

    zc_l: list = None
    t_l: list = None
    plans: dict = None         # Jacobian summation plans, kept with the substitution


def reduce_small(tape: SmallTape, x: np.ndarray, cols: np.ndarray, scale: np.ndarray):
    """:func:`.reduce.reduce` for a :class:`SmallTape`: the same substitution, the same
    floats (remembered per ``cols`` and held values like the tape's)."""
    n = len(cols)
    if not tape.aff or not n:
        return None
    xl = x.tolist()
    colsl = cols.tolist()
    colpos = dict(zip(colsl, range(n)))
    held = tuple(xl[c] for _, terms, _ in tape.aff for c, _ in terms if c not in colpos)
    key = (tuple(colsl), held)
    sub = tape._memo.get(key)
    if sub is None:
        if len(tape._memo) >= _KEEP:
            tape._memo.clear()
        sub = tape._memo[key] = _substitution(tape, n, colpos, xl)
    if sub is False:
        return None
    zc, t, keep, offs, n_live, arrays, plans = sub
    # class means, weights 1/d^2 (as reduce: np.bincount sums in unknown order from 0)
    sl = scale.tolist()
    num = [0.0] * n_live
    den = [0.0] * n_live
    for i in range(n):
        z = zc[i]
        if z >= 0:
            w = _div(1.0, sl[i] * sl[i])
            num[z] += (xl[colsl[i]] - offs[i]) * w
            den[z] += w
    z0 = [a / (b if b > 0 else 1.0) for a, b in zip(num, den)]
    zs = [1.0 / math.sqrt(b if b > 0 else 1.0) for b in den]
    red = SmallReduction(arrays[0], arrays[1], arrays[2], np.array(z0, dtype=float),
                         np.array(zs, dtype=float))
    red.zc_l, red.t_l, red.plans = zc, t, plans
    return red


def _substitution(tape: SmallTape, n: int, colpos: dict, xl: list):
    """:func:`.reduce._substitution` on lists: ``(zc, t, keep, offs, classes, arrays,
    plans)`` (``plans``: filled by :func:`newton_small`)."""
    const, entries = [], []
    for r, terms, b in tape.aff:
        cst = b
        ent = []
        for c, v in terms:
            k = colpos.get(c)
            if k is None:
                cst += v * xl[c]                # np.add.at: in entry order, onto b
            elif v != 0.0:
                ent.append((k, v))
        const.append(cst)
        entries.append(ent)
    sub = classes(n, const, entries)
    if sub is False:
        return False
    zc, t, used, offs, n_live = sub
    dropped = {tape.aff[k][0] for k in range(len(used)) if used[k]}
    keep = [r for r in range(tape.n_rows) if r not in dropped]
    arrays = (np.array(zc, dtype=np.int64), np.array(t, dtype=float),
              np.array(keep, dtype=np.int64))
    return zc, t, keep, offs, n_live, arrays, {}


# ---------------------------------------------------------------------- Newton
def newton_small(tape: SmallTape, x0: np.ndarray, cols: np.ndarray, scale=None, choices=None,
                 max_iter: int = 100, tol: float = 1e-10, reduction=None) -> NewtonResult:
    """:func:`.newton.newton` on a :class:`SmallTape` (dense steps; the same iterates)."""
    xl = x0.tolist()
    colsl = cols.tolist()
    n = len(colsl)
    red = reduction
    if red is not None:
        zc, t = red.zc_l, red.t_l
        zl = red.z0.tolist()
        for i in range(n):
            z = zc[i]
            xl[colsl[i]] = ((0.0 + zl[z]) if z >= 0 else 0.0) + t[i]
        keep = red.keep.tolist()
        d = red.scale
        u = red.z0.copy()
        nz = len(zl)
    else:
        keep = range(tape.n_rows)
        d = np.ones(n) if scale is None else scale
        u = x0[cols]
        nz = n
    # how each kept row's reduced Jacobian is summed: fixed for these unknowns and classes
    store = red.plans if red is not None else tape._memo.setdefault(("plans", tuple(colsl)), {})
    plans = store.get("rows")
    if plans is None:
        colpos = dict(zip(colsl, range(n)))
        plans = store["rows"] = [tape.plan(r, colpos, None if red is None else zc)
                                 for r in keep]

    def place(un: np.ndarray) -> list:
        xn = list(xl)
        ul = un.tolist()
        if red is None:
            for i in range(n):
                xn[colsl[i]] = ul[i]
        else:
            for i in range(n):
                z = zc[i]
                xn[colsl[i]] = ((0.0 + ul[z]) if z >= 0 else 0.0) + t[i]
        return xn

    def maxabs(F: list) -> float:
        m = max(map(abs, F)) if F else 0.0
        return m if m == m and not any(f != f for f in F) else math.nan

    F, V = tape.values(xl, keep)
    Fa = np.array(F, dtype=float)
    res = maxabs(F)
    if res <= tol or not len(u) or not math.isfinite(res):
        return NewtonResult(np.array(xl, dtype=float), res <= tol, 0, res)
    norm = math.sqrt(Fa.dot(Fa))          # np.linalg.norm of a 1-D array, its very steps
    mu = 1e-12
    it = 0
    if not dense_enough(len(F), nz):          # many unknowns for few rows: the sparse step
        from .newton import newton
        return newton(tape.tape, x0, cols, scale, choices, max_iter, tol, reduction)
    while it < max_iter:
        it += 1
        J = tape.jacobian_rows(keep, V, plans, nz)
        Js = np.array(J, dtype=float) * d
        accepted = False
        # newton.unreachable on lists: every row that is off has an all-zero row of J D
        if any(f != 0.0 for f in F) and not any(
                any(row) for row, f in zip(Js.tolist(), F) if f != 0.0):
            break
        step = _Step(Js, dense=True)
        for _ in range(14):
            try:
                du = d * step(Fa, mu)
            except (RuntimeError, np.linalg.LinAlgError):
                mu = max(mu * 100, 1e-8)
                continue
            un = u + du
            xn = place(un)
            Fn, Vn = tape.values(xn, keep)
            Fna = np.array(Fn, dtype=float)
            nn = math.sqrt(Fna.dot(Fna))
            if math.isfinite(nn) and nn < norm:
                u, xl, F, Fa, V, norm = un, xn, Fn, Fna, Vn, nn
                mu = max(mu / 10, 1e-12)
                accepted = True
                break
            mu = max(mu * 10, 1e-8)
        res = maxabs(F)
        if res <= tol or not accepted:
            break
    return NewtonResult(np.array(xl, dtype=float), res <= tol, it, res)
