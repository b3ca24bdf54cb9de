"""Parts stay, features move (issues 73 and 84): the stages the hierarchical solve
(:meth:`.hierarchy.Solver.steps`) tries at a structure before the paper's deepening, when one
of its constraints relates its own geometry (a part) to a descendant's (a hole, a child
solid, a pattern's target) or to another of its own shapes (a knob on a body).  The part's
unknowns are held while the rest moves; only when that fails is the part placed by its own
rows, and only when that fails too does the paper's ladder move it.

:class:`PartsFirst` is a mixin of :class:`.hierarchy.Solver`: its methods read the solver's
rows (``rows``, ``rows_of``, ``_cols``), its unknowns (``own``, ``frame``, ``free``,
``n_model``, ``cut_parts``), its point ``x`` and its ``trace``; each stage is a generator
like ``Solver.steps`` (yields an :class:`~.attempts.Attempt`, is sent whether it succeeded)."""
from __future__ import annotations

import numpy as np

from ...geometry.core.model import Structure
from .attempts import Attempt
from .holds import row_vars
from .tree import (_held_helpers, _helpers, _levels, _part_shape, _references, _shape_ranks,
                   _unknowns, _who_moves)


# Newton steps per round of a rank's shapes stage (:meth:`PartsFirst._place_rank`): it
# finishes what the rank's frames nearly met (three labels of one drawing: 1 step); a rank
# whose shapes cannot meet its rows (a pattern's copy held by its original) gives up here
# rather than after the solver's 100 (a Raspberry Pi plate: 4 steps became 104)
SHAPES_STEPS = 12


class PartsFirst:
    """The features-first and shapes-first stages of :class:`.hierarchy.Solver`."""

    def _features_first(self, s: Structure, local: np.ndarray, order: int, own, frames):
        """Parts stay, features move (issue 73): the stages tried at ``s`` before the
        paper's, when one of ``s``'s constraints relates its own geometry (a part's) to a
        descendant's (a hole, a child solid, a pattern's target; or a part to a hole that
        ``CutInto`` cuts into it).  A generator like :meth:`~.hierarchy.Solver.steps`, with
        its ``own`` and ``frames`` (the unknowns of structures, less those of rigid ones);
        returns whether ``s`` was solved.

        The part's unknowns (:meth:`_part_unknowns`) are held while the rest moves (stage
        "features", the paper's two deepenings without the part: the descendants' frames
        one level deeper at a time, then also the geometry of the descendants that have no
        frame of their own to move, copies made by a pattern or a mirror).  The first such
        attempt takes every row of ``s`` (it ends at once when they all hold, as the local
        stage would); when it fails, the part is placed by the rows that read nothing else
        (stage "own") and the features stages follow.  So a hole placed on a plate goes to
        the plate, and the plate stays where it is written.  When no stage succeeds (the
        part is the only thing free: ``Fixed(h)`` on the feature, a feature that would have
        to change shape, ...) the point is restored and the paper's ladder runs as before,
        moving the part."""
        held, first, helpers, later = self._part_unknowns(s, own, frames)
        if not held or not self._related(local, held):
            return False
        stages = self._feature_stages(s, held, own, frames, helpers)
        top = next(stages, None)
        if top is None:
            return False
        ranks = _who_moves(s)[1] if len(s.children) > 1 else []
        for k in range(1, len(ranks)):    # a chain: each placed on its reference in turn
            yield from self._place_rank(s, local, order, held, ranks, k, frames, own)
        if (yield Attempt("features", top[0], top[1], top[2], order=order)):
            return True
        saved = None
        rows = local[self._own_rows(local, held)]
        if len(rows):
            cols = self._cols(first + later, rows)
            saved = (cols, self.x[cols].copy())
            att = Attempt("own", 0, rows, self._cols(first, rows), order=order)
            if (not first or not (yield att)) and not later:
                return False
            if not att.ok:                 # a reference sibling placed by its own rows
                att = Attempt("own", 1, rows, cols, order=order)
                if not (yield att):
                    return False
            if att.iterations and (yield Attempt("features", top[0], top[1], top[2],
                                                 order=order)):
                return True                # the part placed, the first stage again
        last = None
        for d, rows, cols, shapes in stages:
            if self.trace.budget_exceeded:
                break
            # the shapes stage starts where the features as wholes got (a scaled pick
            # placed, its label off by 1.1 mm): the shapes move only for what their frames
            # could not meet; from the written point, the least-squares steps bent the
            # picks' three free circles apart (105d #09)
            warm = self._go_on_from(last) if shapes else None
            last = Attempt("features", d, rows, cols, order=order)
            if (yield last):
                return True
            self._put_back(warm)
        self._put_back(saved)              # back to where the paper's ladder starts
        return False

    def _go_on_from(self, att: Attempt | None) -> tuple | None:
        """Start the next attempt where the failed ``att`` ended (its unknowns at its
        ``x_end``); returns what :meth:`_put_back` restores, None when there is nothing to
        start from."""
        if att is None or att.x_end is None:
            return None
        saved = (att.cols, self.x[att.cols].copy())
        self.x = self.x.copy()
        self.x[att.cols] = att.x_end
        return saved

    def _put_back(self, saved: tuple | None) -> None:
        """The unknowns ``saved`` (``(columns, values)``) back at their values."""
        if saved is not None:
            cols, values = saved
            self.x = self.x.copy()
            self.x[cols] = values

    def _place_rank(self, s: Structure, local: np.ndarray, order: int, held: set,
                    ranks: list, k: int, frames, own):
        """Before the features stages, when siblings are placed on siblings placed on
        others (``AlignCenterX(b, c)``, ``AlignCenterY(a, b)``): the children of rank ``k``
        (:func:`_who_moves`) move by their frames to meet the rows of ``s`` that read
        nothing of a higher rank, those of lower ranks and the references held (so ``b``
        keeps its written y, which ``a`` then takes).  When their frames cannot (three
        labels of one drawing, each `At` its own pick), their shapes move too, from where
        the frames got, their own rows kept (the picks they are placed on held: before,
        the last stage moved a pick's tip with its label, 105d #09).  A failure changes
        nothing; the features stages follow either way.  A generator like
        :meth:`~.hierarchy.Solver.steps`."""
        mine = set(frames(ranks[k]))
        later = {i for t in ranks[k + 1:] for c in t for i in self._subtree_unknowns(c)}
        if not mine:
            return
        free, n, exprs = self._free_list(), self.n_model, self.rows.exprs
        pick = []
        for r in local.tolist():
            vs: set = set()
            row_vars(exprs[r], vs)
            vs = {v for v in vs if v < n and free[v]}
            if vs & mine and not vs & later:
                pick.append(r)
        if not pick:
            return
        rows = np.asarray(pick, dtype=np.int64)
        att = Attempt("rank", k, rows, self._cols(sorted(mine), rows), order=order)
        if (yield att) or self.trace.budget_exceeded:
            return
        inner = [c for t in ranks[k] for c in t.subtree()]
        shapes = [i for i in own(inner) if i not in held and i not in later]
        saved = self._go_on_from(att) if shapes else None
        if saved is None:
            return
        rows = np.union1d(rows, self.rows_of(inner))
        if not (yield Attempt("rank", k, rows, self._cols(sorted(mine) + shapes, rows),
                              order=order, max_iter=SHAPES_STEPS)):
            self._put_back(saved)

    def _place_shapes(self, s: Structure, local: np.ndarray, order: int, own):
        """Who moves between the shapes of ``s`` (issue 105), before every other stage at
        ``s``: of two shapes a constraint of ``s`` relates, the first-named moves to the
        second (:func:`_shape_ranks`).  Rank by rank, the shapes of rank ``k`` move (their
        unknowns only) to meet the rows of ``s`` that read them and nothing but shapes of
        lower ranks and references, which are held: so ``At(ear.center, head.center)``
        written 1 mm off moves the ear, and the head, the body the head is placed on and a
        hole placed on the body stay where they are written (before: the stage own of
        :meth:`_features_first` freed every shape, and the substitution started each class
        of unknowns at its members' mean: the ear moved 0.67 mm, everything else 0.33 mm
        the other way).  A rank whose rows all hold ends at once; one that fails changes
        nothing, and the stages after it run as before; ranks whose relations determine
        their shapes go together.  A generator like
        :meth:`~.hierarchy.Solver.steps`."""
        mine = own([s])
        if not mine:
            return
        _, ranks = _shape_ranks(s, set(mine))
        if not ranks:
            return
        rank_of = {v: k for k, vs in enumerate(ranks) for v in vs}
        allowed = set(mine)
        free, n, exprs = self._free_list(), self.n_model, self.rows.exprs
        picks: list = [[] for _ in ranks]
        for r in local.tolist():
            vs: set = set()
            row_vars(exprs[r], vs)
            top = -1
            for v in vs:                    # held: references, shapes related to none
                if v < n and free[v]:
                    if v not in allowed:
                        top = -2                      # reads a child: not a shapes' row
                        break
                    k = rank_of.get(v, -1)
                    if k > top:
                        top = k
            if top >= 0:
                picks[top].append(r)
        # consecutive ranks whose rows are at least as many as their unknowns (each shape
        # determined by its relations once the ranks below are placed: `At`, a chain of
        # rectangles by their corners) go in one attempt, whose solution is then the same;
        # a rank with fewer rows (`AlignCenterY(ear, head)` leaves the ear's x) goes alone,
        # so that a shape above it cannot give way to it
        group: list = []                    # [first rank, rows, unknowns]
        for k, pick in enumerate(picks):
            if self.trace.budget_exceeded:
                return
            if not pick:
                continue
            sl = self.slack[np.asarray(pick, dtype=np.int64)]
            determined = len(pick) >= len(ranks[k]) + int(np.count_nonzero(sl >= 0))
            if group and not determined:
                yield self._shape_rank(group, order)
                group = []
            if group:
                group[1] += pick
                group[2] += ranks[k]
            else:
                group = [k, list(pick), list(ranks[k])]
            if not determined:
                yield self._shape_rank(group, order)
                group = []
        if group and not self.trace.budget_exceeded:
            yield self._shape_rank(group, order)

    def _shape_rank(self, group: list, order: int) -> Attempt:
        """The attempt of :meth:`_place_shapes` for ``group``: [first rank, rows, unknowns]."""
        k, pick, cols = group
        rows = np.asarray(sorted(pick), dtype=np.int64)
        return Attempt("shape rank", k, rows, self._cols(cols, rows), order=order)

    def _subtree_unknowns(self, c: Structure) -> list:
        return [i for t in c.subtree()
                for i in (*self.frame.get(id(t), ()), *self.own.get(id(t), ()))]

    def _shape_first(self, s: Structure, local: np.ndarray, order: int, own):
        """Parts stay within one structure (issue 73): when one of a solid's constraints
        relates its first drawn closed shape (the part: ``body = Ellipse(...)``) to another
        of its shapes (``knob = Circle(...)``, ``Coincident(knob.center, body)``), an
        attempt first solves its rows with the part's unknowns held, so the knob goes to the
        body and the body stays where it is written.  When that fails (the knob is
        ``Fixed``, or only the part can move) the part is first placed by its own rows, those
        that read none of the other shapes' unknowns (stage "own": ``c.center.y == 2`` on the
        part; as :meth:`_features_first` does), and stage shapes runs again; when that fails
        too the point is restored and the paper's stages follow as before.  So the solve is
        the same whether such an affine row is met by pinning (:func:`.system.pinned`: the
        value is no unknown, the row no row) or by the solve.  A generator like
        :meth:`~.hierarchy.Solver.steps`; returns whether ``s`` was solved."""
        part = _part_shape(s)
        if part is None:
            return False
        mine = own([s])
        held = {i for p in part.points.values() for i in (p.ix, p.iy)}
        held.update(sc.index for sc in part.scalars.values())
        held.intersection_update(mine)
        cols = [i for i in mine if i not in held]
        if not held or not cols or not self._related(local, held):
            return False
        shapes = self._cols(cols, local)
        if (yield Attempt("shapes", 0, local, shapes, order=order)):
            return True
        rows = local[self._own_rows(local, held)]
        if not len(rows):
            return False
        first = [i for i in mine if i in held]
        own_cols = self._cols(first, rows)
        saved = self.x[own_cols].copy()
        att = Attempt("own", 0, rows, own_cols, order=order)
        if not (yield att):
            return False
        moved = not np.array_equal(self.x[own_cols], saved)   # (a substitution takes no step)
        if moved and (yield Attempt("shapes", 0, local, shapes, order=order)):
            return True                    # the part placed, the other shapes to it
        self.x = self.x.copy()             # back to where the paper's stages start
        self.x[own_cols] = saved
        return False

    def _feature_stages(self, s: Structure, held: set, own, frames, helpers=()):
        """The features stages at ``s`` (:meth:`_features_first`), lazily: ``(depth, rows,
        unknowns, shapes)`` with the part's unknowns ``held`` left out, none without
        unknowns; ``shapes``: the last stage, the features' shapes moving in them.
        ``helpers``: the unknowns of ``s``'s own construction geometry, free in every stage
        (a construction square for a bolt pattern goes to the plate, not the plate to it)."""
        levels = _levels(s)
        D = len(levels) - 1
        upto = lambda d: [t for lv in levels[:d + 1] for t in lv]
        below = lambda d: [t for lv in levels[1:d + 1] for t in lv]
        helpers = list(helpers)
        if helpers:                        # the part's helpers alone, against its own rows
            rows = self.rows_of([s])
            yield 0, rows, self._cols(helpers, rows), False
        for d in range(1, D + 1):          # descendants translate
            params = helpers + [i for i in frames(below(d)) if i not in held]
            if params:
                rows = self.rows_of(upto(d - 1))
                yield d, rows, self._cols(params, rows), False
        # then the geometry of what cannot translate by itself (a pattern's or a mirror's
        # copies, held on the frame of the structure that made them) follows: a feature
        # that can translate is not deformed to spare its part (its `Fixed` frame holds)
        # the features inside a pattern's (or a mirror's) original move with it, never back
        # against it: its copies' features are tied to them where they are, and holding
        # those in place by a feature's frame is cheaper than moving the copies (run dg:
        # `rolls[0].bb.left == ...` moved the drawing `roll` 31 mm and its hole back 31 mm,
        # and no copy's hole followed its disc)
        originals = {id(o) for t in below(D) if (o := t.__dict__.get("copy_of")) is not None}
        inner = set(frames([t for t in below(D) if any(id(a) in originals for a in
                                                         _ancestors_below(t, s))]))
        all_frames = [i for i in frames(below(D)) if i not in inner]
        for d in range(1, D + 1):
            params = helpers + [i for i in all_frames + own([t for t in below(d)
                                                             if id(t) not in self.frame])
                                if i not in held]
            if params:
                rows = self.rows_of(upto(max(d, D - 1)))
                yield d, rows, self._cols(params, rows), False
        # last, the shapes of the features whose frames are free move within them, as their
        # own rows allow (five pockets of one hole each aligned to the tray: the part held,
        # each pocket moves; before, the paper's ladder moved the tray 1.5e-4 mm with them,
        # issue 105's who-moves rule); a feature whose frame is held (`Fixed(h)`) is not
        # deformed to spare its part
        rows = self.rows_of(upto(D))
        free, n, exprs = self._free_list(), self.n_model, self.rows.exprs
        pinned: set = set()               # unknowns a row holds alone (`Fixed(h)`: its frame)
        for r in rows.tolist():
            vs: set = set()
            row_vars(exprs[r], vs)
            vs = {v for v in vs if v < n and free[v]}
            if len(vs) == 1:
                pinned |= vs
        free_frames = set(all_frames) - pinned
        movable = [t for t in below(D) if t.fx in free_frames and t.fy in free_frames]
        if movable:
            # the copies follow their originals here too (a scaled pick beside three labels
            # each `At` its pick: without the copies' geometry the picks could not move,
            # and the paper's ladder bent them and moved the plate, 105d #09)
            copies = own([t for t in below(D) if id(t) not in self.frame])
            params = helpers + [i for i in dict.fromkeys(all_frames + copies + own(movable))
                                if i not in held]
            yield D + 1, rows, self._cols(params, rows), True

    def _part_unknowns(self, s: Structure, own, frames) -> tuple[set, list, list, list]:
        """(the unknowns the features-first stages hold at ``s``, those its stage "own"
        frees, those of its construction geometry, those stage "own" frees when the first
        do not meet its rows: the frames of the siblings other siblings are placed on,
        :func:`_references`): ``s``'s own unknowns less those of its
        construction geometry (a helper, placed on the part like a feature: issue 73's
        model run, a NEMA 17 plate moved 15 mm to meet its construction bolt square); and
        when ``s`` is an assembly that declares a hole
        (``hole lid_hole {...}`` beside ``box = finger_box(...)``, with ``CutInto(lid_hole,
        box.lid)``), every unknown of its other children (``box``) held, their frames freed
        in stage own (relations between parts are met there as before: both move)."""
        first = own([s])
        helpers: list = []
        made = _helpers(s)
        if made:
            mine = set(first)
            drawn: set = set()
            for g in s.geometry:
                if not g.construction and not g.__dict__.get("copied"):
                    _unknowns(g, drawn)
            if drawn & mine:               # a drawn part to hold: its helpers move, and the
                cons: set = set()          # copies made of its shapes follow them (a mirror
                for g in s.geometry:       # about a construction line the solve turns)
                    if g.construction or g.__dict__.get("copied"):
                        _unknowns(g, cons)
                cons = (cons & mine) - drawn - _held_helpers(s, made)
                helpers = [i for i in first if i in cons]
                first = [i for i in first if i not in cons]
        held = set(first)
        refs = _references(s)
        later: list = []
        # a part placed on a sibling (`Below(bottom, top)`) is no part to hold: it moves to
        # its reference, as without a declared hole (run z5's tray: a hole cut into `top`
        # held both layers, and the ladder then moved each 65 mm to meet the relation)
        placed = {id(t) for rank in _who_moves(s)[1] for t in rank} if refs else set()
        for c in [c for c in self.cut_parts.get(id(s), ()) if id(c) not in placed] + refs:
            sub = list(c.subtree())
            held.update(frames(sub))
            held.update(own(sub))
            (later if c in refs else first).extend(frames([c]))
        return held, first, helpers, later

    def _related(self, rows: np.ndarray, held: set) -> bool:
        """Whether one of ``rows`` reads unknowns both in ``held`` and outside it (slacks
        and held values do not count)."""
        free, n, exprs = self._free_list(), self.n_model, self.rows.exprs
        for r in rows.tolist():
            vs: set = set()
            row_vars(exprs[r], vs)
            inside = outside = False
            for v in vs:
                if v < n and free[v]:
                    if v in held:
                        inside = True
                    else:
                        outside = True
            if inside and outside:
                return True
        return False

    def _free_list(self) -> list:
        """:attr:`free` as a list of bools (indexed one at a time in Python), made once."""
        f = self.__dict__.get("_free")
        if f is None:
            f = self._free = self.free.tolist()
        return f

    def _own_rows(self, rows: np.ndarray, held: set) -> np.ndarray:
        """A mask of ``rows``: those that read no unknown outside ``held``."""
        free, n, exprs = self._free_list(), self.n_model, self.rows.exprs
        mask = np.zeros(len(rows), dtype=bool)
        for k, r in enumerate(rows.tolist()):
            vs: set = set()
            row_vars(exprs[r], vs)
            mask[k] = not any(v < n and free[v] and v not in held for v in vs)
        return mask


def _ancestors_below(t: Structure, s: Structure):
    """``t``'s ancestors strictly below ``s``, nearest first."""
    a = t.parent
    while a is not None and a is not s:
        yield a
        a = a.parent
