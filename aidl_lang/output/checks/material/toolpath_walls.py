"""``W0507`` from ``aidl render``: a bridge, rim or web that the cutter's own width leaves
thinner than the minimum wall (docs/machines.md, "What the tool leaves").

A through-cut (a ``cut`` structure's curve: a slit, a relief cut) has no width in the design;
the cutter cuts it as wide as itself, round past each end: a router's bit its diameter, a
laser its kerf.  The outlines and holes are offset so that the part comes out at its size
(:func:`~..fabrication.layout.compensate`: outlines outward, holes inward by the tool's
radius; an edge two pieces share stays on its line), but a line has no side to offset, so the
material beside a through-cut is narrower than drawn by the tool's radius.  A slit stopped
1.6 mm short of a plate's edge passes the design's checks (W0507 at 0.5 mm) and, with a
3.175 mm bit, leaves 0.0125 mm there; an arc slit 1 mm inside a disc's rim mills the rim away
over the whole arc.

:func:`eaten_walls` measures what is left on the tool paths themselves: every path the tool's
centre runs along (each through-cut as drawn, each loop offset as the machine cuts it) sweeps
the tool's radius to each side, so between two paths ``d`` mm apart ``d`` less the tool's
diameter is left.  Distances are taken from each path's vertices to the other's chords
(:func:`~..part.nearby.close_pairs`: candidate pairs from a grid, O(n log n)) and exactly
where the nearest point lies inside a chord of a circle.  A through-cut that meets a loop in
the design (a slit from the edge, a relief cut from a hole) is judged against that loop only
at its free ends, ahead of or beside the end (its other points lie along the junction it is
drawn to make); through-cuts that meet one another are one chain, not judged against each
other.  A bridge already thinner than the minimum as drawn is the design's own W0507 (the
checks of :mod:`.through`) and not said again.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ....geometry.shapes.curves import carrier, distance_to, sample_xy
from ....geometry.shapes.curves import foot as foot_on
from ....geometry.shapes.tessellate import CHORD_TOL
from ...part.measure.nearby import box_pairs_between, close_pairs
from ..common import part_min_wall

TOUCH = 2 * CHORD_TOL   # mm: a through-cut this near a loop or another cut meets it in the
                        # design (on chords, up to CHORD_TOL inside a curve)
SHOWN = 5           # warnings per part; the rest are counted in the last one


@dataclass(frozen=True)
class Eaten:
    """Material of part ``part`` between through-cut ``cut`` (its label) and ``other``
    (words: ``the outer edge of `p```, ``hole `p.h```, ``through-cut `p.s.b```): ``drawn``
    mm wide in the design, ``left`` mm once the tool has cut (0 or less: cut through),
    nearest at ``at`` (x, y mm, the middle of what is left there, or the point of the cut
    where nothing is); over ``length`` mm of the
    cut less than ``min_wall`` mm is left (0: at a point, a bridge at the cut's end)."""
    part: str
    cut: str
    other: str
    drawn: float
    left: float
    at: tuple
    length: float
    min_wall: float
    more: int = 0       # further warnings of this part, counted in this one (the last shown)
    two_cuts: bool = False      # ``other`` is a through-cut too: the tool eats from both


class _Paths:
    """The chords of some exact paths: ``A``, ``B`` (n x 2) each chord's ends, ``F`` its
    path's index, ``C`` its segment's carrier (with ``carriers``); ``V`` (m x 2) the
    vertices (every chord's start and each open path's end), ``VF`` their path's index;
    ``box`` (paths x 4) each path's bounding box, ``first`` (paths + 1) where each path's
    chords start in ``A``."""

    def __init__(self, paths: list, closed: list, first: int = 0, carriers: bool = True):
        xs, ys, F, C, ends = [], [], [], [], []      # every point; a chord from each but
        for k, (segs, shut) in enumerate(zip(paths, closed), first):     # the last of a run
            for seg in segs:
                n0 = len(xs)
                sample_xy([seg], xs, ys)
                end = getattr(seg, "end", None)         # a whole circle: back to its start
                xs.append(end[0] if end is not None else xs[n0])
                ys.append(end[1] if end is not None else ys[n0])
                ends.append(len(xs) - 1)
                F.append((k, len(xs) - n0 - 1))
                if carriers:
                    C.append((carrier(seg), len(xs) - n0 - 1))
        P = np.column_stack([xs, ys]) if xs else np.zeros((0, 2))
        last = np.zeros(len(P), dtype=bool)
        last[ends] = True
        chord = np.flatnonzero(~last)               # a chord from each point but a run's end
        self.A, self.B = P[chord], P[chord + 1]
        counts = np.asarray([c for _, c in F], dtype=np.intp)
        self.F = np.repeat(np.asarray([f for f, _ in F], dtype=np.intp), counts)
        self.C = [c for c, n in C for _ in range(n)]
        # the vertices: the chords' starts, and the end of each open path
        V, VF = [self.A], [self.F]
        tail = [(e, k) for (k, shut), e in zip(self._last_of(paths, closed, first), ends)
                if k is not None]
        VC = list(self.C)
        if tail:
            V.append(P[[e for e, _ in tail]])
            VF.append(np.asarray([k for _, k in tail], dtype=np.intp))
            if carriers:
                last = np.searchsorted(self.F, [k for _, k in tail], side="right") - 1
                VC += [self.C[j] for j in last]
        self.V, self.VF = np.concatenate(V), np.concatenate(VF)
        order = np.argsort(self.VF, kind="stable")  # each path's vertices together, in order
        self.V, self.VF = self.V[order], self.VF[order]
        self.VC = [VC[j] for j in order] if carriers else None      # each vertex's carrier
        n = len(paths)
        self.first = np.searchsorted(self.F, np.arange(first, first + n + 1))
        self.box = np.full((n, 4), np.nan)          # NaN: a path with no chords (left out)
        full = np.flatnonzero(self.first[1:] > self.first[:-1])
        if len(full):
            at = self.first[full]
            self.box[full, :2] = np.minimum.reduceat(np.minimum(self.A, self.B), at)
            self.box[full, 2:] = np.maximum.reduceat(np.maximum(self.A, self.B), at)

    @staticmethod
    def _last_of(paths, closed, first):
        """For each segment in order: (the path's index, closed) at an open path's last
        segment, else (None, None)."""
        for k, (segs, shut) in enumerate(zip(paths, closed), first):
            for j, seg in enumerate(segs):
                yield ((k, shut) if j == len(segs) - 1 and not shut
                       and getattr(seg, "end", None) is not None else (None, None))


def _exact(dist, foot, A, B, C, P, PC=None) -> tuple:
    """``dist`` (from points ``P`` to chords ``A``-``B`` with feet ``foot``) made exact on
    circles: where the foot lies inside a chord of a circle, the point's distance to the
    circle; where the point lies on a circle (its carrier in ``PC``) and the chord on a line,
    the circle's distance to the chord when its nearest point is within a chord of ``P``
    (a hole's round edge beside a straight slit, between its vertices).  Returns the
    distances, and the points and feet moved to where they are reached."""
    out = np.array(dist, dtype=float)
    P, foot = np.array(P, dtype=float).reshape(-1, 2), np.array(foot, dtype=float).reshape(-1, 2)
    if not len(out):
        return out, P, foot
    e = B - A
    L2 = np.einsum("ij,ij->i", e, e)
    u = np.einsum("ij,ij->i", foot - A, e) / np.where(L2 > 0, L2, 1.0)
    for q in range(len(out)):
        c = C[q]
        if c[0] == "C":
            if 1e-9 < u[q] < 1 - 1e-9:
                out[q] = distance_to(c, tuple(P[q]))
                foot[q] = foot_on(c, tuple(P[q]))
            continue
        pc = PC[q] if PC is not None else None
        if c[0] != "L" or pc is None or pc[0] != "C":
            continue
        o = np.asarray(pc[1:3])
        k = min(max(float(np.dot(o - A[q], e[q]) / L2[q]) if L2[q] > 0 else 0.0, 0.0), 1.0)
        f = A[q] + k * e[q]                         # the chord's point nearest the centre
        L = float(np.hypot(*(f - o)))
        d = L - pc[3]
        if d > 0 and L > 0:
            x = o + (f - o) / L * pc[3]             # the circle's point nearest the chord
            if np.hypot(*(x - P[q])) <= 4 * math.sqrt(2 * pc[3] * CHORD_TOL) + 1e-9 \
                    and d < out[q]:
                out[q], P[q], foot[q] = d, x, f
    return out, P, foot


def _crossing(P: _Paths, Q: _Paths) -> list:
    """The pairs (path of ``P``, path of ``Q``) some chords of which cross: the chords of
    the paths of ``Q`` whose boxes meet a path of ``P``'s, against ``P``'s chords whose boxes
    meet theirs."""
    ip, iq = (np.flatnonzero(~np.isnan(X.box[:, 0])) for X in (P, Q))
    fp = box_pairs_between(P.box[ip], Q.box[iq], TOUCH)
    if not len(fp):
        return []
    near = np.unique(iq[fp[:, 1]])
    qk = np.concatenate([np.arange(Q.first[j], Q.first[j + 1]) for j in near])
    box = lambda A, B: np.hstack([np.minimum(A, B), np.maximum(A, B)])     # noqa: E731
    ij = box_pairs_between(box(P.A, P.B), box(Q.A[qk], Q.B[qk]), TOUCH)
    if not len(ij):
        return []
    i, j = ij[:, 0], qk[ij[:, 1]]
    a, b, c, d = P.A[i], P.B[i], Q.A[j], Q.B[j]

    def orient(p, q, r):
        return (q[:, 0] - p[:, 0]) * (r[:, 1] - p[:, 1]) - (q[:, 1] - p[:, 1]) * (r[:, 0] - p[:, 0])
    hit = (orient(a, b, c) * orient(a, b, d) <= 0) & (orient(c, d, a) * orient(c, d, b) <= 0)
    return [(int(x), int(y)) for x, y in
            np.unique(np.column_stack([P.F[i[hit]], Q.F[j[hit]]]), axis=0)]


def _seg_box(seg) -> tuple:
    """A box around exact segment ``seg`` (a whole circle's or arc's: its circle's)."""
    c = carrier(seg)
    if c[0] == "C":
        return (c[1] - c[3], c[2] - c[3], c[1] + c[3], c[2] + c[3])
    if c[0] == "L":
        (x0, y0), (x1, y1) = seg.start, seg.end
        return (min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))
    xs, ys = [], []
    sample_xy([seg], xs, ys)
    xs.append(seg.end[0])
    ys.append(seg.end[1])
    pad = 1e-2                               # a curve's chords within CHORD_TOL of it
    return (min(xs) - pad, min(ys) - pad, max(xs) + pad, max(ys) + pad)


def _near_loops(loops: list, slits: _Paths, reach: float) -> list:
    """``loops`` with those farther than ``reach`` from every through-cut's box left empty
    (so that a panel of 20,000 holes samples only the holes beside its cuts)."""
    if not len(loops):
        return []
    boxes = np.asarray([[f(v) for f, v in zip((min, min, max, max), zip(
        *[_seg_box(g) for g in lp.segments]))] if lp.segments else [np.nan] * 4
        for lp in loops], dtype=float)
    full = np.flatnonzero(~np.isnan(slits.box[:, 0]))
    near = set(box_pairs_between(slits.box[full], boxes, reach)[:, 1].tolist())
    return [lp.segments if k in near else [] for k, lp in enumerate(loops)]


def _meets(slits: _Paths, design: _Paths, m: int) -> tuple[set, np.ndarray]:
    """Which paths meet in the design: the pairs (through-cut, other path: a cut ``< m`` or
    a loop ``m + k``), and for each vertex of ``slits`` whether it touches another path."""
    meet = set()
    touching = np.zeros(len(slits.V), dtype=bool)
    v, s, _, _ = close_pairs(slits.V, slits.VF, design.A, design.B, design.F, TOUCH)
    for a, b in zip(slits.VF[v], design.F[s]):
        meet.add((int(a), int(b)))
    touching[v] = True
    for a, b in _crossing(slits, design):
        if a != b:
            meet.add((int(a), int(b)))
    loops = _Paths.__new__(_Paths)          # the loops' vertices against the cuts' chords
    keep = design.VF >= m
    loops.V, loops.VF = design.V[keep], design.VF[keep]
    v, s, _, _ = close_pairs(loops.V, loops.VF, slits.A, slits.B, slits.F, TOUCH)
    for a, b in zip(slits.F[s], loops.VF[v]):
        meet.add((int(a), int(b)))
    return meet, touching


def _chains(meet: set, m: int) -> list[int]:
    """Each through-cut's chain (the cuts that meet, joined): the first cut of its chain,
    by a walk over the cuts that meet."""
    nbrs: list = [[] for _ in range(m)]
    for a, b in meet:
        if b < m and a != b:
            nbrs[a].append(b)
            nbrs[b].append(a)
    chain = [-1] * m
    for first in range(m):
        if chain[first] >= 0:
            continue
        chain[first], todo = first, [first]
        while todo:
            for b in nbrs[todo.pop()]:
                if chain[b] < 0:
                    chain[b] = first
                    todo.append(b)
    return chain


def _tooled(output, width, apart: bool) -> dict:
    """Part name -> its loops as the machine cuts them (offset by half of ``width``: mm, or a
    dict part name -> mm), for the parts with through-cuts, and whether they are offset: a
    part whose exact offset fails (a spline or ellipse, which the router's writer first makes
    arcs; a feature smaller than the tool, which it refuses) keeps its loops as drawn."""
    from ...fabrication.layout import LayoutError, compensate
    names = {st.part for st in output.cuts if st.part}
    w = {n: (width.get(n, 0.0) if isinstance(width, dict) else width) for n in names}
    w = {n: k for n, k in w.items() if k}
    if not w:
        return {}
    try:
        done = compensate(output, w, apart=apart)
        return {p.name: (p.loops, True) for p in done.parts if p.name in w}
    except LayoutError:
        pass
    out = {p.name: (p.loops, False) for p in output.parts if p.name in w}
    for n, k in w.items():
        try:
            done = compensate(output, {n: k}, apart=apart)
        except LayoutError:
            continue
        out.update({p.name: (p.loops, True) for p in done.parts if p.name == n})
    return out


def eaten_walls(output, width, min_wall_of, apart: bool = False, design=None,
                tick=lambda: None) -> list[Eaten]:
    """The material a cutter of ``width`` mm (a router's bit's diameter, a laser's kerf; or
    a dict part name -> mm) leaves thinner than the minimum wall beside the through-cuts of
    ``output`` (the module docstring), part by part in ``output``'s order, at most
    :data:`SHOWN` a part (the last counting the rest).  ``min_wall_of(name)``: the minimum
    wall of part ``name`` in mm; ``apart``: the parts are cut apart (a layout: no shared
    edges); ``design``: the :class:`~..part.part.Output` the widths as drawn are taken from
    (default ``output``: a router's G-code gets the kerf-offset parts)."""
    tooled = _tooled(output, width, apart)
    drawn_parts = {p.name: p for p in (design or output).parts}
    by_part: dict = {}
    for st in output.cuts:
        if st.segments and st.part in tooled:
            by_part.setdefault(st.part, []).append(st)
    out = []
    for p in output.parts:
        strokes = by_part.get(p.name)
        if not strokes:
            continue
        tick()
        w = width.get(p.name, 0.0) if isinstance(width, dict) else width
        loops, offset = tooled[p.name]
        found = _part(p, drawn_parts.get(p.name, p), strokes, loops, w / 2,
                      min_wall_of(p.name), offset)
        out += found
    return out


def _loop_name(part: str, lp) -> str:
    return f"a hole of `{part}`" if lp.is_hole else f"the outer edge of `{part}`"


def _part(p, drawn, strokes: list, loops: list, r: float, t: float,
          offset: bool = True) -> list[Eaten]:
    """:func:`eaten_walls` for one part ``p`` (``drawn``: as in the design) with through-cuts
    ``strokes``, its tool-path ``loops`` (``offset`` False: as drawn, the tool outside them)
    and a tool of radius ``r``, minimum wall ``t``."""
    eat = 2 * r if offset else r            # what a cut and a loop's path leave less than
    # their distance; two cuts' paths, 2 r
    m = len(strokes)
    slits = _Paths([st.segments for st in strokes], [st.closed for st in strokes])
    reach = 2 * r + max(t, 0.0) + 1e-6
    design = _Paths([st.segments for st in strokes] + _near_loops(drawn.loops, slits, reach),
                    [st.closed for st in strokes] + [True] * len(drawn.loops), carriers=False)
    meet, touching = _meets(slits, design, m)
    chain = np.asarray(_chains(meet, m), dtype=np.intp)
    path = _Paths(_near_loops(loops, slits, reach), [True] * len(loops), first=m)
    meets_loop = {(int(chain[a]), b) for a, b in meet if b >= m}
    # (kind, chain, other chain or loop) -> [left, at, point on the cut, (kind, cut, other)]:
    # one warning for the thinnest place between two chains of cuts, or a chain and a loop
    found: dict = {}

    def note(kind, i, o, left, at, on_cut):
        key = (kind, *sorted((int(chain[i]), int(chain[o])))) if kind == "cut" else \
            (kind, int(chain[i]), o)
        got = found.setdefault(key, [math.inf, None, None, None])
        if left < got[0]:
            got[:] = [left, at, on_cut, (kind, i, o)]
    tol = 1e-9 * max(1.0, t)
    thin = (lambda left: left < t - tol or left <= tol)
    # the cuts' vertices against every other path's chords (cuts by chain: one chain's own
    # bends are no bridges)
    A = np.vstack([slits.A, path.A])
    B = np.vstack([slits.B, path.B])
    F = np.concatenate([chain[slits.F], path.F])
    C = slits.C + path.C
    SF = np.concatenate([slits.F, path.F])
    v, s, dist, ft = close_pairs(slits.V, chain[slits.VF], A, B, F, reach)
    sub = np.where(SF[s] < m, 2 * r, eat)
    keep = np.flatnonzero(dist - sub < max(t, tol) + 4 * CHORD_TOL)   # may be thin
    v, s, ft, sub = v[keep], s[keep], ft[keep], sub[keep]
    dist, on, ft = _exact(dist[keep], ft, A[s], B[s], [C[k] for k in s], slits.V[v],
                          [slits.VC[k] for k in v])
    ends = _free_ends(slits, strokes, touching)
    for q in np.flatnonzero(dist - sub < max(t, tol)):
        vi, k = int(v[q]), int(s[q])
        i, o = int(slits.VF[vi]), int(SF[k])
        if o >= m and (int(chain[i]), o) in meets_loop and not _ahead(ends, vi, ft[q],
                                                                      slits.V[vi]):
            continue
        left = float(dist[q] - sub[q])
        if thin(left):
            note("cut" if o < m else "loop", i, o, left, (on[q] + ft[q]) / 2, on[q])
    # the loops' vertices against the cuts' chords (a hole's corner beside a long slit)
    v, s, dist, ft = close_pairs(path.V, path.VF, slits.A, slits.B, chain[slits.F], reach)
    keep = np.flatnonzero(dist - eat < max(t, tol) + 4 * CHORD_TOL)
    v, s, ft = v[keep], s[keep], ft[keep]
    dist, on, ft = _exact(dist[keep], ft, slits.A[s], slits.B[s], [slits.C[k] for k in s],
                          path.V[v], [path.VC[k] for k in v])
    for q in np.flatnonzero(dist - eat < max(t, tol)):
        i, o = int(slits.F[s[q]]), int(path.VF[v[q]])
        if (int(chain[i]), o) in meets_loop:
            continue
        left = float(dist[q]) - eat
        if thin(left):
            note("loop", i, o, left, (on[q] + ft[q]) / 2, ft[q])
    kept = []
    for got in found.values():
        kind, i, o = got[3]
        pair = ("cut", min(i, o), max(i, o)) if kind == "cut" else got[3]   # at the first
        e = _said(p, drawn, strokes, pair, got, r, t, m)
        if e is not None:
            kept.append((e, pair))
    kept.sort(key=lambda ek: ek[0].left)
    out = [replace(e, length=_stretch(slits, key, path if key[0] == "loop" else slits,
                                      eat if key[0] == "loop" else 2 * r, t))
           for e, key in kept[:SHOWN]]
    if len(kept) > SHOWN:
        out[-1] = replace(out[-1], more=len(kept) - SHOWN)
    return out


def _free_ends(slits: _Paths, strokes: list, touching: np.ndarray) -> dict:
    """Vertex index -> the direction out of its cut, for each end of an open cut that
    touches nothing in the design (a free end, inside the material)."""
    out = {}
    first = np.searchsorted(slits.VF, np.arange(len(strokes) + 1))
    for i, st in enumerate(strokes):
        if st.closed or first[i + 1] - first[i] < 2:
            continue
        a, b = int(first[i]), int(first[i + 1]) - 1
        if not touching[a]:
            out[a] = slits.V[a] - slits.V[a + 1]
        if not touching[b]:
            out[b] = slits.V[b] - slits.V[b - 1]
    return out


def _ahead(ends: dict, vi: int, foot, at) -> bool:
    """Vertex ``vi`` is a free end and ``foot`` lies ahead of it or beside it."""
    d = ends.get(vi)
    if d is None:
        return False
    toward = np.asarray(foot) - np.asarray(at)
    return float(np.dot(toward, d)) >= -1e-3 * float(np.hypot(*toward) * np.hypot(*d))


def _said(p, drawn, strokes, key, got, r, t, m) -> Eaten | None:
    """The :class:`Eaten` of one pair (``key``: ("cut", i, j) or ("loop", i, loop)), its
    stretch not yet measured; None when it is as thin as drawn (the design's W0507 says
    it)."""
    left, at, on_cut, _ = got
    kind, i, o = key
    if kind == "cut":
        drawn_w = left + 2 * r
        other = (f"another through-cut drawn by `{strokes[o].source}`"
                 if strokes[o].source == strokes[i].source else
                 f"through-cut `{strokes[o].source}`")
    else:
        lp = drawn.loops[o - m] if o - m < len(drawn.loops) else None
        drawn_w = _drawn_distance(strokes[i].segments, lp, at, 2 * r + t + 1.0) \
            if lp is not None else left + r
        drawn_w = left + r if not math.isfinite(drawn_w) else drawn_w
        other = _loop_name(p.name, lp) if lp is not None else f"an edge of `{p.name}`"
    if t > 0 and drawn_w < t - 1e-9 * max(1.0, t):
        return None
    if left <= 0:               # nothing left: where on the cut it breaks through
        at = on_cut
    return Eaten(p.name, strokes[i].source or "a through-cut", other, float(drawn_w),
                 float(left), (float(at[0]), float(at[1])), 0.0, t, two_cuts=kind == "cut")


STRETCH_SAMPLES = 4000      # points along a cut at most, where its stretch is measured


def _stretch(slits: _Paths, key, others: _Paths, eat: float, t: float) -> float:
    """The length (mm) of cut ``key[1]`` along which less than ``t`` is left between it and
    path ``key[2]`` (among ``others``; the tool leaves ``eat`` mm less than their distance):
    the cut sampled every ``min(eat / 2, t) / 2`` mm or so."""
    r = eat / 2
    _, i, o = key
    k = np.flatnonzero(slits.F == i)
    A, B = slits.A[k], slits.B[k]
    L = np.hypot(*(B - A).T)
    total = float(L.sum())
    if total <= 0:
        return 0.0
    h = max(min(r, t if t > 0 else r) / 2, total / STRETCH_SAMPLES, 1e-3)
    n = np.maximum(1, np.ceil(L / h).astype(int))
    f = np.concatenate([(np.arange(c) + 0.5) / c for c in n])
    which = np.repeat(np.arange(len(k)), n)
    P = A[which] + f[:, None] * (B - A)[which]
    w = np.repeat(L / n, n)
    sel = others.F == o
    OA, OB = others.A[sel], others.B[sel]
    reach = eat + t + 1e-6                  # only the other path's chords within reach
    lo, hi = P.min(0) - reach, P.max(0) + reach
    near = (np.maximum(OA, OB) >= lo).all(1) & (np.minimum(OA, OB) <= hi).all(1)
    thin = _least(P, OA[near], OB[near]) - eat < max(t, 1e-9)
    return float(w[thin].sum())


def _least(P, A, B) -> np.ndarray:
    """The least distance from each point ``P`` (n x 2) to the chords ``A``-``B``."""
    if not len(A):
        return np.full(len(P), np.inf)
    e = B - A
    L2 = np.where(np.einsum("ij,ij->i", e, e) > 0, np.einsum("ij,ij->i", e, e), 1.0)
    out = np.empty(len(P))
    for a in range(0, len(P), 256):
        d = P[a:a + 256, None, :] - A[None]
        u = np.clip(np.einsum("pij,ij->pi", d, e) / L2, 0.0, 1.0)
        q = d - u[..., None] * e[None]
        out[a:a + 256] = np.sqrt(np.einsum("pij,pij->pi", q, q)).min(1)
    return out


def _feet(V, A, B):
    """For each point ``V``: the index of its nearest chord ``A``-``B``, the distance and
    the foot."""
    e = B - A
    L2 = np.where(np.einsum("ij,ij->i", e, e) > 0, np.einsum("ij,ij->i", e, e), 1.0)
    d = V[:, None, :] - A[None]
    u = np.clip(np.einsum("pij,ij->pi", d, e) / L2, 0.0, 1.0)
    q = d - u[..., None] * e[None]
    dist = np.sqrt(np.einsum("pij,pij->pi", q, q))
    k = dist.argmin(1)
    rows = np.arange(len(V))
    return k, dist[rows, k], A[k] + u[rows, k][:, None] * e[k]


def _drawn_distance(segments, lp, at, pad: float) -> float:
    """The least distance, as drawn, between a through-cut (its exact ``segments``) and loop
    ``lp`` within ``pad`` of ``at`` (exact on lines and circles)."""
    P, Q = _Paths([segments], [False]), _Paths([lp.segments], [True])
    lo, hi = np.asarray(at) - pad, np.asarray(at) + pad
    best = math.inf
    for X, Y in ((P, Q), (Q, P)):
        inV = ((X.V >= lo) & (X.V <= hi)).all(1)
        inC = ((np.maximum(Y.A, Y.B) >= lo) & (np.minimum(Y.A, Y.B) <= hi)).all(1)
        V, VC = X.V[inV], [c for c, ok in zip(X.VC, inV) if ok]
        ci = np.flatnonzero(inC)
        if not len(V) or not len(ci):
            continue
        k, d, ft = _feet(V, Y.A[ci], Y.B[ci])
        d = _exact(d, ft, Y.A[ci][k], Y.B[ci][k], [Y.C[j] for j in ci[k]], V, VC)[0]
        best = min(best, float(d.min()))
    return best


def _mm(x: float) -> str:
    """A length in mm to 1e-4 mm, as written (2.0875, not 2.087)."""
    return f"{round(x, 4) + 0.0:g}"


def _words(r: float, router: bool) -> tuple[str, str]:
    """The tool and its reach, in words."""
    if router:
        return f"the router's bit ({_mm(2 * r)} mm across)", f"its radius, {_mm(r)} mm,"
    return f"the laser's kerf ({_mm(2 * r)} mm)", f"half of it, {_mm(r)} mm,"


def eaten_message(e: Eaten, width: float, router: bool) -> tuple[str, str]:
    """The warning's words and its hint for ``e`` (``width``: the tool's mm)."""
    r = width / 2
    tool, half = _words(r, router)
    sides = "each cut's side" if e.two_cuts else "the cut's side"
    stretch = f" over {e.length:.3g} mm of the cut" if e.length > 2 * r else ""
    what = "strip" if stretch else "bridge"
    where = f"near ({e.at[0]:.2f}, {e.at[1]:.2f})"
    if e.left <= 1e-9 * max(1.0, e.min_wall):
        said = (f"{tool} cuts away the {what} of `{e.part}` between through-cut `{e.cut}` and "
                f"{e.other}{stretch} {where}: {_mm(e.drawn)} mm as drawn, and the tool takes "
                f"{half} from {sides}: nothing is left there")
    else:
        said = (f"{tool} leaves {_mm(e.left)} mm of the {what} of `{e.part}` between "
                f"through-cut `{e.cut}` and {e.other}{stretch} {where}: {_mm(e.drawn)} mm as "
                f"drawn, less {half} on {sides}; thinner than the minimum wall "
                f"{e.min_wall:g} mm")
    if e.more:
        said += f" (and {e.more} more like it in `{e.part}`)"
    gap = (2 * r if e.two_cuts else r) + e.min_wall
    smaller = "a smaller tool (the profile's `tool_diameter`)" if router else \
        "a smaller kerf (`kerf` in the program, or --kerf)"
    meant = (f"; a bridge this thin, meant: a smaller `min_wall` in `{e.part}`"
             if e.left > 0 else "")
    hint = (f"keep `{e.cut}` at least {_mm(gap)} mm from {e.other} (the tool's reach plus the "
            f"minimum wall), or use {smaller}; if the cut is meant to go through, run it on to "
            f"meet it{meant}")
    return said, hint


def machine_warnings(drawing, cut, design, width, router: bool, sink, given=None,
                     apart: bool = False, relief: str = "none") -> None:
    """The warnings of cutting ``cut`` (what the machine gets; ``design``: as drawn) with a
    tool of ``width`` mm (a router's bit, ``router``; else a laser's kerf: mm or a dict part
    name -> mm) into ``sink``, located: W0510 for each part a router's bit cuts into more
    pieces than the design has (:func:`~..fabrication.bridges.router_bridges`, at the
    through-cut's structure), W0507 for the material beside the through-cuts the tool leaves
    thinner than the minimum wall (``given``: ``--min-wall``, else the program's) or cuts
    away (:func:`eaten_walls`, at the through-cut), the parts of a W0510 not said again.
    ``drawing``: the booleans' result (the spans, the minimum walls).  A router whose
    profile has ``relief`` ``none``: W0527 at each part with inside corners the bit does not
    reach (:func:`~...fabrication.reliefs.unreached`); with a relief, W0527 at each hole or
    outline with corners whose relief is not cut as asked (an acute corner, a wall the stroke
    would cut through or thin below the minimum: :func:`~...fabrication.reliefs.plan`, the
    relief strokes judged as the G-code runs them); W0531 for parts nearer each other than
    the tool is wide (:func:`.tool_gaps.tool_gap_warnings`)."""
    if router and width and relief == "none":
        _corners(drawing, cut, width, sink)
    elif router and width:
        _reliefs(drawing, cut, width, relief, sink)
    if width:                   # W0531: parts nearer each other than the tool is wide
        from .tool_gaps import tool_gap_warnings
        tool_gap_warnings(drawing, cut, (lambda n: width.get(n, 0.0)) if isinstance(width, dict)
                          else width, router, sink)
    if not width or not getattr(drawing, "through", ()):
        return
    split = _splits(drawing, design, width, sink) if router else set()
    spans = {th.geometry.label: th.geometry.span for th in drawing.through}
    for e in eaten_walls(cut, width, lambda n: part_min_wall(drawing, drawing.part_of.get(n),
                                                             given),
                         apart=apart, design=design):
        if e.part in split:
            continue
        w = width.get(e.part, 0.0) if isinstance(width, dict) else width
        said, hint = eaten_message(e, w, router)
        node = drawing.part_of.get(e.part)
        sink.warning("W0507", said, spans.get(e.cut) or (node.span if node else None),
                     hint=hint)


def _corners(drawing, cut, diameter: float, sink) -> None:
    """W0527 in ``sink`` for each part of ``cut`` with inside corners a router's bit of
    ``diameter`` mm leaves material in (no relief), at the part's structure."""
    from ...fabrication.reliefs import RELIEF_HINT, unreached, unreached_message
    for part, corners in unreached(cut, diameter / 2).items():
        node = drawing.part_of.get(part) if drawing is not None else None
        sink.warning("W0527", unreached_message(part, corners, diameter),
                     node.span if node is not None else None, hint=RELIEF_HINT)


def _reliefs(drawing, cut, diameter: float, relief: str, sink) -> None:
    """W0527 in ``sink`` for each loop of ``cut``'s parts with inside corners whose
    ``relief`` a router's bit of ``diameter`` mm does not cut as asked (the G-code's
    :func:`~...fabrication.reliefs.plan`, at the program's minimum wall), located at the
    hole (or the outline's shape) the corners are on."""
    from ...fabrication.layout import LayoutError, compensate
    from ...fabrication.reliefs import (NOT_RELIEVED_HINT, not_relieved, not_relieved_message,
                                        relieve)
    from ...part.part import Output
    part_of = getattr(drawing, "part_of", None) or {}
    for p in cut.parts:
        node = part_of.get(p.name)
        one = Output([p], [], cut.title, cut.drawing, cut.page)
        try:            # the corners the offset path reaches, as the G-code's (a part the
            tooled = compensate(one, diameter)      # tool does not fit is refused there)
        except LayoutError:
            continue
        _, _, plans = relieve(one, tooled, diameter / 2, relief,
                              part_min_wall(drawing, node))
        for ps in not_relieved(plans).values():
            span = _shape_at(drawing, node, ps[0].corner.at)
            sink.warning("W0527", not_relieved_message(ps, diameter),
                         span or (node.span if node is not None else None),
                         hint=NOT_RELIEVED_HINT)


def _shape_at(drawing, node, at) -> object:
    """The span of what drew point ``at`` (x, y mm) of part structure ``node``'s outline: the
    hole (or `cut`) structure whose shape's edge passes nearest it, else the part's own shape
    there (its statement); None when nothing lies within 1 mm."""
    if node is None:
        return None
    own = getattr(drawing, "own", None) or {}
    best, span = 1.0, None
    stack = [node, *getattr(node, "cut_by", ())]
    while stack:
        s = stack.pop()
        stack += [c for c in s.children.values() if c.kind in ("solid", "hole", "cut")]
        for g, face in own.get(s, ()):
            for poly in face.to_polygons():
                pts = np.asarray(poly, dtype=float)
                if len(pts) < 2:
                    continue
                a, b = pts, np.roll(pts, -1, axis=0)
                e = b - a
                L2 = np.maximum((e * e).sum(1), 1e-300)
                t = np.clip(((np.asarray(at) - a) * e).sum(1) / L2, 0.0, 1.0)
                d = float(np.hypot(*(a + t[:, None] * e - np.asarray(at)).T).min())
                if d < best:
                    best = d
                    span = s.span if s.kind in ("hole", "cut") and s.span is not None \
                        else (getattr(g, "span", None) or s.span)
    return span


def _splits(drawing, output, diameter: float, sink) -> set:
    """W0510 in ``sink`` for each part of ``output`` (the design) that a router's bit of
    ``diameter`` mm cuts into more pieces than the design has (through-cuts nearer the
    part's edges, holes or each other than the bit's reach), located at the through-cut's
    structure (else the part's); the names of those parts whose warning names a bridge."""
    from ...fabrication.bridges import router_bridges, split_message
    _, splits = router_bridges(output, diameter)
    for sp in splits:
        node = drawing.part_of.get(sp.part)
        if node is None:
            continue
        path = sp.bridges[0].cut if sp.bridges else (sp.cuts or [""])[0]
        rest = path[len(sp.part) + 1:].split(".") if path.startswith(sp.part + ".") else []
        for name in rest:
            child = node.children.get(name) if hasattr(node, "children") else None
            if child is None:
                break
            node = child
        sink.warning("W0510", split_message(sp, diameter), node.span,
                     hint="the design (`aidl check`, `aidl parts`) has one piece; the bit "
                          "cuts the through-cut as wide as itself, round past its ends")
    return {sp.part for sp in splits if sp.bridges}     # else W0507 names the bridges


__all__ = ["Eaten", "eaten_walls", "eaten_message", "machine_warnings"]
