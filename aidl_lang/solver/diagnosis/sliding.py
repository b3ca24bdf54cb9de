"""What the freedom left means: which whole parts and which features can still translate.

In: a solved :class:`~.hierarchy.Solver`.  Out: :class:`Sliding` (issue 35: the parts whose
whole body can move, harmless, and the features that can move relative to their part) and
:func:`sliding_text`, the words ``aidl check``'s ok line says it in.  A structure slides along
an axis when the move of its frame changes no row but the rows of inactive inequalities: one
product of the whole model's Jacobian with each candidate move; a part's features move jointly
in the null space of ``J V`` (``V``: a unit column per feature frame and axis, by the Gram
matrix's eigenvectors).
"""
from __future__ import annotations

import numpy as np

from ...base.records import Compared
from ..core.rank import DENSE_CELLS


class Sliding(Compared):
    """What the freedom left means (issue 35): ``placement`` the parts whose whole body can
    still move (``[(part, "x"|"y"|"x, y")]``: where the part sits, harmless), ``features``
    the structures inside a part that can move relative to it (``[(structure, axes)]``);
    ``constrained`` the ids of those some row reads along an axis it slides on, with
    ``read`` those axes (``{id: "x"|"y"|"x, y"}``: a changed value moves it there, W0404);
    ``bounded`` the ids of those that slide only within inequalities not reached
    (``Inside``, ...); ``placed`` the ids of those a relation places on a sibling that stays
    where written (the labels of `Below(labels, holes, gap=4)`: harmless, said so).  A
    feature that slides only along axes no row reads stays where it is written (issue 111:
    `AlignTop(groove, body)` placed the groove in y and left x as written, as a groove with
    no constraint at all)."""
    __slots__ = ("placement", "features", "constrained", "bounded", "read", "placed")

    def __init__(self, placement: list | None = None, features: list | None = None,
                 constrained: set | None = None, bounded: set | None = None,
                 read: dict | None = None, placed: set | None = None):
        self.placement = [] if placement is None else placement
        self.features = [] if features is None else features
        self.constrained = set() if constrained is None else constrained
        self.bounded = set() if bounded is None else bounded
        self.read = {} if read is None else read
        self.placed = set() if placed is None else placed


def _parts(model) -> list:
    """The parts: the root when it is a solid (or drawing), else the solids of its
    assemblies."""
    root = model.root
    if root is None:
        return []
    if root.kind != "assembly":
        return [root]
    out, todo = [], list(root.children.values())
    while todo:
        t = todo.pop(0)
        if t.kind == "assembly":
            todo += t.children.values()
        elif t.kind in ("solid", "drawing"):
            out.append(t)
    return out


def sliding(solver) -> Sliding:
    """Which whole parts and which features can translate, at the solution: structure ``t``
    slides along x when the move ``t.frame.x += 1`` (for a root without a frame: each of its
    own points and children's frames) changes no row, except rows of an inactive inequality
    (its slack is positive: the bound is not reached).  One product of the whole model's
    Jacobian with each candidate move: linear in the model's size.  A feature is reported
    only where its parent does not slide the same way with it."""
    model = solver.model
    out = Sliding()
    parts = _parts(model)
    # only the columns a move touches: every frame, and the points of a part without one
    # (the rows' other unknowns stay put); a few columns, so the Jacobian is dense and small
    need = np.zeros(len(solver.free), dtype=bool)
    need[:len(solver.is_frame)] |= solver.is_frame
    for g in model.all_geometry():
        if g.owner in parts and g.owner.parent is None:
            for pt in g.points.values():
                need[pt.ix] = need[pt.iy] = True
    cols = np.flatnonzero(need & solver.free)
    if not parts or not len(cols):
        return out
    x = solver.x
    whole = solver.whole
    if whole.n_rows * len(cols) <= DENSE_CELLS:
        J = whole.jacobian(x, cols, dense=True)
        scale = np.abs(J).max(axis=1) if J.shape[1] else np.zeros(J.shape[0])
    else:       # by columns: each move and each part reads a few of them
        J = whole.jacobian(x, cols).tocsc()
        scale = np.asarray(abs(J).max(axis=1).todense()).ravel()
    slack = solver.slack[:J.shape[0]] if len(solver.slack) >= J.shape[0] else None
    loose = np.zeros(J.shape[0], dtype=bool)
    if slack is not None:
        has = slack >= 0
        loose[has] = x[slack[has]] > 1e-9           # an inequality whose bound is not reached
    where = np.full(len(solver.free), -1, dtype=np.int64)
    where[cols] = np.arange(len(cols))
    px: dict = {}
    for g in model.all_geometry():
        for p in g.points.values():
            px.setdefault(id(p.owner), []).append((p.ix, p.iy))

    def move(t, axis: int):
        v = np.zeros(len(cols))
        f = (t.fx, t.fy)[axis]
        if t.parent is not None and 0 <= f < len(where) and where[f] >= 0:
            v[where[f]] = 1.0
            return v
        if t.parent is not None:
            return None                             # a held frame: it does not slide
        for pt in px.get(id(t), ()):
            k = where[pt[axis]]
            if k < 0:
                return None                         # a held point: the whole cannot move
            v[k] = 1.0
        for c in t.children.values():
            k = where[(c.fx, c.fy)[axis]] if 0 <= (c.fx, c.fy)[axis] < len(where) else -1
            if k < 0:
                return None
            v[k] = 1.0
        return v

    def slides(t, axis: int) -> bool:
        v = move(t, axis)
        if v is None or not v.any():
            return False
        rows, r = _moved(J, np.flatnonzero(v))       # J @ v on the rows the move touches
        r = np.abs(r)
        return not np.any((r > 1e-9 * np.maximum(1.0, scale[rows])) & ~loose[rows])

    def axes(t) -> str:
        return ", ".join(a for a, k in (("x", 0), ("y", 1)) if slides(t, k))
    for p in parts:
        a = axes(p)
        if a:
            out.placement.append((p, a))
        found = _features(p, J, loose, scale, where, px, model)
        out.features += found
        if found and loose.any():
            strict = {id(t) for t, _ in _features(p, J, np.zeros_like(loose), scale, where,
                                                   px, model)}
            out.bounded |= {id(t) for t, _ in found if id(t) not in strict
                            and _bounded_within(t, p, J, loose, where, solver.rows.constraint)}
        held, placed = _held(found)
        out.placed |= placed
        for t, a in found:
            if id(t) in held or id(t) in placed:
                continue
            read = [n for n, f in (("x", t.fx), ("y", t.fy))
                    if n in a.split(", ") and _reads(J, where[f], loose)]
            if read:        # a row reads it along a free axis: a changed value moves it there
                out.constrained.add(id(t))
                out.read[id(t)] = ", ".join(read)
    asm = [t for t in model.structures if t.kind == "assembly"]
    if not out.placement and not out.features:
        for t in asm:                       # a group of parts placed only as a whole
            a = axes(t)
            if a:
                out.placement.append((t, a))
                break
    return out


def _bounded_within(t, p, J, loose, where, owners: list) -> bool:
    """Feature ``t`` of part ``p`` slides only within an inequality not reached that its part
    or something in it writes (`Inside(hole, plate)`): a bound of the feature's own.  The box
    inequalities of a relation that lays the whole part out (`RightOf(brace, gusset)`, written
    in the assembly) read every point of the part, a corner relief poking past the outline
    too, and bound nothing the program placed there: such a feature stays where it is written
    (issue 111's run dd: "hole `brace.corner` can slide along y within its bounds" for a
    relief square written at numbers, and an unneeded `Rigid(self)` added for it)."""
    cols = [where[f] for f in (t.fx, t.fy) if 0 <= f < len(where) and where[f] >= 0]
    rows, B = _block(J, cols)
    for r in rows[np.any(B != 0, axis=1) & loose[rows]].tolist():
        c = owners[r] if r < len(owners) else None
        if c is None or c.owner is p or c.owner.is_within(p):
            return True
    return False


def _held(found: list) -> tuple[set, set]:
    """``(held, placed)``: the ids of the sliding features ``found`` (and their siblings) that
    the solve keeps where they are written although rows read them, those no constraint
    moves to a sibling (the references among siblings, and those placed only on the part in
    other axes: :func:`..core.tree.placed_on`, held while the features are placed), and of
    those placed on siblings, rank by rank (not in a cycle of relations).  Labels tied to
    holes written by their coordinates, `At(names.t[i].position, knobs.c[i].center,
    dy=-11 mm)`, go with the holes, which stay where written (issue 111: W0404 warned both, "can slide along x, y", and its hint's tie
    to the part was a second placement of the labels)."""
    from ..core.tree import placed_on
    held: set = set()
    placed: set = set()
    seen: set = set()
    for t, _ in found:
        up = t.parent
        if up is None or id(up) in seen:
            continue
        seen.add(id(up))
        _, ranks, on = placed_on(up)
        held |= {id(c) for c in up.children.values() if not on.get(id(c))}
        placed |= {id(m) for rank in ranks for m in rank if on.get(id(m))}
    return held, placed


MAX_CANDIDATES = 400     # features of one part whose joint motions are searched (2 per axis)


def _block(J, cols) -> tuple[np.ndarray, np.ndarray]:
    """Columns ``cols`` of the Jacobian ``J`` (a dense array, or sparse by columns) on the rows
    where any of them is non-zero: ``(rows, dense block of len(rows) x len(cols))``.  A part's
    moves read a few columns of the whole model's Jacobian; taking only those rows keeps the
    sliding check linear in the number of parts (1,000 parts: each product was over every row)."""
    if isinstance(J, np.ndarray):
        sub = J[:, cols]
        rows = np.flatnonzero(np.any(sub != 0, axis=1))
        return rows, sub[rows]
    # read the compressed columns directly (SciPy's indexing costs ~0.5 ms a call)
    spans = [slice(J.indptr[c], J.indptr[c + 1]) for c in cols]
    rows = np.unique(np.concatenate([J.indices[s] for s in spans])) if spans else \
        np.zeros(0, dtype=np.int64)
    B = np.zeros((len(rows), len(spans)))
    for j, s in enumerate(spans):
        np.add.at(B[:, j], np.searchsorted(rows, J.indices[s]), J.data[s])
    return rows, B


def _reads(J, col: int, loose: np.ndarray) -> bool:
    """Some row that is not an inactive inequality reads column ``col``: a changed value
    would move the feature there (issue 111's glass charms: the inequality a structure's
    box reads a hole's point through, the hole's throat poking past the disc, pinned
    nothing at the solution, and W0404 warned six holes exactly where written)."""
    rows, B = _block(J, [col])
    return bool(np.any((B[:, 0] != 0) & ~loose[rows]))


def _moved(J, cols) -> tuple[np.ndarray, np.ndarray]:
    """``(rows, J[rows][:, cols].sum(axis=1))``: the rows where any of columns ``cols`` is
    non-zero and the sum of those columns there (``J @ v`` for ``v`` one on ``cols``), as
    :func:`_block` then a sum, without its dense block: a part of 2,500 squares touching
    edge to edge moves 10,000 columns over 10,000 rows (a 10,000 x 10,000 block, one
    ``np.add.at`` per column; its `aidl check` 3.8 s of CPU, now 2.1 s); here one
    ``np.add.at`` over the columns' entries in their order (O(their non-zeros))."""
    if isinstance(J, np.ndarray):
        rows, B = _block(J, cols)
        return rows, B.sum(axis=1)
    cols = np.asarray(cols, dtype=np.int64)
    if not len(cols):
        return np.zeros(0, dtype=np.int64), np.zeros(0)
    a, b = J.indptr[cols], J.indptr[cols + 1]
    k = np.repeat(a - np.cumsum(np.r_[0, (b - a)[:-1]]), b - a) + np.arange(int((b - a).sum()))
    idx, data = J.indices[k], J.data[k]
    rows = np.unique(idx)
    r = np.zeros(len(rows))
    np.add.at(r, np.searchsorted(rows, idx), data)
    return rows, r


def _features(p, J, loose, scale, where, px, model) -> list:
    """``[(structure, axes)]``: the structures inside part ``p`` that can move relative to it.
    Candidates are the frames of its structures; their joint moves that change no row
    (beyond inactive inequalities) are the null space of ``J V`` (``V``: one column per
    candidate and axis; by its Gram matrix).  A candidate slides along an axis when some such
    move changes its absolute position there (its frame and those above it, inside ``p``)
    against ``p``'s own shapes, or, when ``p`` has none, against its first child: a move of
    the whole part is not a slide.  Only the outermost sliding structure is named."""
    desc, todo = [], list(p.children.values())
    while todo:
        t = todo.pop(0)
        desc.append(t)
        todo += t.children.values()
    cands = [t for t in desc
             if all(0 <= f < len(where) and where[f] >= 0 for f in (t.fx, t.fy))]
    if not cands or len(cands) > MAX_CANDIDATES:
        return []
    n = len(cands)
    # J V (V: a unit column per candidate frame and axis) on the rows those columns touch;
    # the other rows are zero in J V and add nothing to its Gram matrix
    rows, M = _block(J, [where[f] for t in cands for f in (t.fx, t.fy)])
    keep = ~loose[rows]
    M = M[keep] / np.maximum(1.0, scale[rows][keep])[:, None]
    w, Q = np.linalg.eigh(M.T @ M)
    null = Q[:, w <= 1e-12 * max(1.0, float(w.max(initial=0.0)))]
    if not null.shape[1]:
        return []
    index = {id(t): i for i, t in enumerate(cands)}
    A = np.zeros((2 * n, 2 * n))          # absolute motion: a frame and the frames above it
    for i, t in enumerate(cands):
        s_ = t
        while s_ is not None and s_ is not p:
            if id(s_) in index:
                A[2 * i, 2 * index[id(s_)]] = A[2 * i + 1, 2 * index[id(s_)] + 1] = 1.0
            s_ = s_.parent
    motion = A @ null
    anchor = None
    if not any(not g.construction for g in p.geometry):
        anchor = next((i for i, t in enumerate(cands) if t.parent is p), None)
    out, reported = [], set()
    for i, t in enumerate(cands):
        if i == anchor:
            continue
        ax = []
        for k, name in ((0, "x"), (1, "y")):
            m = motion[2 * i + k] - (motion[2 * anchor + k] if anchor is not None else 0.0)
            if np.any(np.abs(m) > 1e-6):
                ax.append(name)
        up, hidden = t.parent, False
        while up is not None and up is not p:
            hidden = hidden or id(up) in reported
            up = up.parent
        if ax and not hidden:
            reported.add(id(t))
            out.append((t, ", ".join(ax)))
    return out


def sliding_text(sl: Sliding) -> str:
    """``free: hole `bore` can slide along x``, ``hole `recess` free but stays where written
    (harmless)`` or ``free: only where the whole part sits (harmless)``; "" when nothing
    slides.  A feature that some constraint reads along an axis it slides on (``W0404``,
    that axis named) or that slides within an inequality's bounds is said to slide; one
    placed by its coordinates alone along its free axes stays where it is written (a part
    stays, its features are placed on it: the solve keeps the positions nothing else
    gives), so its freedom is harmless and said so (issue 84: "can slide along x, y" read
    as a problem to three of four models)."""
    if sl.features:
        moves = [(t, a if id(t) in sl.bounded else sl.read.get(id(t), a))
                 for t, a in sl.features if id(t) in sl.constrained or id(t) in sl.bounded]
        kept = [t for t, _ in sl.features if id(t) not in sl.constrained
                and id(t) not in sl.bounded and id(t) not in sl.placed]
        follow = [t for t, _ in sl.features if id(t) in sl.placed and id(t) not in sl.bounded]
        said = [f"{_name(t)} can slide along {a}"
                + (" within its bounds" if id(t) in sl.bounded else "")
                for t, a in moves[:3]]
        more = f" and {len(moves) - 3} more" if len(moves) > 3 else ""
        out = "free: " + "; ".join(said) + more if said else ""
        if kept or follow:
            parts = []
            if kept:
                parts.append(f"{_names(kept)} free but "
                             + ("stays where written on its part" if len(kept) == 1 else
                                "stay where written on their parts"))
            if follow:
                parts.append(f"{_names(follow)} placed on "
                             + (("it" if len(kept) == 1 else "them") if kept else
                                "features that stay where written"))
            harmless = "; ".join(parts) + " (harmless)"
            out = f"{out}; {harmless}" if out else harmless
        return out
    if sl.placement:
        return "free: only where the whole part sits (harmless)"
    return ""


def _names(ts: list) -> str:
    """The first three of ``ts`` by :func:`_name`, ``and N more``."""
    return ", ".join(_name(t) for t in ts[:3]) + (f" and {len(ts) - 3} more" if len(ts) > 3
                                                   else "")


def _name(o) -> str:
    """``hole `plate.bore``` for a structure, ```plate.pin.c``` for a shape."""
    if hasattr(o, "path"):
        return f"{o.kind} `{o.path}`"
    return f"`{o.label}`"


def where_now(t, part, axes: str, model) -> str | None:
    """W0404's tie that keeps feature ``t`` where the solve left it: the equation, in ``t``'s
    parent (``part``), of its box's centre against the box of the part's first named shape
    along each of ``axes``, with the offset read at the solution to 1e-6 mm
    (```bits.bb.center.y == plate.bb.center.y + 3.2 mm```; an `AlignCenterY(bits, ...)`
    written as an example moved a hole written off-centre to the centre).  None when the
    feature is not the part's own child or the part has no named shape."""
    from ...geometry.relations.bbox import numeric_box
    if t.parent is not part:
        return None
    shape = next((g for g in part.geometry if g.closed and g.name and not g.construction
                  and not g.__dict__.get("copied")), None)
    if shape is None:
        return None
    x = model.xs()
    a, b = numeric_box(t, None, x), numeric_box(shape, None, x)
    if a is None or b is None:
        return None
    out = []
    for ax in axes.split(", "):
        k = 0 if ax == "x" else 2
        off = round((a[k] + a[k + 1]) / 2 - (b[k] + b[k + 1]) / 2, 6) + 0.0
        tail = "" if off == 0 else f" {'+' if off > 0 else '-'} {abs(off):.10g} mm"
        out.append(f"`{t.name}.bb.center.{ax} == {shape.name}.bb.center.{ax}{tail}`")
    return " and ".join(out)
