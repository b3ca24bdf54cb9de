"""Loops drawn across another loop's edge, for ``aidl import`` (:mod:`.program`): a small
loop across a part's edge is the part's notch whatever its probe point (:func:`_notches`),
and parts that share an edge are told apart (:func:`_polygons_touch`); a loop is cut where
another crosses it by :func:`~.hole_cuts.cut_at_crossings` and :func:`~.hole_cuts.runs_of`
to keep the cut of a notch's outer rest and of the part's edge across it."""
from __future__ import annotations


NOTCH_AREA = 0.25   # a loop across a larger one's edge is its notch: at most this of its area
NOTCH_SHARE = 0.1   # ... and at least this share of its own area inside it
EDGE_ACROSS = "a part's edge across its notch"     # the source of such a piece of edge cut


def _notches(out: list, across: dict, polys: list, loops: list, areas: list,
             deadline=None) -> None:
    """Make each loop drawn across the edge of a larger part or island a hole of it, in
    ``out`` (:func:`~.program._containers`' lists, changed in place): a loop ``i`` (not a whole circle)
    of at most :data:`NOTCH_AREA` of the area of a loop ``j`` whose outline it crosses, with at
    least :data:`NOTCH_SHARE` of its own area inside ``j`` (Manifold's 2D intersection of the
    sampled polygons), that its probe point put beside ``j`` (its containers some of ``j``'s),
    gets ``j``'s containers and ``j``: Boxes.py's WallChiselHolder slots across a plate's
    edge are the plate's notches wherever their probe falls (the outer rest of their outline
    is cut by :func:`~.program._outside_remainders`).  The size and share keep apart what is not a
    notch: parts drawn touching, their shared edges overlapping by a burn correction
    (UnevenHeightBox's walls: 1.6 % of the smaller, and 0.4 to 2.7 times its area), stay
    parts.  ``j`` must be a part or island (inside an even number of loops): a loop across
    a hole's edge is left as its probe puts it.  ``across``: loop -> the candidate ``j``;
    ``polys``: each loop's sampled polygon (None for a whole circle: sampled here when it is
    a candidate), ``loops`` their segments, ``areas`` their areas (mm^2)."""
    import manifold3d as mf
    import numpy as np

    from ...geometry.shapes.curves import Loop
    from ...geometry.shapes.drawing2d import _inside_many
    found: dict = {}
    for i, cand in across.items():
        H = polys[i]
        if len(H) < 3:
            continue
        lo, hi = H.min(axis=0), H.max(axis=0)
        for j in cand:
            if polys[j] is None:
                polys[j] = np.asarray(Loop(list(loops[j])).points(), dtype=float)
            P = polys[j]            # a corner of one inside the other: they may overlap
            Q = P[np.all((P >= lo) & (P <= hi), axis=1)]
            if not (_inside_many(H[:, 0], H[:, 1], P).any() or
                    _inside_many(Q[:, 0], Q[:, 1], H).any()):
                continue
            if deadline is not None:
                deadline.check("finding the holes that cross their part's edge")
            share = (mf.CrossSection([H.tolist()], mf.FillRule.NonZero) ^
                     mf.CrossSection([polys[j].tolist()], mf.FillRule.NonZero)).area()
            if share >= NOTCH_SHARE * areas[i]:
                found.setdefault(i, []).append((-share, j))
    for i in sorted(found, key=lambda k: -areas[k]):    # a larger loop's own place first
        for _, j in sorted(found[i]):                   # the largest share first
            if len(out[j]) % 2 == 0 and set(out[i]) <= set(out[j]):
                out[i] = out[j] + [j]
                break


def _polygons_touch(P, Q, reach: float = 1e-3) -> bool:
    """Whether closed polygons ``P`` and ``Q`` (arrays of points, mm) that do not overlap run
    along one another for more than :data:`~.model.GAP_NOTE` (0.5 mm): the area of ``Q``
    within ``reach`` mm of ``P`` (``P`` offset by it, square joins: Manifold's 2D booleans),
    divided by ``reach``, is the length of the edge they share; parts that touch at a corner
    share none."""
    import manifold3d as mf

    from ..model import GAP_NOTE
    a = mf.CrossSection([P.tolist()], mf.FillRule.NonZero).offset(reach, mf.JoinType.Square)
    b = mf.CrossSection([Q.tolist()], mf.FillRule.NonZero)
    return (a ^ b).area() > GAP_NOTE * reach
