"""``aidl import --infer``: groups of holes read as the spec says a maker means them
(issue 93; docs/import.md, "What an edit means"): four at the body's corners even about a
bore (:meth:`_Groups.at_corners`), a board's holes as one set from the corner nearest them
(:meth:`_Groups.hole_set`), and the comment saying what a row or grid follows
(:func:`follows`).  The writing half of :class:`~.infer._Part`: needs ``w``, ``p``,
``stats``, ``anchor``, ``at``, ``edge``, ``nearest``, ``center``, ``shared``,
``surrounds``, ``rings_at``, ``name_near``, ``sunk_as`` and ``hole_block``.  Coordinates in
mm; the results are program text."""
from __future__ import annotations

import math

from ..params import _hole_name
from .find import _whole
from ..shapes import EQUAL_TOL, Shape
from ...write.writer import _pt


def follows(terms: list) -> str:
    """What a row or grid written with the coordinate texts ``terms`` (x, y) follows, as
    its comment says it: ``about its middle`` or ``from its end member`` along each axis
    it runs along."""
    out = []
    for axis, t in enumerate(terms):
        if " - 1) / 2)" in t or "- 1) / 2 -" in t:
            out.append(f"{'xy'[axis]} about its middle")
        elif "range" not in t and any(v in t for v in ("i *", "j *", "(i -", "(j -")):
            out.append(f"{'xy'[axis]} from its end member")
    return ", ".join(out)


def corner_sets(centres: list, body, rest: bool = False) -> list[list[int]] | None:
    """Equal holes that are two or more sets of four at a rectangular body's corners (its
    mounting holes 5 mm in and its feet 12 mm in): their indices by set, each four about the
    body's centre at one distance from it, a 2 x 2 grid nearer the edges than the centre
    lines; else None.  ``rest``: also when other holes are left (a flange's bolt circle of
    the corner holes' size), the others one group after the sets."""
    if body is None or body[0].kind == "Circle" or len(centres) < (5 if rest else 8):
        return None
    c = body[0].center
    W, H = body[0].args.get("width", 0.0), body[0].args.get("height", 0.0)
    by: dict = {}
    for i, p in enumerate(centres):
        by.setdefault(round(math.dist(p, c), 6), []).append(i)
    sets, others = [], []
    for g in by.values():
        pts = [centres[i] for i in g]
        if len(g) == 4 and len({round(abs(p[0] - c[0]), 6) for p in pts}) == 1 and \
                len({round(abs(p[1] - c[1]), 6) for p in pts}) == 1 and \
                len({(p[0] > c[0], p[1] > c[1]) for p in pts}) == 4 and \
                abs(pts[0][0] - c[0]) > W / 4 and abs(pts[0][1] - c[1]) > H / 4:
            sets.append(g)
        else:
            others += g
    if not sets or (others and not rest) or (not others and len(sets) < 2):
        return None
    return sets + ([sorted(others)] if others else [])


def _edge_gap(feat: Shape, p) -> float:
    """How far point ``p`` is from the edge of the feature ``feat`` (a circle, a
    rectangle's box, a regular polygon's circle), outside it."""
    c = feat.center
    if feat.kind in ("Rectangle", "RoundedRectangle") and not feat.args.get("rotation"):
        dx = max(abs(p[0] - c[0]) - feat.args["width"] / 2, 0.0)
        dy = max(abs(p[1] - c[1]) - feat.args["height"] / 2, 0.0)
        return math.hypot(dx, dy)
    return math.dist(p, c) - feat.args.get("radius", 0.0)


def corners_and_pattern(centres: list, body, r: float) -> list[list[int]] | None:
    """Four (or more sets of four) holes at the body's corners and the rest of that size
    one pattern (a grille's mounting holes the size of its holes): the sets, then the
    pattern; else None (:func:`corner_sets`)."""
    sets = corner_sets(centres, body, rest=True)
    if sets is None or len(sets) < 2 or not _whole([centres[i] for i in sets[-1]], r):
        return None
    return sets


# the hole sets of boards a maker places by the board's corner (datasheets; mm from the board's
# lower left corner, its size first): their holes tell where that corner is (issue 114)
KNOWN_BOARDS = {
    "Arduino Uno": ((68.58, 53.34), ((13.97, 2.54), (15.24, 50.8), (66.04, 7.62), (66.04, 35.56))),
    "Arduino Mega": ((101.6, 53.34), ((13.97, 2.54), (15.24, 50.8), (66.04, 7.62), (66.04, 35.56),
                                      (90.17, 50.8), (96.52, 2.54))),
}
BOARD_TOL = 0.02    # mm: a set's holes this near a known board's are that board's
# a distance from an edge that a maker dimensions: a whole number of one of these (mm): half a
# millimetre, a fortieth of an inch (a board drawn in inches, written in mm by an SVG's viewBox)
ROUND_STEPS = (0.5, 0.635)


def known_board(centres: list) -> tuple | None:
    """The lower left corner and size of the known board (:data:`KNOWN_BOARDS`, upright as
    its datasheet draws it) whose holes are exactly ``centres`` (program units), else None."""
    from ...write.units import UNIT
    from ...model import UNIT_MM
    per = UNIT_MM[UNIT.get()]
    for size, holes in KNOWN_BOARDS.values():
        if len(holes) != len(centres):
            continue
        pts = [(x / per, y / per) for x, y in holes]
        first, drawn = min(pts), min(centres)
        o = (drawn[0] - first[0], drawn[1] - first[1])
        if all(min(math.dist((x + o[0], y + o[1]), c) for c in centres) <= BOARD_TOL / per
               for x, y in pts):
            return o, (size[0] / per, size[1] / per)
    return None


def _dimensioned(v: float) -> bool:
    """Whether ``v`` (program units) is a distance a maker dimensions: above 0 and a whole
    number of one of :data:`ROUND_STEPS` (20 mm, 12.5 mm; 0.375 in)."""
    from ...write.units import UNIT
    from ...model import UNIT_MM
    mm = v * UNIT_MM[UNIT.get()]
    return v > EQUAL_TOL and any(abs(mm / q - round(mm / q)) * q <= 1e-6 for q in ROUND_STEPS)


def set_sides(rest: list, body, mid) -> list[int]:
    """Per axis what a board's set ``rest`` (holes of one size in no pattern) on the
    rectangular ``body`` is placed from (docs/import.md, "What an edit means"): -1/1 the low/
    high edge, 0 the centre line.  The reference nearest their middle ``mid`` (ties: the
    centre); but a set off the centre line whose nearer edge is at a dimensioned distance
    (:func:`_dimensioned`) from it, from its nearest hole or, a known board's
    (:func:`known_board`), from the board's side, is placed from that edge, as its maker
    drew it (issue 114: an Arduino Mega 20 mm from the left of a 200 mm plate, its holes'
    middle nearer the centre line, moved with the centre)."""
    board = known_board([m.center for m in rest])
    out = []
    for k, key in ((0, "width"), (1, "height")):
        c, half = body.center[k], body.args[key] / 2
        gaps = {s: abs(mid[k] - c - s * half) for s in (0, -1, 1)}
        side = min((0, -1, 1), key=lambda s: (round(gaps[s], 9), s != 0, s))
        lo, hi = min(m.center[k] for m in rest), max(m.center[k] for m in rest)
        if side == 0 and abs((lo + hi) / 2 - c) > EQUAL_TOL:
            near = -1 if lo - (c - half) <= (c + half) - hi + 1e-9 else 1
            dist = [lo - (c - half) if near < 0 else (c + half) - hi]
            if board is not None:
                o, size = board[0][k], board[1][k]
                if abs(o + size / 2 - c) <= EQUAL_TOL:
                    dist = []           # the board centred on the plate: the centre
                else:
                    dist.append(o - (c - half) if near < 0 else (c + half) - o - size)
            if any(_dimensioned(g) for g in dist):
                side = near
        out.append(side)
    return out


class _Groups:
    def at_corners(self, g: list, mid) -> bool:
        """Whether four equal holes about ``mid`` may be read as at the body's corners
        (docs/import.md, "What an edit means"): about no feature, or, about one (a bore),
        when they are not round (a motor plate's corner slots) or another group about it is
        nearer it (the motor's holes inside them): then said in the head."""
        around = self.surrounds(mid)
        if around is None:
            return True
        far = sum(math.dist(h.center, mid) for h in g) / len(g)
        inner = any(math.dist(c, mid) <= EQUAL_TOL and r < far - EQUAL_TOL
                    for c, r in self.rings_at)
        if g[0].kind == "Circle" and not inner and not self._nearer_corners(g, mid):
            return False
        self.stats.readings.append(
            f"{len(g)} {_hole_name(g[0])}s both about {self.shared(mid)} and at the corners: "
            f"read as at the corners (their inset kept when the plate grows)")
        return True

    def _nearer_corners(self, g: list, mid) -> bool:
        """Whether each of four holes about a feature is nearer its corner of the body
        than the feature's edge (a panel's mounting holes round a window, a grille's round
        its fan's bore; a motor's holes hug their bore)."""
        feat = getattr(self, "shared_shape", {}).get(self.shared(mid))
        if feat is None or self.anchor is None:
            return False
        body = self.anchor[0]
        half = (body.args["width"] / 2, body.args["height"] / 2)
        for h in g:
            inset = [half[a] - abs(h.center[a] - body.center[a]) for a in (0, 1)]
            if min(inset) <= 0 or _edge_gap(feat, h.center) <= math.hypot(*inset) + EQUAL_TOL:
                return False
        return True

    def hole_set(self, depth: int, rest: list, sh: Shape, base: str, sizes: dict) -> None:
        """Holes of one size in no pattern (a board's) as one set placed from the body's
        corner nearest their middle (the spec, docs/import.md: a board's holes move as one
        with that corner; per axis the centre line when it is nearer): params ``<set>_x``
        and ``<set>_y`` from those edges to the hole nearest it, the others listed as
        offsets from that hole."""
        mid = [sum(m.center[k] for m in rest) / len(rest) for k in (0, 1)]
        hn = self.name_near(base + "s", mid)
        if self.anchor is None:
            pts = ", ".join(self.center(m.center) for m in rest)
            self.w.emit(depth, f"for c in [{pts}] {{")
            self.sunk_as(rest)
            self.hole_block(depth + 1, hn, sh, "c", sizes)
            self.w.emit(depth, "}")
            return
        body = self.anchor[0]
        sides = set_sides(rest, body, mid)
        # the hole nearest that corner (on a centre line: nearest the centre) is the origin
        corner = [body.center[k] + sides[k] * body.args["width" if k == 0 else "height"] / 2
                  for k in (0, 1)]
        ref = min(rest, key=lambda m: (math.dist(m.center, corner), m.center))
        at, said = [], []
        for k, word in ((0, "x"), (1, "y")):
            side = sides[k]
            if side == 0:
                # its place from the centre line is a param too (issue 114: `- 13.96` was
                # a number in the text, and "move the board 8 mm up" had no param)
                at.append(self.from_centre(f"{hn}_{word}", ref.center[k], k,
                                           "the set's hole nearest the centre"))
                said.append("centre line")
                continue
            at.append(self.from_edge(f"{hn}_{word}", ref.center[k], k, side,
                                     "the set's hole nearest the corner"))
            said.append({(0, -1): "left", (0, 1): "right", (1, -1): "bottom",
                         (1, 1): "top"}[(k, side)])
        pts = [_pt((m.center[0] - ref.center[0], m.center[1] - ref.center[1])) for m in rest]
        offs = ", ".join(pts)
        # each hole's turn of the loop: its offset (a countersink on some, a label)
        turn = {id(m): (("c.x", p[1:-1].split(", ")[0]), ("c.y", p[1:-1].split(", ")[1]))
                for m, p in zip(rest, pts)}
        edges = [x for x in reversed(said) if x != "centre line"]
        where = f"the {' '.join(edges)} corner" if len(edges) == 2 else \
            f"the {edges[0]} edge, about the centre line" if edges else "the centre"
        self.w.emit(depth, f"# {len(rest)} holes in no pattern (a board's): one set, from "
                           f"{where}")
        # the head says it too (issue 103: a drawing that fits no row of the spec says so)
        self.stats.readings.append(f"{len(rest)} {_hole_name(sh)}s fit no pattern: one set "
                                   f"`{hn}`, placed from {where}")
        self.w.emit(depth, f"for c in [{offs}] {{")
        self.sunk_as(rest)
        self.hole_block(depth + 1, hn, sh, f"({at[0]} + c.x, {at[1]} + c.y)", sizes,
                        lambda m: turn[id(m)])
        self.w.emit(depth, "}")
