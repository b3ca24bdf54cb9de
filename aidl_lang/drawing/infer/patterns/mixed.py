"""``aidl import --infer``: one lattice of holes of two or more sizes (issue 114, round
seven: a 4 x 3 checkerboard of 6 mm and 5 mm holes on a 30 / 25 mm pitch; a panel whose grid
has a row of larger holes among its smaller ones), read as one grid with a per-hole size
(docs/import.md, "What an edit means": a pattern with members of another size), never as a
pattern for each size placed from different edges (the checkerboard was two staggered grids,
one from the left edge, one from the right: a wider plate tore it into halves 50 mm apart).
The mixed half of :class:`~.infer._Part`: needs ``shared``, ``p``, ``stats``,
``sink_members``.  Coordinates in the drawing's unit; the results are program text."""
from __future__ import annotations

from itertools import combinations

from ...write.units import UNIT
from ...write.writer import _num
from .find import _gapped_as, _grid, lattices

MIXED_GROUPS = 6    # at most this many hole sizes looked at for one lattice (2^6 subsets)
MIXED_RATIO = 2.0   # the largest hole of a mixed lattice at most this many times the smallest
MIXED_MAX = 4000    # holes: past this many circles the sizes are not tried together


def _separated(a: set, b: set) -> bool:
    """Whether index sets ``a`` and ``b`` (a lattice's columns or rows) lie apart, one all
    before the other (two groups side by side: two patterns, not one mixed)."""
    return max(a) < min(b) or max(b) < min(a)


def mixed_lattice(sets: list) -> tuple | None:
    """The lattice ``(x0, y0, dx, dy, nx, ny)`` that holes of two or more sizes (``sets``:
    a list of centre lists, one a size) fill together, every node once, when they are
    interleaved in it (no size's columns all left of another's, nor its rows all below:
    side by side they are two patterns), else None."""
    cs = [c for s in sets for c in s]
    gr = _grid(cs)
    if gr is None or gr[4] * gr[5] < 4:
        return None
    x0, y0, dx, dy, nx, ny = gr
    cols, rows = [], []
    for s in sets:
        cols.append({round((c[0] - x0) / dx) if nx > 1 else 0 for c in s})
        rows.append({round((c[1] - y0) / dy) if ny > 1 else 0 for c in s})
    for a, b in combinations(range(len(sets)), 2):
        if nx > 1 and _separated(cols[a], cols[b]) or ny > 1 and _separated(rows[a], rows[b]):
            return None
    return gr


def alike(parts, cs: list, kin: list) -> bool:
    """Whether the groups ``parts`` (index lists) that equal holes were split into are one
    feature's alike groups (two 2 x 2 groups at the ends of a plate, one CAD rounded, one
    missing a hole): two to four (``cs``: the holes' centres), each within one hole of the
    largest, each a row or grid or one with holes left out of a sibling's lattice, their
    lattices (``kin``, :func:`~.find.lattices`) one; they then share one size param (issue 114), where
    features of a size by chance (a grid and a row of 4 mm holes) keep one each."""
    if not parts or not 2 <= len(parts) <= 4:
        return False
    most = max(len(p) for p in parts)
    if any(len(p) < most - 1 for p in parts) or not kin:
        return False
    for p in parts:             # each a row or grid (a board's set beside corners is not)
        pcs = [cs[i] for i in p]
        if not lattices([pcs]) and not any(_gapped_as(pcs, lat) for lat in kin):
            return False
    return all(max(abs(a - b) for a, b in zip(k, kin[0])) <= 1e-6 for k in kin)


def _turn_text(turn: tuple) -> str:
    return " and ".join(f"{v} == {k}" for v, k in turn) or "true"


def condition(turns: list, every: list) -> str:
    """The loop condition that holds on ``turns`` (``(("i", 1), ("j", 0))`` each) and on no
    other of ``every`` (the turns of the pattern's holes): ``(i + j) % 2 == 1`` for a
    checkerboard's, ``j == 2`` for a row of them, ``i == 0 or i == 3`` for columns, else
    the turns listed."""
    mine = set(turns)
    rest = [t for t in every if t not in mine]
    names = [v for v, _ in every[0]] if every else []
    if names == ["i", "j"]:
        par = {(dict(t)["i"] + dict(t)["j"]) % 2 for t in mine}
        if len(par) == 1 and all((dict(t)["i"] + dict(t)["j"]) % 2 not in par for t in rest):
            return f"(i + j) % 2 == {par.pop()}"
    for v in names:
        ks = sorted({dict(t)[v] for t in mine})
        if all(dict(t)[v] not in ks for t in rest):
            return " or ".join(f"{v} == {k}" for k in ks)
    return " or ".join(_turn_text(t) for t in sorted(mine))


class _Mixed:
    def merge_mixed(self, groups: dict) -> None:
        """Round holes of two or more sizes that fill one lattice together, interleaved
        (:func:`mixed_lattice`), made one group (``groups``: size key -> holes, changed in
        place) under the size most of them have, the others' members noted in
        :attr:`mixed` (id -> diameter) so that the pattern writes each its own size on its
        turn (:meth:`mixed_sizes`); said in the program's head."""
        self.mixed = {}
        keys = [k for k, g in groups.items() if g[0].kind == "Circle"
                and not any(self.shared(h.center) is not None for h in g[:1])]
        if len(keys) < 2 or sum(len(groups[k]) for k in keys) > MIXED_MAX:
            return
        keys.sort(key=lambda k: -len(groups[k]))
        keys = keys[:MIXED_GROUPS]
        for n in range(len(keys), 1, -1):
            for sub in combinations(keys, n):
                if any(k not in groups for k in sub):
                    continue
                radii = [groups[k][0].args["radius"] for k in sub]
                if min(radii) <= 0 or max(radii) > MIXED_RATIO * min(radii):
                    continue
                gr = mixed_lattice([[h.center for h in groups[k]] for k in sub])
                if gr is None:
                    continue
                main = groups[sub[0]]
                u = UNIT.get()
                for k in sub[1:]:
                    for h in groups[k]:
                        self.mixed[id(h)] = 2 * h.args["radius"]
                    main.extend(groups.pop(k))
                sizes = " and ".join(f"{_num(2 * r)} {u}" for r in sorted(set(radii),
                                                                          reverse=True))
                self.stats.readings.append(
                    f"{len(main)} holes of {sizes} fill one {gr[4]} x {gr[5]} lattice "
                    f"together: one pattern, each hole its own size on its turn (not a "
                    f"pattern for each size)")

    def mixed_sizes(self, hn: str, sh, sizes: dict, index) -> dict:
        """``sizes`` (a pattern's ``{"diameter": "holes_d"}``, its holes ``sh``'s size) with
        the holes of the other sizes of a mixed lattice (:meth:`merge_mixed`) given theirs on
        their turns: ``(holes_small_d if (i + j) % 2 == 1 else holes_d)``, a param for each
        other size named for it against ``sh``'s (``_small_d``, ``_large_d``: a name that
        ends as every diameter's)."""
        mixed = getattr(self, "mixed", None)
        if not mixed or index is None or "diameter" not in sizes:
            return sizes
        by: dict = {}
        every = []
        for m in self.sink_members:
            t = index(m)
            every.append(t)
            if id(m) in mixed:
                by.setdefault(round(mixed[id(m)], 9), []).append(t)
        if not by:
            return sizes
        expr = sizes["diameter"]
        for d, turns in sorted(by.items(), key=lambda kv: -len(kv[1])):
            cond = condition(turns, every)
            word = "small" if d < 2 * sh.args["radius"] else "large"
            own = self.p(f"{hn}_{word}_d", d, f"the holes where {cond}")
            expr = f"{own} if {cond} else {expr}"
        return {**sizes, "diameter": f"({expr})"}
