"""Profiles with a known design (issue 93, round five: "L, T, U, Z brackets and stepped plates
come in as literal Line/Arc chains"), for benchmarks/imports/infer_edits.py ``--kinds
profiles``.  Their truths are the spec's (docs/import.md, "What an edit means": a profile
keeps its walls' thickness), written here as a maker dimensions each kind, not from the
inference:

* ``l_bracket``: legs ``a`` (along x) and ``b`` (along y) to the outside, walls ``t`` (the
  upright leg's) and ``u`` (the level leg's); equal legs are one number (an equal angle) and
  then so are the walls; a hole in the middle of each leg (``hole_d``), or none;
* ``t_bracket``: a bar ``W`` wide and ``t`` thick, a stem ``s`` wide centred under it, ``H``
  high in all;
* ``u_bracket``: ``W`` by ``H``, walls ``t`` and a base ``tb`` (one number when equal), its
  opening wider than half its width (narrower, it is a plate with a notch);
* ``z_bracket``: ``W`` by ``H``, flanges and web ``t`` thick, the web ``e`` from the end
  nearer it;
* ``stepped``: a plate ``W`` by ``H`` with two steps down at one corner: ``h1`` up from the
  bottom and ``a1`` in from the right, then ``h2`` down from the top and ``a2`` in from the
  right.

Any of them is turned (its axes swapped) and mirrored either way, drawn from any origin, its
inside corners rounded by ``ri`` and its outside ones by ``ro`` (0: sharp; equal: one
number).  A design whose numbers a drawing cannot tell apart (two of its lengths equal by
chance, a face as near the other edge) is not drawn: the spec would read it otherwise.
"""
from __future__ import annotations

import copy
import math
import random

from gen_drawings import IN, MM, Design, Edit, circle, polygon

PROFILE_KINDS = ("l_bracket", "t_bracket", "u_bracket", "z_bracket", "stepped")
EQUAL = {"l_bracket": [("a", "b"), ("t", "u")], "t_bracket": [("t", "s")],
         "u_bracket": [("t", "tb")]}


def _corners(k: str, P: dict) -> list:
    """The profile's corners, counter-clockwise, before it is turned (design units)."""
    if k == "l_bracket":
        a, b, t, u = P["a"], P["b"], P["t"], P["u"]
        return [(0, 0), (a, 0), (a, u), (t, u), (t, b), (0, b)]
    if k == "t_bracket":
        W, H, t, s = P["W"], P["H"], P["t"], P["s"]
        return [(W / 2 - s / 2, 0), (W / 2 + s / 2, 0), (W / 2 + s / 2, H - t), (W, H - t),
                (W, H), (0, H), (0, H - t), (W / 2 - s / 2, H - t)]
    if k == "u_bracket":
        W, H, t, tb = P["W"], P["H"], P["t"], P["tb"]
        return [(0, 0), (W, 0), (W, H), (W - t, H), (W - t, tb), (t, tb), (t, H), (0, H)]
    if k == "z_bracket":
        W, H, t, e = P["W"], P["H"], P["t"], P["e"]
        return [(0, 0), (e + t, 0), (e + t, H - t), (W, H - t), (W, H), (e, H), (e, t), (0, t)]
    W, H, h1, a1, h2, a2 = (P[x] for x in ("W", "H", "h1", "a1", "h2", "a2"))
    return [(0, 0), (W, 0), (W, h1), (W - a1, h1), (W - a1, H - h2), (W - a2, H - h2),
            (W - a2, H), (0, H)]


def _lengths(k: str, P: dict) -> list:
    """The lengths a maker reads off the drawing, ``(name, value)``: two of different names
    must differ (else the drawing cannot tell which is meant)."""
    g = P.get
    if k == "l_bracket":
        out = [("a", P["a"]), ("b", P["b"]), ("t", P["t"]), ("u", P["u"]),
               ("fa", P["a"] - P["t"]), ("fb", P["b"] - P["u"])]
    elif k == "t_bracket":
        out = [("W", P["W"]), ("H", P["H"]), ("t", P["t"]), ("s", P["s"]),
               ("side", (P["W"] - P["s"]) / 2), ("stem", P["H"] - P["t"])]
    elif k == "u_bracket":
        out = [("W", P["W"]), ("H", P["H"]), ("t", P["t"]), ("tb", P["tb"]),
               ("gap", P["W"] - 2 * P["t"]), ("depth", P["H"] - P["tb"])]
    elif k == "z_bracket":
        W, H, t, e = P["W"], P["H"], P["t"], P["e"]
        out = [("W", W), ("H", H), ("t", t), ("e", e), ("f", W - e - t), ("b", e + t),
               ("top", W - e), ("web", H - 2 * t)]
    else:
        W, H = P["W"], P["H"]
        out = [("W", W), ("H", H)] + [(x, P[x]) for x in ("h1", "a1", "h2", "a2")] + \
            [("top", W - P["a2"]), ("run", P["a2"] - P["a1"]), ("rise", H - P["h1"] - P["h2"])]
    del g
    return out


class ProfileDesign(Design):
    """A profile (module doc) as a :class:`~gen_drawings.Design`: ``width`` and ``height``
    its box, ``features`` its holes, ``P`` its numbers, ``turn`` ``(swap, flip x, flip y)``."""

    def __init__(self, units: str, kind: str, P: dict, turn: tuple, origin: tuple,
                 same: set, holes: float = 0.0):
        super().__init__(units, 0.0, 0.0, ("square", 0.0), origin)
        self.kind, self.P, self.turn, self.same = kind, P, turn, set(same)
        self.hole_d = holes
        self._box()

    def _box(self) -> None:
        pts = _corners(self.kind, self.P)
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        w, h = max(xs) - min(xs), max(ys) - min(ys)
        self.width, self.height = (h, w) if self.turn[0] else (w, h)
        self.features = [{"kind": "hole", "d": self.hole_d, "i": i}
                         for i in range(len(self._hole_spots()))]

    def _hole_spots(self) -> list:
        if not self.hole_d or self.kind != "l_bracket":
            return []
        a, b, t, u = (self.P[x] for x in "abtu")
        return [((t + a) / 2, u / 2), (t / 2, (u + b) / 2)]

    def _map(self, p) -> tuple:
        x, y = p
        if self.turn[0]:
            x, y = y, x
        if self.turn[1]:
            x = self.width - x
        if self.turn[2]:
            y = self.height - y
        return (self.origin[0] + x, self.origin[1] + y)

    def radii(self) -> list:
        pts = _corners(self.kind, self.P)
        n = len(pts)
        out = []
        for k in range(n):
            p, q, r = pts[k - 1], pts[k], pts[(k + 1) % n]
            convex = (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]) > 0
            out.append(self.P["ro"] if convex else self.P["ri"])
        return out

    def outline(self) -> list:
        pts = [self._map(p) for p in _corners(self.kind, self.P)]
        radii = self.radii()
        if sum(self.turn) % 2:          # mirrored: counter-clockwise again
            pts, radii = pts[::-1], radii[::-1]
        return _filleted(pts, radii)

    def place(self, f) -> tuple:
        return self._map(self._hole_spots()[f["i"]])

    def feature_loops(self, i: int) -> list:
        return [circle(self.place(self.features[i]), self.hole_d / 2)]

    def marks(self) -> list:
        return []

    def labels(self) -> list:
        return []

    def describe(self) -> str:
        return (f"{self.kind} {self.units}, turned {self.turn}, from {self.origin}: "
                + ", ".join(f"{k} {v:g}" for k, v in self.P.items())
                + (f"; equal {sorted(self.same)}" if self.same else "")
                + (f"; holes d {self.hole_d:g}" if self.hole_d else ""))

    def edits(self) -> list:
        k = self.kind
        ext = [(r"leg|width|height", 1.0)]
        wall = [(r"wall(_[xy])?|stem_width|step(_[xy])?(_\d+)?", 1.0)]
        fil = [(r"fillet|corner_radius", 1.0)]
        keys = {"l_bracket": [("body", "a", "leg a"), ("body", "b", "leg b"),
                              ("size", "t", "wall"), ("size", "u", "wall u")],
                "t_bracket": [("body", "W", "width"), ("body", "H", "height"),
                              ("size", "t", "bar thickness"), ("size", "s", "stem width")],
                "u_bracket": [("body", "W", "width"), ("body", "H", "height"),
                              ("size", "t", "wall"), ("size", "tb", "base")],
                "z_bracket": [("body", "W", "width"), ("body", "H", "height"),
                              ("size", "t", "thickness"), ("size", "e", "web place")],
                "stepped": [("body", "W", "width"), ("body", "H", "height"),
                            ("size", "h1", "first step"), ("size", "a1", "first step in"),
                            ("size", "h2", "second step"), ("size", "a2", "second step in")]}[k]
        out = []
        for kind, key, label in keys:
            if any(key == b for a, b in EQUAL.get(k, ()) if (a, b) in self.same):
                continue                # one number with its equal
            out.append(Edit(kind, k, -1, key, f"{k} {label}", ext if kind == "body" else wall,
                            whole=kind == "body"))
        for key, label in (("ri", "fillet"), ("ro", "corner radius")):
            if self.P[key] and not (key == "ro" and "r" in self.same):
                out.append(Edit("size", k, -1, key, f"{k} {label}", fil))
        if self.hole_d:
            out.append(Edit("size", k, 0, "d", f"{k} hole diameter",
                            [(r"d|dia|diameter", 1.0)]))
        return out

    def value(self, e: Edit) -> float:
        return self.hole_d if e.key == "d" else self.P[e.key]

    def edited(self, e: Edit, new: float) -> "ProfileDesign":
        d = copy.deepcopy(self)
        if e.key == "d":
            d.hole_d = new
        else:
            d.P[e.key] = new
            for a, b in list(EQUAL.get(self.kind, ())) + [("ri", "ro")]:
                if e.key == a and ((a, b) in self.same or (a == "ri" and "r" in self.same)):
                    d.P[b] = new
        d._box()
        return d

    def valid(self) -> bool:
        return _valid(self)


def _filleted(pts: list, radii: list) -> list:
    """The loop through ``pts`` with corner ``k`` rounded by a quarter arc of ``radii[k]``."""
    n = len(pts)
    if not any(radii):
        return polygon(pts)
    ends = []
    for k in range(n):
        p, q, r = pts[k - 1], pts[k], pts[(k + 1) % n]
        rad = radii[k]
        if not rad:
            ends.append((q, q, None))
            continue
        u = _unit(q, p)
        v = _unit(q, r)
        a = (q[0] + u[0] * rad, q[1] + u[1] * rad)
        b = (q[0] + v[0] * rad, q[1] + v[1] * rad)
        c = (q[0] + (u[0] + v[0]) * rad, q[1] + (u[1] + v[1]) * rad)
        t0 = math.atan2(a[1] - c[1], a[0] - c[0])
        t1 = math.atan2(b[1] - c[1], b[0] - c[0])
        sw = (t1 - t0 + math.pi) % (2 * math.pi) - math.pi
        ends.append((a, b, ("A", c, rad, t0, sw)))
    out = []
    for k in range(n):
        if ends[k][2] is not None:
            out.append(ends[k][2])
        p, q = ends[k][1], ends[(k + 1) % n][0]
        if math.dist(p, q) > 1e-12:
            out.append(("L", p, q))
    return out


def _unit(a, b) -> tuple:
    d = math.dist(a, b)
    return ((b[0] - a[0]) / d, (b[1] - a[1]) / d)


def _valid(d: ProfileDesign) -> bool:
    """Every number positive, each face nearer the edge it is measured from, the fillets
    room on every side, no two lengths of different names equal (module doc)."""
    m = 1.5 / d.u
    P, k = d.P, d.kind
    if any(v < 0 for v in P.values()) or d.hole_d < 0:
        return False
    lens = _lengths(k, P)
    if any(v <= m for _, v in lens):
        return False
    same = {frozenset(p) for p in EQUAL.get(k, ()) if p in d.same}
    if frozenset(("a", "b")) in same:
        same.add(frozenset(("fa", "fb")))       # equal legs, equal walls: equal free lengths
    for i in range(len(lens)):
        for j in range(i + 1, len(lens)):
            a, b = lens[i], lens[j]
            if frozenset((a[0], b[0])) in same:
                if abs(a[1] - b[1]) > 1e-9:
                    return False
            elif abs(a[1] - b[1]) < m:
                return False
    if k == "l_bracket" and not (P["t"] < P["a"] / 2 - m and P["u"] < P["b"] / 2 - m):
        return False
    if k == "l_bracket" and ("a", "b") in d.same and ("t", "u") not in d.same:
        return False
    if k == "t_bracket" and not (P["t"] < P["H"] / 2 - m and P["s"] < P["W"] - 2 * m):
        return False
    if k == "u_bracket" and not (P["t"] < P["W"] / 4 - m and P["tb"] < P["H"] / 2 - m):
        return False
    if k == "z_bracket" and not (P["e"] < P["W"] - P["e"] - P["t"] - m and P["t"] < P["H"] / 2 - m):
        return False
    if k == "stepped" and not (P["h1"] < P["H"] / 2 - m and P["h2"] < P["H"] / 2 - m
                               and P["a1"] < P["a2"] - m and P["a2"] < P["W"] / 2 - m):
        return False
    if max(d.width, d.height) > 3 * min(d.width, d.height):
        return False
    # each side long enough for the fillets at its ends
    pts = _corners(k, P)
    rad = d.radii()
    n = len(pts)
    for i in range(n):
        if math.dist(pts[i], pts[(i + 1) % n]) < 2 * max(rad[i], rad[(i + 1) % n]) + m:
            return False        # a fillet takes at most half a side (as `Fillet` rounds)
    if "r" in d.same and P["ri"] != P["ro"]:
        return False
    if P["ri"] and P["ro"] and "r" not in d.same and abs(P["ri"] - P["ro"]) < m:
        return False
    if d.hole_d:
        t = min(P["t"], P["u"])
        if d.hole_d > t - 2 * m or d.hole_d / 2 + m > min(P["a"] - P["t"], P["b"] - P["u"]) / 2 \
                - P["ri"]:
            return False
    return True


def random_profile(rng: random.Random, kind: str) -> ProfileDesign:
    """A random profile of ``kind`` (module doc) that the spec reads one way."""
    units = "in" if rng.random() < 0.25 else "mm"
    T = IN if units == "in" else MM
    big, off, r = T["plate"], T["off"], T["r"]
    for _ in range(500):
        same = set()
        if kind == "l_bracket":
            P = {"a": rng.choice(big[:8]), "b": rng.choice(big[:8]), "t": rng.choice(off[:5])}
            P["u"] = P["t"] if rng.random() < 0.6 else rng.choice(off[:5])
            if rng.random() < 0.4:
                P["b"], P["u"] = P["a"], P["t"]
                same |= {("a", "b")}
            if P["u"] == P["t"]:
                same |= {("t", "u")}
        elif kind == "t_bracket":
            P = {"W": rng.choice(big[:9]), "H": rng.choice(big[:8]), "t": rng.choice(off[:5])}
            P["s"] = P["t"] if rng.random() < 0.4 else rng.choice(off[1:] + T["pitch"])
            if P["s"] == P["t"]:
                same.add(("t", "s"))
        elif kind == "u_bracket":
            P = {"W": rng.choice(big[:9]), "H": rng.choice(big[:8]), "t": rng.choice(off[:5])}
            P["tb"] = P["t"] if rng.random() < 0.6 else rng.choice(off[:6])
            if P["tb"] == P["t"]:
                same.add(("t", "tb"))
        elif kind == "z_bracket":
            P = {"W": rng.choice(big[:9]), "H": rng.choice(big[:8]), "t": rng.choice(off[:5]),
                 "e": rng.choice(off[2:] + T["pitch"])}
        else:
            P = {"W": rng.choice(big[2:]), "H": rng.choice(big[1:]),
                 "h1": rng.choice(off), "h2": rng.choice(off), "a1": rng.choice(off + T["pitch"]),
                 "a2": rng.choice(T["pitch"] + T["big"])}
        P["ri"] = rng.choice([0.0, 0.0, r[0], r[1]]) if kind != "stepped" else \
            rng.choice([0.0, r[0]])
        P["ro"] = rng.choice([0.0, 0.0, P["ri"], r[0]])
        if P["ri"] and P["ri"] == P["ro"]:
            same.add("r")
        turn = (rng.random() < 0.5, rng.random() < 0.5, rng.random() < 0.5)
        origin = rng.choice([(0.0, 0.0), (0.0, 0.0), (rng.choice(T["step"]), rng.choice(T["step"]))])
        hole = rng.choice([0.0, rng.choice(T["d"][:6])]) if kind == "l_bracket" else 0.0
        d = ProfileDesign(units, kind, P, turn, origin, same, hole)
        if origin != (0.0, 0.0) and rng.random() < 0.3:
            d.origin = (-d.width / 2, -d.height / 2)
        if d.valid():
            d.style = {"format": "svg" if rng.random() < 0.25 else "dxf",
                       "layers": rng.choice([None, None, ("OUTLINE", "HOLES", "LABELS")]),
                       "blocks": rng.random() < 0.4, "bulges": rng.random() < 0.6,
                       "insunits": True}
            return d
    raise RuntimeError(f"no {kind} found")
