"""The passes a structure's ``Fillet``/``Chamfer`` operations make over its exact outline
(:func:`finish`, called by the renderer): consecutive ``Fillet``s of chosen corners are one
pass (:func:`_batch`), each pass :func:`.corners.corners` on every loop, and what a pass did
not do said by :func:`.corners.report` (E0408, W0406), W0410 and W0411."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .corners import (CORNER_TOL, SHRUNK, _narrow_holes, _narrow_notches, _tip_back, corners,
                      outline_shapes, report)

if TYPE_CHECKING:
    from ..core.model import Structure


def finish(s: Structure, loops: list, x=None, check=None, said=None) -> list:
    """Apply the structure's Fillet/Chamfer operations, in order, to its exact outline
    ``loops`` (:class:`~.curves.Loop`, outer loops counter-clockwise and holes clockwise);
    ``x`` (the solved unknowns) places corners chosen with ``at``.  Consecutive ``Fillet``s
    of chosen corners, none choosing a corner an earlier one of them chose, are one pass
    (:func:`_batch`): a fillet adds no corner, so their order cannot matter, and each
    corner takes at most half of the pieces beside it as first drawn, as one call of all of
    them would (run ft: ``Fillet([body.top, notches.u[i]], 3)`` once per loop pass left each
    flat 5 mm for the next and capped R3 at 2.5 mm nine times; the list in one call got R3).
    ``check``: called before each loop (the compile's deadline: it raises to stop).
    ``said``: a list that gets ``(call, code, index of the chosen corner or -1, message,
    hint)`` (:func:`report`) for a chosen corner that is no corner of the outline (E0408),
    one rounded smaller than asked and an operation that finds no corner at all (W0406).
    Returns the new loops."""
    first = loops                       # before any finishing (E0408: an earlier one took it)
    off, ops, start = None, list(getattr(s, "finish", [])), 0
    while start < len(ops):
        batch = _batch(ops, start, loops, x)
        start += len(batch)
        got, deep = [{} for _ in batch], []
        narrow = []
        sizes = None if batch[0][5] is None else [
            b[1] for b in batch for _ in b[5]]
        only = None if sizes is None else [p for b in batch for p, _ in b[5]]
        owner = [] if sizes is None else [(k, j) for k, b in enumerate(batch)
                                          for j in range(len(b[5]))]
        kind, r = batch[0][0], batch[0][1]
        done = []
        for lp in loops:
            if check is not None:
                check()
            mine: dict = {}
            done.append(corners(lp, r if sizes is None else sizes, kind == "Fillet", only,
                                mine, deep))
            for j, v in mine.items():
                k, jj = (0, j) if sizes is None else owner[j]
                got[k][jj] = min(v, got[k].get(jj, v))
            if only is None and kind == "Fillet":     # (a Chamfer leaves inside corners)
                if lp.is_hole and 0 < mine.get(-1, r) < r * (1 - SHRUNK):
                    narrow.append((lp, mine[-1]))
                elif not lp.is_hole:
                    narrow += _narrow_notches(lp, r)
        if said is not None:
            if off is None:
                # the points said in the frame the Fillet is written in (run bu: its hint
                # gave a template's corner where the sheet has it, and the point it wrote
                # missed by 2 mm)
                off = (0.0, 0.0)
                if x is not None:
                    from ..core.expr import evaluate
                    off = tuple(float(evaluate(e, x)) for e in s.frame_offset(None))
            for k, (kind, r, _, call, chosen, pts, why) in enumerate(batch):
                said += report(kind, r, call, chosen, why, pts, got[k], loops,
                               first if loops is not first else None, off)
            # (run fj: W0411's tips given where the layout had moved the deer)
            for n, (p, *rest, j) in enumerate(deep):
                call = batch[0 if sizes is None else owner[j][0]][3]
                said.append(_tip_back(call, n, (p[0] - off[0], p[1] - off[1]), *rest))
            if narrow:
                said += _narrow_holes(kind, r, batch[0][3], narrow, outline_shapes(s))
        loops = done
    return loops


def _placed(op, loops: list, x) -> tuple:
    """A finishing operation ``op`` ((kind, size, at, call)) with its corners found on
    ``loops``: ``(kind, size, at, call, chosen, pts, why)``, ``chosen`` the placed
    :class:`Chosen` of ``at``, ``pts`` [(point, index into chosen)] (None: the whole
    outline), ``why`` index -> why two edges make no corner."""
    kind, r, at, call = op
    chosen, why, pts = [], {}, None
    if at is not None and x is not None:
        chosen = [c.placed(x) for c in at]
        pts = []
        for i, c in enumerate(chosen):
            meet, why[i] = c.targets(loops)
            pts += [(p, i) for p in meet]
    return (kind, r, at, call, chosen, pts, why)


def _batch(ops: list, start: int, loops: list, x) -> list:
    """The pass :func:`finish` makes from ``ops[start]`` on the outline ``loops``, a list of
    :func:`_placed` operations: a run of ``Fillet``s of chosen corners is one pass as long as
    no corner of one lies within :data:`CORNER_TOL` of a corner an earlier one of the run
    chose (a corner rounded twice is rounded by the first and then no corner: E0408, as
    written in order); a ``Chamfer`` (whose cut makes two new corners) and a whole-outline
    operation are passes of their own."""
    out = [_placed(ops[start], loops, x)]
    if out[0][0] != "Fillet" or out[0][5] is None:
        return out
    taken = [p for p, _ in out[0][5]]
    for op in ops[start + 1:]:
        if op[0] != "Fillet" or op[2] is None:
            break
        nxt = _placed(op, loops, x)
        if any(math.hypot(p[0] - q[0], p[1] - q[1]) <= CORNER_TOL
               for p, _ in nxt[5] for q in taken):
            break
        out.append(nxt)
        taken += [p for p, _ in nxt[5]]
    return out
