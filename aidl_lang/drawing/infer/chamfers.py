"""``aidl import --infer``: a plate whose four corners are cut by equal 45-degree chamfers
(:func:`_chamfered`), and whether the notches of its sides leave room for ``Chamfer``
(:func:`_clear_of_chamfers`); used by :meth:`~.infer._Part.body`.  Lengths in mm."""
from __future__ import annotations

from .shapes import EQUAL_TOL, Shape


def _clear_of_chamfers(cuts: list, rect: Shape, leg: float) -> bool:
    """Whether every notch ``(side, shape, lo, hi, depth)`` leaves at least two chamfer legs
    of its side between it and each corner: ``Chamfer`` cuts at most half of each segment of
    the final outline, so a notch nearer a corner would shorten that corner's chamfer."""
    for side, _, lo, hi, _ in cuts:
        axis = 1 if side in ("left", "right") else 0
        key = "width" if axis == 0 else "height"
        a = rect.center[axis] - rect.args[key] / 2
        b = rect.center[axis] + rect.args[key] / 2
        if lo - a < 2 * leg - 1e-9 or b - hi < 2 * leg - 1e-9:
            return False
    return True


def _chamfered(sh: Shape | None) -> tuple | None:
    """A Polygon of 8 corners that is an upright rectangle with its four corners cut by
    equal 45-degree chamfers: ``(the Rectangle, the chamfer's leg in mm)``, else None."""
    if sh is None or sh.kind != "Polygon" or len(sh.args["points"]) != 8:
        return None
    pts = sh.args["points"]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    legs = []
    for (ax, ay), (bx, by) in zip(pts, pts[1:] + pts[:1]):
        on_side = (abs(ax - bx) <= EQUAL_TOL and min(abs(ax - x0), abs(ax - x1)) <= EQUAL_TOL) \
            or (abs(ay - by) <= EQUAL_TOL and min(abs(ay - y0), abs(ay - y1)) <= EQUAL_TOL)
        if on_side:
            continue
        dx, dy = abs(bx - ax), abs(by - ay)
        if abs(dx - dy) > EQUAL_TOL:
            return None
        legs.append(dx)
    if len(legs) != 4 or max(legs) - min(legs) > EQUAL_TOL or min(legs) <= EQUAL_TOL or \
            2 * legs[0] >= min(x1 - x0, y1 - y0) - EQUAL_TOL:
        return None
    # every corner point on the box's sides, a leg in from its corner
    for x, y in pts:
        if min(abs(x - x0), abs(x - x1)) > EQUAL_TOL and min(abs(y - y0), abs(y - y1)) > EQUAL_TOL:
            return None
    W, H = x1 - x0, y1 - y0
    rect = Shape("Rectangle", ((x0 + x1) / 2, (y0 + y1) / 2), {"width": W, "height": H},
                 ("Rectangle", W, H), sh.pieces)
    return rect, legs[0]
