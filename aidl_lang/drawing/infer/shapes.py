"""``aidl import --infer``: the primitives recognised in a closed chain of exact pieces
(docs/import.md, "Inferring the design").

:func:`recognise` takes one closed loop (a list of :class:`~aidl_lang.geometry.shapes.curves.Line`
and :class:`~aidl_lang.geometry.shapes.curves.Arc` pieces, or one
:class:`~aidl_lang.geometry.shapes.curves.Circle`) and returns a :class:`Shape`: a ``Circle``,
``Rectangle``, ``RoundedRectangle`` (every corner, or some: ``corner_radii=``), ``Slot``,
``RegularPolygon``, ``Sector`` (a pie slice or an annulus segment) or ``Polygon``, turned by
its ``rotation``; or None when the loop is none of them (it stays an exact chain).

A recognition is *made by construction and checked*: the shape's parameters are read from the
pieces, the shape's own pieces are generated from them (as the language draws the shape:
docs/language.md, each shape's section) and every generated piece must match one piece of
the loop, one for one, to :data:`EQUAL_TOL` (1e-7 mm: a point, a radius, an arc's ends and
middle), so nothing moves by more than that; tests/test_import_infer.py renders every example
back through the compiler and compares to 1e-6 mm.  Lengths in mm, angles in radians.
"""
from __future__ import annotations

import contextvars
import math
from dataclasses import dataclass, field

from ...geometry.shapes.curves import Arc, Circle, Line
from ..chains.chain import circular  # noqa: F401  (the loops' own form, as the plain import reads them)

EQUAL_TOL = 1e-7    # mm: two points, radii or lengths this close are the same
ROUND_TOL = 1e-9    # mm: a number within this of a shorter decimal is written as that decimal
# the drawing's own precision (the program's unit): one unit of the last decimal its file
# writes numbers to (an SVG's 6 decimals: 1e-6), 0 for a float's; set by to_program_inferred
# (issue 114: a bolt circle whose centres carry 6 decimals is one, equal within 2 of it)
PRECISION: "contextvars.ContextVar[float]" = contextvars.ContextVar("aidl_infer_precision",
                                                                   default=0.0)


@dataclass
class Shape:
    """A recognised primitive: ``kind`` (the constructor), ``center`` (mm), ``args`` (the
    keyword arguments after ``center``, as numbers: mm, or radians for ``rotation`` and
    angles), ``size`` (the numbers that make two shapes "the same size", for patterns) and
    ``pieces`` (how many pieces of the drawing it stands for)."""
    kind: str
    center: tuple
    args: dict = field(default_factory=dict)
    size: tuple = ()
    pieces: int = 1


def _rot(p, c, s):
    return (p[0] * c - p[1] * s, p[0] * s + p[1] * c)


def _close(p, q, tol=EQUAL_TOL) -> bool:
    return abs(p[0] - q[0]) <= tol and abs(p[1] - q[1]) <= tol


def arcs_and_lines(segs: list, arcs: int, lines: int) -> tuple | None:
    """``(the arcs, the lines)`` of a loop made of exactly ``arcs`` arcs and ``lines`` lines
    (in its order), else None: the first test of the holes with flats (a D, a double-D, a
    keyway)."""
    a = [s for s in segs if isinstance(s, Arc)]
    ln = [s for s in segs if isinstance(s, Line)]
    return (a, ln) if len(segs) == arcs + lines and len(a) == arcs and len(ln) == lines \
        else None


def _key(seg):
    """``(kind, points)`` of a piece whatever its direction: a line's two ends, an arc's centre,
    its ends and its middle (which side it bulges), its radius as the last number."""
    if isinstance(seg, Line):
        return ("L", [seg.start, seg.end], 0.0)
    mid = seg.at(seg.start_angle + seg.sweep / 2)
    return ("A", [seg.center, seg.start, seg.end, mid], seg.radius)


def _same(a, b) -> bool:
    ka, kb = _key(a), _key(b)
    if ka[0] != kb[0] or abs(ka[2] - kb[2]) > EQUAL_TOL:
        return False
    pa, pb = ka[1], kb[1]
    if ka[0] == "L":
        return (_close(pa[0], pb[0]) and _close(pa[1], pb[1])) or \
            (_close(pa[0], pb[1]) and _close(pa[1], pb[0]))
    if not (_close(pa[0], pb[0]) and _close(pa[3], pb[3])):
        return False
    return (_close(pa[1], pb[1]) and _close(pa[2], pb[2])) or \
        (_close(pa[1], pb[2]) and _close(pa[2], pb[1]))


def same_pieces(made: list, segs: list) -> bool:
    """True when ``made`` and ``segs`` are the same pieces, one for one (any order and
    direction), each to :data:`EQUAL_TOL`."""
    if len(made) != len(segs):
        return False
    left = list(segs)
    for m in made:
        for i, s in enumerate(left):
            if _same(m, s):
                del left[i]
                break
        else:
            return False
    return True


def _arc(center, r, a0, sweep) -> Arc:
    return Arc(center, r, a0, sweep)


def rrect_pieces(center, w, h, rot, radii) -> list:
    """The pieces of ``RoundedRectangle(center, w, h, corner_radii=radii, rotation=rot)``
    (``radii``: top_left, top_right, bottom_right, bottom_left; 0 a sharp corner): each
    corner a quarter arc tangent to its sides, the lines between them (none of zero length)."""
    c, s = math.cos(rot), math.sin(rot)
    cx, cy = center

    def W(p):
        q = _rot(p, c, s)
        return (cx + q[0], cy + q[1])
    hw, hh = w / 2, h / 2
    # corners counter-clockwise from bottom_right: (corner, radius, inward x, inward y, angle)
    tl, tr, br, bl = radii
    corners = [((hw, -hh), br, -1, 1, -math.pi / 2), ((hw, hh), tr, -1, -1, 0.0),
               ((-hw, hh), tl, 1, -1, math.pi / 2), ((-hw, -hh), bl, 1, 1, math.pi)]
    out = []
    ends = []       # each corner's (first point, last point) counter-clockwise
    for (x, y), r, ix, iy, a in corners:
        if r > EQUAL_TOL:
            cc = (x + ix * r, y + iy * r)
            arc = _arc(W(cc), r, a + rot, math.pi / 2)
            out.append(arc)
            ends.append((arc.start, arc.end))
        else:
            ends.append((W((x, y)), W((x, y))))
    for k in range(4):
        p, q = ends[k][1], ends[(k + 1) % 4][0]
        if math.dist(p, q) > EQUAL_TOL:
            out.append(Line(p, q))
    return out


def _frame_angle(segs) -> float:
    """The rotation of a rectangle-like loop: its longest line's direction, folded into
    (-45°, 45°]."""
    lines = [s for s in segs if isinstance(s, Line)]
    ln = max(lines, key=lambda s: s.length)
    a = math.atan2(ln.end[1] - ln.start[1], ln.end[0] - ln.start[0])
    q = math.pi / 2
    a = a - q * math.floor(a / q)        # [0, 90°)
    if a > math.pi / 4 + 1e-12:
        a -= q
    return _snap_angle(a, 1e3)


def _snap_angle(a: float, reach: float) -> float:
    """``a`` (radians) as a round number of degrees when that moves a point ``reach`` mm away
    by at most :data:`ROUND_TOL`."""
    d = math.degrees(a)
    for digits in range(0, 10):
        r = round(d, digits)
        if abs(math.radians(r) - a) * max(reach, 1.0) <= ROUND_TOL:
            return math.radians(r)
    return a


def _extent(segs, c, s):
    """``(x0, y0, x1, y1)`` of ``segs`` in the frame turned by the angle of (``c``, ``s``)."""
    pts = []
    for g in segs:
        pts += [g.start, g.end]
        if isinstance(g, Arc):
            a0 = math.atan2(s, c)
            for k in range(8):
                t = a0 + k * math.pi / 2
                # the arc passes the frame's axis direction t when t lies in its sweep
                lo = min(g.start_angle, g.end_angle)
                hi = max(g.start_angle, g.end_angle)
                t = t + 2 * math.pi * math.ceil((lo - t) / (2 * math.pi))
                if t <= hi:
                    pts.append(g.at(t))
    loc = [(p[0] * c + p[1] * s, -p[0] * s + p[1] * c) for p in pts]
    return (min(p[0] for p in loc), min(p[1] for p in loc), max(p[0] for p in loc),
            max(p[1] for p in loc))


def _as_rrect(segs):
    if not any(isinstance(s, Line) for s in segs) or len(segs) > 8:
        return None
    rot = _frame_angle(segs)
    c, s = math.cos(rot), math.sin(rot)
    x0, y0, x1, y1 = _extent(segs, c, s)
    w, h = x1 - x0, y1 - y0
    lc = ((x0 + x1) / 2, (y0 + y1) / 2)
    center = (lc[0] * c - lc[1] * s, lc[0] * s + lc[1] * c)
    radii = []
    for (px, py) in ((x0, y1), (x1, y1), (x1, y0), (x0, y0)):     # tl, tr, br, bl
        r = 0.0
        for g in segs:
            if isinstance(g, Arc):
                gx = g.center[0] * c + g.center[1] * s
                gy = -g.center[0] * s + g.center[1] * c
                if abs(abs(gx - px) - g.radius) <= EQUAL_TOL and \
                        abs(abs(gy - py) - g.radius) <= EQUAL_TOL:
                    r = g.radius
        radii.append(r)
    made = rrect_pieces(center, w, h, rot, radii)
    if not same_pieces(made, segs):
        return None
    n = len(segs)
    if not any(radii):
        return Shape("Rectangle", center, {"width": w, "height": h, "rotation": rot},
                     ("Rectangle", w, h, rot), n)
    if max(radii) - min(radii) <= EQUAL_TOL and abs(2 * radii[0] - min(w, h)) <= EQUAL_TOL \
            and abs(w - h) > EQUAL_TOL:
        # its ends whole half circles: an obround (a slot), its end caps drawn as two
        # quarter arcs each (as SVG writers split arcs), at any angle
        length, width = max(w, h), min(w, h)
        if h > w:
            rot += math.pi / 2
        if rot > math.pi / 2 + 1e-12:
            rot -= math.pi
        rot = _snap_angle(rot, length)
        return Shape("Slot", center, {"length": length, "width": width, "rotation": rot},
                     ("Slot", length, width, rot), n)
    if max(radii) - min(radii) <= EQUAL_TOL:
        return Shape("RoundedRectangle", center, {"width": w, "height": h,
                                                  "corner_radius": radii[0], "rotation": rot},
                     ("RoundedRectangle", w, h, radii[0], rot), n)
    return Shape("RoundedRectangle", center, {"width": w, "height": h, "corner_radii": radii,
                                              "rotation": rot},
                 ("RoundedRectangle", w, h, tuple(radii), rot), n)


def merged(segs: list) -> list:
    """The loop ``segs`` (in order) with each run of arcs on one circle, turning one way,
    joined into one arc (a reader splits an arc at its quadrants, a writer at 180 degrees);
    lines as they are."""
    out: list = []
    for s in segs:
        p = out[-1] if out else None
        if isinstance(s, Arc) and isinstance(p, Arc) and _same_circle(p, s) and \
                (p.sweep > 0) == (s.sweep > 0) and _close(p.end, s.start):
            out[-1] = Arc(p.center, p.radius, p.start_angle, p.sweep + s.sweep)
        else:
            out.append(s)
    if len(out) > 1:
        a, b = out[-1], out[0]
        if isinstance(a, Arc) and isinstance(b, Arc) and _same_circle(a, b) and \
                (a.sweep > 0) == (b.sweep > 0) and _close(a.end, b.start):
            out = [Arc(a.center, a.radius, a.start_angle, a.sweep + b.sweep)] + out[1:-1]
    return out


def _same_circle(a: Arc, b: Arc) -> bool:
    return _close(a.center, b.center) and abs(a.radius - b.radius) <= EQUAL_TOL


def _as_slot(segs):
    if len(segs) > 4:               # half circles split at their quadrants (an SVG path's
        segs = merged(segs)         # arcs, a reader's): the slot's four pieces
    arcs = [s for s in segs if isinstance(s, Arc)]
    lines = [s for s in segs if isinstance(s, Line)]
    if len(segs) != 4 or len(arcs) != 2 or len(lines) != 2:
        return None
    a, b = arcs
    r = a.radius
    if abs(a.radius - b.radius) > EQUAL_TOL or math.dist(a.center, b.center) <= EQUAL_TOL:
        return None
    dx, dy = b.center[0] - a.center[0], b.center[1] - a.center[1]
    rot = math.atan2(dy, dx)
    if rot <= -math.pi / 2 + 1e-12:       # a slot turned half a turn is the same slot
        rot += math.pi
    elif rot > math.pi / 2 + 1e-12:
        rot -= math.pi
    rot = _snap_angle(rot, math.hypot(dx, dy) + 2 * r)
    span = math.hypot(dx, dy)
    c, s = math.cos(rot), math.sin(rot)
    mid = ((a.center[0] + b.center[0]) / 2, (a.center[1] + b.center[1]) / 2)
    p, q = (mid[0] - c * span / 2, mid[1] - s * span / 2), (mid[0] + c * span / 2,
                                                            mid[1] + s * span / 2)
    nx, ny = -s * r, c * r
    made = [Line((p[0] - nx, p[1] - ny), (q[0] - nx, q[1] - ny)),
            _arc(q, r, rot - math.pi / 2, math.pi),
            Line((q[0] + nx, q[1] + ny), (p[0] + nx, p[1] + ny)),
            _arc(p, r, rot + math.pi / 2, math.pi)]
    if not same_pieces(made, segs):
        return None
    return Shape("Slot", mid, {"length": span + 2 * r, "width": 2 * r, "rotation": rot},
                 ("Slot", span + 2 * r, 2 * r, rot), 4)


def _as_lines(segs):
    """A Rectangle, a RegularPolygon, or a Polygon of a loop of lines only."""
    pts = [s.start for s in segs]
    n = len(pts)
    if n == 4:
        r = _as_rrect(segs)
        if r is not None:
            return r
    cx = sum(p[0] for p in pts) / n
    cy = sum(p[1] for p in pts) / n
    rad = [math.dist((cx, cy), p) for p in pts]
    R = sum(rad) / n
    if 3 <= n <= 1000 and max(rad) - min(rad) <= EQUAL_TOL and R > EQUAL_TOL:
        a0 = math.atan2(pts[0][1] - cy, pts[0][0] - cx)
        step = 2 * math.pi / n
        k0 = math.floor(a0 / step + 1e-12)
        a0 = _snap_angle(a0 - step * k0, R)
        # vertex i of the loop is vertex k0 + i (or k0 - i) of the polygon: checked in order
        made = [(cx + R * math.cos(a0 + k * step), cy + R * math.sin(a0 + k * step))
                for k in range(n)]
        if any(all(_close(pts[i], made[(k0 + d * i) % n]) for i in range(n)) for d in (1, -1)):
            return Shape("RegularPolygon", (cx, cy), {"radius": R, "sides": n, "rotation": a0},
                         ("RegularPolygon", R, n, a0), n)
    area = sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(pts, pts[1:] + pts[:1])) / 2
    span = max(math.dist(pts[0], p) for p in pts)
    if abs(area) <= EQUAL_TOL * max(span, 1.0):
        return None                 # no area: the compiler refuses such a Polygon
    return Shape("Polygon", (cx, cy), {"points": pts}, ("Polygon",), n)


def _as_sector(segs):
    """A pie slice (an arc and two lines to its centre) or an annulus segment (two concentric
    arcs and two radial lines)."""
    arcs = [s for s in segs if isinstance(s, Arc)]
    lines = [s for s in segs if isinstance(s, Line)]
    if len(lines) != 2 or len(arcs) not in (1, 2) or len(segs) != len(lines) + len(arcs):
        return None
    outer = max(arcs, key=lambda a: a.radius)
    inner = min(arcs, key=lambda a: a.radius) if len(arcs) == 2 else None
    if inner is not None and (not _close(inner.center, outer.center) or
                              inner.radius >= outer.radius - EQUAL_TOL):
        return None
    a0, sw = (outer.start_angle, outer.sweep) if outer.sweep > 0 else (outer.end_angle,
                                                                       -outer.sweep)
    a0 = math.atan2(math.sin(a0), math.cos(a0))
    a0 = _snap_angle(a0, outer.radius)
    sw = _snap_angle(sw, outer.radius)
    c, R = outer.center, outer.radius
    made = [_arc(c, R, a0, sw)]
    p0, p1 = made[0].start, made[0].end
    if inner is None:
        made += [Line(c, p0), Line(p1, c)]
    else:
        ri = inner.radius
        made.append(_arc(c, ri, a0, sw))
        made += [Line(made[1].start, p0), Line(p1, made[1].end)]
    if not same_pieces(made, segs):
        return None
    args = {"radius": R, "start_angle": a0, "end_angle": a0 + sw}
    if inner is not None:
        args["inner_radius"] = inner.radius
    return Shape("Sector", c, args, ("Sector", R, a0, sw, inner.radius if inner else 0),
                 len(segs))


def recognise(segs) -> Shape | None:
    """The primitive that loop ``segs`` is (counter-clockwise or not), or None (module doc)."""
    if len(segs) == 1 and isinstance(segs[0], Circle):
        c = segs[0]
        return Shape("Circle", tuple(c.center), {"radius": c.radius}, ("Circle", c.radius), 1)
    if not all(isinstance(s, (Line, Arc)) for s in segs):
        return None
    if all(isinstance(s, Line) for s in segs):
        return _as_lines(segs) if len(segs) >= 3 else None
    for f in (_as_slot, _as_rrect, _as_sector):
        got = f(segs)
        if got is not None:
            return got
    return None
