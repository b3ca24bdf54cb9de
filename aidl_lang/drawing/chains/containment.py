"""Which loops of a drawing lie inside which (``aidl import``, plain and ``--infer``): in,
loops as lists of segments (mm); out, for each loop the loops it lies inside
(:func:`_containers`: a grid of boxes, so O(n log n) in the loops), and the loops of a
:class:`~.model.Drawing` (:func:`_loops_of`) with how many are parts (:func:`_outer_count`),
which overlap (:func:`_overlapping_parts`) and whether they are apart (:func:`_apart`).
Used by :mod:`.program` (holes, islands, parts) and :mod:`.infer_layers` (layers of holes)."""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Loop, Spline
from ...geometry.shapes.drawing2d import _inside_many
from ..model import Drawing
from .hole_cuts import polygons_overlap
from .notches import NOTCH_AREA, _notches, _polygons_touch


# work units of one probe point tested against one edge of a loop (numpy: about 8 ns)
PROBE_EDGE_UNITS = 0.001

def _probe(segs) -> tuple[float, float]:
    s = segs[0]
    if isinstance(s, Circle):
        return (s.center[0] + s.radius, s.center[1])
    if isinstance(s, Arc):
        return s.at(s.start_angle + s.sweep / 2)
    if isinstance(s, Spline):
        # a point of the piece itself (a piece of a curve split at a crossing: the curve's
        # own middle may lie on the other side of the crossing, in another loop)
        return s.spans[0][3] if len(s.spans) > 1 else s.curve.at((s.u0 + s.u1) / 2)
    return ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2)


def _containers(loops: list, deadline=None) -> list[list[int]]:
    """For each loop (a list of segments) the indices of the other loops it lies inside (its
    probe point inside their polygon, and their area larger than its own: two parts drawn
    overlapping, their joint's tabs interlocked, each have points inside the other, and
    neither is the other's hole): each probe is tested only against the loops whose box
    holds it, found through a grid (:func:`~..output.part.nearby.box_pairs_between`), so a
    sheet of 20,000 holes takes a moment (each probe against every box: 4.3 s).  A loop
    drawn across the edge of a larger part or island (:func:`~.notches._notches`) is that
    loop's hole (its notch) whatever its probe point."""
    import numpy as np

    from ...output.part.measure.nearby import box_pairs_between
    # a whole circle is measured as itself (its area, a distance), not as its polygon
    polys = [None if len(segs) == 1 and isinstance(segs[0], Circle) else
             np.asarray(Loop(list(segs)).points(), dtype=float) for segs in loops]
    areas, boxes, real = [], [], []
    for j, (segs, P) in enumerate(zip(loops, polys)):
        if P is None:
            (cx, cy), r = segs[0].center, segs[0].radius
            areas.append(math.pi * r * r)
            boxes.append((cx - r, cy - r, cx + r, cy + r))
            real.append(j)
            continue
        areas.append(abs(float(np.dot(P[:, 0], np.roll(P[:, 1], -1)) -
                               np.dot(P[:, 1], np.roll(P[:, 0], -1)))) / 2
                     if len(P) >= 3 else 0.0)
        if len(P) >= 3:
            boxes.append((P[:, 0].min(), P[:, 1].min(), P[:, 0].max(), P[:, 1].max()))
            real.append(j)
    probes = np.array([_probe(segs) for segs in loops], dtype=float).reshape(-1, 2)
    out: list[list[int]] = [[] for _ in loops]
    if deadline is not None:
        deadline.check("finding the holes of the drawing")
    pairs = box_pairs_between(np.hstack([probes, probes]), np.array(boxes, dtype=float))
    A = np.asarray(areas)
    i_all, j_all = pairs[:, 0], np.asarray(real, dtype=np.intp)[pairs[:, 1]]
    keep = (i_all != j_all) & (A[j_all] > A[i_all])
    i_all, j_all = i_all[keep], j_all[keep]
    order = np.argsort(j_all, kind="stable")          # each container's probes at once
    i_all, j_all = i_all[order], j_all[order]
    starts = np.flatnonzero(np.r_[True, j_all[1:] != j_all[:-1]]) if len(j_all) else []
    for a, b in zip(starts, list(starts[1:]) + [len(j_all)]):
        j, ii = int(j_all[a]), i_all[a:b]
        if deadline is not None:    # paid before: each probe against each edge of the loop
            deadline.check("finding the holes of the drawing", ahead=PROBE_EDGE_UNITS * len(ii)
                           * (1 if polys[j] is None else len(polys[j])))
        x, y = probes[ii, 0], probes[ii, 1]
        if polys[j] is None:
            (cx, cy), r = loops[j][0].center, loops[j][0].radius
            hit = np.hypot(x - cx, y - cy) < r
        else:
            hit = _inside_many(x, y, polys[j])
        for i in ii[hit].tolist():
            out[i].append(j)
    for js in out:
        js.sort()
    # a loop drawn across the edge of a larger part: its notch whatever its probe point
    big = NOTCH_AREA * max(areas, default=0.0)
    small = [k for k, i in enumerate(real) if polys[i] is not None and areas[i] <= big]
    across: dict = {}
    for a, b in (box_pairs_between(np.array(boxes, dtype=float)[small],
                                   np.array(boxes, dtype=float)).tolist() if small else ()):
        i, j = real[small[a]], real[b]
        if i != j and areas[i] <= NOTCH_AREA * areas[j] and j not in out[i]:
            across.setdefault(i, []).append(j)
    if across:
        _notches(out, across, polys, loops, areas, deadline)
    return out


def _outer_count(d: Drawing, inside: list | None, deadline=None) -> int:
    """How many of ``d``'s loops lie inside no other (its separate parts); ``inside``:
    :func:`_containers` of :func:`_loops_of` when already found."""
    loops = _loops_of(d)
    if len(loops) < 2:
        return len(loops)
    if inside is None:
        inside = _containers(loops, deadline)
    return sum(1 for c in inside if not c)


def _loops_of(d: Drawing) -> list:
    """``d``'s closed loops (lists of segments): its outlines, then its circles, then its
    whole ellipses (:func:`_whole_ellipse`)."""
    return [o.segments for o in d.outlines] + [[c] for c in d.circles] + \
        [[_whole_ellipse(el)] for el in d.ellipses]


def _whole_ellipse(el: tuple) -> EllipticArc:
    """The whole ellipse ``(cx, cy, rx, ry, rotation)`` of a :class:`Drawing` (mm, radians)
    as a loop's one segment, its numbers as the drawing gives them (written back as they
    are: :func:`_loop`)."""
    from ...geometry.shapes.ellipse import EllipseCurve
    cx, cy, rx, ry, rot = el
    return EllipticArc(EllipseCurve((cx, cy), rx, ry, rot), 0.0, 2 * math.pi)


MAX_APART = 500     # separate parts on one layer written as a solid each (more: one solid)


def _apart(d: Drawing, inside: list | None, deadline=None) -> bool:
    """Whether ``d`` (a layer without a cut role) is separate parts, each written as a solid
    of its own: 2 to :data:`MAX_APART` loops inside no other, no two of which overlap or
    touch along an edge (:func:`_overlapping_parts`: frames drawn across one another, as
    ezdxf's text samples have, stay one solid, as the file draws them)."""
    if len(d.outlines) + len(d.circles) + len(d.ellipses) < 2:
        return False
    if inside is None:
        inside = _containers(_loops_of(d), deadline)
    if not 2 <= _outer_count(d, inside) <= MAX_APART:
        return False
    return _overlapping_parts(d, inside, deadline) == (0, 0)


def _overlapping_parts(d: Drawing, inside: list, deadline=None) -> tuple[int, int]:
    """How many pairs of ``d``'s outer loops (those inside no other loop: its parts) overlap
    (share an area, on the loops' sampled polygons), and how many others touch along an
    edge (:func:`_polygons_touch`): parts drawn overlapping on a laser sheet (Boxes.py's
    UnevenHeightBox walls) or sharing an edge (WallChiselHolder's walls), which one solid
    would fuse, losing the cut lines inside the union.  ``inside``: :func:`_containers` of
    :func:`_loops_of`."""
    import numpy as np
    loops = _loops_of(d)
    if len(loops) < 2:
        return 0, 0
    outer = [i for i, c in enumerate(inside) if not c]
    polys = {i: np.asarray(Loop(list(loops[i])).points(), dtype=float) for i in outer}
    box = {i: (P[:, 0].min(), P[:, 1].min(), P[:, 0].max(), P[:, 1].max())
           for i, P in polys.items() if len(P) >= 3}
    keys = sorted(box)
    pairs = touch = 0
    for a_i, i in enumerate(keys):
        if deadline is not None:
            deadline.check("finding the parts that overlap")
        for j in keys[a_i + 1:]:
            a, b = box[i], box[j]
            if a[0] > b[2] or b[0] > a[2] or a[1] > b[3] or b[1] > a[3]:
                continue
            if polygons_overlap(polys[i], polys[j]):
                pairs += 1
            elif _polygons_touch(polys[i], polys[j]):
                touch += 1
    return pairs, touch


ON_EDGE = 0.01      # mm: a probe this near a part's edge lies on it
ON_PART = 1.0       # of a drawing's probe points on one part's material: engraved on it (all:
#                     a layer partly off the part stays an illustration, which W0505 would warn)


def engraved_on(drawings: list, solids: list) -> dict:
    """For the import's drawing layers and solid parts (``[(name, Drawing)]`` each), the
    part each drawing lies on: ``{drawing name: part name}`` where :data:`ON_PART` (all) of
    its probe points (each piece's ends and middle, each text's position) lie on that
    part's material (inside its outer loops, outside its holes: the even-odd rule over all its
    loops; each loop tested only against the probes in its box, so a panel of 20,000 holes
    costs n log n), the part with the most.  `aidl import` then writes `CutInto(drawing, part)`, so
    that a cutting layout carries the engraving with its part (W0116: a KiCad board's
    `F.SilkS` text on its `Edge.Cuts` outline)."""
    import numpy as np
    polys = []
    for name, d in solids:
        ps = [Loop(list(segs)).points() for segs in _loops_of(d)]
        polys.append((name, [np.asarray(p, dtype=float) for p in ps if len(p) >= 3]))
    out = {}
    for name, d in drawings:
        pts = [(t[1][0], t[1][1]) for t in d.texts]
        for segs in [p.segments for p in d.paths] + _loops_of(d):
            for s in segs:
                if not isinstance(s, (Circle, EllipticArc)):
                    pts += [tuple(s.start), tuple(s.end)]
                pts.append(tuple(_probe([s])))
        if not pts:
            continue
        P = np.asarray(pts, dtype=float)
        best, most = None, 0
        order = np.argsort(P[:, 0], kind="stable")
        xs = P[order, 0]
        for part, loops in polys:
            if not loops:
                continue
            odd = np.zeros(len(P), dtype=bool)
            near = []                   # (the probes by a loop's box, the loop)
            for L in loops:             # each loop against the probes in its box (grown by
                (x0, y0), (x1, y1) = L.min(axis=0) - ON_EDGE, L.max(axis=0) + ON_EDGE
                k = order[np.searchsorted(xs, x0):np.searchsorted(xs, x1, side="right")]
                k = k[(P[k, 1] >= y0) & (P[k, 1] <= y1)]     # ON_EDGE): n log n, not n x m
                if len(k):
                    odd[k] ^= _inside_many(P[k, 0], P[k, 1], L)
                    near.append((k, L))
            for k, L in near:           # a mark that ends on the cut (a ruler's tick) is on it
                off = k[~odd[k]]
                if len(off):
                    odd[off] = _near_edges(P[off], [L], ON_EDGE)
            if int(odd.sum()) > most:
                best, most = part, int(odd.sum())
        if best is not None and most >= ON_PART * len(P):
            out[name] = best
    return out


def _near_edges(P, loops: list, tol: float):
    """Which points ``P`` (N x 2, mm) lie within ``tol`` of an edge of one of the polygons
    ``loops``, in runs of at most a million (point, edge) pairs."""
    import numpy as np
    out = np.zeros(len(P), dtype=bool)
    for L in loops:
        A, B = L, np.roll(L, -1, axis=0)
        D = B - A
        dd = np.maximum((D * D).sum(axis=1), 1e-300)
        step = max(1, 1_000_000 // max(1, len(A)))
        for k in range(0, len(P), step):
            Q = P[k:k + step, None, :]
            t = np.clip(((Q - A) * D).sum(axis=2) / dd, 0.0, 1.0)
            near = np.hypot(*(A + t[..., None] * D - Q).transpose(2, 0, 1)).min(axis=1) <= tol
            out[k:k + step] |= near
    return out
