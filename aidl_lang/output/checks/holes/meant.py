"""W0508's exceptions (issue 111): two overlapping holes that cut one opening as drawn.

:class:`MeantMerge` is asked by :func:`.openings._analyse` for each pair of holes of a part
whose regions overlap; a pair it answers True for is neither W0508 nor measured as a web."""
from __future__ import annotations

from ..common import _area, _union

# a hole is a trim of the part's outline (W0508 leaves the holes it opens alone) when at least
# this share of its drawn area lies off the part and what it cuts is at least TRIM_PART of it
TRIM_OFF, TRIM_PART = 0.5, 0.25


class MeantMerge:
    """Whether two overlapping holes of a part (features ``i``, ``j`` of :func:`_analyse`,
    their ``common`` region) cut one opening as drawn, so that W0508 says nothing:

    * one of them is a **trim** of the outline: at least :data:`TRIM_OFF` of its drawn area
      lies off the part and it cuts at least :data:`TRIM_PART` of the part (a rectangle hole
      that halves a ring, the other half laid out beside it: the ring's opening, halved with
      it, opens onto the new edge as drawn; issue 111's second run, a mirror frame in two
      halves, 2 of its 8 false alarms);
    * their common area lies wholly in one hole's run past its cut: in its ``overrun=true``
      shapes and none of its others (a joint template's cut run 1 mm past its ends, which
      meets the ring's opening instead of the air: the run is there to cut cleanly through
      whatever edge it meets; 6 of the 8).

    Each hole's trim and its shapes other than the overrun are found once, when first asked."""

    def __init__(self, d, shape, feats, areas):
        self.d, self.shape, self.feats, self.areas = d, shape, feats, areas
        self.part = None                # the part's area, found when first needed
        self.trim: dict = {}
        self.cuts: dict = {}

    def _trim(self, k: int) -> bool:
        if k not in self.trim:
            drawn = self.d.shapes.get(self.feats[k].hole)
            cut = self.areas[k + 1]          # (feature k + 1: 0 is the outline)
            whole = _area(drawn) if drawn is not None else 0.0
            off = whole > 0 and cut <= (1 - TRIM_OFF) * whole     # mostly off the part
            if off and self.part is None:
                self.part = _area(self.shape)
            self.trim[k] = off and cut >= TRIM_PART * (self.part + cut)
        return self.trim[k]

    def _cut(self, k: int):
        """Hole ``k``'s shapes other than its ``overrun=true`` ones (united), when it has
        some overrun (a joint template's hole); else None."""
        if k not in self.cuts:
            own = [(g, f) for g, f in self.d.own.get(self.feats[k].hole, ())
                   if f is not None and not f.is_empty()]
            runs = any(g.data.get("overrun") for g, _ in own)
            cut = [f for g, f in own if not g.data.get("overrun")]
            self.cuts[k] = (_union(cut) if cut else False) if runs else None
        return self.cuts[k]

    def __call__(self, i: int, j: int, common) -> bool:
        if self._trim(i) or self._trim(j):
            return True
        for k in (i, j):                # the common area only in k's run past its cut
            cut = self._cut(k)
            if cut is False or (cut is not None and _area(common ^ cut) <= 1e-9):
                return True
        return False
