"""Bores that makers draw for a shaft (issue 85, "recognise what makers draw"): a double-D
hole (:func:`double_d`: a circle with two parallel flats, for a flatted shaft or a panel
switch) and a keyway (:func:`keyway`: a bore with a rectangular key slot), recognised from a
hole's exact loop and written with the size params a person keeps (``ddhole_d``,
``ddhole_flat`` across the flats; ``keyway_d``, ``keyway_w``, ``keyway_depth`` past the
bore) by :meth:`_BoreFeatures.bore_hole`, placed from the body (:mod:`.anchors`).

The recognisers take the loop's pieces (:class:`~aidl_lang.geometry.shapes.curves.Arc` and
``Line``, in any order and direction, arcs on one circle joined by
:func:`~.shapes.merged`) and return the numbers the program writes (mm, radians) or None.
"""
from __future__ import annotations

import math

from ..params import _deg
from ..shapes import EQUAL_TOL, _close, arcs_and_lines


def _across(p, c, ux, uy) -> tuple[float, float]:
    """``(along, across)`` of point ``p`` from ``c`` in the frame of unit direction ``u``."""
    dx, dy = p[0] - c[0], p[1] - c[1]
    return dx * ux + dy * uy, -dx * uy + dy * ux


def double_d(segs: list) -> tuple | None:
    """``(centre, diameter, across flats, direction)`` of a loop of two arcs of one circle,
    each less than a half circle, and two lines (the flats) as far from the centre on
    either side, their normal toward ``direction`` (radians, in (-90, 90] degrees); else
    None."""
    got = arcs_and_lines(segs, 2, 2)
    if got is None:
        return None
    arcs, lines = got
    a, b = arcs
    if not _close(a.center, b.center) or abs(a.radius - b.radius) > EQUAL_TOL or \
            any(abs(s.sweep) >= math.pi - 1e-9 for s in arcs):
        return None
    c, r = a.center, a.radius
    mids = [((ln.start[0] + ln.end[0]) / 2, (ln.start[1] + ln.end[1]) / 2) for ln in lines]
    f0, f1 = (math.dist(c, m) for m in mids)
    if f0 <= EQUAL_TOL or abs(f0 - f1) > EQUAL_TOL or f0 >= r - EQUAL_TOL:
        return None
    ang = math.atan2(mids[0][1] - c[1], mids[0][0] - c[0])
    ux, uy = math.cos(ang), math.sin(ang)
    if abs(_across(mids[1], c, ux, uy)[1]) > EQUAL_TOL:        # the flats opposite
        return None
    for ln in lines:                                            # each across the normal
        for p in (ln.start, ln.end):
            if abs(abs(_across(p, c, ux, uy)[0]) - f0) > EQUAL_TOL:
                return None
    if ang <= -math.pi / 2 + 1e-12 or ang > math.pi / 2 + 1e-12:
        ang = math.atan2(-uy, -ux)
    return c, 2 * r, 2 * f0, ang


def keyway(segs: list) -> tuple | None:
    """``(centre, bore diameter, key width, key depth past the bore, direction)`` of a loop
    of one arc of more than a half circle (the bore) and three lines: two sides parallel to
    ``direction`` (radians) half the key's width either side of the centre, and the key's
    top across it; else None."""
    got = arcs_and_lines(segs, 1, 3)
    if got is None or abs(got[0][0].sweep) <= math.pi + 1e-9:
        return None
    (bore,), lines = got
    c, r = bore.center, bore.radius
    ends = (bore.start, bore.end)
    top = next((ln for ln in lines if not any(_close(ln.start, e) or _close(ln.end, e)
                                              for e in ends)), None)
    if top is None:
        return None
    m = ((top.start[0] + top.end[0]) / 2, (top.start[1] + top.end[1]) / 2)
    T = math.dist(c, m)
    if T <= r + EQUAL_TOL:
        return None
    ux, uy = (m[0] - c[0]) / T, (m[1] - c[1]) / T
    a = math.dist(top.start, top.end) / 2
    if a >= r - EQUAL_TOL or a <= EQUAL_TOL:
        return None
    s = math.sqrt(r * r - a * a)
    for ln in lines:
        for p in (ln.start, ln.end):
            along, across = _across(p, c, ux, uy)
            if abs(abs(across) - a) > EQUAL_TOL or not (
                    abs(along - s) <= EQUAL_TOL or abs(along - T) <= EQUAL_TOL):
                return None
    return c, 2 * r, 2 * a, T - r, math.atan2(uy, ux)


class _BoreFeatures:
    """The writing half of :class:`~.infer._Part` for double-D holes and keyways: needs
    ``w``, ``stats``, ``name``, ``pos`` and ``kind_params`` (:class:`~.makers._MakerFeatures`)."""

    def bore_hole(self, depth: int, segs: list) -> bool:
        """A double-D hole or a keyway (the merged loop ``segs``) written as a ``hole`` at its
        centre placed from the body, with size params shared by the holes of its kind and
        size; False when the loop is neither."""
        got = double_d(segs)
        if got is not None:
            c, d, af, ang = got
            D, F = self.kind_params("ddhole", (("d", d), ("flat", af)))
            if F[0].isalpha():            # the flats cut the circle: closer than its diameter
                self.params.bound(F, "0 mm", D, "the flats cut the circle: closer together "
                                                "than its diameter")
            turn = f"{_deg(ang)} " if abs(ang) > 1e-15 else ""

            def at(term: str) -> str:        # an angle `term` from the flats' normal
                if not turn:
                    return term
                return f"{turn}{'- ' + term[1:] if term.startswith('-') else '+ ' + term}"
            arcs = [f"e{k} = Arc(center=c, start=polar(c, {D} / 2, {at(a0)}), "
                    f"end=polar(c, {D} / 2, {at(a1)}))"
                    for k, (a0, a1) in enumerate((("t", "180 deg - t"), ("180 deg + t", "-t")))]
            self._bore(depth, "ddhole", "double-D", c, [f"t = acos({F} / {D})", *arcs,
                                                        "e2 = Line(start=e0.end, end=e1.start)",
                                                        "e3 = Line(start=e1.end, end=e0.start)"],
                       ["e0", "e1"])
            return True
        got = keyway(segs)
        if got is not None:
            c, d, kw, kd, ang = got
            D, W, K = self.kind_params("keyway", (("d", d), ("w", kw), ("depth", kd)))
            A, S0, S1 = (_deg(x) for x in (ang, ang - math.pi / 2, ang + math.pi / 2))
            corners = ", ".join(f"polar({p}, {W} / 2, {s})"
                                for p, s in (("c", S0), ("top", S0), ("top", S1), ("c", S1)))
            self._bore(depth, "keyway", "keyway", c, [f"top = polar(c, {D} / 2 + {K}, {A})",
                                                      f"bore = Circle(center=c, diameter={D})",
                                                      f"key = Polygon([{corners}])"],
                       ["bore", "key"])
            return True
        return False

    def _bore(self, depth: int, base: str, kind: str, c, lines: list, fixed: list) -> None:
        """``hole <base> { c = <c placed>; lines }`` and the ``Fixed`` of its ``fixed``
        members, counted as ``kind``."""
        hn = self.name(base)
        self.w.emit(depth, f"hole {hn} {{")
        for ln in [f"c = {self.pos(c)}", *lines]:
            self.w.emit(depth + 1, ln)
        self.w.emit(depth, "}")
        self.w.emit(depth, f"for x in [{', '.join(f'{hn}.{x}' for x in fixed)}] {{ Fixed(x) }}")
        self.stats.kinds[kind] += 1
