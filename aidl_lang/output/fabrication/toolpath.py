"""The cut order: what a machine runs, in which order, from the exact output model
(:class:`~.part.Output`), for the machine writers (G-code, HPGL, LightBurn) and the job-time
estimate (docs/machines.md, "Cut order").

:func:`plan` returns :class:`Cut` s, each one exact path (the output model's lines, arcs,
circles, ellipse and spline pieces, each segment starting where the one before ends) with its
operation:

1. every engraving first (text and drawings: ``engrave``; open outlines: ``score``), while the
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

import math
from dataclasses import dataclass

import numpy as np

from ...geometry.curves import Circle, Loop, Segment, reverse
from ..part.part import Output
from ..part.shared import cut_once, loop_paths

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


def plan(output: Output, origin: Point = (0.0, 0.0), back=()) -> list[Cut]:
    """The :class:`Cut` s of ``output`` in cut order (the module's docstring), starting from
    ``origin`` (mm).  ``back``: the operations whose open paths the machine runs there and
    back (an even number of passes, :mod:`.writers.gcode`): the tour goes on from where such
    a path started."""
    back = tuple(back)

    def after(c: Cut) -> Point:
        """Where the tool is once cut ``c`` is done."""
        return c.start if not c.closed and c.operation in back else c.end
    at = origin
    out: list[Cut] = []
    strokes = [Cut("score" if st.style == "open" else "engrave", st.part, list(st.segments),
                   st.closed) for st in output.engrave if st.segments and st.style != "cut"]
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
    parts = [p for p in output.parts if p.loops]
    once = cut_once(output)         # the pieces of one cut part: each shared edge once
    index = {id(p): n for n, p in enumerate(output.parts)}
    names = {p.name for p in parts}
    loose = [c for name, cs in through.items() if name not in names for c in cs]
    for c in _tour(loose, at, after):   # through-cuts of no part left (they cut nothing)
        out.append(c)
        at = after(c)
    loops = [(i, lp) for i, p in enumerate(parts) for lp in p.loops]
    depth = _depths([lp for _, lp in loops])
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
        own = _depths([lp for _, lp in got])
        by_part[i] = [(d, lp) for d, (_, lp) in zip(own, got)]
    remaining = sorted(by_part, key=lambda i: -part_depth.get(i, 0))
    while remaining:
        deepest = part_depth.get(remaining[0], 0)
        level = [i for i in remaining if part_depth.get(i, 0) == deepest]
        while level:
            # the part whose nearest loop start is nearest
            i = min(level, key=lambda i: min(_dist(at, _start(lp.segments[0]))
                                             for _, lp in by_part[i]))
            level.remove(i)
            remaining.remove(i)
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
    last ended; an open path is turned round, a loop rotated to start there.  Each step is
    one array operation over the entries left (n cuts of k entries: O(n^2 k))."""
    if not cuts:
        return []
    entries = [_entries(c) for c in cuts]
    E = np.array([p for es in entries for p in es], dtype=float)
    owner = np.repeat(np.arange(len(cuts)), [len(es) for es in entries])
    index = np.concatenate([np.arange(len(es)) for es in entries])
    alive = np.ones(len(E), dtype=bool)
    out = []
    for _ in range(len(cuts)):
        d = np.hypot(E[:, 0] - at[0], E[:, 1] - at[1])
        d[~alive] = np.inf
        best = int(np.argmin(d))
        k = int(owner[best])
        alive[owner == k] = False
        c = _enter(cuts[k], int(index[best]))
        out.append(c)
        at = after(c)
    return out


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


def _depths(loops: list[Loop]) -> list[int]:
    """For each loop, how many of the others enclose it (a point of it inside their
    polylines, by the even-odd rule), the bounding boxes tested first."""
    n = len(loops)
    if n < 2:
        return [0] * n
    polys = [lp.points() for lp in loops]
    boxes = np.array([[p[:, 0].min(), p[:, 1].min(), p[:, 0].max(), p[:, 1].max()]
                      if len(p) else [0.0, 0.0, 0.0, 0.0] for p in polys])
    # a point on each loop: its first vertex (a loop touches no other, so any of its points
    # is inside exactly the loops that enclose it)
    probe = np.array([p[0] if len(p) else (0.0, 0.0) for p in polys])
    area = (boxes[:, 2] - boxes[:, 0]) * (boxes[:, 3] - boxes[:, 1])
    depth = []
    for i in range(n):
        x, y = probe[i]
        cand = np.flatnonzero((boxes[:, 0] <= x) & (x <= boxes[:, 2]) & (boxes[:, 1] <= y)
                              & (y <= boxes[:, 3]) & (area > area[i]))
        depth.append(sum(1 for j in cand if _inside((x, y), polys[j])))
    return depth


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
