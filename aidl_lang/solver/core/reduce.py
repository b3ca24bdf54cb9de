"""Remove trivial equations before Newton: fixed values and equal pairs (substitution).

SolveSpace's ``System::SolveBySubstitution`` idea, for the affine rows of a tape:

* a row with a single unknown (``Fixed``, a coordinate set to a value, a held dimension copied
  onto a free one) fixes that unknown directly; repeated until no such row is left;
* a row ``x_i - x_j + c == 0`` between two unknowns (``Horizontal``, ``Vertical``,
  ``Coincident`` in one frame, ``HorizontalDistance``, ``Equal`` of two values) puts both in one
  class of a weighted union-find: ``x_i = x_root + offset_i``.

What remains is solved for one unknown per class: ``x[cols] = S z + t``.  A row that becomes
constant (a cycle in the union-find, a second value for a fixed unknown) stays in the system, so
a conflict is still seen, reported and diagnosed on the unreduced rows.  Scaling keeps the
minimum-norm step meaningful: a class of ``k`` unknowns weighs like its members together.
"""
from __future__ import annotations

import numpy as np

from ...base.records import Compared
from .tape import Tape


class Reduction(Compared):
    """``x[cols] = S @ z + t``; ``keep``: positions (in the tape) of rows still to solve.

    ``S`` (len(cols), n_z) has one 1 per row of an unknown left to solve, in column ``zc[i]``
    (``-1``: the unknown is fixed, its row of ``S`` is empty).  :meth:`expand` applies it with
    array indexing; the SciPy matrix :attr:`S` is made only when a sparse solve asks for it.
    """
    __slots__ = ("zc", "t", "keep", "z0", "scale", "rows")

    def __init__(self, zc: np.ndarray, t: np.ndarray, keep: np.ndarray, z0: np.ndarray,
                 scale: np.ndarray, rows: np.ndarray | None = None):
        self.zc = zc  # (len(cols),) class column of each unknown, -1 if fixed
        self.t = t  # (len(cols),)
        self.keep = keep
        self.z0 = z0  # starting unknowns (class means)
        self.scale = scale  # (n_z,)
        self.rows = rows  # the unknowns in a class (zc >= 0), if known

    def expand(self, z: np.ndarray) -> np.ndarray:
        """``S @ z`` (bit for bit the sparse product: ``0.0 + z[zc[i]]``, 0 where fixed)."""
        out = np.zeros(len(self.zc))
        rows = self._rows()
        out[rows] += z[self.zc[rows]]
        return out

    def dense(self) -> np.ndarray:
        """``S`` as an ndarray."""
        out = np.zeros((len(self.zc), len(self.z0)))
        rows = self._rows()
        out[rows, self.zc[rows]] = 1.0
        return out

    @property
    def S(self):
        """``S`` as a SciPy CSR matrix (imports SciPy)."""
        import scipy.sparse as sp
        rows = self._rows()
        return sp.csr_matrix((np.ones(len(rows)), (rows, self.zc[rows])),
                             shape=(len(self.zc), len(self.z0)))

    def _rows(self) -> np.ndarray:
        if self.rows is None:
            self.rows = np.flatnonzero(self.zc >= 0)
        return self.rows


_KEEP = 8          # substitutions remembered per tape (a re-solve reuses the last ones)


def reduce(tape: Tape, x: np.ndarray, cols: np.ndarray, scale: np.ndarray) -> Reduction | None:
    """The substitution for ``tape``'s rows over unknowns ``cols`` at ``x``; None if nothing
    is trivial (solve the system as it is).

    The classes, offsets and fixed values depend on ``x`` only through the held parameters,
    so they are remembered on the tape, keyed by ``cols`` and those values: a re-solve from
    new starting guesses recomputes only the class means ``z0``.  A
    :class:`~.small.SmallTape` does the same in Python floats (``substitute``)."""
    small = getattr(tape, "substitute", None)
    if small is not None:
        return small(x, cols, scale)
    n = len(cols)
    if not len(tape.aff_rows) or not n:
        return None
    memo = tape.__dict__.setdefault("_substitutions", {})
    ckey = cols.tobytes()
    hidx = memo.get(ckey)                   # the held entries' parameters, per set of unknowns
    if hidx is None:
        colmap = -np.ones(tape.n_params, dtype=np.int64)
        colmap[cols] = np.arange(n)
        hidx = memo[ckey] = tape.a_col[colmap[tape.a_col] < 0]
    held = x[hidx]
    key = (ckey, held.tobytes())
    sub = memo.get(key)
    if sub is None:
        if len(memo) >= 2 * _KEEP:
            memo.clear()
            memo[ckey] = hidx
        colmap = -np.ones(tape.n_params, dtype=np.int64)
        colmap[cols] = np.arange(n)
        sub = memo[key] = _substitution(tape, n, colmap, colmap[tape.a_col] >= 0, held)
    if sub is False:
        return None
    zc, t, keep, offs, n_live, rows, wkey, parts = sub
    # start each class at the mean of its members (least total movement), weights 1/d^2;
    # the weights' sums depend on the scale only (kept with the substitution)
    if wkey != scale.tobytes():
        w = 1.0 / scale ** 2
        den = np.bincount(zc[rows], weights=w[rows], minlength=n_live)
        dd = np.where(den > 0, den, 1.0)
        parts = (cols[rows], zc[rows], offs[rows], w[rows], dd, 1.0 / np.sqrt(dd))
        sub[6], sub[7] = scale.tobytes(), parts
    xi, zr, offr, wr, dd, zscale = parts
    num = np.bincount(zr, weights=(x[xi] - offr) * wr, minlength=n_live)
    return Reduction(zc, t, keep, num / dd, zscale, rows)


def _substitution(tape: Tape, n: int, colmap: np.ndarray, free: np.ndarray, held: np.ndarray):
    """``[zc, t, keep, offs, number of classes, unknowns in a class, None, None]`` (the last
    two: the class weights, filled by :func:`reduce` per scale), or False when no row is
    trivial."""
    # each affine row's constant (b, then its held terms in entry order, as np.add.at sums
    # them) and its free entries with a nonzero coefficient, on Python lists
    const = tape.b.tolist()
    entries: list = [[] for _ in const]
    vals = tape.a_val.tolist()
    hv = iter(held.tolist())
    for r, k, v in zip(tape.a_row.tolist(), colmap[tape.a_col].tolist(), vals):
        if k < 0:
            const[r] += v * next(hv)
        elif v != 0.0:
            entries[r].append((k, v))
    sub = classes(n, const, entries)
    if sub is False:
        return False
    zc, t, used, offs, n_live = sub
    zc = np.array(zc, dtype=np.int64)
    dropped = np.zeros(tape.n_rows, dtype=bool)      # np.setdiff1d, without importing numpy.ma
    dropped[tape.aff_rows[np.array(used, dtype=bool)]] = True
    return [zc, np.array(t, dtype=float), np.flatnonzero(~dropped), np.array(offs, dtype=float),
            n_live, np.flatnonzero(zc >= 0), None, None]


def classes(n: int, const: list, entries: list):
    """The substitution over ``n`` unknowns from affine rows given as ``const[k]`` (the row's
    constant, held parameters included) and ``entries[k]`` (its ``(unknown, coefficient)``
    pairs, nonzero, in entry order): ``(zc, t, used, offs, number of classes)`` as lists
    (``used[k]``: row ``k`` is solved by the substitution), or False when no row is.

    Pass 1 merges the unknowns of every row ``a x_i - a x_j + c == 0`` into one class of a
    weighted union-find (``x_i = x_root + offs_i``); pass 2 fixes the class of every row left
    with one unknown class, repeated while new ones appear."""
    parent = list(range(n))
    off = [0.0] * n
    used = [False] * len(const)

    def find(i):
        """Root of i and x_i - x_root, compressing the path."""
        path = []
        while parent[i] != i:
            path.append(i)
            i = parent[i]
        root = i
        # second pass: point every node on the path at the root with its total offset
        acc = 0.0
        for k in reversed(path):
            acc += off[k]
            off[k] = acc
            parent[k] = root
        return root, (off[path[0]] if path else 0.0)

    # pass 1: equal pairs (x_i - x_j + c == 0 with coefficients a, -a)
    for r, ent in enumerate(entries):
        if len(ent) != 2:
            continue
        (i, a), (j, b) = ent
        if a != -b:
            continue
        ri, oi = find(i)
        rj, oj = find(j)
        if ri == rj:
            continue                      # a cycle: keep the row (redundant or conflicting)
        # a x_i - a x_j + c = 0  ->  x_ri + oi = x_rj + oj - c/a
        parent[ri] = rj
        off[ri] = oj - const[r] / a - oi
        used[r] = True
    roots, offs = [], []
    for i in range(n):
        ro, o = find(i)
        roots.append(ro)
        offs.append(o)
    # pass 2: single-unknown rows fix their class, repeated while new ones appear
    fixed_root: dict = {}
    changed = True
    while changed:
        changed = False
        for r in [r for r, u in enumerate(used) if not u]:
            cst = const[r]
            unk: dict = {}
            for c, v in entries[r]:
                root, o = roots[c], offs[c]
                if root in fixed_root:
                    cst += v * (fixed_root[root] + o)
                else:
                    unk[root] = unk.get(root, 0.0) + v
                    cst += v * o
            unk = {k: v for k, v in unk.items() if v != 0.0}
            if len(unk) == 1:
                (root, v), = unk.items()
                fixed_root[root] = -cst / v
                used[r] = True
                changed = True
    if not any(used):
        return False
    zidx: dict = {}
    for ro in sorted(set(roots)):             # one column per live class, in root order
        if ro not in fixed_root:
            zidx[ro] = len(zidx)
    zc = [zidx.get(ro, -1) for ro in roots]
    t = [o + fixed_root[ro] if ro in fixed_root else o for ro, o in zip(roots, offs)]
    return zc, t, used, offs, len(zidx)
