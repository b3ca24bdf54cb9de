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
from dataclasses import dataclass

import numpy as np

from ...geometry.curves import carrier, distance_to, sample_xy
from ..part.nearby import box_pairs_between, close_pairs

TOUCH = 1e-6        # mm: a through-cut this near a loop or another cut meets it in the design
SHOWN = 5           # warnings per part; the rest are counted in the last one


@dataclass(frozen=True)
class Eaten:
    """Material of part ``part`` between through-cut ``cut`` (its label) and ``other``
    (words: ``the outer edge of `p```, ``hole `p.h```, ``through-cut `p.s.b```): ``drawn``
    mm wide in the design, ``left`` mm once the tool has cut (0 or less: cut through),
    nearest at ``at`` (x, y mm, the middle of what is left there); over ``length`` mm of the
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


class _Paths:
    """The chords of some exact paths: ``A``, ``B`` (n x 2) each chord's ends, ``F`` its
    path's index, ``C`` its segment's carrier; ``V`` (m x 2) the vertices (every chord's
    start and each open path's end), ``VF`` their path's index."""

    def __init__(self, paths: list, closed: list, first: int = 0):
        A, B, F, C, V, VF = [], [], [], [], [], []
        for k, (segs, shut) in enumerate(zip(paths, closed), first):
            for seg in segs:
                xs, ys = [], []
                sample_xy([seg], xs, ys)
                end = getattr(seg, "end", None)         # a whole circle: back to its start
                xs.append(end[0] if end is not None else xs[0])
                ys.append(end[1] if end is not None else ys[0])
                P = np.column_stack([xs, ys])
                A.append(P[:-1])
                B.append(P[1:])
                F.append(np.full(len(P) - 1, k))
                C += [carrier(seg)] * (len(P) - 1)
                V.append(P[:-1])
                VF.append(np.full(len(P) - 1, k))
            if not shut and segs and getattr(segs[-1], "end", None) is not None:
                V.append(np.asarray([segs[-1].end], dtype=float))
                VF.append(np.asarray([k]))
        z2, zi = np.zeros((0, 2)), np.zeros(0, dtype=np.intp)
        self.A = np.concatenate(A) if A else z2
        self.B = np.concatenate(B) if B else z2
        self.F = np.concatenate(F).astype(np.intp) if F else zi
        self.C = C
        self.V = np.concatenate(V) if V else z2
        self.VF = np.concatenate(VF).astype(np.intp) if VF else zi


def _exact(dist, foot, A, B, C, P) -> np.ndarray:
    """``dist`` (from points ``P`` to chords ``A``-``B`` with feet ``foot``) made exact
    where the foot lies inside a chord of a circle (the point's distance to the circle)."""
    out = np.array(dist, dtype=float)
    if not len(out):
        return out
    e = B - A
    L2 = np.einsum("ij,ij->i", e, e)
    u = np.einsum("ij,ij->i", foot - A, e) / np.where(L2 > 0, L2, 1.0)
    for q in np.flatnonzero((u > 1e-9) & (u < 1 - 1e-9)):
        c = C[q]
        if c[0] == "C":
            out[q] = distance_to(c, tuple(P[q]))
    return out


def _crossing(P: _Paths, Q: _Paths) -> np.ndarray:
    """The pairs (path of ``P``, path of ``Q``) some chords of which cross (k x 2)."""
    if not len(P.A) or not len(Q.A):
        return np.zeros((0, 2), dtype=np.intp)
    pb = np.hstack([np.minimum(P.A, P.B), np.maximum(P.A, P.B)])
    qb = np.hstack([np.minimum(Q.A, Q.B), np.maximum(Q.A, Q.B)])
    ij = box_pairs_between(pb, qb, TOUCH)
    if not len(ij):
        return np.zeros((0, 2), dtype=np.intp)
    i, j = ij[:, 0], ij[:, 1]
    a, b, c, d = P.A[i], P.B[i], Q.A[j], Q.B[j]

    def orient(p, q, r):
        return (q[:, 0] - p[:, 0]) * (r[:, 1] - p[:, 1]) - (q[:, 1] - p[:, 1]) * (r[:, 0] - p[:, 0])
    hit = (orient(a, b, c) * orient(a, b, d) <= 0) & (orient(c, d, a) * orient(c, d, b) <= 0)
    return np.unique(np.column_stack([P.F[i[hit]], Q.F[j[hit]]]), axis=0)


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
    """Each through-cut's chain (the cuts that meet, joined): a root index per cut."""
    root = list(range(m))

    def find(i):
        while root[i] != i:
            root[i] = root[root[i]]
            i = root[i]
        return i
    for a, b in meet:
        if b < m:
            root[find(a)] = find(b)
    return [find(i) for i in range(m)]


def _tooled(output, width, apart: bool) -> dict:
    """Part name -> its loops as the machine cuts them (offset by half of ``width``: mm, or a
    dict part name -> mm), for the parts with through-cuts; a part whose offset fails (a
    feature smaller than the tool: the writer refuses it) is left out."""
    from ..fabrication.layout import LayoutError, compensate
    names = {st.part for st in output.cuts if st.part}
    w = {n: (width.get(n, 0.0) if isinstance(width, dict) else width) for n in names}
    w = {n: k for n, k in w.items() if k}
    if not w:
        return {}
    try:
        done = compensate(output, w, apart=apart)
        return {p.name: p.loops for p in done.parts if p.name in w}
    except LayoutError:
        pass
    out = {}
    for n, k in w.items():
        try:
            done = compensate(output, {n: k}, apart=apart)
        except LayoutError:
            continue
        out.update({p.name: p.loops for p in done.parts if p.name == n})
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
        found = _part(p, drawn_parts.get(p.name, p), strokes, tooled[p.name], w / 2,
                      min_wall_of(p.name))
        found.sort(key=lambda e: e.left)
        if len(found) > SHOWN:
            last = found[SHOWN - 1]
            found = found[:SHOWN - 1] + [Eaten(**{**last.__dict__, "more": len(found) - SHOWN})]
        out += found
    return out


def _loop_name(part: str, lp) -> str:
    return f"a hole of `{part}`" if lp.is_hole else f"the outer edge of `{part}`"


def _part(p, drawn, strokes: list, loops: list, r: float, t: float) -> list[Eaten]:
    """:func:`eaten_walls` for one part ``p`` (``drawn``: as in the design) with through-cuts
    ``strokes``, its tool-path ``loops`` and a tool of radius ``r``, minimum wall ``t``."""
    m = len(strokes)
    slits = _Paths([st.segments for st in strokes], [st.closed for st in strokes])
    design = _Paths([st.segments for st in strokes] + [lp.segments for lp in drawn.loops],
                    [st.closed for st in strokes] + [True] * len(drawn.loops))
    meet, touching = _meets(slits, design, m)
    chain = np.asarray(_chains(meet, m), dtype=np.intp)
    path = _Paths([lp.segments for lp in loops], [True] * len(loops), first=m)
    meets_loop = {(int(chain[a]), b) for a, b in meet if b >= m}
    reach = 2 * r + max(t, 0.0) + 1e-6
    found: dict = {}        # (kind, cut, other) -> [left, at, point on the cut, vertices]

    def note(key, left, at, on_cut, vi):
        got = found.setdefault(key, [math.inf, None, None, set()])
        if left < got[0]:
            got[0], got[1], got[2] = left, at, on_cut
        if vi is not None:
            got[3].add(vi)
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
    dist = _exact(dist, ft, A[s], B[s], [C[k] for k in s], slits.V[v])
    ends = _free_ends(slits, strokes, touching)
    for q in np.flatnonzero(dist - 2 * r < max(t, tol)):
        vi, k = int(v[q]), int(s[q])
        i, o = int(slits.VF[vi]), int(SF[k])
        if o >= m and (int(chain[i]), o) in meets_loop and not _ahead(ends, vi, ft[q],
                                                                      slits.V[vi]):
            continue
        left = float(dist[q]) - 2 * r
        if thin(left):
            key = ("cut", min(i, o), max(i, o)) if o < m else ("loop", i, o)
            note(key, left, (slits.V[vi] + ft[q]) / 2, slits.V[vi], vi)
    # the loops' vertices against the cuts' chords (a hole's corner beside a long slit)
    v, s, dist, ft = close_pairs(path.V, path.VF, slits.A, slits.B, chain[slits.F], reach)
    dist = _exact(dist, ft, slits.A[s], slits.B[s], [slits.C[k] for k in s], path.V[v])
    for q in np.flatnonzero(dist - 2 * r < max(t, tol)):
        i, o = int(slits.F[s[q]]), int(path.VF[v[q]])
        if (int(chain[i]), o) in meets_loop:
            continue
        left = float(dist[q]) - 2 * r
        if thin(left):
            note(("loop", i, o), left, (path.V[v[q]] + ft[q]) / 2, ft[q], None)
    said = (_said(p, drawn, strokes, slits, key, got, r, t, m,
                  path if key[0] == "loop" else slits) for key, got in found.items())
    return [e for e in said if e is not None]


def _free_ends(slits: _Paths, strokes: list, touching: np.ndarray) -> dict:
    """Vertex index -> the direction out of its cut, for each end of an open cut that
    touches nothing in the design (a free end, inside the material)."""
    out = {}
    for i, st in enumerate(strokes):
        if st.closed:
            continue
        idx = np.flatnonzero(slits.VF == i)
        if len(idx) < 2:
            continue
        a, b = int(idx[0]), int(idx[-1])
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


def _said(p, drawn, strokes, slits: _Paths, key, got, r, t, m, others: _Paths) -> Eaten | None:
    """The :class:`Eaten` of one pair (``key``: ("cut", i, j) or ("loop", i, loop), the
    other path's chords among ``others``); None when it is as thin as drawn (the design's
    W0507 says it)."""
    left, at, on_cut, hits = got
    kind, i, o = key
    if kind == "cut":
        drawn_w = left + 2 * r
        other = f"through-cut `{strokes[o].source}`"
    else:
        lp = drawn.loops[o - m] if o - m < len(drawn.loops) else None
        drawn_w = _distance_to_loop(on_cut, lp) if lp is not None else left + r
        other = _loop_name(p.name, lp) if lp is not None else f"an edge of `{p.name}`"
    if t > 0 and drawn_w < t - 1e-9 * max(1.0, t):
        return None
    length = 0.0
    if len(hits) > 1:           # the chords of the cut thin at both ends and in the middle
        k = np.flatnonzero(slits.F == i)
        ok = np.isin(slits.A[k], slits.V[list(hits)]).all(1) & \
            np.isin(slits.B[k], slits.V[list(hits)]).all(1)
        k = k[ok]
        if len(k):
            mid = (slits.A[k] + slits.B[k]) / 2
            sel = others.F == o
            gone = _least(mid, others.A[sel], others.B[sel]) - 2 * r < max(t, 1e-9)
            length = float(np.hypot(*(slits.B[k] - slits.A[k])[gone].T).sum())
    return Eaten(p.name, strokes[i].source or "a through-cut", other, float(drawn_w),
                 float(left), (float(at[0]), float(at[1])), length, t)


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


def _distance_to_loop(P, lp) -> float:
    """The least distance from point ``P`` to loop ``lp`` (exact on lines and circles)."""
    L = _Paths([lp.segments], [True])
    e = L.B - L.A
    L2 = np.einsum("ij,ij->i", e, e)
    u = np.clip(np.einsum("ij,ij->i", np.asarray(P)[None] - L.A, e) / np.where(L2 > 0, L2, 1.0),
                0.0, 1.0)
    foot = L.A + u[:, None] * e
    d = np.hypot(*(np.asarray(P)[None] - foot).T)
    k = int(np.argmin(d))
    return float(_exact(d[k:k + 1], foot[k:k + 1], L.A[k:k + 1], L.B[k:k + 1], [L.C[k]],
                        np.asarray([P]))[0])


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
    sides = "each cut's side" if e.other.startswith("through-cut") else "the cut's side"
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
    gap = (2 * r if sides == "each cut's side" else r) + e.min_wall
    smaller = "a smaller tool (the profile's `tool_diameter`)" if router else \
        "a smaller kerf (`kerf` in the program, or --kerf)"
    hint = (f"keep `{e.cut}` at least {_mm(gap)} mm from {e.other} (the tool's reach plus the "
            f"minimum wall), or use {smaller}; if the cut is meant to go through, run it on to "
            "meet it")
    return said, hint


__all__ = ["Eaten", "eaten_walls", "eaten_message"]
