"""``aidl import --infer``: where a text of an engraving is placed from (issue 85) - with the
hole it names (directly above, below or beside it, within :data:`LABEL_REACH` of its edge),
so that it moves with that hole when the plate grows, else from the body's centre line or
nearer edge (:class:`~.anchors._Anchored`).  Used by :func:`~.infer._solid` through
:func:`~.engraving._engraving` (docs/import.md, "Where things are placed from").
"""
from __future__ import annotations

import math
from collections import Counter

from ..holes.features import arc_slot, d_hole, keyhole, merged
from ..shapes import EQUAL_TOL, recognise
from ...write.writer import _pt
from ...write.units import UNIT
from ...model import _segs_box


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
    it when the plate grows or the hole's size changes, else from the body's centre line or
    nearer edge (:meth:`~.anchors._Anchored.at`).  A text names the nearest hole it is
    directly above, below or beside: on the line through the hole's centre, that line
    crossing the hole (an arc slot's centre, off the slot, names nothing), and nearer the
    hole's edge than :data:`LABEL_REACH` or than the body's edge behind the text (a text
    sits with what is nearest it); a hole of a size no other hole has before a pattern's
    member.  A text in line with none names none (near a hole but off its lines, it is as
    likely the plate's).  The text follows the hole's place as written (a cut-out's centre
    moves with its width from the edge it is tied to: :meth:`~.anchors._Anchored.
    written_at`).  Along an axis on which the text is on the body's centre line it stays on
    that line."""
    if part.anchor is None:
        return lambda p, size: _pt(p)
    unit = 25.4 if UNIT.get() == "in" else 1.0
    known: dict = {}
    cell = 10 * EQUAL_TOL

    def index() -> dict:         # on the first text: most drawings have none
        if not known:
            refs = [_hole_ref(segs) for segs in holes]
            lines: tuple = ({}, {})         # per axis: the holes whose centre is on a line
            for i, (c, _) in enumerate(refs):
                for a in (0, 1):
                    lines[a].setdefault(math.floor(c[a] / cell), []).append(i)
            known.update(refs=refs, boxes=[_segs_box(segs) for segs in holes], lines=lines,
                         shared=Counter(k for _, k in refs if k))
        return known

    def behind(p, a: int, sign: int) -> float:
        """How far the body's edge is from ``p`` along axis ``a`` on the side ``sign``."""
        sh = part.anchor[0]
        half = sh.args["width" if a == 0 else "height"] / 2
        return abs(sh.center[a] + sign * half - p[a])

    def aligned(p) -> int | None:
        k = index()
        best = None
        for a in (0, 1):                # a: the axis along which the text is in line
            o = 1 - a                   # the text is above/below (a = 0) or beside
            key = math.floor(p[a] / cell)
            for i in (i for kk in (key - 1, key, key + 1) for i in k["lines"][a].get(kk, ())):
                (c, key_), b = k["refs"][i], k["boxes"][i]
                if abs(p[a] - c[a]) > EQUAL_TOL or not b[a] <= p[a] <= b[a + 2]:
                    continue
                gap = max(b[o] - p[o], p[o] - b[o + 2])
                if gap <= 0:
                    continue
                # the body's edge on the text's far side from the hole
                far = behind(p, o, -1 if p[o] < b[o] else 1)
                if gap > LABEL_REACH / unit and gap >= far:
                    continue
                # one of a pattern's size only when no hole of its own is in line
                rank = (key_ is not None and k["shared"][key_] > 1, gap, i)
                if best is None or rank < best:
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
        return "(" + ", ".join(part.at(p[a], a) if part.on_centre(p[a], a)
                               else part.written_at(p[a], a, base) for a in (0, 1)) + ")"
    return place
