"""The holes makers draw, written (issue 85): arc slots, keyholes and D-holes
(:meth:`_MakerFeatures.maker_hole`) and notches cut into a body's side
(:meth:`_MakerFeatures.edge_notch`), each with size params shared by holes of one kind and
size (:meth:`_MakerFeatures.kind_params`) and placed from the body (:mod:`.anchors`); the
loops are recognised by :mod:`.features`."""
from __future__ import annotations

from .bores import _BoreFeatures
from .features import arc_slot, d_hole, keyhole
from ..shapes import merged
from ..params import _deg, _r

SINGLE_PARAMS = 12     # a part with more holes of sizes no other has: their sizes as numbers


def _sum(term: str) -> bool:
    """Whether expression text ``term`` has a ``+`` or ``-`` outside brackets (after its
    first character): it needs brackets to be subtracted or multiplied."""
    depth = 0
    for k, ch in enumerate(term):
        depth += ch in "([" and 1 or ch in ")]" and -1 or 0
        if depth == 0 and k > 0 and ch in "+-" and term[k - 1] == " ":
            return True
    return False


class _MakerFeatures(_BoreFeatures):
    """The writing half of :class:`~.infer._Part` for makers' holes: needs ``w``, ``stats``,
    ``kinds`` (``{(kind, sizes): params}``), ``name``, ``p``, ``pos``, ``edge`` and
    ``span_at``."""

    def maker_hole(self, depth: int, segs: list) -> bool:
        """An arc slot, a keyhole or a D-hole (:mod:`.features`) written with its size
        params (one set for holes of one kind and size) at its centre placed from the body
        (:meth:`pos`); False when the loop is none of them."""
        w = self.w
        segs = merged(segs)
        if self.bore_hole(depth, segs):     # a double-D or a keyway (:mod:`.bores`)
            return True
        got = arc_slot(segs)
        if got is not None:
            C, R, a0, a1, wd = got
            hn = self.name("arc_slot")
            ps = self.kind_params("arc_slot", (("radius", R), ("width", wd)))
            w.emit(depth, f"hole {hn} {{ s = ArcSlot(center={self.pos(C)}, radius={ps[0]}, "
                          f"start_angle={_deg(a0)}, end_angle={_deg(a1)}, width={ps[1]}) }}")
            w.emit(depth, f"Fixed({hn}.s)")
            self.stats.kinds["ArcSlot"] += 1
            return True
        got = keyhole(segs)
        if got is not None:
            c, D, wd, L, ang = got
            hn = self.name("keyhole")
            ps = self.kind_params("keyhole", (("d", D), ("slot_width", wd), ("length", L)))
            w.emit(depth, f"hole {hn} {{")
            w.emit(depth + 1, f"c = {self.pos(c)}")
            w.emit(depth + 1, f"head = Circle(center=c, diameter={ps[0]})")
            w.emit(depth + 1, f"slot = Slot(start=c, end=polar(c, {ps[2]}, {_deg(ang)}), "
                              f"width={ps[1]})")
            w.emit(depth, "}")
            w.emit(depth, f"for x in [{hn}.head, {hn}.slot] {{ Fixed(x) }}")
            self.stats.kinds["keyhole"] += 1
            return True
        got = d_hole(segs)
        if got is not None:
            c, d, flat, ang = got
            hn = self.name("d_hole")
            ps = self.kind_params("d_hole", (("d", d), ("flat", flat)))
            if ps[1][0].isalpha():        # the flat cuts the circle: short of its radius
                self.params.bound(ps[1], "0 mm", f"{ps[0]} / 2",
                                  "the flat cuts the circle: nearer its centre than its radius")
            turn = f"{_deg(ang)} " if abs(ang) > 1e-15 else ""
            start, end = (f"{turn}+ t", f"{turn}- t") if turn else ("t", "-t")
            w.emit(depth, f"hole {hn} {{")
            w.emit(depth + 1, f"c = {self.pos(c)}")
            w.emit(depth + 1, f"t = acos(2 * {ps[1]} / {ps[0]})")
            w.emit(depth + 1, f"e0 = Arc(center=c, start=polar(c, {ps[0]} / 2, {start}), "
                              f"end=polar(c, {ps[0]} / 2, {end}))")
            w.emit(depth + 1, "e1 = Line(start=e0.end, end=e0.start)")
            w.emit(depth, "}")
            w.emit(depth, f"Fixed({hn}.e0)")
            self.stats.kinds["D-hole"] += 1
            return True
        return False

    def notch_row(self, depth: int, group: list) -> None:
        """Notches of one size evenly spaced along a side (:func:`~.features.notch_rows`) as
        one loop of :meth:`edge_notch`: their count and pitch params, placed by their middle
        or by their end within a pitch of an edge (:meth:`run_at`)."""
        side, shape, lo, hi, dep = group[0]
        along = 1 if side in ("left", "right") else 0
        mids = [(c[2] + c[3]) / 2 for c in group]
        hn = self.name({"square": "notches", "round": "round_notches", "V": "v_notches"}[shape])
        n = len(group)
        cnt = self.p(hn + "_n", n, unit="")
        step = (mids[-1] - mids[0]) / (n - 1)
        pp = self.p(hn + "_pitch", step, times=n)
        mid = self.run_at(mids[0], mids[-1], along, "i", cnt, pp, step)
        # the pattern's own sizes (another comb's notches of one size are its own)
        own = (self.p(hn + "_width", hi - lo), self.p(hn + "_depth", dep))
        self.w.emit(depth, f"# {n} notches in the {side} side, {pp} apart: a pattern of the side")
        self.w.emit(depth, f"for i in range({cnt}) {{")
        self.edge_notch(depth + 1, group[0], mid, hn, own)
        self.w.emit(depth, "}")

    def edge_notch(self, depth: int, cut: tuple, mid: str | None = None,
                   hn: str | None = None, sizes: tuple | None = None) -> None:
        """A notch cut into a side of the body (:func:`~.features.edge_notches`) as a hole
        flush with the side: a Rectangle (square), a Rectangle and a Circle (round bottom) or
        a triangle (V), its width and depth params, placed along the side from the edge or
        centre its near side is tied to (:meth:`span_at`), or at ``mid`` (its centre along
        the side, a row's member) named ``hn``, its width and depth ``sizes``."""
        side, shape, lo, hi, dep = cut
        across = 0 if side in ("left", "right") else 1
        along = 1 - across
        sign = 1 if side in ("right", "top") else -1
        wd, dp = sizes or self.kind_params(f"{shape}_notch" if shape != "square" else "notch",
                                           (("width", hi - lo), ("depth", dep)))
        edge = self.edge(across, sign)

        def inward(term: str) -> str:        # the side moved into the part by `term`
            if term == "-1 mm":               # ... or 1 mm out of it
                return f"{edge} {'+' if sign > 0 else '-'} 1 mm" if edge != "0" else \
                    ("1 mm" if sign > 0 else "-1 mm")
            t = f"({term})" if _sum(term) else term
            if edge == "0":
                return f"-{t}" if sign > 0 else t
            return f"{edge} {'-' if sign > 0 else '+'} {t}"
        mid = mid or self.span_at(lo, hi, along, wd)
        hn = hn or self.name({"square": "notch", "round": "round_notch", "V": "v_notch"}[shape])

        def pt(a: str, c: str) -> str:       # (along, across) as (x, y)
            return f"({a}, {c})" if along == 0 else f"({c}, {a})"

        def rect(inner: str) -> str:          # from 1 mm outside the side to `inner` in
            size = (f"width={wd}, height={inner} + 1 mm" if along == 0 else
                    f"width={inner} + 1 mm, height={wd}")
            return f"Rectangle(center={pt(mid, inward(f'({inner} - 1 mm) / 2'))}, {size})"
        w = self.w
        # each hole runs 1 mm past the side (a notch, not a hole touching the edge: W0514)
        if shape == "square":
            w.emit(depth, f"hole {hn} {{ h = {rect(dp)} }}")
            w.emit(depth, f"Fixed({hn}.h)")
        elif shape == "round":
            w.emit(depth, f"hole {hn} {{")
            w.emit(depth + 1, f"h = {rect(f'{dp} - {wd} / 2')}")
            w.emit(depth + 1, f"bottom = Circle(center={pt(mid, inward(f'{dp} - {wd} / 2'))}, "
                              f"diameter={wd})")
            w.emit(depth, "}")
            w.emit(depth, f"for x in [{hn}.h, {hn}.bottom] {{ Fixed(x) }}")
        else:                                 # the sides carried on to 1 mm outside
            half = f"{wd} / 2 * ({dp} + 1 mm) / {dp}"
            ends = [pt(f"{mid} {o} {half}", inward("-1 mm")) for o in "-+"]
            apex = pt(mid, inward(dp))
            w.emit(depth, f"hole {hn} {{ h = Polygon([{ends[0]}, {apex}, {ends[1]}]) }}")
            w.emit(depth, f"Fixed({hn}.h)")

    def kind_params(self, kind: str, sizes: tuple) -> list[str]:
        """The size params of a hole of ``kind`` (``sizes``: (name, mm) pairs), shared by the
        holes of that kind and size; numbers past :data:`SINGLE_PARAMS` kinds and sizes."""
        key = (kind,) + tuple(round(v, 6) for _, v in sizes)
        if key not in self.kinds:
            if len(self.kinds) >= SINGLE_PARAMS:
                return [_r(v) for _, v in sizes]
            k = 1 + sum(key[0] == kind for key in self.kinds)    # this kind's k-th size
            base = kind if k == 1 else f"{kind}_{k}"   # (params: a namespace of their own)
            self.kinds[key] = [self.p(f"{base}_{n}", v) for n, v in sizes]
        return self.kinds[key]
