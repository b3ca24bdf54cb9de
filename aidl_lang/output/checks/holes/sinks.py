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


def check_sinks(d, sink, tick=lambda: None) -> None:
    """W0528 and W0529 for the countersinks and counterbores of ``d`` (the booleans'
    result, its ``sinks``) into ``sink``."""
    said = set()
    shapes = {p.name: p.shape for p in d.parts}
    for sk in getattr(d, "sinks", None) or ():
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
        shape = shapes.get(sk.part)
        if shape is not None:
            off = (_disc(sk.center, sk.diameter / 2) - _disc(sk.center, sk.hole_d / 2)
                   - shape).area()
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
