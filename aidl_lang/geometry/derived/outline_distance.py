"""How far a point lies from the outline of a shape that ``Fillet([a, b], r)`` names
(:func:`.fillet_at.outline_spec` gives the kind and its points, :func:`_sizes` its solved
sizes): what :func:`.corners.shapes_meet` reads to find the corners of the final outline on
both shapes' outlines (issue 111: a round-ended tab on a disc, a handle's edge into an oval,
a hook's band on a plate)."""
from __future__ import annotations

import math


def _unit(x: float, y: float) -> tuple[float, float]:
    n = math.hypot(x, y)
    return (x / n, y / n) if n > 0 else (0.0, 0.0)


def one_radius(g) -> bool:
    """A RoundedRectangle whose corners are all of one radius (``corner_radius=``, or
    ``corner_radii=`` all alike: runs bw, ce, `[8, 8, 8, 8]` was taken for its sharp polygon
    and E0408 found no crossing on its arcs)."""
    radii = g.data.get("corner_radii")
    return g.kind == "RoundedRectangle" and bool(g.data.get("corner_radius")) and (
        radii is None or max(radii) - min(radii) <= 1e-12)


def _sizes(g, x) -> tuple:
    """The solved sizes of shape ``g`` a distance to its outline needs: (radius,) of a
    Circle or Slot, (rx, ry, rotation) of an Ellipse, () otherwise."""
    if g.kind in ("Circle", "Slot"):
        return (abs(float(x[g.scalars["radius"].index])),)
    if one_radius(g):                                     # (the "rounded" spec)
        return (float(g.data["corner_radius"]),)
    if g.kind == "RoundedRectangle" and g.data.get("corner_radii"):
        return tuple(float(r) for r in g.data["corner_radii"])    # (points_of's order)
    if g.kind == "Stroke":          # half its width, then each path piece's count of points
        from ..relations.members import points_of                  # (an Arc's: 3, centre first)
        return (float(g.data["width"]) / 2,) + tuple(
            -3 if src.kind == "Arc" else len(points_of(src)) if src.kind == "Polyline" else 2
            for src in g.data["sources"])
    if g.kind == "ArcSlot":
        return (g.data["dims"]["width"] / 2,)
    if g.kind == "Ellipse":
        from ..relations.bbox import held_rotation
        return (abs(float(x[g.scalars["rx"].index])), abs(float(x[g.scalars["ry"].index])),
                float(held_rotation(g, x)))
    return ()


def outline_distance(kind: str, pts: list, sizes: tuple, p) -> float:
    """How far (mm) point ``p`` lies from the outline of a shape given by
    :func:`.fillet_at.outline_spec` (``pts`` placed) and :func:`_sizes`; an ellipse's by
    its implicit function over its gradient (first order: exact on the curve, where it is
    asked)."""
    px, py = p
    if kind == "circle":
        (cx, cy), = pts
        return abs(math.hypot(px - cx, py - cy) - sizes[0])
    if kind == "ellipse":
        (cx, cy), = pts
        rx, ry, rot = sizes
        co, si = math.cos(rot), math.sin(rot)
        u, v = co * (px - cx) + si * (py - cy), -si * (px - cx) + co * (py - cy)
        f = (u / rx) ** 2 + (v / ry) ** 2 - 1
        grad = 2 * math.hypot(u / rx ** 2, v / ry ** 2)
        return abs(f) / grad if grad > 0 else math.inf
    if kind in ("slot", "segment"):
        (ax, ay), (bx, by) = pts
        dx, dy = bx - ax, by - ay
        L2 = dx * dx + dy * dy
        t = 0.0 if L2 == 0 else min(max(((px - ax) * dx + (py - ay) * dy) / L2, 0.0), 1.0)
        d = math.hypot(px - ax - t * dx, py - ay - t * dy)
        return abs(d - sizes[0]) if kind == "slot" else d
    if kind == "arcslot":                 # its centre line's arc, ccw from start to end,
        (cx, cy), st, en = pts            # grown by half its width
        r = math.hypot(st[0] - cx, st[1] - cy)
        a0 = math.atan2(st[1] - cy, st[0] - cx)
        sweep = (math.atan2(en[1] - cy, en[0] - cx) - a0) % (2 * math.pi)
        if (math.atan2(py - cy, px - cx) - a0) % (2 * math.pi) <= sweep:
            d = abs(math.hypot(px - cx, py - cy) - r)
        else:
            d = min(math.hypot(px - st[0], py - st[1]), math.hypot(px - en[0], py - en[1]))
        return abs(d - sizes[0])
    if kind == "rounded":                 # a RoundedRectangle: the rectangle its corners'
        (bl, br, tr, tl), rc = pts, sizes[0]   # centres span, grown by the corner radius
        ux, uy = br[0] - bl[0], br[1] - bl[1]
        vx, vy = tl[0] - bl[0], tl[1] - bl[1]
        lu, lv = math.hypot(ux, uy), math.hypot(vx, vy)
        if lu <= 2 * rc or lv <= 2 * rc:
            return outline_distance("polygon", list(pts), (), p)
        ux, uy, vx, vy = ux / lu, uy / lu, vx / lv, vy / lv
        # the point in the rectangle's own axes, about its centre; the inner half sizes
        mx, my = (bl[0] + tr[0]) / 2, (bl[1] + tr[1]) / 2
        a = abs((px - mx) * ux + (py - my) * uy) - (lu / 2 - rc)
        b = abs((px - mx) * vx + (py - my) * vy) - (lv / 2 - rc)
        inner = math.hypot(max(a, 0.0), max(b, 0.0)) + min(max(a, b), 0.0)
        return abs(inner - rc)
    if kind == "stroke":                  # a band: half its width from its path
        best, at = math.inf, 0
        for n in sizes[1:]:
            if n == -3:                   # an Arc: its centre line, ccw from start to end
                best = min(best, outline_distance("arcslot", pts[at:at + 3], (0.0,), p))
                at += 3
                continue
            for a, b in zip(pts[at:at + n], pts[at + 1:at + n]):
                best = min(best, outline_distance("segment", [a, b], (), p))
            at += n
        return abs(best - sizes[0])
    if kind == "rounded_radii":           # corners of several radii (run hb's paddle head,
        best = math.inf                   # [70, 70, 60, 60]: taken as its sharp rectangle,
        n = len(pts)                      # E0408 "no corner on both" where the throat met it)
        for k in range(n):                # each side between its corners' tangent points,
            a, b, c = pts[k - 1], pts[k], pts[(k + 1) % n]      # and each corner's arc
            r = sizes[k]
            ua = _unit(b[0] - a[0], b[1] - a[1])
            ub = _unit(c[0] - b[0], c[1] - b[1])
            s0 = (b[0] + r * ub[0], b[1] + r * ub[1])           # side k starts past the arc
            e0 = (c[0] - sizes[(k + 1) % n] * ub[0], c[1] - sizes[(k + 1) % n] * ub[1])
            best = min(best, outline_distance("segment", [s0, e0], (), p))
            if r > 0:
                cx, cy = b[0] - r * ua[0] + r * ub[0], b[1] - r * ua[1] + r * ub[1]
                # the quarter arc from the tangent point on the side in to the one out
                t0, t1 = (b[0] - r * ua[0], b[1] - r * ua[1]), s0
                if ((px - cx) * (t0[0] - cx) + (py - cy) * (t0[1] - cy) >= 0
                        and (px - cx) * (t1[0] - cx) + (py - cy) * (t1[1] - cy) >= 0):
                    best = min(best, abs(math.hypot(px - cx, py - cy) - r))
                else:
                    best = min(best, math.hypot(px - t0[0], py - t0[1]),
                               math.hypot(px - t1[0], py - t1[1]))
        return best
    best = math.inf                       # a polygon: its nearest side
    for (ax, ay), (bx, by) in zip(pts, pts[1:] + pts[:1]):
        best = min(best, outline_distance("segment", [(ax, ay), (bx, by)], (), p))
    return best
