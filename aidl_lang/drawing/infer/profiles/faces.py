"""What each face of a profile follows (docs/import.md, "What an edit means": a profile keeps
its thicknesses; issue 93).  A face is one x (or y) that sides of the profile lie on; the
outer faces are its box's edges, placed by the profile's width and height (an L's equal
legs: one ``leg``); each inner face, taken nearest its edge first, is placed

* by the **thickness** from the edge nearer it, when it is that far in (an L's, a U's
  walls; the thickness is an arm's: the shortest side between two outside corners);
* about the centre line with the **width** between them, when it and another face are as
  far from it on either side (a T's stem);
* by the thickness from the face beside it, when that face is placed and they are the
  thickness apart (a Z's web);
* else by its own distance from the edge nearer it (a step, a second thickness).

A hole in a profile sits midway between the two faces either side of it when it does (an
arm's middle), else by its distance from the nearest face.  Values equal within
:data:`~..shapes.EQUAL_TOL` are one param.  Lengths in mm; no program text here (the writer,
:mod:`.write`, names and writes what this finds)."""
from __future__ import annotations

from dataclasses import dataclass, field

from ..shapes import EQUAL_TOL


@dataclass
class Face:
    """Where one face is placed from: ``how`` ``"edge"`` (``side`` -1/1, the box's low or
    high edge, ``dist`` in from it; ``dist`` 0: the edge itself), ``"mid"`` (``side`` -1/1
    of the centre line, ``dist`` the width between the pair) or ``"next"`` (``ref`` the face
    it is ``dist`` from, toward ``side``).  ``role`` names the value: ``thickness``,
    ``width`` (a centred pair's), ``step`` or ``outer``."""
    value: float
    how: str
    side: int
    dist: float
    role: str
    ref: float | None = None


@dataclass
class Faces:
    """The faces of a profile per axis (``faces[axis]``: value -> :class:`Face`), its box,
    its thickness and whether it is an L of equal legs and thicknesses."""
    box: tuple
    thickness: float
    faces: list = field(default_factory=lambda: [{}, {}])
    equal_legs: bool = False

    def face(self, v: float, axis: int) -> Face:
        for k, f in self.faces[axis].items():
            if abs(k - v) <= EQUAL_TOL:
                return f
        raise KeyError(v)

    def values(self, axis: int) -> list:
        return sorted(self.faces[axis])


def _eq(a: float, b: float) -> bool:
    return abs(a - b) <= EQUAL_TOL


def _distinct(vals) -> list:
    out: list = []
    for v in sorted(vals):
        if not out or v - out[-1] > EQUAL_TOL:
            out.append(v)
    return out


def arm_ends(corners: list, convex: list) -> list:
    """The lengths of the sides between two outside corners (each arm's end)."""
    n = len(corners)
    return [abs(corners[k][0] - corners[(k + 1) % n][0]) + abs(corners[k][1] - corners[(k + 1) % n][1])
            for k in range(n) if convex[k] and convex[(k + 1) % n]]


def find_faces(corners: list, convex: list) -> Faces:
    """The faces of a profile (module doc)."""
    xs = [p[0] for p in corners]
    ys = [p[1] for p in corners]
    box = (min(xs), min(ys), max(xs), max(ys))
    ends = arm_ends(corners, convex)
    t = min(ends) if ends else 0.0     # the thickness: the shortest arm's end
    out = Faces(box, t)
    for axis, vals in ((0, xs), (1, ys)):
        lo, hi = box[axis], box[axis + 2]
        got = out.faces[axis]
        got[lo] = Face(lo, "edge", -1, 0.0, "outer")
        got[hi] = Face(hi, "edge", 1, 0.0, "outer")
        inner = [v for v in _distinct(vals) if v - lo > EQUAL_TOL and hi - v > EQUAL_TOL]
        every = _distinct(vals)

        def near(v):
            return (v - lo, -1) if v - lo <= hi - v + EQUAL_TOL else (hi - v, 1)
        for v in sorted(inner, key=lambda v: (round(near(v)[0], 9), v)):
            if any(_eq(v, k) for k in got):
                continue
            d, side = near(v)
            if _eq(d, t):
                got[v] = Face(v, "edge", side, d, "thickness")
                continue
            pair = next((w for w in inner if not _eq(w, v) and _eq(v + w, lo + hi)), None)
            if pair is not None:
                width = abs(pair - v)
                got[v] = Face(v, "mid", -1 if v < pair else 1, width, "width")
                got[pair] = Face(pair, "mid", -1 if pair < v else 1, width, "width")
                continue
            k = every.index(next(w for w in every if _eq(w, v)))
            nb = [w for w in (every[k - 1], every[k + 1]) if any(_eq(w, g) for g in got)
                  and _eq(abs(w - v), t) and got[next(g for g in got if _eq(g, w))].role != "outer"]
            if nb:
                got[v] = Face(v, "next", 1 if v > nb[0] else -1, t, "thickness", ref=nb[0])
                continue
            role = "thickness" if any(_eq(d, e) for e in ends) else "step"
            got[v] = Face(v, "edge", side, d, role)
    six = len(corners) == 6
    out.equal_legs = six and _eq(box[2] - box[0], box[3] - box[1]) and all(
        f.role == "thickness" and f.how == "edge" and _eq(f.dist, t)
        for axis in (0, 1) for f in out.faces[axis].values() if f.role != "outer")
    return out


def hole_place(fc: Faces, v: float, axis: int) -> tuple:
    """Where a hole's coordinate ``v`` is placed from in a profile: ``("mid", a, b)``
    midway between faces ``a`` and ``b`` either side of it, else ``("face", a, d)`` ``d``
    from the nearest face ``a``."""
    vals = fc.values(axis)
    below = [w for w in vals if w <= v + EQUAL_TOL]
    above = [w for w in vals if w >= v - EQUAL_TOL]
    if below and above:
        a, b = max(below), min(above)
        if b - a > EQUAL_TOL and _eq((a + b) / 2, v):
            return ("mid", a, b)
    a = min(vals, key=lambda w: (round(abs(w - v), 9), w))
    return ("face", a, v - a)
