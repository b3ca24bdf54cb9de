"""``aidl import --infer``: countersinks and counterbores written with their holes (issue 85,
"countersink pairs").  A layer of circles named for them (COUNTERSINK, CSK, C-BORE, Spotface:
:data:`~..chains.layers._SINK_LAYER`) is marked, not cut; a mark concentric with a hole and
larger than it is the top circle of that hole's countersink.  Each mark is written with its
hole's statement - a countersink's as ``Countersink(HOLE, diameter=countersink_d)`` (issue
102), a counterbore's or spotface's (whose depth the drawing does not give) as a circle at the
hole's centre as written - its diameter a param, so that every edit that moves the holes (the
plate's size, an inset, a pitch) moves the marks with them; when only some of a pattern's holes are marked (issue 91:
three of four corner holes), under an ``if`` naming their turns of the loop (:func:`condition`,
the turns from :mod:`.turns`).  A mark on no hole stays where the drawing puts it, in the
layer's ``drawing``.  Lengths in the drawing's unit; the results are program text.
"""
from __future__ import annotations

import re
from ..shapes import EQUAL_TOL, Shape
from ...chains.layers import _SINK_LAYER
from dataclasses import replace

from ...model import Drawing


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
    def common(sunk: dict, members: list) -> list | None:
        """The marks of the holes one hole statement writes (``members``: a pattern's Shapes,
        or a single hole), by word and radius (within EQUAL_TOL): ``[(word, radius, mark
        ids, marked Shapes)]``; None when no member has a mark in ``sunk`` (:meth:`attach`).
        A group that is every member is written as the hole's own mark; a group of some
        (three of four corner holes countersunk) under an ``if`` naming those members
        (:meth:`write`)."""
        groups: list = []
        for sh in members:
            g = sunk.get(id(sh))
            if g is None:
                continue
            radius, word_g, mark = g
            for word, r, ids, shapes in groups:
                if word == word_g and abs(r - radius) <= EQUAL_TOL:
                    ids.append(mark)
                    shapes.append(sh)
                    break
            else:
                groups.append((word_g, radius, [mark], [sh]))
        return groups or None

    def write(self, part, depth: int, hn: str, sh: Shape, center: str, groups: list,
              members: list, index=None) -> None:
        """The marks of hole ``hn`` (Shape ``sh`` at ``center``, program text) beside it in
        ``part``: ``Countersink(hn, diameter=...)`` for a countersink, else a ``drawing`` of a
        circle at the same centre; the diameter the param of its word, one for each pattern of holes, named by them (``countersink_d``
        of ``holes``, ``corner_countersink_d`` of ``corner_holes``).  A group marking some
        of ``members`` only is written under ``if`` over the loop's variables
        (``index(Shape)``: ``((variable, value), ...)`` of that member's turn of the loop,
        :func:`condition`); without ``index`` it stays as drawn."""
        for k, (word, r, ids, marked) in enumerate(groups):
            cond = None
            if len(marked) < len(members):
                cond = condition(index, marked, members) if index is not None else None
                if cond is None:
                    continue
            self.used.update(ids)
            key = (id(part), hn, k)    # a pattern written in several statements: one param
            if key not in self.words:
                base = re.sub(r"_?holes?$", "", hn)
                self.words[key] = part.params.add(
                    f"{base}_{word}_d" if base else f"{word}_d", 2 * r,
                    f"marked about {hn}" + (" (some of them)" if cond else "") + ", not cut")
            nm = f"{hn}_{word}" + (f"_{k + 1}" if k else "")
            d = depth
            if cond is not None:
                part.w.emit(depth, f"if {cond} {{     # {word}s on {len(marked)} of these "
                                   f"{len(members)} holes, as drawn")
                d += 1
            if word == "countersink":       # the hole's own countersink (issue 102)
                part.w.emit(d, f"Countersink({hn}, diameter={self.words[key]})")
            else:                           # a counterbore's depth is not in the drawing
                part.w.emit(d, f"drawing {nm} {{ c = Circle(center={center}, "
                               f"diameter={self.words[key]}) }}")
                part.w.emit(d, f"Fixed({nm}.c)")
            if cond is not None:
                part.w.emit(depth, "}")

    def left(self, name: str, d: Drawing) -> Drawing | None:
        """The drawing item ``name`` (``d``) without the circles written with a hole; None
        when it is a sink layer's and every circle of it is."""
        if name not in self.names:
            return d
        d = replace(d, circles=[c for c in d.circles if id(c) not in self.used])
        return None if not d.circles else d



def condition(index, marked: list, members: list) -> str | None:
    """The condition over a loop's variables that holds on the turns writing ``marked`` and
    no other of ``members`` (``index(Shape)``: ``((variable, value), ...)``): the marked
    turns listed (``i == 1 or i == 3``), or the others excluded (``i != 2``,
    ``not (sx == 1 and sy == 1)``), whichever is shorter; None when two members share a
    turn (the index does not tell them apart)."""
    keys = {id(sh): tuple(index(sh)) for sh in members}
    if len(set(keys.values())) != len(members) or not all(keys.values()):
        return None
    ids = {id(sh) for sh in marked}
    yes = [keys[id(sh)] for sh in members if id(sh) in ids]
    no = [keys[id(sh)] for sh in members if id(sh) not in ids]

    def term(t: tuple, op: str = "==", join: str = " and ") -> str:
        return join.join(f"{v} {op} {x}" for v, x in t)

    def wrap(t: tuple) -> str:
        return f"({term(t)})" if len(t) > 1 else term(t)
    pos = " or ".join(term(t) if len(yes) == 1 else wrap(t) for t in yes)
    if len(no) == 1:
        neg = term(no[0], "!=", " or ") if len(no[0]) == 1 else f"not ({term(no[0])})"
    else:
        neg = f"not ({' or '.join(wrap(t) for t in no)})"
    return pos if len(pos) <= len(neg) else neg
