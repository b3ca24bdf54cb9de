"""``aidl import --infer``: countersinks and counterbores written with their holes (issue 85,
"countersink pairs").  A layer of circles named for them (COUNTERSINK, CSK, C-BORE, Spotface:
:data:`~..chains.layers._SINK_LAYER`) is marked, not cut; a mark concentric with a hole and
larger than it is the top circle of that hole's countersink.  When every hole of one kind and
size has such a mark, of one diameter, each mark is written in the hole's statement - its
centre the hole's centre as written, its diameter a param (``countersink_d``) - so that
every edit that moves the holes (the plate's size, an inset, a pitch) moves the marks with
them.  A mark on no hole, or on a group only partly marked, stays where the drawing puts it,
in the layer's ``drawing``.  Lengths in the drawing's unit; the results are program text.
"""
from __future__ import annotations

import re
from .shapes import EQUAL_TOL, Shape
from ..chains.layers import _SINK_LAYER
from dataclasses import replace

from ..model import Drawing


def _word(layer: str) -> str:
    """What a sink layer's marks are, from its name: countersink, counterbore or spotface."""
    low = layer.lower()
    if "bore" in low:
        return "counterbore"
    if "spot" in low:
        return "spotface"
    return "countersink"


class Marks:
    """The circles of the sink layers of an import: ``circles`` a list of ``(centre, radius,
    word, id)``; ``used`` the ids written with a hole (:meth:`attach`)."""

    def __init__(self, items: list) -> None:
        self.circles: list = []
        self.used: set = set()
        self.names: set = set()     # the sink layers' items
        for kind, name, d, *_ in items:
            if kind == "drawing" and _SINK_LAYER.search(name) and d.circles and not (
                    d.outlines or d.paths or d.texts or d.ellipses):
                self.names.add(name)
                self.circles += [(c.center, c.radius, _word(name), id(c)) for c in d.circles]
        self.words: dict = {}       # (part, hole name) -> its marks' param

    def attach(self, holes: list) -> dict:
        """``{id(Shape): (word, radius, mark id)}`` of each round hole of ``holes`` (Shapes)
        with one concentric, larger mark (within EQUAL_TOL) no other hole took."""
        if not self.circles:
            return {}
        from scipy.spatial import cKDTree
        tree = cKDTree([c for c, *_ in self.circles])
        out = {}
        for sh in holes:
            if sh.kind != "Circle":
                continue
            hits = [self.circles[i] for i in tree.query_ball_point(sh.center, EQUAL_TOL)
                    if self.circles[i][1] > sh.args["radius"] + EQUAL_TOL
                    and self.circles[i][3] not in self.used]
            if len(hits) == 1:
                out[id(sh)] = hits[0][1:]
        return out

    @staticmethod
    def common(sunk: dict, members: list) -> tuple | None:
        """``(word, radius, mark ids)`` when every one of ``members`` (the Shapes one hole
        statement writes: a pattern's, or a single hole) has a mark in ``sunk``
        (:meth:`attach`), all of one word and radius (within EQUAL_TOL); else None (the
        marks stay as drawn)."""
        got = [sunk.get(id(sh)) for sh in members]
        if not got or None in got or any(g[1] != got[0][1] or abs(g[0] - got[0][0]) > EQUAL_TOL
                                          for g in got):
            return None
        return got[0][1], got[0][0], [g[2] for g in got]

    def write(self, part, depth: int, hn: str, sh: Shape, center: str, got: tuple) -> None:
        """The mark of hole ``hn`` (Shape ``sh`` at ``center``, program text) as a
        ``drawing`` beside it in ``part``: a circle at the same centre, its diameter the
        param of its word, one for each pattern of holes, named by them (``countersink_d``
        of ``holes``, ``corner_countersink_d`` of ``corner_holes``)."""
        word, r, ids = got
        self.used.update(ids)
        key = (id(part), hn)       # a pattern written in several statements: one param
        if key not in self.words:
            base = re.sub(r"_?holes?$", "", hn)
            self.words[key] = part.params.add(f"{base}_{word}_d" if base else f"{word}_d",
                                             2 * r, f"marked about {hn}, not cut")
        nm = f"{hn}_{word}"
        part.w.emit(depth, f"drawing {nm} {{ c = Circle(center={center}, "
                           f"diameter={self.words[key]}) }}")
        part.w.emit(depth, f"Fixed({nm}.c)")

    def left(self, name: str, d: Drawing) -> Drawing | None:
        """The drawing item ``name`` (``d``) without the circles written with a hole; None
        when it is a sink layer's and every circle of it is."""
        if name not in self.names:
            return d
        d = replace(d, circles=[c for c in d.circles if id(c) not in self.used])
        return None if not d.circles else d

