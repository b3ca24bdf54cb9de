"""What the countersinks and counterbores that go through a part leave of it (issue 109, law 2:
every output is the same part).

A head goes through a part ``t`` mm thick when its cone (a countersink's, ``(D - d) / 2 /
tan(angle / 2)`` deep) or its recess (a counterbore's ``depth``) reaches the bottom face (W0529
says so).  Each cone or recess only widens upward, so every point of the sunk part lies above a
point of its bottom face: the part's solid is in one piece for each piece of its bottom face,
and empty when the bottom face is.  The bottom face is the part's outline less a disc per head
that goes through: a countersink's ``D / 2 - t tan(angle / 2)`` in radius, a counterbore's
``D / 2``.  A design whose heads leave nothing of a part, or cut it apart, would give an STL,
3MF or GLB of nothing (or of pieces) beside an SVG and DXF of the whole plate: it is the
located ``E0503`` at the call of the widest head, before any output is written, in every
format (the compile's check at the program's thickness, :func:`sunk_away`; the writers' at a
thickness given for the output, ``--thickness``)."""
from __future__ import annotations

import math

import manifold3d as mf

from ....geometry.shapes.tessellate import CHORD_TOL

DEFAULT_THICKNESS = 3.0     # mm: every output's thickness when none is given (the one definition)
LEFT_AREA = 1e-2            # mm²: a piece of the bottom face smaller than this is no piece


def floor_radius(sk, t: float) -> float | None:
    """The radius (mm) of what head ``sk`` (:class:`~.result.SinkAt`) removes of the bottom
    face of a part ``t`` mm thick: None when it does not reach that face, or no wider than its
    hole there."""
    if sk.cone_depth() < t - 1e-9:
        return None
    r = (sk.diameter / 2 - t * math.tan(sk.angle / 2) if sk.kind == "countersink"
         else sk.diameter / 2)
    return r if r > sk.hole_d / 2 + 1e-9 else None


def _disc(center, r: float) -> mf.CrossSection:
    n = max(24, min(720, int(math.ceil(math.pi / math.acos(max(-1.0, 1 - CHORD_TOL / r))))))
    return mf.CrossSection.circle(r, n).translate([float(center[0]), float(center[1])])


def sunk_away(shape: mf.CrossSection, heads: list, t: float) -> tuple | None:
    """Whether the heads ``heads`` (``[(centre, SinkAt)]``, the part's) leave nothing of a
    part of outline ``shape`` ``t`` mm thick, or cut it apart: ``(pieces left, pieces drawn,
    the widest head through, its floor radius)``, or None when they leave it as drawn (no head
    goes through, or what goes through leaves as many pieces)."""
    through = [(c, sk, r) for c, sk in heads if (r := floor_radius(sk, t)) is not None]
    if not through or shape is None or shape.is_empty():
        return None
    left = shape - mf.CrossSection.batch_boolean([_disc(c, r) for c, _, r in through],
                                                 mf.OpType.Add)
    n = sum(1 for piece in left.decompose() if piece.area() > LEFT_AREA)
    drawn = sum(1 for piece in shape.decompose() if piece.area() > LEFT_AREA)
    if n == drawn:
        return None
    _, sk, r = max(through, key=lambda h: h[2])
    return n, drawn, sk, r


def sunk_message(part: str, found: tuple, t: float) -> tuple[str, str]:
    """``E0503``'s message and hint for part ``part`` ``t`` mm thick (:func:`sunk_away`'s
    ``found``)."""
    n, drawn, sk, r = found
    kind = sk.kind
    how = (f"its {math.degrees(sk.angle):g} deg cone" if kind == "countersink"
           else f"its {sk.depth:g} mm recess")
    left = ("leave nothing of it" if n == 0 else
            f"cut it into {n} pieces (it is drawn in {drawn})" if n > drawn else
            f"leave {n} of its {drawn} pieces")
    message = (f"the {kind}s of part `{part}` {left}: the {sk.diameter:g} mm head on "
               f"`{sk.hole}` ({sk.hole_d:g} mm hole) goes through the {t:g} mm part, {how} "
               f"{2 * r:.4g} mm wide at its bottom face; the 3D formats would hold "
               f"{'no part' if n == 0 else 'the pieces'} while the drawings show the part "
               "whole, so nothing is written")
    hint = ("give the head the screw's size (an M4 flat-head screw: a 4.5 mm hole, a 9 mm "
            "head), a wider angle or thicker material" if kind == "countersink" else
            f"give a `depth` under {t:g} mm or a smaller head, or thicker material")
    return message, hint


__all__ = ["DEFAULT_THICKNESS", "floor_radius", "sunk_away", "sunk_message"]
