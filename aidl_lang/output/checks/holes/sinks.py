"""The checks of countersinks and counterbores (issue 102): ``W0528`` a head that is not
larger than its hole or reaches past the material around it (off the part's edge, into
another hole), ``W0529`` a head deeper than the part is thick (a countersink's cone or a
counterbore's recess through the part), each at the ``Countersink`` / ``Counterbore`` call.
Measured on the booleans' shapes (chords within ``CHORD_TOL`` of the exact circles): the head's
disc less the hole's and the part's material, more than :data:`OFF_AREA` mm² of it."""
from __future__ import annotations

import math

from ....geometry.shapes.tessellate import CHORD_TOL

OFF_AREA = 1e-2         # mm²: a head with more than this off the material reaches past it


def _disc(center, r: float):
    import manifold3d as mf
    n = max(24, min(720, int(math.ceil(math.pi / math.acos(max(-1.0, 1 - CHORD_TOL / r))))))
    return mf.CrossSection.circle(r, n).translate(list(center))


class _Near:
    """A part's material near a point: its loops (``CrossSection.to_polygons``, outer
    counter-clockwise, holes clockwise) kept in a grid of square cells by their boxes, so a
    head is measured against the loops whose boxes meet its own, not the whole part (issue
    110: 3,025 sunk holes took 31.7 s of CPU against 1.98 s unsunk, each head's disc less the
    whole part).  A loop whose box misses a region winds nothing there, so those loops under
    the positive fill rule are the part's material within it, exactly."""

    def __init__(self, shape, cell: float):
        import numpy as np
        self.cell = cell
        self.loops = shape.to_polygons()
        self.grid: dict = {}
        self.big: list = []            # loops over more than BIG cells: met by every query
        for k, lp in enumerate(self.loops):
            a = np.asarray(lp)
            (x0, y0), (x1, y1) = a.min(axis=0), a.max(axis=0)
            i0, i1, j0, j1 = self._cells(x0, x1, y0, y1)
            if (i1 - i0 + 1) * (j1 - j0 + 1) > BIG:
                self.big.append(k)
                continue
            for i in range(i0, i1 + 1):
                for j in range(j0, j1 + 1):
                    self.grid.setdefault((i, j), []).append(k)

    def _cells(self, x0, x1, y0, y1) -> tuple[int, int, int, int]:
        c = self.cell
        return (math.floor(x0 / c), math.floor(x1 / c), math.floor(y0 / c), math.floor(y1 / c))

    def around(self, center, r: float):
        """The part's material within the square of half-side ``r`` about ``center`` (a
        CrossSection that equals the part there)."""
        import manifold3d as mf
        x, y = center
        i0, i1, j0, j1 = self._cells(x - r, x + r, y - r, y + r)
        ks = set(self.big)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                ks.update(self.grid.get((i, j), ()))
        return mf.CrossSection([self.loops[k] for k in sorted(ks)], mf.FillRule.Positive)


BIG = 64       # cells a loop's box may cover before it is met by every query instead


def check_sinks(d, sink, tick=lambda: None) -> None:
    """W0528 and W0529 for the countersinks and counterbores of ``d`` (the booleans'
    result, its ``sinks``) into ``sink``.  Each head is measured against the material near
    it (:class:`_Near`): n heads on a part of n holes cost n log n, not n²."""
    said = set()
    sinks = getattr(d, "sinks", None) or ()
    near: dict = {}
    if sinks:
        cell = max(max(sk.diameter for sk in sinks), 1e-3)
        near = {p.name: _Near(p.shape, cell) for p in d.parts
                if p.shape is not None and any(sk.part == p.name for sk in sinks)}
    for sk in sinks:
        tick()
        what = f"the {sk.diameter:g} mm head of the {sk.kind} of `{sk.hole}`"
        fn = "Countersink" if sk.kind == "countersink" else "Counterbore"
        if sk.diameter <= sk.hole_d + 1e-9:
            if (id(sk.span), "small") not in said:
                said.add((id(sk.span), "small"))
                sink.warning("W0528", f"{what} is not larger than the hole ({sk.hole_d:g} mm): "
                             "there is no head to sink", sk.span,
                             hint=f"give `{fn}` a diameter above {sk.hole_d:g} mm (a M4 "
                                  "flat-head screw: a 4.5 mm hole, a 9 mm head)")
            continue
        material = near.get(sk.part)
        if material is not None:
            off = (_disc(sk.center, sk.diameter / 2) - _disc(sk.center, sk.hole_d / 2)
                   - material.around(sk.center, sk.diameter / 2)).area()
            if off > OFF_AREA and (id(sk.span), "off") not in said:
                said.add((id(sk.span), "off"))
                x, y = sk.center
                sink.warning("W0528", f"{what} at ({x:.4g}, {y:.4g}) reaches past the material "
                             f"around it: {off:.3g} mm² of it lies off part `{sk.part}` (past "
                             "its edge or in another hole)", sk.span,
                             hint=f"move the hole {sk.diameter / 2:g} mm or more from the "
                                  "edges and other holes, or give a smaller head")
        t = d.thickness.get(sk.part)
        depth = sk.cone_depth()
        if t is not None and depth >= t - 1e-9 and (id(sk.span), "deep") not in said:
            said.add((id(sk.span), "deep"))
            how = (f"its {math.degrees(sk.angle):g} deg cone is {depth:.3g} mm deep"
                   if sk.kind == "countersink" else f"it is {depth:g} mm deep")
            sink.warning("W0529", f"{what}: {how}, past the part's thickness ({t:g} mm): "
                         "it goes through the part and leaves no seat", sk.span,
                         hint=("give a smaller head or a wider angle, or thicker material"
                               if sk.kind == "countersink" else
                               f"give a `depth` under {t:g} mm, or thicker material"))


__all__ = ["check_sinks", "OFF_AREA"]
