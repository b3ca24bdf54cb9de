"""``aidl import --infer``: patterns as makers' files draw them, not perfectly regular
(issue 103; docs/import.md, "What an edit means"): a hole of a near size that completes a
pattern is its odd member, written with its own size on its turn (:meth:`_Irregular.
merge_odd`, :meth:`_Irregular.own_sizes`); a row or grid with holes left out is one pattern
with a gap list, one a CAD program rounded keeps each hole's offset off its node on its turn
(:meth:`_Irregular.off_turns`).  The irregular half of
:class:`~.infer._Part`: needs ``w``, ``p``, ``stats``, ``name``, ``shared``, ``at``,
``size_params``, ``sink_members``, ``check``, ``grid`` and ``hole_block``.  Coordinates in
the drawing's unit (mm, or inches for an inch drawing); the results are program text."""
from __future__ import annotations

import bisect

from ..params import _r
from ..shapes import ROUND_TOL, Shape
from ...write.units import UNIT
from ...write.writer import _num, _pt
from . import turns
from .find import _gapped_as, _gapped_grid, _grid_field, _near_grid, _stagger, _whole
from .groups import corner_sets


ODD_SIZE = 1.5      # a hole at most this many times larger (or smaller) than a pattern's
#                     may be its odd member (merge_odd: 4.4 mm among 4 mm holes)


def _near_size(a: Shape, b: Shape) -> bool:
    """Whether ``a`` and ``b`` are circles whose diameters are within :data:`ODD_SIZE` of
    each other (an odd member is a round hole: a clearance hole drilled larger)."""
    if a.kind != "Circle" or b.kind != "Circle":
        return False
    x, y = a.args["radius"], b.args["radius"]
    return 0 < min(x, y) and max(x, y) <= ODD_SIZE * min(x, y)


def _beside_drawn(cs: list) -> bool:
    """Whether the last of ``cs`` (an odd hole after a pattern's holes) sits next to a drawn
    member when the pattern it would complete has nodes left out (:func:`_gapped_grid`): on
    a node one step from a held one along a row or column.  A hole of another size past
    missing members (a terminal strip's 5 mm mounting hole at 118 = 10 + 12 x 9, two nodes
    past its ten 3.5 mm terminals) is no member: it is a hole of its own, by its nearer edge
    (issue 114's maker run, #49-51).  True when no node is left out."""
    gapped = _gapped_grid(cs)
    if gapped is None or not gapped[1]:
        return True
    (x0, y0, dx, dy, nx, ny), missing = gapped
    gone = set(missing)
    p = cs[-1]
    i = round((p[0] - x0) / dx) if nx > 1 else 0
    j = round((p[1] - y0) / dy) if ny > 1 else 0
    return any(0 <= a < nx and 0 <= b < ny and (a, b) not in gone
               for a, b in ((i - 1, j), (i + 1, j), (i, j - 1), (i, j + 1)))


class _Irregular:
    def merge_odd(self, groups: dict, body) -> None:
        """A hole of a size no other has that completes a pattern of holes of its kind and
        a near size (one corner hole 4.4 mm among three of 4 mm, a row's last hole larger)
        joined to that pattern's group (``groups``: size key -> holes, changed in place) as
        its odd member (:attr:`odd`), so the pattern stays one and the odd hole keeps its
        own size (:meth:`hole_block`): when the group with it is one pattern (a grid it
        completes, a row it extends) or it is one of four at the corners of ``body`` among
        them (three corner holes of a grille's hole size).  A hole a pattern surrounds (a
        bore) is never one; only the first eight groups of a near size are tried."""
        self.odd = {}
        # the groups an odd hole may join, by radius: each hole looks only at those of a
        # near size (a binary search), not at every group (8,000 holes each of its own size)
        big = sorted(((g[0].args["radius"], k) for k, g in groups.items()
                      if len(g) >= 3 and g[0].kind == "Circle"), key=lambda t: t[0])
        radii = [r for r, _ in big]
        for n, key in enumerate([k for k, g in groups.items() if len(g) == 1] if big else []):
            self.check(n, "finding the odd members of the patterns")
            odd = groups[key][0]
            if odd.kind != "Circle" or self.shared(odd.center) is not None:
                continue
            r0 = odd.args["radius"]
            lo = bisect.bisect_left(radii, r0 / ODD_SIZE)
            hi = bisect.bisect_right(radii, r0 * ODD_SIZE)
            for _, k2 in big[lo:hi][:8]:
                g = groups[k2]
                if not _near_size(odd, g[0]):
                    continue
                r = g[0].args.get("radius", 0.0) if odd.kind == "Circle" else 0.0
                cs = [m.center for m in g] + [odd.center]
                # the pattern it completes: the group's, or four at the body's corners
                # among the group's holes (three corner holes of a grille's hole size)
                sets = corner_sets(cs, body, rest=True) if len(cs) >= 5 else None
                if _whole(cs, r) and _beside_drawn(cs) or \
                        sets and any(len(cs) - 1 in st for st in sets if len(st) == 4):
                    u = UNIT.get()
                    self.stats.readings.append(
                        f"a {_num(2 * r0)} {u} hole at {_pt(odd.center)} completes a "
                        f"pattern of {_num(2 * r)} {u} holes: one pattern, that hole its "
                        f"own size (`_odd_d`)")
                    g.append(odd)
                    del groups[key]
                    self.odd[id(odd)] = g
                    break

    def own_sizes(self, hn: str, sh: Shape, sizes: dict, index=None) -> dict:
        """The sizes a pattern's hole statement writes: ``sizes`` (its common params), with
        each odd member's own (:meth:`merge_odd`: ``<hn>_odd_d``) chosen on its turn of the
        loop (``index``: Shape -> the loop's variables on that turn), ``(corner_holes_odd_d
        if sx == 1 and sy == 1 else corner_hole_d)``; the odd member's own when ``sh`` is
        it and there is no loop."""
        sizes = self.mixed_sizes(hn, sh, sizes, index)     # a lattice of two sizes (mixed.py)
        odd = getattr(self, "odd", None)
        if not odd or not sizes:
            return sizes
        if index is None:
            return self.size_params(hn + "_odd", sh, True) if id(sh) in odd else sizes
        out = dict(sizes)
        for m in self.sink_members:
            if id(m) not in odd or not any(x is sh for x in odd[id(m)]):
                continue
            own = self.size_params(hn + "_odd", m, True)
            turn = index(m)
            cond = " and ".join(f"{v} == {x}" for v, x in turn) if turn else "true"
            for k in out:
                if k in own:
                    out[k] = f"({own[k]} if {cond} else {out[k]})"
        return out

    def off_turns(self, center: str, index) -> str:
        """``center`` (a loop's ``(x, y)`` text) with each member's offset off its node
        (:attr:`offs`, a pattern CAD rounded: :func:`~.find._near_grid`) added on its turn
        (``index``), ``x + (0.02 if i == 1 else -0.01 if i == 3 else 0)``, so the program
        draws every hole where the drawing has it."""
        offs = getattr(self, "offs", None)
        if not offs or index is None:
            return center
        xy = turns._split(center)
        if xy is None:
            return center
        terms = [[], []]
        for axis, var in ((0, "i"), (1, "j")):
            # one offset a column (row) when the CAD rounded each column's x (row's y)
            lines: dict = {}
            for m in self.sink_members:
                turn = dict(index(m))
                if var in turn:
                    lines.setdefault(turn[var], set()).add(
                        round(offs.get(id(m), (0.0, 0.0))[axis] / ROUND_TOL))
            by_line = bool(lines) and all(len(v) == 1 for v in lines.values())
            for m in self.sink_members:
                d = offs.get(id(m), (0.0, 0.0))
                if abs(d[axis]) <= ROUND_TOL:
                    continue
                turn = index(m)
                if by_line:
                    cond = f"{var} == {dict(turn)[var]}"
                    if any(t.endswith(f"if {cond} else ") for t in terms[axis]):
                        continue
                else:
                    cond = " and ".join(f"{v} == {x}" for v, x in turn) or "true"
                terms[axis].append(f"{_r(d[axis])} if {cond} else ")
        out = [f"{t} + ({''.join(terms[a])}0)" if terms[a] else t
               for a, t in enumerate(xy)]
        return f"({out[0]}, {out[1]})"

    def irregular(self, depth: int, g: list, sh: Shape, base: str, cs: list) -> bool:
        """Equal holes ``g`` (centres ``cs``) that are no exact row or grid but one a maker
        drew irregular: a square-set grid clipped to a round field (a fan grille), a row or
        grid with holes left out (its gap list), one a CAD program rounded (its offsets);
        written and True, else False."""
        gf = _grid_field(cs, sh.args["radius"]) if sh.kind == "Circle" else None
        if gf is not None:      # a square-set grid clipped to a round field (a fan grille)
            self.grid_field(depth, sh, base, gf)
            return True
        gg = _gapped_grid(cs) if _stagger(cs) is None else None
        # the lattice of a sibling group of these holes with one left out (three of a 2 x 2)
        gg = gg or next(filter(None, (_gapped_as(cs, lat) for lat in getattr(self, "kin", ()))),
                        None)
        if gg is not None:      # a grid or row with holes left out: its gap list
            self.grid(depth, sh, base, gg[0], gg[1])
            return True
        ng = _near_grid(cs, least=2 if getattr(self, "kin", ()) else 3)   # 2 x 2 by a sibling
        if ng is not None:      # a grid or row CAD rounded off its pitch: its offsets
            self.offs = {id(g[m]): d for m, d in ng[1].items()}
            worst = max(max(abs(d[0]), abs(d[1])) for d in ng[1].values())
            self.stats.readings.append(
                f"{len(g)} holes within {_num(worst)} {UNIT.get()} of the nodes of one "
                f"{'grid' if ng[0][4] > 1 and ng[0][5] > 1 else 'row'} (CAD rounding): one "
                f"pattern, {len(ng[1])} of them written off their node as drawn")
            self.grid(depth, sh, base, ng[0])
            self.offs = {}
            return True
        return False
