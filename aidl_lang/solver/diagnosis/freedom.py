"""What is still free in a solved model: the degrees of freedom of each structure.

In: a :class:`~.hierarchy.Solver` after solving (its point, rows, pins, and the model's
structures).  Out: a :class:`StructureDof` per structure (``aidl check --dof``, the editor's
hints, ``aidl serve``, ``aidl batch``) and :func:`freedom_text`, the words of ``aidl check``'s
ok line.

For each structure, its own unknowns plus its children's frames, against its own constraints
and those of its ancestors that use these unknowns (a parent's ``CenterInside(bore, self)``
places the hole's geometry), everything else held at the solution: ``dof = unknowns -
rank(J)``; a parameter whose column has a component in the null space of ``J`` is not
determined, and its geometry (or child) *floats* (issues 23, 37, 38; docs/solver.md).  The
ranks and null spaces are :mod:`.diagnose`'s (NumPy only up to
:data:`~..core.rank.DENSE_CELLS` cells: a cold ``aidl check`` does not import SciPy for its
count); what the freedom means (which parts and features slide) is :mod:`.sliding`'s.
"""
from __future__ import annotations

import numpy as np

from ...base.limits import now
from ...base.memory import gc_paused
from ...base.records import Compared
from ..core.arrays import unique
from ..core.rank import (DENSE_CELLS, NOT_COUNTED_TIME, _block_rank, _dense_block_rank,
                         _dense_cut, null_support)
from .diagnose import used_free_columns
from .sliding import Sliding, sliding_text


class StructureDof(Compared):
    """Remaining freedom of one structure's own sketch (its unknowns and children's frames)."""
    __slots__ = ("structure", "unknowns", "rank", "floating", "why")

    def __init__(self, structure: object, unknowns: int, rank: int, floating: list | None = None,
                 why: str = ""):
        self.structure = structure
        self.unknowns = unknowns
        self.rank = rank  # -1: not counted (``why`` says why)
        self.floating = [] if floating is None else floating  # labels of undetermined entities
        self.why = why  # "too large" or "out of time"

    @property
    def dof(self) -> int:
        return self.unknowns - self.rank


def degrees_of_freedom(solver, floating: bool = True,
                       deadline: float | None = None) -> list[StructureDof]:
    """Per-structure degrees of freedom and floating entities, at the solver's current point
    (call after solving).  ``floating=False`` counts only (singular values, no null space:
    what the summary line of ``aidl check`` needs).  Past ``deadline`` (:func:`aidl_lang.base.limits.now`: CPU seconds,
    the run's end), or where a dense SVD would end past it (at
    :data:`~.diagnose.SVD_FLOPS_PER_SECOND`), a structure is not counted: rank -1, ``why``
    "out of time" (or "too large" past :data:`~.diagnose.MAX_SVD_FLOPS`).

    For the count, the model's whole Jacobian is formed once (:attr:`~.hierarchy.Solver.whole`,
    every row against every structure's columns; dense up to :data:`DENSE_CELLS` cells, else
    sparse) and each structure's block is cut out of it: the same entries, bit for bit, as
    the structure's own tape gives (each entry sums the same terms in the same order),
    without compiling or evaluating a tape per structure."""
    with gc_paused():           # a few small records per structure: no cyclic collections
        return _degrees_of_freedom(solver, floating, deadline)


def _degrees_of_freedom(solver, floating: bool, deadline: float | None) -> list[StructureDof]:
    model = solver.model
    x = solver.x
    out = []
    label_of = {}
    if floating:
        for g in model.all_geometry():
            for p in g.points.values():
                label_of[p.ix] = label_of[p.iy] = g.label
            for s in g.scalars.values():
                label_of[s.index] = g.label
            # a drawing's circles are the drawing (one rigid body, issue 49): named as it
            for c in _drawing_circles(g):
                for p in c.points.values():
                    label_of[p.ix] = label_of[p.iy] = g.label
    axis = [-1] * len(solver.x)           # per parameter: a point's x 0, its y 1, else -1
    for g in model.all_geometry():
        for c in _drawing_circles(g):
            for p in c.points.values():
                axis[p.ix], axis[p.iy] = 0, 1
        for p in g.points.values():
            axis[p.ix], axis[p.iy] = 0, 1
    systems = []                       # (structure, params, rows, cols)
    touching = _ancestor_rows(solver, x)
    for s in model.structures:
        params = list(solver.own.get(id(s), ()))
        for c in s.children.values():
            params += [i for i in solver.frame.get(id(c), ())]
            if floating:
                for i in solver.frame.get(id(c), ()):
                    label_of[i] = f"{c.path} (position)"
        rows = solver.rows_of([s])
        if touching is not None and s.parent is not None and params:
            rows = touching(s, rows, params)
        if len(rows):
            sl = solver.slack[rows]
            cols = unique(np.concatenate([np.asarray(params, dtype=np.int64), sl[sl >= 0]]))
        else:                   # no row (a pattern's hole placed by its coordinates)
            cols = np.array(sorted(set(params)), dtype=np.int64)
        systems.append((s, params, rows, cols))
    whole = None
    if not floating:
        # the columns some row uses: the others are zero in every structure's block (a
        # panel's 20,000 holes' frames against its few rows), left out of each rank
        used = np.zeros(len(solver.free), dtype=bool)
        used[used_free_columns(solver)] = True
        used[solver.slack[solver.slack >= 0]] = True
        systems = [(s, p, r, c, c[used[c]]) for s, p, r, c in systems]
        whole = _whole_jacobian(solver, x, [u for s, _, r, c, u in systems if len(r) and len(u)])
    else:
        systems = [(s, p, r, c, c) for s, p, r, c in systems]
    held = _held_by_rigid(model)
    pinned = solver.pinned_by
    pinned_axes: dict[int, set] = {}      # id(structure) -> axes of its pinned points
    owner = model.param_owner
    for v, _ in solver.pins:
        if axis[v] >= 0:
            pinned_axes.setdefault(id(owner[v]), set()).add(axis[v])
    for s, params, rows, cols, use in systems:
        if deadline is not None and now() > deadline and len(rows) and len(cols) \
                and id(s) not in held:
            d = StructureDof(s, len(params), -1, why="out of time")
        else:
            d = _dof_of(solver, model, s, params, rows, cols, whole, held, label_of, floating,
                        axis, pinned_axes.get(id(s), ()), deadline, use)
        k = pinned.get(id(s), 0)
        if k:
            # geometry pinned in s's frame (system.pinned) is held by the solver, but it is
            # still s's geometry: k unknowns that s's own rows fix (a square invertible block
            # that no other row touches): k more unknowns, k more rank, nothing floats
            d.unknowns += k
            if d.rank >= 0:
                d.rank += k
        out.append(d)
    return out


def _drawing_circles(g) -> list:
    """The construction Circles of a ``Drawing2D`` (its ``circles[i]``; not in its
    structure's geometry list), else none."""
    return g.data.get("circles", ()) if g.kind == "Drawing2D" else ()


def _dof_of(solver, model, s, params, rows, cols, whole, held, label_of, floating,
            axis, pinned_axes, deadline, use=None) -> StructureDof:
    """One structure's :class:`StructureDof` (see :func:`degrees_of_freedom`); ``axis`` and
    ``pinned_axes`` as :func:`_gauge_shifts` takes them, ``deadline`` as
    :func:`degrees_of_freedom`; ``use``: the columns of ``cols`` some row uses (the count's
    Jacobian is over them: the others are zero columns, of no rank), None for all."""
    x = solver.x
    n_unknowns = len(params)
    if id(s) in held:
        # ``Rigid(s)`` (or a rigid ancestor): its shapes keep their placement to each
        # other and to its frame, which alone moves (the parent counts it): nothing inside
        # floats
        return StructureDof(s, n_unknowns, n_unknowns)
    if not len(cols):
        return StructureDof(s, 0, 0)
    if not len(rows):
        if not floating:
            # no row: each axis the content can shift along is one frame move (see below)
            return StructureDof(s, n_unknowns, _shift_axes(solver, s, params, axis,
                                                           pinned_axes))
        gauge = _gauge_shifts(solver, s, np.zeros((0, len(cols))), cols, axis, pinned_axes)
        if not gauge:
            free = (sorted({label_of.get(i, model.param_label[i]) for i in params})
                    if floating else [])
            return StructureDof(s, n_unknowns, 0, free)
        rows_t = np.array(gauge)          # no row: only the frame's shift to leave out
        if not floating:
            return StructureDof(s, n_unknowns, len(gauge))
        rank, moving = null_support(rows_t)
        pos = {int(c): k for k, c in enumerate(cols)}
        free = sorted({label_of.get(i, model.param_label[i]) for i in params
                       if moving[pos[i]]})
        return StructureDof(s, n_unknowns, rank - (len(cols) - n_unknowns), free)
    if not floating:
        use = cols if use is None else use
        if len(rows) * len(use) <= DENSE_CELLS:
            if whole is not None:
                J = _dense_cut(*whole, rows, use)
            else:
                J = solver.tape(rows).jacobian(x, use, dense=True)
            rank = _dense_block_rank(J)
        else:
            J = solver.tape(rows).jacobian(x, use)
            rank = _block_rank(J, deadline)
        if rank < 0:
            return StructureDof(s, n_unknowns, -1, why=_why_not(rank))
        rank += _gauge_count(solver, s, J, use, params, axis, pinned_axes)
        return StructureDof(s, n_unknowns, rank - (len(cols) - n_unknowns))
    J = solver.tape(rows).jacobian(x, cols)
    gauge = _gauge_shifts(solver, s, J, cols, axis, pinned_axes)
    if gauge:
        import scipy.sparse as sp
        J = sp.vstack([sp.csr_matrix(J), sp.csr_matrix(np.array(gauge))])
    rank, moving = null_support(J, deadline)
    if rank < 0:
        return StructureDof(s, n_unknowns, -1, why=_why_not(rank))
    # slack columns each come with a LINK row of full rank: they neither add nor remove
    n_slack = len(cols) - n_unknowns
    free = []
    if moving.any():
        pos = {int(c): k for k, c in enumerate(cols)}
        free = sorted({label_of.get(i, model.param_label[i])
                       for i in params if moving[pos[i]]})
    return StructureDof(s, n_unknowns, rank - n_slack, free)


def _gauge_shifts(solver, s, J, cols, axis: list, pinned_axes=()) -> list:
    """The shifts of all of structure ``s``'s content (its own points and its children's
    frames) along x and along y, as vectors over ``cols`` (sorted), that change no row of
    ``J``: each is the move of ``s``'s frame, which its parent counts (a frame shifted one way
    and its contents the other change nothing drawn), so ``s``'s own count leaves it out
    (issue 38: a part of 3 structures in an assembly of 1 counted its one placement 3 times,
    6 freedoms for 2).  Only for a structure whose frame is an unknown (not the root's).
    ``axis``: per parameter, 0 for a point's x, 1 for its y, -1 otherwise.  ``pinned_axes``:
    the axes of ``s``'s points pinned in its frame (:func:`~.system.pinned`): their dropped rows
    fix them in the frame, so they see a shift along that axis, and it is no frame move."""
    if s.parent is None or not (0 <= s.fx < len(solver.free) and solver.free[s.fx]):
        return []
    pos = {c: k for k, c in enumerate(cols.tolist())}
    own = solver.own.get(id(s), ())
    children = s.children.values()
    scale = None
    out = []
    for a in (0, 1):
        if a in pinned_axes:
            continue
        k = [pos[i] for i in own if axis[i] == a and i in pos]
        k += [pos[i] for i in ((c.fx, c.fy)[a] for c in children) if i in pos]
        if not k:
            continue
        if J.shape[0]:
            if scale is None:
                scale = max(1.0, float(abs(J).max()))
            if np.abs(np.asarray(J[:, k].sum(axis=1), dtype=float)).max() > 1e-9 * scale:
                continue                # some row sees the shift: not the frame's move
        t = np.zeros(len(cols))
        t[k] = 1.0
        out.append(t)
    return out


def _gauge_count(solver, s, J, use: np.ndarray, params: list, axis: list,
                 pinned_axes=()) -> int:
    """How many gauge shifts :func:`_gauge_shifts` finds for structure ``s`` whose Jacobian
    ``J`` is over the columns ``use`` only (the columns rows use; the others of ``params``,
    its own unknowns and children's frames, are zero columns): a shift along an axis with a
    column moving along it, that changes no row (its columns in ``use`` sum to zero in every
    row, within 1e-9 of the largest entry).  The count of the vectors, without them."""
    if s.parent is None or not (0 <= s.fx < len(solver.free) and solver.free[s.fx]):
        return 0
    pos = {c: k for k, c in enumerate(use.tolist())}
    own = solver.own.get(id(s), ())
    cols = set(params)
    scale = None
    n = 0
    for a in (0, 1):
        if a in pinned_axes:
            continue
        moving = [i for i in own if axis[i] == a]
        moving += [i for i in ((c.fx, c.fy)[a] for c in s.children.values()) if i in cols]
        if not moving:
            continue
        k = [pos[i] for i in moving if i in pos]
        if J.shape[0] and k:
            if scale is None:
                scale = max(1.0, float(abs(J).max()))
            if np.abs(np.asarray(J[:, k].sum(axis=1), dtype=float)).max() > 1e-9 * scale:
                continue                # some row sees the shift: not the frame's move
        n += 1
    return n


def _shift_axes(solver, s, params: list, axis: list, pinned_axes=()) -> int:
    """How many gauge shifts :func:`_gauge_shifts` finds for a structure ``s`` without rows
    (``params``: its own unknowns and its children's frames, the columns): one per axis with
    a column that moves along it, none when ``s``'s frame is not an unknown.  The same count,
    without building the vectors (a pattern of 20,000 holes asks it 20,000 times)."""
    if s.parent is None or not (0 <= s.fx < len(solver.free) and solver.free[s.fx]):
        return 0
    axes = {axis[i] for i in solver.own.get(id(s), ())}
    if s.children:
        cols = set(params)
        axes.update(a for c in s.children.values() for a, i in ((0, c.fx), (1, c.fy))
                    if i in cols)
    return (0 in axes and 0 not in pinned_axes) + (1 in axes and 1 not in pinned_axes)


def _held_by_rigid(model) -> set:
    """The ids of the structures whose inside ``Rigid`` holds: each rigid structure and every
    structure below it (the solver moves them only by the rigid structure's frame,
    :func:`aidl_lang.solver.core.tree._rigid_below`)."""
    out: set = set()
    todo = [s for s in model.structures if getattr(s, "rigid", False)]
    while todo:
        t = todo.pop()
        if id(t) in out:
            continue
        out.add(id(t))
        todo += t.children.values()
    return out


def _why_not(rank: int) -> str:
    return "out of time" if rank == NOT_COUNTED_TIME else "too large"


def _ancestor_rows(solver, x: np.ndarray):
    """``touching(s, rows, params)``: structure ``s``'s own ``rows`` and the rows of its
    ancestors that use one of ``params`` (its own unknowns and its children's frames), in
    increasing order; ``None`` when no structure has a parent.

    A parent may constrain its descendants' geometry (``CenterInside(bore, self)`` reads the
    hole's circle; validity rule 2): at the solution those rows pin the child's unknowns as
    much as the child's own constraints do, so the count holds them too (issue 23: a hole
    placed by its parent was counted, and listed by ``--dof``, as floating).  The rows are
    found from the sparsity of the whole model's Jacobian (one evaluation over every free
    column)."""
    model = solver.model
    if not any(s.parent is not None for s in model.structures):
        return None
    cols = used_free_columns(solver)      # the unknowns no row uses meet no row
    if not len(cols):
        return None
    whole = solver.whole
    if whole.n_rows * len(cols) <= DENSE_CELLS:       # numpy only (no SciPy on a cold check)
        nz_r, nz_c = np.nonzero(whole.jacobian(x, cols, dense=True).T)
        indices, indptr = nz_c, np.searchsorted(nz_r, np.arange(len(cols) + 1))
    else:
        C = whole.jacobian(x, cols).tocsc()
        indices, indptr = C.indices, C.indptr
    n_rows = whole.n_rows
    where = np.full(len(solver.free), -1, dtype=np.int64)
    where[cols] = np.arange(len(cols))
    # the structure each row belongs to (its index in model.structures), so that "is this
    # row an ancestor's?" costs the depth of the tree, not the ancestors' rows (a sorted list
    # of them per structure was quadratic: a 10 000-copy pattern took 31 s and 2.6 GB)
    number = {id(a): i for i, a in enumerate(model.structures)}
    owner = np.full(n_rows, -1, dtype=np.int64)
    for a in model.structures:
        if a.children:
            owner[np.asarray(solver.rows_of([a]), dtype=np.int64)] = number[id(a)]
    # the unknowns some row of a structure with children uses: only they can meet an
    # ancestor's row (a pattern's holes placed by their coordinates meet none), found for
    # all columns at once instead of per structure
    of_entry = np.repeat(np.arange(len(cols)), np.diff(indptr))
    reached = np.zeros(len(solver.free), dtype=bool)
    reached[cols[of_entry[owner[np.asarray(indices, dtype=np.int64)] >= 0]]] = True
    reached = reached.tolist()

    def touching(s, rows: np.ndarray, params: list) -> np.ndarray:
        for i in params:
            if reached[i]:
                break
        else:
            return rows                 # no row of any parent uses them
        chain = []
        a = s.parent
        while a is not None:
            chain.append(number[id(a)])
            a = a.parent
        if not chain:
            return rows
        k = where[np.asarray(params, dtype=np.int64)]
        k = k[k >= 0]
        if not len(k):
            return rows
        # the rows that use one of the unknowns (a few per unknown), kept where an ancestor's
        used = np.concatenate([indices[indptr[j]:indptr[j + 1]] for j in k]).astype(np.int64)
        of = owner[used]
        hit = np.zeros(len(used), dtype=bool)
        for a in chain:
            hit |= of == a
        extra = used[hit]
        if not len(extra):
            return rows
        both = np.sort(np.concatenate([np.asarray(rows, dtype=np.int64), extra]))
        return both[np.concatenate([[True], both[1:] != both[:-1]])]

    return touching


def _whole_jacobian(solver, x: np.ndarray, col_sets: list):
    """``(J, cols)``: the Jacobian of every row of the model against the union ``cols``
    (increasing) of ``col_sets``: dense up to :data:`DENSE_CELLS` cells, else sparse (CSR;
    :func:`_dense_cut` reads a structure's block out of it).  One tape for the whole model,
    not one per structure: a model of 1,000 parts compiled 1,000 tapes (0.6 s)."""
    if not col_sets:
        return None
    whole = solver.whole
    cols = unique(np.concatenate(col_sets))
    return whole.jacobian(x, cols, dense=whole.n_rows * len(cols) <= DENSE_CELLS), cols


def freedom_text(dofs: list[StructureDof], slide: "Sliding | None" = None) -> str:
    """``fully constrained`` or ``N degrees of freedom left, see --dof`` for a whole model
    (structures too large for the dense rank count are reported as unknown); with ``slide``
    (:func:`~.sliding.sliding`) it says what is free: ``N degrees of freedom left (free: hole
    `bore` can slide along x), see --dof``, ``(hole `recess` free but stays where written
    (harmless))`` or ``(free: only where the whole part sits (harmless))``."""
    if any(d.rank < 0 for d in dofs):
        why = ("model too large" if any(d.why == "too large" for d in dofs if d.rank < 0)
               else "out of time")
        return f"degrees of freedom not counted ({why}), see --dof"
    n = sum(max(0, d.dof) for d in dofs)
    if n == 0:
        return "fully constrained"
    if slide is None:           # what slides not measured (too large, out of time): not said
        return f"{n} degree{'s' if n != 1 else ''} of freedom left, see --dof"
    return (f"{n} degree{'s' if n != 1 else ''} of freedom left ({freedom_meaning(n, slide)}), "
            "see --dof")


WRITTEN = "that nothing places, which stay where written (harmless)"
NONE_SLIDES = "nothing slides against its part"


def freedom_meaning(n: int, slide: "Sliding") -> str:
    """What ``n`` (> 0) degrees of freedom left are, said always (issue 105: "2 degrees of
    freedom left" alone told nothing, and "no hole ... slides" read as the contrary of
    ``--dof``'s floating column): what can slide (:func:`~.sliding.sliding_text`), what stays
    where written (harmless), or where the whole part sits (harmless); when some freedom is
    not the part's placement and no feature slides, the rest is what nothing pulls on (a
    shape or part placed only by its written coordinates: the solve keeps them), said with
    its count."""
    said = sliding_text(slide)
    placed = sum(len(a.split(", ")) for _, a in slide.placement)
    if said.startswith("free: only") and n != placed:
        sits = "the whole part sits" if len(slide.placement) == 1 else "the parts sit"
        return (f"free: {placed} where {sits} and {n - placed} of shapes or parts "
                f"{WRITTEN}; {NONE_SLIDES}")
    if not said:
        return f"free: shapes or parts {WRITTEN}; {NONE_SLIDES}"
    if slide.features and slide.placement:      # the features said; the placement too
        sits = "the whole part sits" if len(slide.placement) == 1 else "the parts sit"
        return f"{said}; {placed} where {sits} (harmless)"
    return said


def floating_legend(freedom: str) -> str:
    """The line under ``aidl check --dof``'s table: what its floating column is (what each
    structure's free directions move: a child's position is where it sits in its parent), in
    the words of the ok line's ``freedom`` (:func:`freedom_text`), so that the two agree."""
    what = freedom[freedom.find("(") + 1:freedom.rfind(")")] if "(" in freedom else freedom
    return ("floating: what each structure's free directions move (a child's `position`: "
            f"where it sits in its parent), not what slides; here: "
            f"{what[len('free: '):] if what.startswith('free: ') else what}")
