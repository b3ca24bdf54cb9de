"""The hierarchical solve: post-order over the structure tree with iterative deepening.

Paper, appendix "Solver Details", *Iterative Deepening Recursive Solve*.  Structures are solved
children first.  At a structure ``S`` only ``S``'s own geometry and parameters are unknown and
only ``S``'s own constraints are solved; everything deeper is held.  When that fails:

* stage 1 (translation deepening), ``d = 1 .. depth``: the translation frames of descendants
  down to relative depth ``d`` become unknowns too, and the constraints of their parents (the
  structures at depth ``< d``), which a move could break, are solved again;
* stage 2 (geometric deepening), ``d = 1 .. depth``: all frames stay free and all parameters of
  the structures down to depth ``d`` become unknowns, with the constraints at those levels.

Before those stages, when a constraint of ``S`` relates ``S``'s own geometry (a part) to a
descendant's (a feature: a hole, a child solid, a pattern's target), the part is placed by
its own constraints and held while the features move (:mod:`.parts_first`,
issue 73: parts stay, features move); only when that fails do the stages above move it.
Between two children related by a constraint of ``S`` the first-named moves to the second,
which is held the same way (:func:`.tree._who_moves`, issue 84; a hole, cut or engraving moves to a
solid whichever is named first).

The solve of ``S`` fails only when stage 2 has reached the bottom of its subtree (then the
subtree was solved flat and the system is inconsistent or intractable).  Frames are cheaper to
move than geometry (column scaling), so a solved substructure moves rigidly before it deforms.

Every attempt solves min/max with frozen branches and re-checks (*Iterated Newton solve for
branching expressions*): solve with the branches active at the start, evaluate the true min/max
at the result, and repeat from there with the new branches until they agree.

A :class:`Solver` compiles each row set once (:class:`~.tape.Tape`), so re-solving after an edit
of a held value (:meth:`Solver.set_value`) only reruns Newton.
"""
from __future__ import annotations


import numpy as np

from ...base.limits import now
from .arrays import unique

from ...geometry.core.model import Model, Structure
from ...base.memory import gc_paused
from .attempts import Attempt, Failure, Trace
from .batch import newton_batch
from .newton import TOL, dense_enough, newton
from .holds import build_rows
from .parts_first import PartsFirst
from .system import LINK, SIGN, Rows, pin_values, pinned, pinned_none
from .reduce import reduce
from .small import SMALL_ROWS, small_tape
from .tape import Tape
from .tree import _cut_parts, _helpers, _levels, _post_order, _rigid_below

MAX_ROUNDS = 12           # min/max branch re-checks per attempt
MAX_ITER = 100            # Newton steps per attempt and round
ITER_BUDGET = 20000       # Newton steps for a whole solve; beyond it the solve gives up (E0402)
CHECK_TOL = 1e-6          # a row counts as satisfied below this residual (mm or rad)
FRAME_SCALE = 100.0       # frames move 1e4x cheaper (in the squared step norm) than geometry
SLACK_SCALE = 100.0       # an inactive inequality barely resists motion


class Solver(PartsFirst):
    """Compiled solver state for one model.

    ``x``: extended parameter vector (model parameters, then inequality slacks), mm / rad.
    """

    deadline: float | None = None       # limits.now() (CPU s) after which solving stops
    pinning = True                      # False: pinned geometry stays unknown (for tests)

    def __init__(self, model: Model):
        self.model = model
        x = model.xs()
        built = build_rows(model, x)
        n = built.n_params
        self.n_model = len(x)
        self.x = np.concatenate([x, np.zeros(n - len(x))])
        self.free = np.concatenate([np.asarray(model.free, dtype=bool),
                                    np.ones(n - len(x), dtype=bool)])
        self.scale = np.ones(n)
        self.scale[len(x):] = SLACK_SCALE
        self.is_frame = np.zeros(n, dtype=bool)
        for s in model.structures:
            for i in (s.fx, s.fy):
                if 0 <= i < len(x):
                    self.is_frame[i] = True
        # geometry fixed in its structure's frame (rigid template geometry: a gear's teeth)
        # is held at its pinned values, its rows dropped (system.pinned): its structure's
        # frame moves it
        self.rows_built = built            # every row, pinning rows included (warm reuse)
        with gc_paused():          # thousands of small records: no cyclic collections
            self.pins = pinned(built, self.free, self.is_frame, model.param_owner) \
                if self.pinning else pinned_none()
        self.pinned_by: dict[int, int] = {}     # id(structure) -> its pinned parameters
        self.pinned_rows: dict[int, int] = {}   # id(constraint) -> its rows dropped so
        # each solver row's index among the rows built (pinning rows included): the order of
        # rows the diagnostics take, the same with and without pinning (None: the identity)
        self.built_index: np.ndarray | None = None
        if self.pins:
            pins = self.pins
            pin_values(built, pins, self.x)
            self.pinned_by = _count(map(id, model.param_owner), len(model.param_owner),
                                    pins.var)
            self.pinned_rows = _count(map(id, built.constraint), len(built.exprs), pins.row)
            self.free[pins.var] = False
            keep = np.ones(len(built.exprs), dtype=bool)
            keep[pins.row] = False
            self.built_index = np.flatnonzero(keep)
            built = built.subset(self.built_index.tolist())
        self.rows: Rows = built
        self.scale[self.is_frame] = FRAME_SCALE
        self.slack = np.asarray(self.rows.slack, dtype=np.int64)
        self.kind = np.asarray(self.rows.kind, dtype=np.int64)
        # parameters by owning structure: own (geometry, scalars) and frame
        self.own: dict[int, list[int]] = {}
        self.frame: dict[int, list[int]] = {}
        root = model.root
        frame, owners = self.is_frame.tolist(), model.param_owner
        with gc_paused():          # a list per structure: no cyclic collections meanwhile
            for i in np.flatnonzero(self.free[:len(owners)]).tolist():
                owner = owners[i] or root
                if owner is None:
                    continue
                (self.frame if frame[i] else self.own).setdefault(id(owner), []).append(i)
        self._tapes: dict[bytes, Tape] = {}
        self._rows_of: dict[tuple, np.ndarray] = {}
        self.failed: set[int] = set()          # ids of constraints given up on
        self.trace = Trace()
        self.compiles = 0
        self.last_x = self.x
        self.use_reduction = True
        self.batching = True          # False: plain post-order, one attempt at a time
        self.use_small = True         # small row sets in Python floats (small.py)
        self.any_rigid = any(getattr(t, "rigid", False) for t in model.structures)
        self.cut_parts = _cut_parts(model)    # an assembly's parts, beside its holes
        self._not_small: set[int] = set()     # rows small.py does not compile

    # ------------------------------------------------------------------ helpers
    def tape(self, rows: np.ndarray) -> Tape:
        """The compiled tape of ``rows`` (row indices), cached by row set.

        The whole model is compiled once (:attr:`whole`); the tape of an increasing row set
        is cut out of it by array selection (:meth:`.Tape.subset`), so no expression is walked
        twice however many attempts share its row (a parent's translation attempts repeat its
        children's rows).  A small row set gets a :class:`~.small.SmallTape` instead (the same
        numbers in Python floats), when :mod:`.small` compiles it."""
        if self.use_small and len(rows) <= SMALL_ROWS:
            key = rows.tobytes()
            t = self._tapes.get(key)
            if t is not None:
                return t
            t = small_tape(self.rows.exprs, self.rows.n_params, rows, self._not_small,
                           self.__dict__.get("_whole"))
            if t is not None:
                self._tapes[key] = t
                self.compiles += 1
                return t
        return self.array_tape(rows)

    def array_tape(self, rows: np.ndarray) -> Tape:
        """The :class:`~.tape.Tape` (NumPy arrays) of ``rows``, cut from :attr:`whole` and
        cached by row set: what :meth:`tape` gives, and what a batch needs whatever the size
        of its row set (:meth:`attempt_batch` reads the tape's arrays: groups, entries)."""
        key = rows.tobytes()
        t = self._tapes.get(key)
        if t is None or not isinstance(t, Tape):
            akey = b"array:" + key
            t = self._tapes.get(akey)
            if t is None:
                whole = self.whole
                if len(rows) == whole.n_rows:
                    t = whole                   # rows of an attempt are distinct: all of them
                elif len(rows) < 2 or bool(np.all(rows[1:] > rows[:-1])):
                    t = whole.subset(rows)
                else:
                    t = Tape([self.rows.exprs[r] for r in rows], self.rows.n_params)
                self._tapes[key if key not in self._tapes else akey] = t
                self.compiles += 1
        return t

    @property
    def whole(self) -> Tape:
        """The tape of every row of the model, compiled on first use."""
        t = self.__dict__.get("_whole")
        if t is None:
            t = self._whole = Tape(self.rows.exprs, self.rows.n_params)
        return t

    def _init_slacks(self, t: Tape, rows: np.ndarray) -> None:
        """Set each inequality's slack to max(g, 0) at the current point (g = LINK row + s)."""
        pos = np.flatnonzero(self.kind[rows] == LINK)
        if not len(pos):
            return
        s = self.slack[rows[pos]]
        self.x[s] = 0.0
        g = t.evaluate(self.x)[pos]
        self.x[s] = np.maximum(g, 0.0)

    def set_value(self, index: int, value: float) -> None:
        """Edit a parameter (typically a held dimension) before re-solving.  A pinned
        parameter (:func:`.system.pinned`) keeps the value its rows give it."""
        if self.pins and not self.free[index] and index in self._pinned_set():
            return
        self.x[index] = float(value)

    def _pinned_set(self) -> set:
        s = self.__dict__.get("_pinned")
        if s is None:
            s = self._pinned = {v for v, _ in self.pins}
        return s

    def rows_of(self, structs) -> np.ndarray:
        """The rows (increasing) of the constraints owned by ``structs``, less those given up
        on; remembered per structure set while nothing has failed (a re-solve repeats them)."""
        key = tuple(map(id, structs))
        if not self.failed:
            hit = self._rows_of.get(key)
            if hit is not None:
                return hit
            if len(structs) == 1:          # one owner's rows: already increasing
                own = self.rows.by_owner.get(key[0])
                if own is None:            # none (most structures of a large pattern)
                    return np.zeros(0, dtype=np.int64)
                rows = np.asarray(own, dtype=np.int64)
                self._rows_of[key] = rows
                return rows
        out = []
        for s in structs:
            for r in self.rows.by_owner.get(id(s), ()):
                if id(self.rows.constraint[r]) not in self.failed:
                    out.append(r)
        rows = np.asarray(sorted(out), dtype=np.int64)
        if not self.failed:
            self._rows_of[key] = rows
        return rows

    def _cols(self, params: list[int], rows: np.ndarray) -> np.ndarray:
        sl = self.slack[rows]
        return unique(np.concatenate([np.asarray(params, dtype=np.int64), sl[sl >= 0]]))

    # ------------------------------------------------------------------ attempts
    def _steps_left(self, tr) -> int:
        """Newton steps the solve may still take (:data:`ITER_BUDGET` over the whole solve),
        or 0 when the budget or the deadline is used up (then ``tr`` says which)."""
        left = ITER_BUDGET - tr.iterations
        if left <= 0:
            tr.budget_exceeded = True
            return 0
        if self.deadline is not None and now() > self.deadline:
            tr.budget_exceeded = tr.out_of_time = True
            return 0
        return left

    def attempt(self, att: Attempt) -> bool:
        """Run one attempt from the current point; on success keep its result."""
        tr = self.trace
        tr.attempts.append(att)
        if not len(att.rows):
            att.ok = True
            return True
        t = self.tape(att.rows)
        self._init_slacks(t, att.rows)
        x = self.x
        choices = np.zeros(t.n_choices, dtype=np.int64)
        if float(np.max(np.abs(t.evaluate(x, record=choices)))) <= CHECK_TOL:
            att.ok = True
            return True
        scale = self.scale[att.cols]
        sign_choice = t.root_choice[self.kind[att.rows] == SIGN]
        released = False
        for rnd in range(1, MAX_ROUNDS + 1):
            left = self._steps_left(tr)
            if not left:
                break
            red = reduce(t, x, att.cols, scale) if self.use_reduction else None
            res = newton(t, x, att.cols, scale, choices,
                         max_iter=min(att.max_iter or MAX_ITER, left), tol=TOL, reduction=red)
            att.iterations += res.iterations
            att.rounds = rnd
            tr.iterations += res.iterations
            x = res.x
            new = np.zeros(t.n_choices, dtype=np.int64)
            F = t.evaluate(x, record=new)         # the true min/max, and their branches
            if float(np.max(np.abs(F))) <= CHECK_TOL:
                att.ok = True
                break
            if tr.iterations >= ITER_BUDGET:
                tr.budget_exceeded = True
                break
            if np.array_equal(new, choices):
                # an inequality made active may be what blocks the solve: release them all
                # once (the next round's check re-activates any that end up violated)
                # (a SIGN row is 2 min(s, 0): branch 1, the 0, is the inactive bound)
                if released or not len(sign_choice) or bool(np.all(new[sign_choice] == 1)):
                    break
                released = True
                new = new.copy()
                new[sign_choice] = 1
            choices = new
        self.last_x = x
        if att.ok:
            self.x = x
        else:
            att.x_end = x[att.cols]
        return att.ok

    def batchable(self, att: Attempt) -> bool:
        """Whether ``att`` may join a batch (:meth:`attempt_batch`): it has rows, and its
        system is small enough to be solved densely even before substitution."""
        return len(att.rows) > 0 and att.max_iter is None \
            and dense_enough(len(att.rows), len(att.cols))

    def attempt_batch(self, atts: list) -> None:
        """Run independent attempts (disjoint rows and unknowns, each row using only its own
        attempt's unknowns) at once, each with exactly the result :meth:`attempt` gives it
        alone: one tape cut, one substitution, one evaluation per Newton step or try for all
        (:func:`.batch.newton_batch`), and per attempt its own rounds of branch re-checks,
        damping and stops.  Falls back to one :meth:`attempt` after the other when the rows
        are not independent."""
        rows = np.concatenate([a.rows for a in atts])
        cols = np.concatenate([a.cols for a in atts])
        order = np.argsort(rows, kind="stable")
        rows = rows[order]
        cols = np.sort(cols)
        if (len(rows) > 1 and not bool(np.all(rows[1:] > rows[:-1]))) or \
                (len(cols) > 1 and not bool(np.all(cols[1:] > cols[:-1]))):
            for a in atts:
                self.attempt(a)
            return
        t = self.array_tape(rows)
        blocks = [(np.searchsorted(rows, a.rows), np.searchsorted(cols, a.cols)) for a in atts]
        if not _independent(t, rows, cols, blocks):
            for a in atts:
                self.attempt(a)
            return
        tr = self.trace
        tr.attempts.extend(atts)
        self._init_slacks(t, rows)
        x = self.x
        rowblock = np.empty(len(rows), dtype=np.int64)
        for k, (rb, _) in enumerate(blocks):
            rowblock[rb] = k
        # each block's min/max choices, and those of its SIGN rows (2 min(s, 0))
        chblock = np.empty(t.n_choices, dtype=np.int64)
        for g in t.groups:
            if g.sel is not None:
                chblock[g.sel] = rowblock[t.root_of[g.idx]]
        chorder = np.argsort(chblock, kind="stable")
        chcut = np.searchsorted(chblock[chorder], np.arange(len(atts) + 1)).tolist()
        sign_choice = t.root_choice[self.kind[rows] == SIGN]
        sign_choice = sign_choice[np.argsort(chblock[sign_choice], kind="stable")]
        sgcut = np.searchsorted(chblock[sign_choice], np.arange(len(atts) + 1)).tolist()
        choices = np.zeros(t.n_choices, dtype=np.int64)
        F = t.evaluate(x, record=choices)
        live = []
        for k, a in enumerate(atts):
            if float(np.max(np.abs(F[blocks[k][0]]))) <= CHECK_TOL:
                a.ok = True
            else:
                live.append(k)
        if not live:
            return
        scale = self.scale[cols]
        released = [False] * len(atts)
        for rnd in range(1, MAX_ROUNDS + 1):
            if not live:
                break
            left = self._steps_left(tr)
            if not left:
                break
            red = reduce(t, x, cols, scale) if self.use_reduction else None
            x, results, over = newton_batch(t, x, cols, scale, [blocks[k] for k in live],
                                            choices, max_iter=min(MAX_ITER, left), tol=TOL,
                                            reduction=red, budget=left)
            for k, res in zip(live, results):
                atts[k].iterations += res.iterations
                atts[k].rounds = rnd
                tr.iterations += res.iterations
            if over:
                tr.budget_exceeded = True
                break
            new = np.zeros(t.n_choices, dtype=np.int64)
            F = t.evaluate(x, record=new)         # the true min/max, and their branches
            going = []
            for k in live:
                if float(np.max(np.abs(F[blocks[k][0]]))) <= CHECK_TOL:
                    atts[k].ok = True
                    continue
                if tr.iterations >= ITER_BUDGET:
                    tr.budget_exceeded = True
                    continue
                c = chorder[chcut[k]:chcut[k + 1]]
                if np.array_equal(new[c], choices[c]):
                    sb = sign_choice[sgcut[k]:sgcut[k + 1]]
                    if released[k] or not len(sb) or bool(np.all(new[sb] == 1)):
                        continue
                    released[k] = True
                    new[sb] = 1
                going.append(k)
            choices = new
            live = [] if tr.budget_exceeded else going
        self.last_x = x
        good = np.zeros(len(cols), dtype=bool)
        for k, a in enumerate(atts):
            if a.ok:
                good[blocks[k][1]] = True
            else:
                a.x_end = x[a.cols]
        self.x[cols[good]] = x[cols[good]]

    # ------------------------------------------------------------------ strategies
    def solve_flat(self) -> bool:
        """Everything at once: all unknowns, all rows (the baseline the paper improves on)."""
        rows = np.arange(len(self.rows.exprs), dtype=np.int64)
        cols = np.flatnonzero(self.free)
        att = Attempt("flat", 0, rows, cols)
        ok = self.attempt(att)
        if not ok:
            self.trace.failures.append(Failure(self.model.root, att))
            self.x = self.last_x
        return ok

    def solve_hierarchical(self) -> bool:
        """Every structure after its subtree (paper: post-order), with the iterative
        deepening of :meth:`steps`.  Structures whose subtrees are disjoint are independent
        (validity rule 2), so the structures at one depth of the tree are solved together,
        after everything below them: their attempts go in lockstep, and the small ones of
        each step are one :meth:`attempt_batch`.  Each attempt's result is what the plain
        post-order gives it (same steps, same bits); the trace lists attempts and failures
        in post-order.  (Only when the iteration budget runs out, E0402, which structures
        were tried before it did depends on this order.)"""
        root = self.model.root
        if root is None:
            return True
        rank = {id(s): i for i, s in enumerate(_post_order(root))}
        self._rank = rank
        if not self.batching:              # the plain post-order, one attempt at a time
            ok = True
            for s in _post_order(root):
                ok = self.solve_structure(s) and ok
                if self.trace.budget_exceeded:
                    return False
            return ok
        ok = self._solve_forest([root])
        tr = self.trace
        tr.attempts.sort(key=lambda a: a.order)
        tr.failures.sort(key=lambda f: rank.get(id(f.structure), -1))
        return ok and not tr.budget_exceeded

    def _solve_forest(self, structs: list) -> bool:
        """Solve ``structs`` (disjoint subtrees), each after its children."""
        kids = [c for s in structs for c in s.children.values()]
        ok = True
        if kids:
            ok = self._solve_forest(kids)
            if self.trace.budget_exceeded:
                return False
        pending = []                       # (ladder, attempt it waits on)
        by_owner = self.rows.by_owner
        for s in structs:
            if id(s) not in by_owner:
                continue                   # no row of its own: solved as it stands (steps)
            g = self.steps(s)
            try:
                pending.append((g, next(g)))
            except StopIteration as stop:
                ok = stop.value and ok
        while pending:
            small = [a for _, a in pending if self.batchable(a)]
            if len(small) > 1:
                self.attempt_batch(small)
            for _, a in pending:
                if not (len(small) > 1 and self.batchable(a)):
                    self.attempt(a)
            if self.trace.budget_exceeded:
                return False
            nxt = []
            for g, a in pending:
                try:
                    nxt.append((g, g.send(a.ok)))
                except StopIteration as stop:
                    ok = stop.value and ok
            pending = nxt
        return ok

    def solve_structure(self, s: Structure) -> bool:
        """Solve ``s`` alone (its subtree solved already): :meth:`steps` one attempt at a
        time."""
        if not hasattr(self, "_rank"):
            self._rank = {}
        g = self.steps(s)
        try:
            att = next(g)
            while True:
                att = g.send(self.attempt(att))
        except StopIteration as stop:
            return stop.value

    def _frame_of(self, t: Structure) -> list:
        """The unknowns that move ``t`` as a whole: its frame; for a structure scaled in
        place (its frame held on its parent's, its points tied to its original's), its
        original's frame and its own geometry, which follows that frame by its rows
        (``Scale(small, 0.85)`` of a pick of three free circles placed by its box: the pick
        moves whole, as it does unscaled; before, only the paper's ladder could move it,
        and it bent the pick, 105d #09)."""
        mine = self.frame.get(id(t), ())
        was = t.__dict__.get("in_place_of") if not mine else None
        if was is None:
            return mine
        return [*self.frame.get(id(was), ()),
                *(i for c in t.subtree() for i in self.own.get(id(c), ()))]

    def steps(self, s: Structure):
        """The iterative deepening at ``s`` as a generator: yields each :class:`Attempt` in
        turn and is sent whether it succeeded; returns whether ``s`` was solved (paper,
        appendix "Solver Details", *Iterative Deepening Recursive Solve*)."""
        local = self.rows_of([s])
        if not len(local):
            return True
        order = self._rank.get(id(s), 0)
        # a rigid structure below s (``Rigid(part)``) moves only by its own frame: its own
        # parameters, and everything of its descendants, stay as its own solve left them
        no_own, no_frame = _rigid_below(s) if self.any_rigid else ((), ())
        own = lambda structs: [i for t in structs if id(t) not in no_own
                               for i in self.own.get(id(t), ())]
        frames = lambda structs: [i for t in structs if id(t) not in no_frame
                                  for i in self._frame_of(t)]
        if s.geometry:                     # of two shapes related, the first-named moves
            yield from self._place_shapes(s, local, order, own)
        if (s.children or _helpers(s)) \
                and (yield from self._features_first(s, local, order, own, frames)):
            return True
        if (yield from self._shape_first(s, local, order, own)):
            return True
        # stage 0: only this structure's own unknowns
        last = Attempt("local", 0, local, self._cols(own([s]), local), order=order)
        if (yield last):
            return True
        levels = _levels(s)
        D = len(levels) - 1
        upto = lambda d: [t for lv in levels[:d + 1] for t in lv]
        # stage 1: translate descendants, one level deeper at a time
        for d in range(1, D + 1):
            if self.trace.budget_exceeded:
                break
            rows = self.rows_of(upto(d - 1))
            moved = [t for lv in levels[1:d + 1] for t in lv]
            # a pattern's copies have no frame of their own: their geometry follows their
            # original's frame here (run z5's buttons: `first_flower.s.center == (100, 0)`
            # on a GridPattern's original moved the star alone, its holes left behind)
            copies = [c for t in moved if id(t) not in self.frame for c in t.subtree()]
            params = own([s]) + frames(moved) + own(list({id(c): c for c in copies}.values()))
            last = Attempt("translate", d, rows, self._cols(params, rows), order=order)
            if (yield last):
                return True
        # stage 2: deform descendants, one level deeper at a time
        all_frames = frames([t for lv in levels[1:] for t in lv])
        for d in range(1, D + 1):
            if self.trace.budget_exceeded:
                break
            rows = self.rows_of(upto(max(d, D - 1)))
            params = all_frames + own(upto(d))
            last = Attempt("deform", d, rows, self._cols(params, rows), order=order)
            if (yield last):
                return True
        self.trace.failures.append(Failure(s, last))
        if last.x_end is not None:
            # where the last attempt ended (its unknowns; the rest of x is untouched by it)
            self.x = self.x.copy()
            self.x[last.cols] = last.x_end
        # do not retry these constraints at every ancestor
        F = self.tape(last.rows).evaluate(self.x)
        for r, v in zip(last.rows, F):
            if abs(v) > CHECK_TOL:
                self.failed.add(id(self.rows.constraint[r]))
        return False


def _count(ids, n: int, which: np.ndarray) -> dict[int, int]:
    """How many of ``which`` (indices into the ``n`` ids ``ids``) have each id."""
    keys, counts = np.unique(np.fromiter(ids, dtype=np.int64, count=n)[which],
                             return_counts=True)
    return dict(zip(keys.tolist(), counts.tolist()))


def _independent(t: Tape, rows: np.ndarray, cols: np.ndarray, blocks: list) -> bool:
    """Whether every row of tape ``t`` (the rows ``rows``) uses no unknown of another block:
    ``blocks`` gives each block's rows (positions in ``t``) and unknowns (positions in
    ``cols``).  Validity rule 2 makes this hold for disjoint subtrees; checked anyway, since
    the batch's equality with one-by-one solving rests on it."""
    owner = -np.ones(t.n_params, dtype=np.int64)
    rowblock = np.empty(t.n_rows, dtype=np.int64)
    for k, (rb, cp) in enumerate(blocks):
        owner[cols[cp]] = k
        rowblock[rb] = k
    ao = owner[t.a_col]
    lo = owner[t.l_col]
    return not (bool(np.any((ao >= 0) & (ao != rowblock[t.aff_rows[t.a_row]]))) or
                bool(np.any((lo >= 0) & (lo != rowblock[t.root_of[t.leaf_node[t.l_row]]]))))
