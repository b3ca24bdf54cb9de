"""W0508's exceptions (issue 111): two overlapping holes that cut one opening as drawn.

:class:`MeantMerge` is asked by :func:`.openings._analyse` for each pair of holes of a part
whose regions overlap; a pair it answers True for is neither W0508 nor measured as a web."""
from __future__ import annotations

import manifold3d as mf

from ..common import _area, _union

# a hole is a trim of the part's outline (W0508 leaves the holes it opens alone) when at least
# this share of its drawn area lies off the part and what it cuts is at least TRIM_PART of it
TRIM_OFF, TRIM_PART = 0.5, 0.25
MOUTH_TOUCH = 0.01      # mm: a hole this near a joint's mouth opens it (the drawn edges meet)
RUN_OUT = 0.01          # of a hole's drawn area off the part: it runs out through the edge


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

    * the smaller runs out through the part's edge (a **channel** from the edge into the
      other: a USB notch into a board pocket, run dn);
    * one is a joint template's cut whose **mouth opens into the other**: the strip its run
      past its cut adds (where the cut meets the edge) touches the other hole, which has
      taken that edge away (issue 111's third run: a plant stand's cross-halving slot cut up
      from the bottom edge, through the arch between its feet; the slot reaches the edge
      through the arch, as it must to slide onto its mate).

    Each hole's trim, its shapes other than the overrun and its mouth are found once, when
    first asked."""

    def __init__(self, d, shape, feats, areas):
        self.d, self.shape, self.feats, self.areas = d, shape, feats, areas
        self.part = None                # the part's area, found when first needed
        self.trim: dict = {}
        self.cuts: dict = {}
        self.mouths: dict = {}

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

    def _mouth(self, k: int):
        """Hole ``k``'s mouth: its ``overrun=true`` shapes less its others (the 1 mm strip a
        joint's cut runs past the edge), or None when it has no overrun."""
        if k not in self.mouths:
            cut = self._cut(k)
            mouth = None
            if cut is not None:
                runs = _union([f for g, f in self.d.own.get(self.feats[k].hole, ())
                               if f is not None and g.data.get("overrun")])
                mouth = runs - cut if cut is not False else runs
                mouth = None if mouth.is_empty() else mouth
            self.mouths[k] = mouth
        return self.mouths[k]

    def opens_into(self, i: int, j: int) -> bool:
        """One of holes ``i``, ``j`` is a joint's cut whose mouth touches the other (drawn
        as written, grown by :data:`MOUTH_TOUCH`)."""
        for k, m in ((i, j), (j, i)):
            mouth = self._mouth(k)
            other = self.d.shapes.get(self.feats[m].hole) if mouth is not None else None
            if other is not None and not other.is_empty() and _area(
                    mouth ^ other.offset(MOUTH_TOUCH, mf.JoinType.Miter)) > 1e-9:
                return True
        return False

    def _runs_out(self, k: int) -> bool:
        """Hole ``k`` runs out through the part's edge: part of its drawn area (at least
        :data:`RUN_OUT` of it) lies off the part's material."""
        drawn = self.d.shapes.get(self.feats[k].hole)
        whole = _area(drawn) if drawn is not None else 0.0
        return whole > 0 and whole - self.areas[k + 1] >= RUN_OUT * whole

    def channel(self, i: int, j: int) -> bool:
        """The smaller of holes ``i``, ``j`` runs out through the part's edge into the other:
        a notch from the edge into an opening, one opening as drawn (issue 111's run dn: a
        USB notch through a case's bottom edge into its board pocket)."""
        k = i if self.areas[i + 1] <= self.areas[j + 1] else j
        return self._runs_out(k)

    def __call__(self, i: int, j: int, common) -> bool:
        if self._trim(i) or self._trim(j) or self.opens_into(i, j) or self.channel(i, j):
            return True
        for k in (i, j):                # the common area only in k's run past its cut
            cut = self._cut(k)
            if cut is False or (cut is not None and _area(common ^ cut) <= 1e-9):
                return True
        return False
