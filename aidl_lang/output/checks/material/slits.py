"""``W0519``, the dual of a thin wall for empty space: a slit narrower than ``min_wall``
between two shapes of one outline, by a gap search between its edges (:func:`_check_slits`):
pairs of an outline's vertices and segments that face each other (:data:`FACING`) closer than
the minimum, grouped by cells of half of it (:func:`_clusters`), each group named by the faces
it lies between (:func:`_faces_at`, also W0520's); loops no pair can come from are left out of
the search (:func:`_lone_circles`).  The fix where a slit's sides meet is :mod:`.nicks`'.
"""
from __future__ import annotations

import math

import numpy as np

from ....base.diagnostics import DiagnosticSink, Label
from ....geometry.core.model import Structure
from ...part.build.booleans import Drawing
from ...part.measure.nearby import _median, box_pairs
from ...part.measure.nearby import components as _components
from ..common import _cut_openings, _solids_within, below
from ..marks.engravings import _copy_label
from .nicks import slit_fix
from .walls import _facing, _ring
FACING = 0.866     # cos 30 deg: two stretches of the outline face each other across a slit
                   # when their directions are opposite within 30 degrees (a V-notch sharper
                   # than 30 degrees; a square inner corner's sides are at 90 and do not count)


def _lone_circles(loops: list, t: float) -> np.ndarray:
    """Which of ``loops`` (each k x 2, mm) hold no pair of W0519's search at width ``t`` (mm),
    so that the search may leave them out: a round hole's or disc's chords (a convex loop
    whose vertices lie on one circle about their mean, within 1e-6 of its radius) farther
    than ``t`` from every other loop and too wide to face itself within ``t``.

    A vertex of such a loop faces one of its own edges only across the loop: the edge's
    normal is turned at least 180 - 30 - ``h`` degrees from the vertex's radius (30: the
    facing angle, :data:`FACING`; ``h``: half the widest edge's angle at the centre), so the
    vertex lies at least ``r_in + r_min * cos(30 deg + h)`` from it (``r_in``: the least
    distance from the centre to an edge's line; ``r_min``: the least radius).  Another loop
    is within ``t`` of it only when the centre is within ``r + t`` of one of that loop's
    edges (the circles' boxes grown by ``t / 2``, :func:`.nearby.box_pairs`, and
    :func:`.nearby.close_pairs` against the other loops' edges, each O(n log n)).  A
    perforated sheet's 50,000 holes: none searched, 2.2 million vertices fewer.  Inputs
    the search takes quickly anyway (up to :data:`.nearby.SMALL_VERTS` vertices) and
    crowds of circles (more than 8 close pairs a circle) are left as they are."""
    from ...part.measure.nearby import SMALL_VERTS, TooManyPairs, close_pairs
    n = len(loops)
    drop = np.zeros(n, dtype=bool)
    sizes = np.array([len(P) for P in loops], dtype=np.int64)
    if not n or int(sizes.sum()) <= SMALL_VERTS:
        return drop
    V, nxt, _ = _ring(loops)
    starts = np.cumsum(sizes) - sizes
    of = np.repeat(np.arange(n), sizes)
    M = np.add.reduceat(V, starts) / sizes[:, None]
    D = V - M.take(of, axis=0)
    R = np.hypot(D[:, 0], D[:, 1])
    rmax, rmin = np.maximum.reduceat(R, starts), np.minimum.reduceat(R, starts)
    E = V.take(nxt, axis=0) - V                 # each vertex's edge, and the next edge
    En = E.take(nxt, axis=0)
    L = np.hypot(E[:, 0], E[:, 1])
    rin = np.minimum.reduceat(np.abs(E[:, 0] * D[:, 1] - E[:, 1] * D[:, 0])
                              / np.maximum(L, 1e-300), starts)
    turn = E[:, 0] * En[:, 1] - E[:, 1] * En[:, 0]
    convex = (np.minimum.reduceat(turn, starts) > 0) | (np.maximum.reduceat(turn, starts) < 0)
    h = np.arcsin(np.minimum(1.0, np.maximum.reduceat(L, starts) / np.maximum(2 * rmax, 1e-300)))
    own = rin + rmin * np.cos(np.arccos(FACING) + h)
    cand = (sizes >= 8) & convex & (rmax - rmin <= 1e-6 * np.maximum(rmax, 1.0)) & (own > t)
    idx = np.flatnonzero(cand)
    if not len(idx):
        return drop
    idx = idx[rmax[idx] <= 4 * _median(rmax[idx])]     # a few large ones: searched as before
    C, r = M[idx], rmax[idx]
    pairs = box_pairs(np.column_stack([C - r[:, None], C + r[:, None]]), t / 2)
    if len(pairs) > 8 * len(idx):
        return drop
    near = np.zeros(len(idx), dtype=bool)
    gap = np.hypot(*(C[pairs[:, 0]] - C[pairs[:, 1]]).T) - r[pairs[:, 0]] - r[pairs[:, 1]]
    near[pairs[gap <= t].ravel()] = True
    other = np.ones(n, dtype=bool)
    other[idx] = False
    seg = np.flatnonzero(other[of])
    if len(seg):
        try:
            v, _, dist, _ = close_pairs(C, n + np.arange(len(idx)), V.take(seg, axis=0),
                                        V.take(nxt[seg], axis=0), of[seg], float(r.max()) + t)
        except TooManyPairs:
            return drop
        near[v[dist <= r[v] + t]] = True
    drop[idx[~near]] = True
    return drop


CUSP_OPEN = math.radians(10)    # an inside corner opening by less: a cusp's floor (its sides
                                # searched densely); a wider V-nick is searched as before
MAX_DENSE = 64                  # points added along each side of one cusp


def _dense(loops: list, t: float) -> tuple:
    """``loops`` (each k x 2, mm; counter-clockwise outside, clockwise around openings) with
    points added every ``t / 4`` along the two edges of each cusp's floor: an inside corner
    whose sides open by less than :data:`CUSP_OPEN`, where one side leaves the other nearly
    along its tangent (a blade's straight root beside a handle's R6 corner: under 0.5 mm
    for 2.2 mm, issue 111's run z4 letter opener) and the vertex-to-edge search saw nothing,
    the sides' only vertices being the floor they share and their far ends.  Out to where
    the gap is ``t`` wide and ``t`` beyond, at most :data:`MAX_DENSE` a side.  Returns the
    loops and, for each of their vertices (:func:`.walls._ring`'s order), the edge of the
    given loops it lies on (the index of its first vertex) and whether it is one of theirs.
    (Dense points everywhere also made every V-nick between two petals a slit: 16 on one
    sunflower, whose V's a laser cuts as drawn.)"""
    out, edge, orig, base = [], [], [], 0
    for P in loops:
        n = len(P)
        E = np.roll(P, -1, axis=0) - P               # edge k: P[k] -> P[k + 1]
        Ein = np.roll(E, 1, axis=0)
        L = np.hypot(E[:, 0], E[:, 1])
        Lin = np.roll(L, 1)
        cross = Ein[:, 0] * E[:, 1] - Ein[:, 1] * E[:, 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            cos = np.einsum("ij,ij->i", Ein, E) / np.maximum(L * Lin, 1e-300)
        cusp = np.flatnonzero((cross <= 0) & (cos < -math.cos(CUSP_OPEN)) & (L > 0) & (Lin > 0))
        extra: dict = {}
        for k in cusp.tolist():
            half = 0.5 * math.acos(min(1.0, max(-1.0, -float(cos[k]))))
            reach = t / (2 * max(math.tan(half), 1e-9)) + t
            for e, from_end in ((k, False), ((k - 1) % n, True)):
                ds = np.arange(t / 4, min(reach, float(L[e]) - t / 8), t / 4)[:MAX_DENSE]
                if len(ds):
                    u = E[e] / L[e]
                    q = (P[e] + u * (L[e] - ds)[:, None]) if from_end else P[e] + u * ds[:, None]
                    extra.setdefault(e, []).append(q)
        # each edge's added points after its first vertex, in order along it (one insert)
        at, Q, on = [], [], []
        for e in sorted(extra):
            q = np.concatenate(extra[e])
            q = q[np.argsort(np.einsum("ij,j->i", q - P[e], E[e]))]
            at += [e + 1] * len(q)
            Q.append(q)
            on += [e] * len(q)
        if Q:
            out.append(np.insert(P, at, np.concatenate(Q), axis=0))
            edge.append(np.insert(np.arange(n), at, on) + base)
            orig.append(np.insert(np.ones(n, dtype=bool), at, False))
        else:                                        # no cusp: the loop as it is
            out.append(P)
            edge.append(np.arange(n) + base)
            orig.append(np.ones(n, dtype=bool))
        base += n
    return out, np.concatenate(edge), np.concatenate(orig)


def _check_slits(d: Drawing, s: Structure, loops, cuts, t: float, sink: DiagnosticSink,
                 tick=lambda ahead=0.0: None, cut_open=None) -> None:
    """W0519 for part ``s`` (its final shape's ``loops``, counter-clockwise outside,
    clockwise around openings) at minimum width ``t`` mm: a slit of EMPTY space narrower than
    ``t`` that reaches into the part, the dual of W0507's thin wall (two lobes of one outline
    that almost meet: a dog-bone tag whose end circles nearly touch beyond the bar).

    Found as a gap search between the non-adjacent edges of one loop
    (:func:`.nearby.close_pairs_facing`, every vertex against the segments within ``t``
    that run against one of its tangents, O(n log n)):
    a pair counts when the two stretches face each other (the vertex's tangent and the
    segment's direction are opposite within 30 degrees, :data:`FACING`) and the middle of the
    gap lies outside the material.  The loops of holes' openings are left out (a hole drawn
    narrow is declared so).  Close pairs are grouped by place; a group whose span along the
    slit is at least ``t`` and whose sides are edges of two different shapes (a cusp drawn in
    one Bezier, a V-notch of one polygon, is meant) is reported: its least width, its
    length, its place and the two shapes (:func:`_faces_at`, at the slit's mouth).
    ``cut_open``: :func:`.common._cut_openings` of ``loops``, when the caller has it."""
    from ...part.measure.nearby import close_pairs_facing
    from ..common import SHOWN, _edges, _inside, _say_few, written
    if t <= 0 or not loops:
        return
    if cut_open is None:
        cut_open = _cut_openings(loops, cuts)
    keep = [np.asarray(P, dtype=float) for P, opening in zip(loops, cut_open)
            if len(P) >= 3 and not opening]      # not an opening a hole cuts
    lone = _lone_circles(keep, t)
    keep = [P for P, out in zip(keep, lone) if not out]
    if not keep:
        return
    _, _, oprv = _ring(keep)                  # the given loops' own order
    keep, edge_of, given = _dense(keep, t)
    tick()
    V, nxt, prv = _ring(keep)
    v, sg, dist, foot = close_pairs_facing(V, nxt, prv, t, FACING)
    if not len(v):
        return
    # a vertex and an edge next to it on the given loops are no slit's two sides: a vertex
    # added on an edge against that edge, a given vertex against an edge it ends
    es, ev = edge_of[sg], edge_of[v]
    beside = np.where(given[v], (es == ev) | (es == oprv[ev]), es == ev)
    ok = (v != nxt[sg]) & ~beside & (dist > 1e-6) & _facing(V, nxt, prv, v, sg, FACING)
    v, sg, dist, foot = v[ok], sg[ok], dist[ok], foot[ok]
    if not len(v):
        return
    mid = (V[v] + foot) / 2
    # the middle of the gap, and 1 um to either side across it (a slit's floor can be an
    # edge of the outline that the gap runs along: its middle lies on the outline itself)
    across = (foot - V[v])[:, ::-1] * np.array([1.0, -1.0])
    across *= 1e-3 / np.maximum(np.hypot(*across.T), 1e-300)[:, None]
    edges = _edges(loops)
    empty = ~_inside(mid, edges, tick)    # and where the middle is inside, either side
    full = np.flatnonzero(~empty)
    empty[full] = ~(_inside(mid[full] + across[full], edges, tick)
                    & _inside(mid[full] - across[full], edges, tick))
    v, sg, dist, foot, mid = v[empty], sg[empty], dist[empty], foot[empty], mid[empty]
    if not len(v):
        return
    tick()
    label = _clusters(mid, t)
    # the groups in the order of their least point, each group's points in order (one sort)
    order = np.argsort(label, kind="stable")
    cut = np.flatnonzero(np.r_[True, label[order][1:] != label[order][:-1]])
    lo, hi = np.minimum.reduceat(mid[order], cut), np.maximum.reduceat(mid[order], cut)
    long = np.flatnonzero(np.max(hi - lo, axis=1) >= t)
    groups = [(order[cut[i]:cut[i + 1] if i + 1 < len(cut) else len(order)],
               float(np.max(hi[i] - lo[i]))) for i in long]
    # the sides are named at each slit's mouth (its widest pair), clear of a floor that
    # another shape may make
    mouth = np.array([k[int(np.argmax(dist[k]))] for k, _ in groups], dtype=np.intp)
    faces = _faces_at(d, s, np.concatenate([V[v[mouth]], foot[mouth]]), tick) \
        if len(groups) else []
    corners: dict = {}                  # the part's nick corners, found once (slit_fix)
    discs: dict = {}                    # the part's Circles' (cx, cy, r), found once
    said: list = []                     # the slits found, said by _say_few
    for i, (k, length) in enumerate(groups):
        tick()
        b = k[int(np.argmin(dist[k]))]
        w = float(dist[b])
        p, q = V[v[b]], foot[b]
        fp, fq = faces[i], faces[len(groups) + i]
        if fp is None or fq is None or fp is fq:
            continue            # a notch drawn in one shape (a heart's cusp) is meant
        if _touching_discs(d, s, fp, fq, discs):
            continue            # the V between two discs that touch: a scalloped edge
        names = [f"`{_copy_label(f)}`" for f in (fp, fq) if f is not None]   # a loop's: [k]
        names = list(dict.fromkeys(names))
        later = max((f for f in (fp, fq) if f is not None and f.span is not None),
                    key=lambda f: (f.span.line, f.span.col), default=None)
        other = next((f for f in (fp, fq) if f is not None and f is not later
                      and f.span is not None), None)
        labels = [Label(other.span, "the other side of the slit", primary=False)] \
            if other is not None else []
        between = " and ".join(names)
        # where the program writes it, not where a layout relation moved the part (run fn:
        # a toy camera's nicks given at its place on the laid-out sheet)
        cx, cy = written(s, *((p + q) / 2))
        fix = slit_fix(d, s, (p + q) / 2, w, t, names, corners, length) \
            if len(said) < SHOWN else ""
        insets = {f.data.get("distance") for f in (fp, fq) if f.kind == "Offset"}
        if fp.kind == fq.kind == "Offset" and len(insets) == 1 and insets.pop() < 0:
            # run gb: two lobes of a heart, each inset 0.5, part at the point (a V slit 4 mm
            # long); the nick's Fillet filled only its narrow end and the V stayed
            k = -fp.data["distance"]
            fix = (f"{names[0]} and {names[-1]} are inset one by one, and two insets part "
                   f"where their shapes meet: inset the shapes as one, "
                   f"`Inset([SHAPE1, SHAPE2], {k:g} mm)` (the inset of their union: one "
                   f"outline, no slit), the shapes those two inset")
        said.append((f"a slit of empty space between {between} in `{s.path}` is "
                     f"{below(w, t)} mm wide, narrower than {t:g} mm (over {length:.1f} mm, near "
                     f"({cx:.1f}, {cy:.1f})): narrower than a laser or router cuts, so it comes "
                     "out as a ragged notch or not at all",
                     later.span if later is not None else s.span,
                     {"labels": labels, "hint": f"{fix}; the minimum is set with --min-wall"}))
    _say_few(sink, "W0519", s.path, said)


TANGENT = 1e-6        # mm: two circles whose centres are this near r1 + r2 apart touch


def _touching_discs(d: Drawing, s: Structure, fp, fq, discs: dict) -> bool:
    """True when ``fp`` and ``fq`` are Circles of part ``s`` that touch from outside (their
    centres ``r1 + r2`` apart within :data:`TANGENT`): the only slit between them is the V
    where the two discs meet, a scalloped edge or a row of beads drawn so on purpose, cut as a notch
    whose floor the kerf rounds (run ec's treat-bag header: 11 tangent circles along each
    edge, 20 cusps warned "a ragged notch or not at all", and a hint to square the corner).
    ``discs`` keeps each Circle's ``(cx, cy, r)`` from its face
    (:func:`.holes.contact.circle_of`) for the part's other slits."""
    from ..holes.contact import circle_of
    if fp.kind != "Circle" or fq.kind != "Circle":
        return False
    if not discs:
        for _, fs in _solids_within(d, s):
            for g, f in fs:
                if g.kind == "Circle" and f is not None and not f.is_empty():
                    P = f.to_polygons()
                    discs[id(g)] = circle_of(np.asarray(P[0], dtype=float)) if len(P) == 1 \
                        else None
    a, b = discs.get(id(fp)), discs.get(id(fq))
    if a is None or b is None:
        return False
    return abs(math.hypot(a[0] - b[0], a[1] - b[1]) - (a[2] + b[2])) <= TANGENT


def _faces_at(d: Drawing, s: Structure, points, tick=lambda: None) -> list:
    """For each of ``points`` (n x 2, mm), the geometry of part ``s``'s solids
    (:attr:`Drawing.own`) whose outline passes nearest to it (a point on the part's outline
    lies on some face's edge), or None; by one search of the
    faces' edges near the points (:func:`.nearby.close_pairs`, O((n + edges) log)): within a
    radius that doubles from 1 nm until every point has an edge, or has none within the
    part's box; the least distance wins, the first face in :attr:`Drawing.own`'s order on a tie
    (tests/test_checks_bounded.py holds the per-face loop it replaced, as its reference)."""
    from ...part.measure.nearby import close_pairs
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    A, Bq, poly, names = [], [], [], []     # the edges, their face (its number in order)
    for st, fs in _solids_within(d, s):
        for g, f in fs:
            if f is None or f.is_empty():
                continue
            for P in f.to_polygons():
                P = np.asarray(P, dtype=float).reshape(-1, 2)
                if len(P):
                    A.append(P)
                    Bq.append(np.roll(P, -1, axis=0))
                    poly.append(np.full(len(P), len(names), dtype=np.intp))
            names.append(g)
    out: list = [None] * len(points)
    if not A or not len(points):
        return out
    A, Bq, face = np.concatenate(A), np.concatenate(Bq), np.concatenate(poly)
    span = float(np.max(np.concatenate([A, points]).max(axis=0)
                        - np.concatenate([A, points]).min(axis=0)))
    todo = np.arange(len(points))
    radius = 1e-6
    while len(todo):
        tick()
        q, e, _dist, _foot = close_pairs(points[todo], np.full(len(todo), -1), A, Bq,
                                         np.zeros(len(A), dtype=np.intp), radius)
        if len(q):
            p = points[todo[q]]
            a, dd = A[e], Bq[e] - A[e]
            L2 = np.einsum("ij,ij->i", dd, dd)
            with np.errstate(divide="ignore", invalid="ignore"):
                u = np.clip(np.where(L2 > 0, np.einsum("ij,ij->i", p - a, dd) / L2, 0.0),
                            0.0, 1.0)
            e2 = a + u[:, None] * dd - p
            dm = np.einsum("ij,ij->i", e2, e2)
            best = np.lexsort((face[e], dm, q))
            first = best[np.r_[True, q[best][1:] != q[best][:-1]]]
            for k in first:
                out[todo[q[k]]] = names[face[e[k]]]
            found = np.zeros(len(todo), dtype=bool)
            found[q] = True
            todo = todo[~found]
        if radius > 2 * span + 1:
            break
        radius *= 8
    return out


def _clusters(points: np.ndarray, r: float) -> np.ndarray:
    """A label per point (n x 2, mm): points at most ``r`` apart in x and in y (their boxes
    grown by ``r / 2`` overlap) share one, transitively; the label is the least index of the
    points that share it.

    O(n log n) whatever the points, never listing the pairs (a map of the USA drawn 30 mm
    wide: 12,000 points all within 0.5 mm of hundreds of others, 5 GB of pairs): the points
    go into square cells of side ``r / 2`` (all points of a cell, and of two cells that touch,
    are closer than ``r``: one group); two cells two apart are joined when their points' x
    (or y) ranges come within ``r`` (rows one apart are within ``r`` in y), and two cells
    two apart diagonally when some pair is within ``r`` in both (a dominance test: the
    greatest y among the points past each x, by binary search).  The cells' groups come
    from :func:`_components` (no SciPy, whose import a cold ``aidl check`` avoids)."""
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    n = len(P)
    if n < 2:
        return np.arange(n)
    s = r / 2
    ij = np.floor((P - P.min(axis=0)) / s).astype(np.int64)
    order = np.lexsort((ij[:, 1], ij[:, 0]))
    cij = ij[order]
    first = np.r_[True, np.any(cij[1:] != cij[:-1], axis=1)]
    start = np.flatnonzero(first)
    cell_of = np.empty(n, dtype=np.intp)
    cell_of[order] = np.cumsum(first) - 1
    C = cij[start]                            # the occupied cells (i, j), sorted
    m = len(C)
    Ps = P[order]
    lo = np.minimum.reduceat(Ps, start)
    hi = np.maximum.reduceat(Ps, start)
    # a cell's key: the rank of its column among the occupied ones, then its row
    cols = C[np.r_[True, C[1:, 0] != C[:-1, 0]], 0]    # sorted: np.unique imports numpy.ma
    rows = int(C[:, 1].max()) + 5
    key = np.searchsorted(cols, C[:, 0]) * rows + (C[:, 1] + 2)

    def find(di, dj):
        """(a, b): the cells a whose cell (i + di, j + dj) is occupied, b that cell."""
        c = C[:, 0] + di
        k = np.minimum(np.searchsorted(cols, c), len(cols) - 1)
        want = k * rows + C[:, 1] + dj + 2
        at = np.minimum(np.searchsorted(key, want), m - 1)
        ok = (cols[k] == c) & (key[at] == want)
        return np.flatnonzero(ok), at[ok]

    def near(b, a, axis):
        # the boxes' test (grown by r / 2 each: the same rounding at the boundary)
        return lo[b, axis] - s <= hi[a, axis] + s

    ea, eb, diag = [], [], []
    for di, dj in ((0, 1), (0, 2), (1, -2), (1, -1), (1, 0), (1, 1), (1, 2),
                   (2, -2), (2, -1), (2, 0), (2, 1), (2, 2)):
        a, b = find(di, dj)
        if not len(a):
            continue
        if di == 2 and abs(dj) == 2:
            diag.append((a, b, dj))
            continue
        if di == 2:
            ok = near(b, a, 0)
        elif dj == 2:
            ok = near(b, a, 1)
        elif dj == -2:
            ok = near(a, b, 1)
        else:
            ok = slice(None)
        ea.append(a[ok])
        eb.append(b[ok])
    root = _components(m, ea, eb)
    more_a, more_b = [], []
    for a, b, dj in diag:       # only the pairs not joined yet whose ranges come within r
        sy = 1.0 if dj > 0 else -1.0
        ok = (root[a] != root[b]) & near(b, a, 0) & (near(b, a, 1) if dj > 0 else
                                                     near(a, b, 1))
        for x, y in zip(a[ok], b[ok]):
            pa = Ps[start[x]:start[x + 1] if x + 1 < m else n]
            pb = Ps[start[y]:start[y + 1] if y + 1 < m else n]
            k = np.argsort(pa[:, 0] + s, kind="stable")
            xa = pa[k, 0] + s
            best = np.maximum.accumulate((sy * pa[k, 1] + s)[::-1])[::-1]   # greatest y past x
            at = np.searchsorted(xa, pb[:, 0] - s, side="left")
            got = at < len(xa)
            if np.any(best[at[got]] >= sy * pb[got, 1] - s):
                more_a.append(np.array([x]))
                more_b.append(np.array([y]))
    if more_a:
        root = _components(m, ea + more_a, eb + more_b)
    comp = root[cell_of]
    least = np.full(m, n, dtype=np.intp)
    np.minimum.at(least, comp, np.arange(n))
    return least[comp]
