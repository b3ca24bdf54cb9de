"""``aidl import --infer``: two equal holes mirrored about the body's centre line (or through
its centre), written as one ``for s in [-1, 1]`` pair (:meth:`_Pairs.mirrored`): on a spacing
about the centre line, or, when they sit nearer the edges than the centre line, each kept from
its own edge by one inset (issue 103: mounting slots 20 mm from the top and the bottom, the far
one too; docs/import.md, "What an edit means"); and a motor's holes round its bore among holes
of their size elsewhere (:func:`_ring_about`, for ``share_centres``).  The pairs' half of
:class:`~.infer._Part`: needs ``w``, ``p``, ``stats``, ``anchor``, ``name``, ``at``,
``from_body_centre``, ``size_params`` and ``hole_block``.  Coordinates in the drawing's unit;
the results are program text."""
from __future__ import annotations

import math

from ..shapes import EQUAL_TOL
from ...write.writer import _num
from . import turns


RING_MIN, RING_MAX = 4, 64     # a group looked at for holes round a bore (share_centres)
RING_WORK = 20_000              # holes x features looked at for them, at most


def _ring_about(c, g: list) -> bool:
    """Whether four or more of the holes ``g`` nearest ``c`` (mm) are at one distance from it
    and about it (their middle ``c``): a motor's holes round its bore among holes of their
    size elsewhere on the plate."""
    ds = [math.dist(h.center, c) for h in g]
    r = min(ds)
    near = [h.center for h, d in zip(g, ds) if d - r <= EQUAL_TOL]
    if len(near) < RING_MIN or r <= EQUAL_TOL:
        return False
    mid = (sum(p[0] for p in near) / len(near), sum(p[1] for p in near) / len(near))
    return math.dist(mid, c) <= EQUAL_TOL


class _Pairs:
    """Two equal holes mirrored about the body's centre line, as one pair."""

    def mirrored(self, depth: int, g: list, body, sh, base: str, cs: list) -> bool:
        """The two holes ``g`` (centres ``cs``, shape ``sh``, named from ``base``) written as
        a pair mirrored about the body's centre line(s) (``body``: its Shape first) when they
        are one; False (nothing written) when not."""
        w = self.w
        if len(g) != 2 or body is None:
            return False
        B = body[0].center
        (x1, y1), (x2, y2) = sorted(cs)
        sym_x = abs(x1 + x2 - 2 * B[0]) <= EQUAL_TOL and x2 - x1 > EQUAL_TOL
        sym_y = abs(y1 + y2 - 2 * B[1]) <= EQUAL_TOL and abs(y2 - y1) > EQUAL_TOL
        same_y, same_x = abs(y1 - y2) <= EQUAL_TOL, abs(x1 - x2) <= EQUAL_TOL
        if (sym_x and (same_y or sym_y)) or (sym_y and same_x):
            hn = self.name(base + "s")
            sizes = self.size_params(hn, sh, True)
            half = self.anchor[0].args["width"] / 2 if self.anchor is not None else None
            half_y = self.anchor[0].args["height"] / 2 if self.anchor is not None else None
            # nearer the edges than the centre line (each dimensioned from its own edge,
            # the far one too: docs/import.md, "What an edit means"): an inset from them
            in_x = sym_x and half is not None and half - x2 + B[0] < x2 - B[0]
            dy_half = abs(y2 - y1) / 2
            in_y = sym_y and half_y is not None and half_y - dy_half < dy_half
            if in_x or in_y:
                edges = "side, top and bottom" if in_x and in_y else "side" if in_x else \
                    "top and bottom"
                self.stats.readings.append(
                    f"2 {base}s mirrored about the centre line, nearer the {edges} edges "
                    f"than it: each kept from its own edge (`{hn}_inset`), the far one too")
            if in_x:
                # nearer the side edges than the centre: each kept from its edge
                inset = self.p(hn + "_inset" + ("_x" if in_y else ""), half - x2 + B[0],
                               "from the left and right edges" if in_y else "from the edges")
                ex = self.from_body_centre(
                    0, f"s * ({self.anchor[1]['width']} / 2 - {inset})", B[0])
            elif sym_x:
                ex = self.from_body_centre(0, f"s * {self.p(hn + '_spacing', x2 - x1)} / 2", B[0])
            else:
                ex = self.at(x1, 0)
            # the y of the one left (s = -1): y1 = B.y - dy / 2 when mirrored through B
            if sym_y:
                dy = y2 - y1 if sym_x else abs(y2 - y1)
                sign = "s" if (not sym_x or y2 > y1) else "-s"
                name = hn + ("_spacing_y" if sym_x else "_spacing")
                if in_y:
                    inset = self.p(hn + "_inset" + ("_y" if in_x else ""), half_y - dy_half,
                                   "from the top and bottom edges" if in_x else "from the edges")
                    ey = self.from_body_centre(
                        1, f"{sign} * ({self.anchor[1]['height']} / 2 - {inset})", B[1])
                else:
                    ey = self.from_body_centre(1, f"{sign} * {self.p(name, abs(dy))} / 2", B[1])
            else:
                ey = self.at(y1, 1)
            w.emit(depth, "# mirrored about the centre line" + ("s" if sym_x and sym_y else ""))
            w.emit(depth, "for s in [-1, 1] {")
            self.hole_block(depth + 1, hn, sh, f"({ex}, {ey})", sizes,
                            turns.mirrored(B, sym_x))
            w.emit(depth, "}")
            self.stats.patterns["mirrored pair"] += 1
            return True
        return False

    def straddling(self, depth: int, g: list, sh, base: str, cs: list) -> bool:
        """Two equal holes ``g`` in line along x (or y) on either side of the body's centre
        line, each nearer its own edge, and not mirrored about the line (:meth:`mirrored`
        takes those): no row a maker dimensions (issue 114: holes at x = 30 and 90.02 on a
        120 mm plate are each 30 mm from an edge), so each is written from its own nearer
        edge, one size param, and the head says which reading was taken; False (nothing
        written) when they are not such a pair."""
        if len(g) != 2 or self.anchor is None or getattr(self, "profile", None) is not None:
            return False
        (x1, y1), (x2, y2) = cs
        for axis in (0, 1):
            if abs((y1, x1)[axis] - (y2, x2)[axis]) > EQUAL_TOL:
                continue            # not in line along this axis
            ends = sorted((x1, x2) if axis == 0 else (y1, y2))
            if [self.nearest(v, v, axis) for v in ends] != [-1, 1]:
                continue
            hn = self.name(base + "s")
            sizes = self.size_params(hn, sh, True)
            B, half = self.anchor[0].center[axis], self.anchor[0].args[
                "width" if axis == 0 else "height"] / 2
            gaps = (ends[0] - (B - half), B + half - ends[1])
            self.stats.readings.append(
                f"2 {base}s in line at {'x' if axis == 0 else 'y'} = {_num(ends[0])} and "
                f"{_num(ends[1])} on either side of the centre line, not mirrored about it "
                f"({_num(gaps[0])} and {_num(gaps[1])} from the edges): each kept from its own "
                f"nearer edge, not a row of 2 from one end")
            for m in sorted(g, key=lambda h: h.center[axis]):
                self.sunk_as([m])
                nm = self.numbered(base) if base == "hole" else self.name(base)
                # its distance from its edge a param (`hole1_x`, `width - hole2_x`)
                self.hole_block(depth, nm, m, self.pos_from_edges(nm, m.center), sizes)
            self.stats.patterns["equal sizes"] += 1
            return True
        return False
