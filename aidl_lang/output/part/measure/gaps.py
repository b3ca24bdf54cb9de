"""Exact distances between outlines (``measure``'s clearance, :meth:`aidl_lang.api.Result.measure`).

An outline is a list of exact segments (:mod:`aidl_lang.geometry.shapes.curves`: lines, arcs,
circles; splines and elliptic arcs as their chords, within ``CHORD_TOL``).  The smallest
distance between two lines or arcs is at an end of one, at a crossing, or where the segment
joining them is normal to both: for a line and an arc the arc's point on the normal through
its centre, for two arcs their points on the line of centres.  :func:`gap` tries exactly
those points, so the distance is exact to rounding (1e-9 mm), not sampled.
"""
from __future__ import annotations

import math

import numpy as np

from ....geometry.shapes.curves import Arc, Circle, Line, sample_xy
from ....geometry.shapes.tessellate import CHORD_TOL

TAU = 2 * math.pi
Point = tuple[float, float]


def pieces(segments) -> list[tuple]:
    """``("L", p, q)`` for lines, ``("A", center, r, a0, sweep)`` for arcs and circles (sweep
    2 pi), chords ``("L", ...)`` for splines and elliptic arcs."""
    out: list[tuple] = []
    for s in segments:
        if isinstance(s, Line):
            out.append(("L", tuple(s.start), tuple(s.end)))
        elif isinstance(s, Arc):
            a0, sw = (s.start_angle, s.sweep) if s.sweep >= 0 else \
                (s.start_angle + s.sweep, -s.sweep)
            out.append(("A", tuple(s.center), s.radius, a0, sw))
        elif isinstance(s, Circle):
            out.append(("A", tuple(s.center), s.radius, 0.0, TAU))
        else:
            xs: list = []
            ys: list = []
            sample_xy([s], xs, ys)
            pts = list(zip(xs, ys)) + [tuple(s.end)]
            out += [("L", p, q) for p, q in zip(pts, pts[1:])]
    return out


def _on_arc(a: tuple, angle: float) -> bool:
    _, _, _, a0, sw = a
    return sw >= TAU - 1e-15 or (angle - a0) % TAU <= sw + 1e-15


def _ends(p: tuple) -> list[Point]:
    if p[0] == "L":
        return [p[1], p[2]]
    _, (cx, cy), r, a0, sw = p
    if sw >= TAU - 1e-15:
        return []
    return [(cx + r * math.cos(a0), cy + r * math.sin(a0)),
            (cx + r * math.cos(a0 + sw), cy + r * math.sin(a0 + sw))]


def point_to(p: Point, q: tuple) -> tuple[float, Point]:
    """``(distance, nearest point)`` from ``p`` to the piece ``q``."""
    if q[0] == "L":
        (ax, ay), (bx, by) = q[1], q[2]
        dx, dy = bx - ax, by - ay
        L2 = dx * dx + dy * dy
        t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L2))
        f = (ax + t * dx, ay + t * dy)
        return math.dist(p, f), f
    _, (cx, cy), r, a0, sw = q
    d = math.hypot(p[0] - cx, p[1] - cy)
    if d == 0.0:
        f = (cx + r * math.cos(a0), cy + r * math.sin(a0))
        return r, f
    ang = math.atan2(p[1] - cy, p[0] - cx)
    if _on_arc(q, ang):
        f = (cx + r * (p[0] - cx) / d, cy + r * (p[1] - cy) / d)
        return abs(d - r), f
    return min(((math.dist(p, e), e) for e in _ends(q)), key=lambda t: t[0])


def _crossing(a: tuple, b: tuple) -> Point | None:
    """A point where pieces ``a`` and ``b`` meet, or None."""
    from ....geometry.shapes.curves import crossings
    ca, cb = _carrier(a), _carrier(b)
    if ca is None or cb is None:
        return None
    for x in crossings(ca, cb):
        if point_to(x, a)[0] <= 1e-9 and point_to(x, b)[0] <= 1e-9:
            return x
    return None


def _carrier(p: tuple):
    if p[0] == "L":
        (ax, ay), (bx, by) = p[1], p[2]
        L = math.hypot(bx - ax, by - ay)
        return None if L == 0 else ("L", ax, ay, (bx - ax) / L, (by - ay) / L)
    return ("C", p[1][0], p[1][1], p[2])


def piece_gap(a: tuple, b: tuple) -> tuple[float, Point, Point]:
    """``(distance, point of a, point of b)``: the nearest points of two pieces (exact)."""
    x = _crossing(a, b)
    if x is not None:
        return 0.0, x, x
    best = (math.inf, (0.0, 0.0), (0.0, 0.0))
    cands_a = list(_ends(a))
    cands_b = list(_ends(b))
    for own, other, cands in ((a, b, cands_a), (b, a, cands_b)):
        if own[0] != "A":
            continue
        (cx, cy), r = own[1], own[2]
        if other[0] == "A":
            ox, oy = other[1]
            d = math.hypot(ox - cx, oy - cy)
            # concentric: the ends give the answer, or any direction for two whole circles
            dirs = [((ox - cx) / d, (oy - cy) / d)] if d else [(1.0, 0.0)]
        else:
            (ax, ay), (bx, by) = other[1], other[2]
            L = math.hypot(bx - ax, by - ay)
            dirs = [] if L == 0 else [(-(by - ay) / L, (bx - ax) / L)]
        if not _ends(own):              # a whole circle: its nearest point to an end
            dirs += [((e[0] - cx) / k, (e[1] - cy) / k) for e in _ends(other)
                     for k in [math.hypot(e[0] - cx, e[1] - cy)] if k > 0]
        for ux, uy in dirs:
            for s in (1.0, -1.0):
                if _on_arc(own, math.atan2(s * uy, s * ux)):
                    cands.append((cx + s * r * ux, cy + s * r * uy))
    for p in cands_a:
        d, f = point_to(p, b)
        if d < best[0]:
            best = (d, p, f)
    for p in cands_b:
        d, f = point_to(p, a)
        if d < best[0]:
            best = (d, f, p)
    return best


def _boxes(ps: list[tuple]) -> np.ndarray:
    out = np.empty((len(ps), 4))
    for i, p in enumerate(ps):
        if p[0] == "L":
            (ax, ay), (bx, by) = p[1], p[2]
            out[i] = (min(ax, bx), min(ay, by), max(ax, bx), max(ay, by))
        else:
            (cx, cy), r = p[1], p[2]
            out[i] = (cx - r, cy - r, cx + r, cy + r)
    return out


def gap(a: list[tuple], b: list[tuple]) -> tuple[float, Point, Point]:
    """The smallest distance between the outlines ``a`` and ``b`` (lists of :func:`pieces`)
    and its two points, exact; only pairs whose boxes lie within the best distance found
    so far are tried."""
    if not a or not b:
        raise ValueError("an outline with no curves")
    A, B = _boxes(a), _boxes(b)
    # box-to-box distance of every pair: a lower bound of the pieces' distance
    dx = np.maximum(0, np.maximum(A[:, None, 0] - B[None, :, 2], B[None, :, 0] - A[:, None, 2]))
    dy = np.maximum(0, np.maximum(A[:, None, 1] - B[None, :, 3], B[None, :, 1] - A[:, None, 3]))
    low = np.hypot(dx, dy)
    order = np.argsort(low, axis=None)
    best = (math.inf, (0.0, 0.0), (0.0, 0.0))
    m = len(b)
    for k in order:
        i, j = divmod(int(k), m)
        if low[i, j] > best[0]:
            break
        got = piece_gap(a[i], b[j])
        if got[0] < best[0]:
            best = got
            if best[0] == 0.0:
                break
    return best


def _polygon(loops) -> list[np.ndarray]:
    out = []
    for lp in loops:
        pts = lp.points(CHORD)
        if len(pts) >= 3:
            out.append(pts)
    return out


# mm: the chords' sagitta in the polygons of a region (the outlines' own chord tolerance:
# Loop.points takes no finer)
CHORD = CHORD_TOL


def _inside(p: Point, polys: list[np.ndarray]) -> bool:
    """Even-odd: ``p`` inside the region of the loops' polygons."""
    x, y = p
    inside = False
    for P in polys:
        X, Y = P[:, 0], P[:, 1]
        X2, Y2 = np.roll(X, -1), np.roll(Y, -1)
        cross = (Y > y) != (Y2 > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            xs = X + (y - Y) * (X2 - X) / (Y2 - Y)
        inside ^= bool(np.count_nonzero(cross & (x < xs)) % 2)
    return inside


def regions(loops) -> list[list]:
    """``loops`` as a list of regions, each a list of loops (one part's: holes clockwise):
    a list of loops is one region; a list of lists (an assembly's parts) is one region each."""
    if loops and isinstance(loops[0], (list, tuple)):
        return [list(r) for r in loops if r]
    return [list(loops)] if loops else []


def clearance(loops_a, loops_b) -> dict:
    """How two regions lie (each a list of exact :class:`~aidl_lang.geometry.shapes.curves.Loop`,
    holes clockwise, or a list of such lists: the union of several parts, :func:`regions`):
    ``{"clearance" mm, "contact", "points"}``.  ``contact`` ``apart``: the
    smallest gap between their outlines, exact; ``touching``: 0, the outlines meet without
    the regions sharing area; ``overlapping``: the regions share area (one may hold the
    other), ``clearance`` the negative of how deep the deepest point of one outline lies
    inside the other (exact for circles; else over the outlines' vertices, chords within
    :data:`CHORD`),
    ``overlap_area`` mm²: exact for two regions of lines, arcs and circles
    (:func:`.overlap.shared_area`); else Manifold's over chords within :data:`CHORD`, rounded
    to the digits it holds, with ``overlap_area_within``: its bound (mm², the chords' sagitta
    times the outlines' length)."""
    import manifold3d as mf
    from .overlap import shared_area
    ra, rb = regions(loops_a), regions(loops_b)
    pa = pieces([s for r in ra for lp in r for s in lp.segments])
    pb = pieces([s for r in rb for lp in r for s in lp.segments])
    d, p, q = gap(pa, pb)
    A, B = [_polygon(r) for r in ra], [_polygon(r) for r in rb]
    sa, sb = (_union([mf.CrossSection([P.tolist() for P in g], mf.FillRule.EvenOdd)
                      for g in G]) for G in (A, B))
    shared = (sa ^ sb).area()
    small = 1e-6 * max(1.0, min(sa.area(), sb.area()))
    # the exact area where the estimate finds some (the outlines meet or one holds the other)
    exact = shared_area(ra[0], rb[0]) if shared > 0 and len(ra) == len(rb) == 1 else None
    shared = shared if exact is None else exact
    if shared <= small:
        contact = "touching" if d <= 1e-9 else "apart"
        return {"clearance": 0.0 if contact == "touching" else d, "contact": contact,
                "points": [list(p), list(q)]}
    depth = 0.0
    for own, other, P in ((pa, pb, A), (pb, pa, B)):
        circ = [x for x in other if x[0] == "A" and x[4] >= TAU - 1e-15]
        cands = [tuple(v) for g in P for poly in g for v in poly]
        for c in own:                   # a circle's deepest point: on the line of centres
            if c[0] == "A" and c[4] >= TAU - 1e-15:
                for o in circ:
                    dd = math.dist(c[1], o[1])
                    if dd > 0:
                        ux, uy = (o[1][0] - c[1][0]) / dd, (o[1][1] - c[1][1]) / dd
                        cands.append((c[1][0] + c[2] * ux, c[1][1] + c[2] * uy))
        groups = B if own is pa else A
        for v in cands:
            if any(_inside(v, g) for g in groups):
                depth = max(depth, gap([("L", v, v)], other)[0])
    out = {"clearance": -depth if depth else 0.0, "contact": "overlapping",
           "overlap_area": shared, "points": [list(p), list(q)]}
    if exact is None:
        bound = CHORD * sum(lp.perimeter for r in ra + rb for lp in r)
        digits = max(0, -math.floor(math.log10(bound))) if bound > 0 else 9
        out["overlap_area"] = round(shared, digits)
        out["overlap_area_within"] = float(f"{bound:.1g}")
    return out


def _union(sections: list):
    """The union of Manifold cross-sections (one region each)."""
    out = sections[0]
    for s in sections[1:]:
        out = out + s
    return out


def stacked_parts(parts, least: float) -> list[tuple[float, str, str, tuple]]:
    """The pairs of solid parts among ``parts`` (:class:`~aidl_lang.output.part.part.Part`)
    that lie over each other where they are drawn: ``(area mm², a, b, (x0, y0, x1, y1) mm of
    the area they share)`` for each pair sharing more than ``least`` mm², in the parts'
    order.  Candidate pairs come from the parts' exact boxes
    (:func:`.nearby.box_pairs`, O(n log n)); each is intersected with Manifold's
    CrossSection (the parts' true outlines in chords within ``CHORD_TOL``, holes cut), so a
    part nested in another's hole, or two L shapes whose boxes cross, do not overlap."""
    from .nearby import box_pairs
    solids = [p for p in parts if p.kind == "solid" and p.loops]
    if len(solids) < 2:
        return []
    boxes = []
    for p in solids:
        bs = [g.box() for lp in p.loops for g in lp.segments]      # exact (x0, y0, x1, y1)
        boxes.append((min(b[0] for b in bs), min(b[1] for b in bs),
                      max(b[2] for b in bs), max(b[3] for b in bs)))
    out = []
    for i, j in box_pairs(boxes):        # a part's CrossSection only where boxes meet
        common = solids[i].shape ^ solids[j].shape
        area = common.area()
        if area > least:
            out.append((float(area), solids[i].name, solids[j].name,
                        tuple(float(v) for v in common.bounds())))
    return out


def entity(g, renderer) -> dict:
    """``{"kind", "pieces", "center"?, "ends"?, "loops"?}`` of geometry ``g`` at the values
    ``renderer`` draws with (``renderer.x``, mm; model frame): a point, a line (its segment),
    a closed shape (its exact loops), else an open curve's exact pieces.  What
    :meth:`aidl_lang.api.Result.measure` and an assert's ``distance(a, b)`` of shapes measure.
    Raises :class:`KeyError` for a geometry with no curve (a construction-only point set)."""
    x = renderer.x
    ox = oy = 0.0
    t = g.owner
    while t is not None:
        ox += x[t.fx]
        oy += x[t.fy]
        t = t.parent
    pts = {k: (float(x[p.ix] + ox), float(x[p.iy] + oy)) for k, p in g.points.items()}
    if "center" not in pts and {"bottom_left", "top_right"} <= set(pts):
        (ax, ay), (cx, cy) = pts["bottom_left"], pts["top_right"]
        pts["center"] = ((ax + cx) / 2, (ay + cy) / 2)
    if g.kind == "Point":
        p = next(iter(pts.values()))
        return {"kind": "point", "pieces": [("L", p, p)], "center": p}
    if g.kind == "Line":
        p, q = pts["start"], pts["end"]
        return {"kind": "line", "pieces": [("L", p, q)], "ends": (p, q)}
    loops = [] if g.kind == "Arc" else renderer.loops_of(g)
    if loops:
        return {"kind": "circle" if g.kind == "Circle" else "shape", "loops": loops,
                "pieces": pieces([sg for lp in loops for sg in lp.segments]),
                "center": pts.get("center")}
    try:                            # an open curve: an arc, a polyline, a spline
        segs = renderer.pieces(g)
    except (KeyError, AttributeError, TypeError):
        segs = []
    if not segs:
        raise KeyError(f"`{g.label}` ({g.kind}) has no curve to measure")
    return {"kind": "arc" if g.kind == "Arc" else "curve", "pieces": pieces(segs),
            "center": pts.get("center") if g.kind == "Arc" else None}
