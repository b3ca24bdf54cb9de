"""``aidl import --infer``: where a text of an engraving is placed from (issue 85) - with the
hole it names (directly above, below or beside it, within :data:`LABEL_REACH` of its edge),
so that it moves with that hole when the plate grows, else from the body's centre line or
nearer edge (:class:`~.anchors._Anchored`).  Used by :func:`~.infer._solid` through
:func:`~.engraving._engraving` (docs/import.md, "Where things are placed from").
"""
from __future__ import annotations

import math
from collections import Counter

from .features import arc_slot, d_hole, keyhole, merged
from .shapes import EQUAL_TOL, recognise
from ..write.program import _pt
from ..write.units import UNIT
from ..model import _segs_box


def _at_as_drawn(p, size: float) -> str:
    """A text's position as the drawing gives it (no feature or edge to place it from)."""
    return _pt(p)


LABEL_REACH = 25.0      # mm: a text in line with a hole this near its edge names it


def _hole_ref(segs: list) -> tuple:
    """``(centre, key)`` of a hole as its statement places it: a recognised shape's centre
    (its kind and size as ``key``), an arc slot's centre, a keyhole's or a D-hole's bore
    centre (:meth:`~.makers._MakerFeatures.maker_hole`), else its box's middle (``key``
    None: a hole of its own)."""
    sh = recognise(segs)
    if sh is not None:
        return sh.center, (sh.kind,) + tuple(round(x, 6) if isinstance(x, float) else x
                                             for x in sh.size)
    one = merged(segs)
    for find in (arc_slot, keyhole, d_hole):
        got = find(one)
        if got is not None:
            return got[0], None
    b = _segs_box(segs)
    return ((b[0] + b[2]) / 2, (b[1] + b[3]) / 2), None


def _label_place(part, holes: list):
    """A text's position as :func:`_engraving` writes it (``place(p, size)``, ``p`` the
    text's insertion point, drawing units): with the hole it names, so that it moves with
    it when the plate grows, else from the body's centre line or nearer edge
    (:meth:`~.anchors._Anchored.at`).  A text names the nearest hole it is directly above,
    below or beside (on the line through the hole's centre, within :data:`LABEL_REACH` of
    its edge; a hole of a size no other hole has before a pattern's member); a text in line
    with none names none (near a hole but off its lines, it is as likely the plate's).
    Along an axis on which the text is on the body's centre line it stays on that line."""
    if part.anchor is None:
        return lambda p, size: _pt(p)
    from scipy.spatial import cKDTree
    unit = 25.4 if UNIT.get() == "in" else 1.0
    known: dict = {}

    def index() -> dict:         # on the first text: most drawings have none
        if not known:
            refs = [_hole_ref(segs) for segs in holes]
            boxes = [_segs_box(segs) for segs in holes]
            known.update(refs=refs, boxes=boxes, shared=Counter(k for _, k in refs if k),
                         tree=cKDTree([c for c, _ in refs]) if refs else None,
                         big=max((math.dist(b[:2], b[2:]) for b in boxes), default=0.0))
        return known

    def aligned(p) -> int | None:
        k = index()
        best = None
        for i in k["tree"].query_ball_point(p, LABEL_REACH / unit + k["big"]):
            (c, key), b = k["refs"][i], k["boxes"][i]
            if abs(p[0] - c[0]) <= EQUAL_TOL:
                gap = max(b[1] - p[1], p[1] - b[3])
            elif abs(p[1] - c[1]) <= EQUAL_TOL:
                gap = max(b[0] - p[0], p[0] - b[2])
            else:
                continue
            # one of a pattern's size only when no hole of its own is in line
            rank = (key is not None and k["shared"][key] > 1, gap, i)
            if 0 < gap <= LABEL_REACH / unit and (best is None or rank < best):
                best = rank
        return None if best is None else best[2]

    def place(p, size: float) -> str:
        base = None
        if holes:
            i = aligned(p)
            base = None if i is None else index()["refs"][i][0]
        if base is None:
            return f"({part.at(p[0], 0)}, {part.at(p[1], 1)})"
        # on the body's centre line a text stays on it (a title centred on the plate)
        return "(" + ", ".join(part.at(p[a], a, ref=None if part.on_centre(p[a], a)
                                       else base[a]) for a in (0, 1)) + ")"
    return place
