"""The cut order: what a machine runs, in which order, from the exact output model
(:class:`~.part.Output`), for the machine writers (G-code, HPGL, LightBurn) and the job-time
estimate (docs/machines.md, "Cut order").

:func:`plan` returns :class:`Cut` s, each one exact path (the output model's lines, arcs,
circles, ellipse and spline pieces, each segment starting where the one before ends) with its
operation:

1. every engraving first (text and drawings: ``engrave``; open outlines: ``score``; then the
   areas engraved filled: ``fill``, as fill lines or as their loops, :func:`plan`), while the
   sheet is still whole and cannot shift;
2. then part by part: a part lying in another part's opening before that part (it would drop
   out with the scrap); within a part, the loops inside others before the loops around them
   (deepest first: a hole before the outline it is cut from, an island in a window before the
   window), so ``cut_inner`` (holes, clockwise loops) comes before ``cut_outer`` (the outline
   that frees the part).  A part's through-cuts (a ``cut`` structure's curves: the output's
   strokes of style ``cut``, open or closed) come first of all its cuts, as ``cut_inner``
   (the inner cut's power, speed and passes), each one path along the curve as written.
3. an edge two pieces of one cut part share is cut once, with the piece cut first
   (:func:`~..part.shared.cut_once`): the other piece's loop is cut as the open paths left.

Within each group the next path is the nearest to where the last one ended (a greedy
nearest-neighbour tour, from the origin), an open path may be run backwards and a closed loop
starts at its segment end nearest to the tool. Lengths in mm.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from ...geometry.shapes.curves import Circle, Line, Loop, Segment, reverse
from ..part.part import Output, fill_regions
from .hatch import hatch_lines
from ..part.edges.shared import cut_once, loop_paths

Point = tuple[float, float]


@dataclass
class Cut:
    """One path the machine runs without lifting: ``operation`` (``engrave``, ``score``,
    ``cut_inner``, ``cut_outer``), ``part`` (the part's name; "" for engraving outside every
    part), ``segments`` (exact, chained), ``closed`` (it ends where it starts)."""
    operation: str
    part: str
    segments: list
    closed: bool

    @property
    def start(self) -> Point:
        return _start(self.segments[0])

    @property
    def end(self) -> Point:
        s = self.segments[-1]
        return _start(s) if isinstance(s, Circle) else tuple(s.end)

    @property
    def length(self) -> float:
        """The path's length (mm)."""
        return sum(s.length for s in self.segments)


def _start(s: Segment) -> Point:
    """Where a segment starts; a whole circle at its point of angle 0."""
    if isinstance(s, Circle):
        return (s.center[0] + s.radius, s.center[1])
    return tuple(s.start)


def plan(output: Output, origin: Point = (0.0, 0.0), back=(),
         hatch: float | None = None) -> list[Cut]:
    """The :class:`Cut` s of ``output`` in cut order (the module's docstring), starting from
    ``origin`` (mm).  ``back``: the operations whose open paths the machine runs there and
    back (an even number of passes, :mod:`.writers.gcode`): the tour goes on from where such
    a path started.  ``hatch``: the areas engraved filled (``fill``, after the engraving) as
    their fill lines ``hatch`` mm apart (:func:`~.hatch.hatch_lines`, one open cut each);
    None: as their closed loops (a writer whose program fills them itself, LightBurn)."""
    back = tuple(back)

    def after(c: Cut) -> Point:
        """Where the tool is once cut ``c`` is done."""
        return c.start if not c.closed and c.operation in back else c.end
    at = origin
    out: list[Cut] = []
    strokes = [Cut("score" if st.style == "open" else "engrave", st.part, list(st.segments),
                   st.closed) for st in output.engrave
               if st.segments and st.style not in ("cut", "fill")]
    through: dict = {}           # part name -> its through-cuts (cut_inner, first in the part)
    for st in output.cuts:
        if st.segments:
            through.setdefault(st.part, []).append(Cut("cut_inner", st.part, list(st.segments),
                                                       st.closed))
    for op in ("engrave", "score"):
        todo = [c for c in strokes if c.operation == op]
        for c in _tour(todo, at, after):
            out.append(c)
            at = after(c)
    for _, part, loops in fill_regions(output.engrave):
        if hatch is None:
            fills = [Cut("fill", part, segs, True) for segs in loops]
        else:
            fills = [Cut("fill", part, [Line(p, q)], False)
                     for p, q in hatch_lines(loops, hatch)]
        for c in fills:                 # in the hatch's own order: row by row, to and fro
            out.append(c)
            at = after(c)
    parts = [p for p in output.parts if p.loops]
    once = cut_once(output)         # the pieces of one cut part: each shared edge once
    index = {id(p): n for n, p in enumerate(output.parts)}
    names = {p.name for p in parts}
    loose = [c for name, cs in through.items() if name not in names for c in cs]
    for c in _tour(loose, at, after):   # through-cuts of no part left (they cut nothing)
        out.append(c)
        at = after(c)
    loops = [(i, lp) for i, p in enumerate(parts) for lp in p.loops]
    polys: dict = {}                # id(loop) -> its polyline, made once for both depths
    depth = _depths([lp for _, lp in loops], polys)
    # a part's depth: how deep its outline lies (an island in another part's window is deeper)
    part_depth = {}
    for (i, lp), d in zip(loops, depth):
        if not lp.is_hole:
            part_depth[i] = min(part_depth.get(i, d), d)
    by_part: dict = {}
    for (i, lp), d in zip(loops, depth):
        by_part.setdefault(i, []).append((d, lp))
    # within a part, the order follows the part's own loops only: another part's outline
    # around this one's (parts that overlap, e.g. a router's paths offset by the tool radius
    # on parts closer than the tool) must not put an outline before its own holes
    for i, got in by_part.items():
        own = _depths([lp for _, lp in got], polys)
        by_part[i] = [(d, lp) for d, (_, lp) in zip(own, got)]
    # the deepest parts first; at each depth the part with the nearest loop start next
    # (nearest first over a grid of the starts, _Nearest: parts x parts distances before, 258 s
    # for the G-code of 20,000 parts)
    order = sorted(by_part, key=lambda i: -part_depth.get(i, 0))
    for _, level in itertools.groupby(order, key=lambda i: part_depth.get(i, 0)):
        level = list(level)
        pick = _Nearest([[_start(lp.segments[0]) for _, lp in by_part[i]] for i in level])
        for _ in level:
            i = level[pick.take(at)[0]]
            name = parts[i].name
            for c in _tour(through.get(name, []), at, after):
                out.append(c)
                at = after(c)
            for d in sorted({d for d, _ in by_part[i]}, reverse=True):
                # a loop an earlier piece of the same cut part shares: the rest of it, open
                cuts = [Cut("cut_inner" if lp.is_hole else "cut_outer", name, segs, closed)
                        for k, (dd, lp) in enumerate(by_part[i]) if dd == d
                        for segs, closed in loop_paths(once, index[id(parts[i])], k, lp)]
                for c in _tour(cuts, at, after):
                    out.append(c)
                    at = after(c)
    return out


def travel(cuts: list[Cut], origin: Point = (0.0, 0.0)) -> float:
    """The length (mm) of the moves between ``cuts`` (from ``origin`` to the first start, and
    from each end to the next start), the tool up."""
    total, at = 0.0, origin
    for c in cuts:
        total += _dist(at, c.start)
        at = c.end
    return total


def _dist(a: Point, b: Point) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def _tour(cuts: list[Cut], at: Point, after=lambda c: c.end) -> list[Cut]:
    """``cuts`` in a greedy nearest-neighbour order from ``at``: each next cut is the one with
    an entry (an open path's either end, a closed loop's segment ends) nearest to where the
    last ended (of equally near entries the first); an open path is turned round, a loop
    rotated to start there (:class:`_Nearest`: 20,000 holes 10.7 s -> about 1 s)."""
    if not cuts:
        return []
    pick = _Nearest([_entries(c) for c in cuts])
    out = []
    for _ in cuts:
        k, j = pick.take(at)
        c = _enter(cuts[k], j)
        out.append(c)
        at = after(c)
    return out


class _Nearest:
    """Items, each with its entry points (``entries[k]``, a list of (x, y) mm, at least one),
    taken nearest first by :meth:`take`.  Up to :data:`TOUR_SMALL` entries each take is one
    array operation over the entries left; more are looked up in a grid (:class:`_Entries`):
    the same answers, in about constant work per take where the entries are spread."""

    def __init__(self, entries: list[list[Point]]):
        counts = [len(es) for es in entries]
        self.E = np.array([p for es in entries for p in es], dtype=float).reshape(-1, 2)
        self.owner = np.repeat(np.arange(len(entries)), counts)
        self.index = np.concatenate([np.arange(n) for n in counts]) if counts else \
            np.zeros(0, dtype=np.int64)
        self.first = np.concatenate(([0], np.cumsum(counts))).astype(np.int64)
        self.alive = np.ones(len(self.E), dtype=bool)
        self.grid = _Entries(self.E) if len(self.E) > TOUR_SMALL else None

    def take(self, at: Point) -> tuple[int, int]:
        """``(k, j)``: the item with the live entry nearest to ``at`` (of equally near
        entries the first) and which of its entries that is; the item's entries are gone."""
        if self.grid is None:
            d = np.hypot(self.E[:, 0] - at[0], self.E[:, 1] - at[1])
            d[~self.alive] = np.inf
            best = int(np.argmin(d))
        else:
            best = self.grid.nearest(at, self.alive)
        k = int(self.owner[best])
        a, b = int(self.first[k]), int(self.first[k + 1])
        self.alive[a:b] = False                    # = alive[owner == k]
        if self.grid is not None:
            self.grid.drop(a, b)
        return k, int(self.index[best])


TOUR_SMALL = 256      # entries of one tour searched whole at each step


class _Entries:
    """The entries of a tour (``E``, n x 2, mm) in a uniform grid of about two per cell, with
    the number of live entries of each cell, for :meth:`nearest`."""

    def __init__(self, E: np.ndarray):
        self.E = E
        lo, hi = E.min(axis=0), E.max(axis=0)
        span = np.maximum(hi - lo, 1e-9)
        h = max(float(np.sqrt(span[0] * span[1] * 2.0 / len(E))), float(span.max()) / 2048,
                1e-9)
        self.lo, self.h = lo, h
        self.nx = int(min(2048, span[0] // h + 1))
        self.ny = int(min(2048, span[1] // h + 1))
        ij = self._cell(E)
        key = ij[:, 1] * self.nx + ij[:, 0]
        self.order = np.argsort(key, kind="stable")
        self.start = np.searchsorted(key[self.order], np.arange(self.nx * self.ny + 1))
        self.live = np.bincount(key, minlength=self.nx * self.ny).reshape(self.ny, self.nx)
        self.key = key

    def _cell(self, P) -> np.ndarray:
        ij = np.floor((np.asarray(P, dtype=float).reshape(-1, 2) - self.lo) / self.h)
        return np.clip(ij, 0, [self.nx - 1, self.ny - 1]).astype(np.int64)

    def drop(self, a: int, b: int) -> None:
        """Entries ``a:b`` are gone (their cut is done)."""
        np.subtract.at(self.live.reshape(-1), self.key[a:b], 1)

    def _gather(self, x0, y0, x1, y1) -> np.ndarray:
        """The entries (indices into ``E``) of the cells x0..x1, y0..y1."""
        parts = [self.order[self.start[y * self.nx + x0]:self.start[y * self.nx + x1 + 1]]
                 for y in range(y0, y1 + 1)]
        return np.concatenate(parts) if parts else np.zeros(0, dtype=np.int64)

    def nearest(self, at: Point, alive: np.ndarray) -> int:
        """The live entry nearest to ``at`` (the least index of equally near ones): the
        distances are those of the whole-array search, over the cells of every entry no
        farther than the nearest one found in the smallest square of cells around ``at``
        that holds a live entry."""
        cx, cy = (int(v) for v in self._cell(at)[0])
        r = 1
        while True:
            x0, x1 = max(cx - r, 0), min(cx + r, self.nx - 1)
            y0, y1 = max(cy - r, 0), min(cy + r, self.ny - 1)
            if self.live[y0:y1 + 1, x0:x1 + 1].any():
                break
            r *= 2
        idx = self._gather(x0, y0, x1, y1)
        idx = idx[alive[idx]]
        d = np.hypot(self.E[idx, 0] - at[0], self.E[idx, 1] - at[1])
        reach = float(d.min())
        # every entry within `reach` of `at`: the cells of the box around it (one more cell
        # each way: a point on a cell's edge)
        a = np.floor((np.array([at[0] - reach, at[1] - reach]) - self.lo) / self.h) - 1
        b = np.floor((np.array([at[0] + reach, at[1] + reach]) - self.lo) / self.h) + 1
        X0, Y0 = (int(v) for v in np.clip(a, 0, [self.nx - 1, self.ny - 1]))
        X1, Y1 = (int(v) for v in np.clip(b, 0, [self.nx - 1, self.ny - 1]))
        if X0 < x0 or Y0 < y0 or X1 > x1 or Y1 > y1:
            idx = self._gather(min(X0, x0), min(Y0, y0), max(X1, x1), max(Y1, y1))
            idx = idx[alive[idx]]
            d = np.hypot(self.E[idx, 0] - at[0], self.E[idx, 1] - at[1])
        ties = idx[d == d.min()]
        return int(ties.min())


def _entries(c: Cut) -> list[Point]:
    """Where cut ``c`` can start: a loop at any segment's start, an open path at either end."""
    if c.closed:
        return [_start(s) for s in c.segments]
    return [c.start, c.end]


def _enter(c: Cut, j: int) -> Cut:
    """Cut ``c`` started at its entry ``j`` (of :func:`_entries`)."""
    if c.closed:
        return Cut(c.operation, c.part, c.segments[j:] + c.segments[:j], True)
    if j == 1:
        return Cut(c.operation, c.part, [reverse(s) for s in reversed(c.segments)], False)
    return c


def _depths(loops: list[Loop], made: dict | None = None) -> list[int]:
    """For each loop, how many of the others enclose it (a point of it inside their
    polylines, by the even-odd rule), the bounding boxes tested first: the loops whose box
    holds a loop's point found through a grid of the points (:class:`..part.nearby._Grid`),
    each box's points tested in one array operation; every box against every point when
    they would be too many pairs.  ``made``: ``{id(loop): polyline}`` already made (kept
    and added to)."""
    n = len(loops)
    if n < 2:
        return [0] * n
    made = {} if made is None else made
    polys = []
    for lp in loops:
        p = made.get(id(lp))
        if p is None:
            p = made[id(lp)] = lp.points()
        polys.append(p)
    boxes = np.array([[p[:, 0].min(), p[:, 1].min(), p[:, 0].max(), p[:, 1].max()]
                      if len(p) else [0.0, 0.0, 0.0, 0.0] for p in polys])
    # a point on each loop: its first vertex (a loop touches no other, so any of its points
    # is inside exactly the loops that enclose it)
    probe = np.array([p[0] if len(p) else (0.0, 0.0) for p in polys])
    area = (boxes[:, 2] - boxes[:, 0]) * (boxes[:, 3] - boxes[:, 1])
    from ..part.measure.nearby import TooManyPairs, _Grid, _median
    try:
        cell = max(_median(np.maximum(boxes[:, 2:] - boxes[:, :2], 0.0).ravel()), 1e-6)
        j, i = _Grid(probe, cell).in_boxes(boxes[:, :2], boxes[:, 2:])
    except TooManyPairs:
        return _depths_each(polys, boxes, probe, area)
    keep = area[j] > area[i]
    j, i = j[keep], i[keep]
    out = np.zeros(n, dtype=np.int64)
    order = np.argsort(j, kind="stable")
    j, i = j[order], i[order]
    cuts = np.flatnonzero(np.r_[True, j[1:] != j[:-1]]) if len(j) else np.zeros(0, int)
    for a, b in zip(cuts.tolist(), cuts[1:].tolist() + [len(j)]):
        who = i[a:b]
        out[who[_inside_all(probe[who], polys[int(j[a])])]] += 1
    return out.tolist()


def _depths_each(polys, boxes, probe, area) -> list[int]:
    """:func:`_depths` one loop at a time against every box."""
    n = len(polys)
    depth = []
    for i in range(n):
        x, y = probe[i]
        cand = np.flatnonzero((boxes[:, 0] <= x) & (x <= boxes[:, 2]) & (boxes[:, 1] <= y)
                              & (y <= boxes[:, 3]) & (area > area[i]))
        depth.append(sum(1 for j in cand if _inside((x, y), polys[j])))
    return depth


def _inside_all(P: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """:func:`_inside` of each point of ``P`` (m x 2), the same operations on each; in
    blocks of at most 4,000,000 (point, edge) pairs."""
    a = poly
    b = np.roll(poly, -1, axis=0)
    out = np.zeros(len(P), dtype=bool)
    step = max(1, 4_000_000 // max(1, len(a)))
    for s in range(0, len(P), step):
        x, y = P[s:s + step, :1], P[s:s + step, 1:]
        cross = (a[:, 1] > y) != (b[:, 1] > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            xs = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
        out[s:s + step] = np.count_nonzero(cross & (x < xs), axis=1) % 2 == 1
    return out


def _inside(p: Point, poly: np.ndarray) -> bool:
    """Point ``p`` inside the closed polyline ``poly`` (k x 2), by the even-odd rule."""
    x, y = p
    a = poly
    b = np.roll(poly, -1, axis=0)
    cross = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xs = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(cross & (x < xs)) % 2)


def job_seconds(cuts: list[Cut], machine, origin: Point = (0.0, 0.0)) -> float:
    """An estimate of the job's time (s) on ``machine`` (:class:`~.machine.Machine`): each
    cut's length times its operation's passes at its speed, and the travel at the travel
    speed (acceleration ignored: a lower bound for short segments)."""
    t = 0.0
    for c in cuts:
        op = machine.operation(c.operation)
        t += c.length * max(1, int(op.passes)) / op.speed * 60.0
    return t + travel(cuts, origin) / machine.travel_speed * 60.0
