"""The cuts of holes drawn overlapping, for ``aidl import`` on a cut role: holes of one part
that share an area (Boxes.py's Planetary2: the sun's and the planets' circles on one plate)
cut one opening of the part, and the pieces of each hole's outline inside the others are
still asked to be cut (the laser cuts the falling scrap apart along them).
:func:`inner_rests` finds those pieces, exact (each on its own carrier, cut at the exact
crossings), for :mod:`.program` to write as the sheet-level cut; :func:`polygons_overlap` is
the area test it shares with :mod:`.program`'s overlapping parts."""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Loop, Spline
from ..model import GAP_NOTE, Path


def polygons_overlap(P, Q) -> bool:
    """Whether closed polygons ``P`` and ``Q`` (arrays of points, mm) share an area: their
    intersection (Manifold's 2D booleans) is larger than 1e-6 of the smaller (parts that only
    touch, or run along one another, do not overlap)."""
    import manifold3d as mf
    a = mf.CrossSection([P.tolist()], mf.FillRule.NonZero)
    b = mf.CrossSection([Q.tolist()], mf.FillRule.NonZero)
    both = (a ^ b).area()
    return both > 1e-6 * max(1e-6, min(a.area(), b.area()))


def overlapping_holes(loops: list, inside: list, deadline=None) -> tuple[dict, dict]:
    """The holes among ``loops`` (closed loops: lists of segments, mm) that share an area
    with other holes of the same part (:func:`polygons_overlap`): ``(partners, polygons)``,
    ``partners`` each such hole's index -> the indices of the holes it overlaps, ``polygons``
    their sampled polygons (N x 2 arrays).  A hole is a loop inside an odd number of others
    (``inside``: for each loop the indices of the loops it lies inside,
    :func:`~.program._containers`), its part the one of those one level up.  Only holes whose
    boxes overlap are compared (:func:`~..output.part.nearby.box_pairs`: a plate of 5,000
    holes is not 12 million pairs).  ``deadline``: a :class:`~aidl_lang.base.limits.Deadline` checked per part, or None."""
    import numpy as np

    from ...output.part.measure.nearby import box_pairs
    depth = [len(c) for c in inside]
    holes: dict = {}                                    # a part's loop -> its holes
    for i in range(len(loops)):
        owner = [j for j in inside[i] if depth[j] == depth[i] - 1] if depth[i] % 2 else []
        if owner:
            holes.setdefault(owner[0], []).append(i)
    poly: dict = {}
    partners: dict = {}

    def polygon(i):
        if i not in poly:
            poly[i] = np.asarray(Loop(list(loops[i])).points(), dtype=float)
        return poly[i]
    for group in holes.values():
        if len(group) < 2:
            continue
        if deadline is not None:
            deadline.check("finding the holes that overlap")
        # boxes holding the loops (no sampling): the polygons only of holes whose boxes meet,
        # found through a grid (a sweep along x met every hole of a column: 1.1 s for a panel
        # of 20,000 holes in 141 columns)
        box = np.array([_loop_box(loops[i]) for i in group])
        for ia, ib in box_pairs(box).tolist():
            i, j = sorted((group[ia], group[ib]))
            P, Q = polygon(i), polygon(j)
            if len(P) >= 3 and len(Q) >= 3 and polygons_overlap(P, Q):
                partners.setdefault(i, []).append(j)
                partners.setdefault(j, []).append(i)
    return partners, poly


def inner_rests(loops: list, inside: list, deadline=None,
                pairs: set | None = None) -> list[Path]:
    """The pieces of the holes among ``loops`` (closed loops: lists of segments, mm) that
    lie inside another hole of the same part, as open paths (mm).  Each hole that shares an
    area with other holes of its part (:func:`overlapping_holes`; ``inside`` as there) is cut
    exactly at its crossings with their loops (:func:`cut_at_crossings`); the runs of pieces
    whose middles lie inside one of those holes are returned in the hole's order, but for
    those no longer than :data:`~.model.GAP_NOTE` (a burn-correction overlap).  A hole that
    crosses none of them (one drawn twice) gives nothing.  ``deadline``: a
    :class:`~aidl_lang.base.limits.Deadline` checked per part and per hole, or None.  ``pairs``:
    a set to which each pair of overlapping holes is added, as the frozenset of their
    :func:`loop_key` (so that the writer can say that the two may cut one opening,
    whichever part the loops are written in)."""
    from ...geometry.shapes.drawing2d import _inside
    partners, poly = overlapping_holes(loops, inside, deadline)
    if pairs is not None:
        pairs.update(frozenset((loop_key(loops[i]), loop_key(loops[j])))
                     for i, js in partners.items() for j in js)
    out: list[Path] = []
    for i in sorted(partners):
        if deadline is not None:
            deadline.check("cutting the holes that overlap at their crossings")
        js = partners[i]
        pieces, _ = cut_at_crossings(loops[i], [t for j in js for t in loops[j]])
        if len(pieces) < 2:
            continue
        flags = [any(_inside(_middle(p), poly[j]) for j in js) for p in pieces]
        out += [Path(r, "the part of a hole inside another hole of its part")
                for r in runs_of(pieces, flags) if sum(p.length for p in r) > GAP_NOTE]
    return out


def loop_key(segs: list):
    """A key of the closed loop ``segs`` (segments) that stays the same however often the
    loop is built from its drawing: its first segment's identity; a whole ellipse's own
    value (a :class:`~aidl_lang.geometry.shapes.curves.EllipticArc` made afresh from the drawing's
    numbers each time, :func:`~.program._whole_ellipse`)."""
    s = segs[0]
    return s if isinstance(s, EllipticArc) and s.whole else id(s)


def _middle(s) -> tuple[float, float]:
    """A point of segment ``s`` (no whole circle) half way along it; a spline piece's: the
    middle of its middle span."""
    if isinstance(s, Arc):
        return s.at(s.start_angle + s.sweep / 2)
    if isinstance(s, EllipticArc):
        return s.at(s.start_param + s.sweep / 2)
    if isinstance(s, Spline):
        from ...geometry.shapes.spline import bez_at
        return bez_at(s.spans[len(s.spans) // 2], 0.5)
    return ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2)


def _loop_box(segs: list) -> tuple[float, float, float, float]:
    """A box (mm) holding the loop ``segs``: the union of its segments' :func:`_hull_box`."""
    bs = [_hull_box(t) for t in segs]
    return (min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
            max(b[3] for b in bs))


def _hull_box(s) -> tuple[float, float, float, float]:
    """A box (mm) holding segment ``s``: its exact box, but a spline piece's is its spans'
    control points' (their hull holds the curve; found without solving for its extremes)."""
    if not isinstance(s, Spline):
        return s.box()
    xs = [q[0] for b in s.spans for q in b]
    ys = [q[1] for b in s.spans for q in b]
    return min(xs), min(ys), max(xs), max(ys)


def cut_at_crossings(segs: list, others: list, box=None) -> tuple[list, list]:
    """``(pieces, near)``: the closed loop ``segs`` (segments, mm) cut exactly at every point
    where it crosses a segment of ``others`` (:func:`~aidl_lang.geometry.shapes.curves.crossings` of
    their carriers, each point on both segments), its pieces in its order, each on its own
    carrier (:func:`~.chain._split_at`: a line stays a line, an arc an arc, a curve the same
    curve); a whole circle that is crossed is first made the full-turn arc from its first
    crossing, turning as it does.  With ``box`` (``(x0, y0, x1, y1)``, mm) only the segments
    whose box meets it are cut, the others kept whole; ``near`` says which pieces come of
    segments that were cut (all, without ``box``)."""
    from ...geometry.shapes.curves import carrier, crossings
    from .chain import _distinct, _piece_length, _split_at

    boxes = [_hull_box(t) for t in others]

    def hits(s) -> list:
        a = _hull_box(s)
        pts: list = []
        for t, b in zip(others, boxes):
            if a[0] > b[2] + 1e-9 or b[0] > a[2] + 1e-9 or a[1] > b[3] + 1e-9 or \
                    b[1] > a[3] + 1e-9:
                continue
            pts += [x for x in crossings(carrier(s), carrier(t)) if isinstance(t, Circle)
                    or _split_at(t, x) is not None
                    or min(math.dist(x, t.start), math.dist(x, t.end)) <= 1e-9]
        return _distinct(pts)

    pieces: list = []
    near: list = []
    for s in segs:
        b = s.box() if box is not None else None
        if b is not None and (b[0] > box[2] or box[0] > b[2] or b[1] > box[3] or
                              box[1] > b[3]):
            pieces.append(s)
            near.append(False)
            continue
        n = len(pieces)
        xs = hits(s)
        if isinstance(s, Circle):
            if not xs:
                pieces.append(s)
                near.append(True)
                continue
            (cx, cy), x0 = s.center, xs[0]
            s = Arc(s.center, s.radius, math.atan2(x0[1] - cy, x0[0] - cx),
                    2 * math.pi if s.ccw else -2 * math.pi)
        xs = [x for x in xs if min(math.dist(x, s.start), math.dist(x, s.end)) > 1e-9]

        def along(x, s=s) -> float:     # how far along s the hit lies
            cut = _split_at(s, x)
            return _piece_length(cut[0]) if cut is not None else math.inf
        xs.sort(key=along)
        rest = s
        for x in xs:
            cut = _split_at(rest, x)
            if cut is not None:
                pieces.append(cut[0])
                rest = cut[1]
        pieces.append(rest)
        near += [True] * (len(pieces) - n)
    return pieces, near


def runs_of(pieces: list, flags: list) -> list:
    """The runs of consecutive ``pieces`` of a closed loop whose ``flags`` are true (a run
    may go on past the loop's start), in the loop's order: none when every flag or none is
    true."""
    if all(flags) or not any(flags):
        return []
    k = flags.index(False)                         # start the walk at a piece not flagged
    runs: list = []
    cur: list = []
    for p, f in zip(pieces[k:] + pieces[:k], flags[k:] + flags[:k]):
        if f:
            cur.append(p)
        elif cur:
            runs.append(cur)
            cur = []
    if cur:
        runs.append(cur)
    return runs
