"""``W0507`` for a neck: two members of a part (solid shapes of its union) that join over a
neck narrower than ``min_wall``, or only at a point, which the opening of :mod:`.walls` misses
(a neck removes less than its ``2 t^2``).  Found by one erosion of the part (a neck splits a
piece in two), its width by bisection, its members by the faces at the two pieces' nearest
points (:func:`_face_at`), with the move that widens it to the minimum as the hint.
"""
from __future__ import annotations

import manifold3d as mf
import numpy as np

from ....base.diagnostics import DiagnosticSink, Label
from ....geometry.core.model import Structure
from ...part.build.booleans import Drawing
from ..common import _area, _solids_within, written
from . import walls     # its THIN_SECONDS_PER_VERTEX, read at the call (one cost for both)

NECK_VERTS = 200_000   # W0507's neck search: not past this many vertices of members that overlap


def _outer_loops(cs) -> list:
    """The counter-clockwise loops (each k x 2, mm) of ``cs``: one per piece."""
    from ..common import _signed
    return [P for P in (np.asarray(p, dtype=float) for p in cs.to_polygons())
            if len(P) >= 3 and _signed(P) > 0]


def _eroded(shape, r: float):
    return shape.offset(-r, mf.JoinType.Round, 2.0, 16)


def _pieces_of(cs) -> tuple[list, np.ndarray]:
    """The loops of ``cs`` (each k x 2, mm) and for each the number of its piece: an outer
    (counter-clockwise) loop is its own piece, a hole belongs to the smallest outer loop
    whose box holds it."""
    from ..common import _signed
    loops = [np.asarray(p, dtype=float) for p in cs.to_polygons() if len(p) >= 2]
    outer = [k for k, P in enumerate(loops) if _signed(P) > 0]
    boxes = np.array([(*P.min(axis=0), *P.max(axis=0)) for P in loops]).reshape(-1, 4)
    area = np.prod(boxes[:, 2:] - boxes[:, :2], axis=1)
    piece = np.arange(len(loops))
    ob = boxes[outer]
    for k in range(len(loops)):
        if k in outer:
            continue
        ok = np.flatnonzero((ob[:, :2] <= boxes[k, :2]).all(axis=1)
                            & (ob[:, 2:] >= boxes[k, 2:]).all(axis=1))
        if len(ok):
            piece[k] = outer[int(ok[np.argmin(area[outer][ok])])]
    return loops, piece


def _closest_pieces(er, parent) -> tuple | None:
    """The two nearest pieces of the eroded shape ``er`` that ``parent`` (a point, mm ->
    the piece of the part before the erosion that holds it) puts in one piece of the part:
    ``(p, q, gap)``, ``p`` and ``q`` their nearest points (mm), by
    :func:`..part.nearby.close_pairs` within a radius that grows from 1 um; None when no two
    pieces of one piece of the part come within its size."""
    from ...part.measure.nearby import TooManyPairs, close_pairs
    loops, piece = _pieces_of(er)
    if len(loops) < 2:
        return None
    of = {int(k): parent(loops[k][0]) for k in set(piece.tolist())}
    V = np.concatenate(loops)
    B = np.concatenate([np.roll(P, -1, axis=0) for P in loops])
    feat = np.concatenate([np.full(len(P), piece[k]) for k, P in enumerate(loops)])
    span = float(np.max(V.max(axis=0) - V.min(axis=0)))
    radius = 1e-3
    while radius < 2 * span + 1:
        try:
            v, sg, dist, foot = close_pairs(V, feat, V, B, feat, radius)
        except TooManyPairs:
            return None
        same = np.array([of[int(feat[a])] is not None and of[int(feat[a])] == of[int(feat[b])]
                         for a, b in zip(v, sg)], dtype=bool)
        if same.any():
            k = np.flatnonzero(same)[int(np.argmin(dist[same]))]
            return V[v[k]], foot[k], float(dist[k])
        radius *= 4
    return None


def _face_at(d: Drawing, s: Structure, point, other):
    """The face ``(geometry, CrossSection)`` of part ``s``'s solids that covers ``point``
    (a 2 um square about it) most, one that does not cover ``other`` first (the member on
    ``point``'s side of a neck, where both overlap), or None."""
    q = mf.CrossSection.square((2e-3, 2e-3)).translate((point[0] - 1e-3, point[1] - 1e-3))
    o = mf.CrossSection.square((2e-3, 2e-3)).translate((other[0] - 1e-3, other[1] - 1e-3))
    best, most = None, (False, 0.0)
    for _, faces in _solids_within(d, s):
        for g, f in faces:
            if f is None:
                continue
            a, b, c, e = f.bounds()
            if a > point[0] + 1e-3 or c < point[0] - 1e-3 or b > point[1] + 1e-3 \
                    or e < point[1] - 1e-3:
                continue
            got = (_area(o ^ f) <= 0.0, _area(q ^ f))
            if got[1] > 0.0 and got > most:
                best, most = (g, f), got
    return best


def _check_necks(d: Drawing, s: Structure, shape, t: float, cuts, sink: DiagnosticSink,
                 tick=lambda ahead=0.0: None) -> None:
    """W0507 for two members of part ``s`` (solid shapes of its union, :attr:`Drawing.own`)
    that join over a neck narrower than ``t`` mm, or only at a point (a hook's loop that
    meets a leaf at its stem's tip: the cut part hangs by that point).  The opening of
    :func:`_check_walls` misses such a neck, which removes less than its ``2 t^2``.  A part
    of one member is not searched; in a part with holes, the members' union without them is
    (a web between holes is measured by the other W0507 checks).

    Found by the erosion of the part by ``t / 2`` (Manifold's offset, round joins): a neck
    narrower than ``t`` splits a piece in two, so the eroded part has more pieces (outer
    loops) than the part.  The neck's width is the least erosion that splits the part
    (bisection to 0.005 mm on the radius), its place the middle of the two pieces' nearest
    points just past that width, and the two members are the faces covering those points;
    a neck within one member (a plate cut nearly through by its holes) belongs to the other
    W0507 checks and is not reported here.  The hint gives how far to move the smaller side's
    member towards the other for a neck of ``t`` (bisection on the move, the two members
    and the shapes around the neck united again).  One erosion of the whole part (O(n log n)
    in its vertices, group by group: the members whose boxes overlap, united) when there is no
    neck; groups of more than :data:`NECK_VERTS` vertices in all are not searched."""
    from ..common import _edges, _inside, _union
    if t <= 0 or shape.is_empty():
        return
    faces = [f for _, fs in _solids_within(d, s) for _, f in fs if f is not None]
    if len(faces) < 2:
        return                  # one member: no neck between members
    # the members are united without the holes: a web a hole leaves is the other W0507s'
    # (a plate of 2,500 holes 0.3 mm apart would erode into 2,500 islands)
    # only members whose boxes overlap can join over a neck: the groups of them (connected by
    # overlapping boxes) are united and eroded each on its own - the same as the whole eroded,
    # since an erosion never joins what lies apart (Clipper's offset of 5,000 disjoint circles
    # at once took 20 s; a decompose of 4,000 of slightly different radii 40 s)
    # (the groups without listing the pairs: 1,000 concentric circles are 500,000 of them)
    from ...part.measure.nearby import box_groups
    group = box_groups(np.array([f.bounds() for f in faces], dtype=float))
    count = np.bincount(group, minlength=len(faces))
    if not (count > 1).any():
        return
    many = [_union([faces[k] for k in np.flatnonzero(group == g)])
            for g in np.flatnonzero(count > 1).tolist()]
    n = sum(p.num_vert() for p in many)
    if n > NECK_VERTS:
        return
    shape = mf.CrossSection.compose(many)       # the groups apart: composed, not united
    base = _outer_loops(shape)
    tick(n * walls.THIN_SECONDS_PER_VERTEX)
    er = mf.CrossSection.compose([_eroded(p, t / 2) for p in many])
    if len(_outer_loops(er)) <= len(base):
        return
    edges = [_edges([P]) for P in base]

    def parent(pt):
        for k, E in enumerate(edges):
            if bool(_inside(np.asarray(pt, dtype=float)[None], E)[0]):
                return k
        return None
    far = _closest_pieces(er, parent)
    if far is None:
        return
    # the width, by bisection on the part within a window about the split (each step an
    # erosion of that window only): the least erosion that parts the two points
    c = (np.asarray(far[0]) + np.asarray(far[1])) / 2
    h = far[2] + 3 * t
    win = shape ^ mf.CrossSection.square((2 * h, 2 * h)).translate((c[0] - h, c[1] - h))
    found = _neck_width(win, far, t, tick)
    if found is None:
        return
    width, hi, far = found
    if width >= t - 0.01:
        return                  # no narrower than the minimum, to the bisection's step
    near = _closest_pieces(_eroded(win, hi), parent)      # where the neck parts
    mid_pt = c if near is None else (np.asarray(near[0]) + np.asarray(near[1])) / 2
    if _beside_hole(d, cuts, mid_pt, t):
        return
    # the members on either side: the faces at the nearest points of the pieces eroded by
    # t / 2 (clear of the neck itself, which both may cover)
    fp, fq = _face_at(d, s, far[0], far[1]), _face_at(d, s, far[1], far[0])
    if fp is None or fq is None or fp[0] is fq[0]:
        return
    # the member to move: the one on the smaller side of the split
    from ..common import _signed
    sides = _outer_loops(er)

    def side_area(pt):
        return next((abs(_signed(P)) for P in sides
                     if bool(_inside(np.asarray(pt, dtype=float)[None], _edges([P]))[0])),
                    np.inf)
    if side_area(far[1]) > side_area(far[0]):
        fp, fq = fq, fp
        far = (far[1], far[0], far[2])
    gp, gq = fp[0], fq[0]
    u, move = _widening_move(d, s, fq, far, t, tick)
    from ..marks.engravings import _copy_label
    what_q, what_p = f"{gq.kind} `{_copy_label(gq)}`", f"{gp.kind} `{_copy_label(gp)}`"
    how = ("only at a point (a neck of zero width)" if width < 5e-3 else
           f"over a neck {width:.2f} mm wide")
    fix = (f"move {what_q} {move:.2f} mm towards {what_p} (by ({u[0] * move:.2f}, "
           f"{u[1] * move:.2f}) mm) so that they overlap over at least {t:g} mm"
           if move is not None else f"make {what_q} and {what_p} overlap over at least {t:g} mm")
    sink.warning(
        "W0507", f"{what_q} and {what_p} of `{s.path}` join {how}, narrower than {t:g} mm, "
        f"near ({written(s, *mid_pt)[0]:.1f}, {written(s, *mid_pt)[1]:.1f}): the cut part hangs by it and breaks there "
        "(or falls apart when the laser burns the neck away)",
        gq.span or s.span,
        labels=[Label(gp.span, "the other member", primary=False)] if gp.span else [],
        hint=f"{fix}; if the request asks for a joint this thin (a breakaway tab), say so: "
             f"`min_wall 0` in `{s.name}`; the minimum is set by `min_wall` or --min-wall")


def _neck_width(win, far, t: float, tick):
    """``(width, hi, far)``: the width of the neck between the points ``far[0]``, ``far[1]``
    (on two pieces of the part eroded by ``t / 2``) by bisection on the erosion of the window
    ``win`` about it, the radius ``hi`` just past it that parts them, and the two points moved
    1 um inside their pieces; None when even ``t / 2`` does not part them."""
    from ..common import _edges, _inside
    wn = win.num_vert()

    def parted(r):
        tick(wn * walls.THIN_SECONDS_PER_VERTEX)
        loops, piece = _pieces_of(_eroded(win, r))
        home = []
        for pt in (far[0], far[1]):
            k = next((int(piece[k]) for k, P in enumerate(loops) if piece[k] == k
                      and bool(_inside(np.asarray(pt)[None], _edges([P]))[0])), None)
            home.append(k)
        return home[0] is None or home[1] is None or home[0] != home[1]
    # the points lie 1 um inside the pieces eroded by t / 2 (on their edge otherwise)
    inward = (np.asarray(far[0]) - np.asarray(far[1]))
    inward = inward / max(float(np.hypot(*inward)), 1e-12) * 1e-3
    far = (np.asarray(far[0]) + inward, np.asarray(far[1]) - inward, far[2])
    lo, hi = 0.0, t / 2
    if not parted(hi):
        return
    while hi - lo > 2.5e-3:
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if parted(mid) else (mid, hi)
    return 2 * lo, hi, far


def _beside_hole(d: Drawing, cuts, mid_pt, t: float) -> bool:
    """Whether a hole lies within ``t`` of the neck at ``mid_pt``: then it is a wall between
    the hole and the edge, the other W0507 checks'."""
    for cut in cuts:
        hs = d.shapes.get(cut.hole)
        if hs is None or hs.is_empty():
            continue
        x0, y0, x1, y1 = hs.bounds()
        if x0 - t <= mid_pt[0] <= x1 + t and y0 - t <= mid_pt[1] <= y1 + t and _area(
                hs ^ mf.CrossSection.circle(t, 32).translate((float(mid_pt[0]),
                                                              float(mid_pt[1])))) > 0:
            return True
    return False


def _widening_move(d: Drawing, s: Structure, fq, far, t: float, tick):
    """``(u, move)``: the direction from ``far[1]`` to ``far[0]`` and how far (mm) member
    ``fq`` (``(structure, face)``, on the smaller side) moves along it until the neck is
    ``t`` wide (bisection on the move, the shapes around it united again); move None when
    no move within reach does it."""
    from ..common import _union
    gq, sq = fq
    u = np.asarray(far[0], dtype=float) - np.asarray(far[1], dtype=float)
    nu = float(np.hypot(*u))
    move = None
    if nu > 1e-9:
        u /= nu
        x0, y0, x1, y1 = sq.bounds()
        reach = max(x1 - x0, y1 - y0) + 2 * t
        others = []
        for _, faces in _solids_within(d, s):
            for g, f in faces:
                if f is None or g is gq:
                    continue
                a, b, c, e = f.bounds()
                if a <= x1 + reach and c >= x0 - reach and b <= y1 + reach and e >= y0 - reach:
                    others.append(f)
        rest = _union(others)
        rest_n = len(_outer_loops(_eroded(rest, t / 2))) if not rest.is_empty() else 0
        own_n = len(_outer_loops(_eroded(sq, t / 2)))

        def joined(m):
            tick()
            whole = _union([rest, sq.translate((float(u[0] * m), float(u[1] * m)))])
            return len(_outer_loops(_eroded(whole, t / 2))) < rest_n + own_n
        top = reach
        if own_n and joined(top):
            a_, b_ = 0.0, top
            while b_ - a_ > 5e-3:
                m = (a_ + b_) / 2
                a_, b_ = (a_, m) if joined(m) else (m, b_)
            move = float(np.ceil(b_ * 100 - 1e-9) / 100)
            if not joined(move):
                move = b_
    return u, move
