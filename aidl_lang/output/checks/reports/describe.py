"""What the final part is, in words and numbers (``aidl check --describe``, ``Result.describe``,
the MCP ``describe`` tool): so that a model without eyes can compare the part with the request
the way a person compares the picture.

Read from the exact output model (:class:`~.part.Output`): for each part its outline (kind,
size, box), each opening (an inner loop) with its centre, size and kind, the engravings (text
with its string, other marks by kind) with their place, the parts of the same shape (copies,
:mod:`.inventory`) and the symmetries found.  All lengths in mm, angles in degrees, y up.

Kinds: ``circle`` (one exact circle: ``d``), ``slot`` (two parallel lines and two half circles:
width ``w``, overall length ``l``, ``angle`` of its axis), ``rectangle`` (four lines at right
angles: ``w`` x ``h``, ``angle``), ``rounded rectangle`` (four lines and four quarter arcs of
one radius ``r``), ``ellipse`` (one exact ellipse: axes ``w`` x ``h`` = 2 rx x 2 ry, ``angle``
of its major axis), ``star`` (a ``Star``'s loop: ``points``, ``outer_radius``, ``inner_radius``,
``angle`` of its first tip from +y), ``arc slot`` (an ``ArcSlot``'s loop: centre-line
``radius``, ``width``, ``start_angle`` and ``sweep``), ``polygon`` (``n`` lines), else
``outline`` (so many lines, arcs, splines).  A star and an arc slot are named after the
primitive that drew the loop (:func:`_primitive`: a shape of that kind whose face has the loop's
box and whose parameters the loop's segments match); the others by their segments.  Texts
carry their string and ``height`` (the ``size`` they were written at).

Each part states its material: ``thickness`` (mm; the program's ``thickness`` statement, else
the 3D outputs' 3 mm, with ``thickness_set`` saying which) and ``kerf`` (mm, or None).  A hole
that breaks through the part's outline leaves no opening (no inner loop) but a **notch** in
the outline: each is listed with the hole that made it, the edge it opens onto (the side of
the part's box nearest the removed material: ``top``, ``bottom``, ``left``, ``right``), its
``width`` along that edge and ``depth`` into the part (the removed region's box, mm), and its
centre (:func:`notches`).

Symmetries are tested on the part's shape (:attr:`~.part.PartOutline.shape`) about its area
centroid: a mirror about the vertical and the horizontal line through it, and rotation by
360/n degrees for n from 2 to 12 and the divisors up to 120 of its loops' segment counts (a
36-tooth gear: 36); a
symmetry holds when the shape and its image differ by less than the chord tolerance along the
perimeter (``2 CHORD_TOL x perimeter`` mm^2 of symmetric difference).
"""
from __future__ import annotations

import math

import numpy as np

from ....geometry.shapes.curves import Arc, Circle, EllipticArc, Line
from ....geometry.shapes.tessellate import CHORD_TOL
from ....geometry.core.model import within_index
from .inventory import parts_list
from ...fabrication.layout import part_box
from ...part.part import Output, PartOutline
from ...part.build.sunk import DEFAULT_THICKNESS

__all__ = ["describe", "describe_text"]

RIGHT = 1e-6          # rad: how far from 90 degrees a corner may be and count as right
SAME = 1e-6           # mm: lengths and radii this close are equal


def _r(v: float, digits: int = 3) -> float:
    v = round(float(v), digits)
    return 0.0 if v == 0 else v


def _pt(p) -> list[float]:
    return [_r(p[0]), _r(p[1])]


def _box(segments) -> tuple[float, float, float, float]:
    x0 = y0 = math.inf
    x1 = y1 = -math.inf
    for s in segments:
        a, b, c, d = s.box()
        x0, y0, x1, y1 = min(x0, a), min(y0, b), max(x1, c), max(y1, d)
    return x0, y0, x1, y1


def _angle(dx: float, dy: float) -> float:
    """The direction of (dx, dy) in degrees, in [0, 180) (an axis, not a vector)."""
    a = math.degrees(math.atan2(dy, dx)) % 180.0
    return 0.0 if abs(a - 180.0) < 1e-9 else a


def loop_shape(segments) -> dict:
    """The kind and size of one closed loop of exact ``segments`` (see the module's kinds),
    with its ``center`` (a circle's centre, else the middle of its box) and ``box``."""
    x0, y0, x1, y1 = _box(segments)
    doc: dict = {"kind": "outline", "center": _pt(((x0 + x1) / 2, (y0 + y1) / 2)),
                 "size": [_r(x1 - x0), _r(y1 - y0)]}
    lines = [s for s in segments if isinstance(s, Line)]
    arcs = [s for s in segments if isinstance(s, Arc)]
    if len(segments) == 1 and isinstance(segments[0], Circle):
        c = segments[0]
        return {**doc, "kind": "circle", "center": _pt(c.center), "d": _r(2 * c.radius)}
    if len(segments) == 1 and isinstance(segments[0], EllipticArc) and segments[0].whole:
        e = segments[0].curve
        return {**doc, "kind": "ellipse", "center": _pt(e.center), "w": _r(2 * e.rx),
                "h": _r(2 * e.ry), "angle": _r(math.degrees(e.rotation))}
    if len(lines) == len(segments):
        if len(lines) == 4 and _right_angles(lines):
            a, b = lines[0].length, lines[1].length
            ax = _angle(lines[0].end[0] - lines[0].start[0], lines[0].end[1] - lines[0].start[1])
            w, h, ang = (a, b, ax) if ax < 45 or ax >= 135 else (b, a, (ax + 90) % 180)
            return {**doc, "kind": "rectangle", "w": _r(w), "h": _r(h), "angle": _r(ang)}
        lengths = [ln.length for ln in lines]
        if max(lengths) - min(lengths) < SAME:     # equal sides (a RegularPolygon): its side
            return {**doc, "kind": "polygon", "n": len(lines), "side": _r(lengths[0])}
        return {**doc, "kind": "polygon", "n": len(lines)}
    if len(lines) == 2 and len(arcs) == 2 and abs(arcs[0].radius - arcs[1].radius) < SAME \
            and all(abs(abs(a.sweep) - math.pi) < 1e-6 for a in arcs):
        (c1, c2), r = (arcs[0].center, arcs[1].center), arcs[0].radius
        dist = math.hypot(c2[0] - c1[0], c2[1] - c1[1])
        return {**doc, "kind": "slot", "center": _pt(((c1[0] + c2[0]) / 2, (c1[1] + c2[1]) / 2)),
                "w": _r(2 * r), "l": _r(dist + 2 * r),
                "angle": _r(_angle(c2[0] - c1[0], c2[1] - c1[1]))}
    if len(lines) == 4 and len(arcs) == 4 and _right_angles(lines, parallel_pairs=True) \
            and max(a.radius for a in arcs) - min(a.radius for a in arcs) < SAME \
            and all(abs(abs(a.sweep) - math.pi / 2) < 1e-6 for a in arcs):
        r = arcs[0].radius
        ax = _angle(lines[0].end[0] - lines[0].start[0], lines[0].end[1] - lines[0].start[1])
        a, b = lines[0].length + 2 * r, lines[1].length + 2 * r
        w, h, ang = (a, b, ax) if ax < 45 or ax >= 135 else (b, a, (ax + 90) % 180)
        return {**doc, "kind": "rounded rectangle", "w": _r(w), "h": _r(h), "r": _r(r),
                "angle": _r(ang)}
    n_other = len(segments) - len(lines) - len(arcs)
    return {**doc, "lines": len(lines), "arcs": len(arcs), "curves": n_other}


class _Shapes:
    """The Stars and ArcSlots drawn as faces of some structure (:attr:`Drawing.own`), with
    their faces' boxes (mm), sorted by the box's left edge: a loop looks only at those whose
    left edge is within its tolerance of its own (a binary search), not at every one (4,000
    stars cut as holes were 16 million box comparisons)."""

    def __init__(self, output: Output):
        d = output.drawing
        got = [] if d is None else [(f.bounds(), g) for faces in d.own.values()
                                    for g, f in faces if g.kind in ("Star", "ArcSlot")]
        got.sort(key=lambda item: item[0][0])
        self.items = got
        self.left = [b[0] for b, _ in got]

    def near(self, x0: float, tol: float):
        import bisect
        a = bisect.bisect_left(self.left, x0 - tol)
        b = bisect.bisect_right(self.left, x0 + tol)
        return [(g, box) for box, g in self.items[a:b]]


def _primitive(doc: dict, segments, shapes: "_Shapes") -> dict:
    """``doc`` (:func:`loop_shape` of ``segments``) named after the primitive that drew the
    loop, when one of ``shapes`` (:class:`_Shapes`) did: a face with the loop's box (to
    twice the chord tolerance: its polygon's vertices lie on the loop) whose kind and solved
    parameters the segments match exactly (a Star: 2 n lines whose ends alternate at the
    outer and inner radius about their mean; an ArcSlot: four arcs of radii R + w/2, w/2,
    R - w/2, w/2).  Else ``doc`` unchanged."""
    if not shapes.items:
        return doc
    x0, y0, x1, y1 = _box(segments)
    tol = 2 * CHORD_TOL + 1e-6 * max(1.0, abs(x0), abs(y0), abs(x1), abs(y1))
    for g, (a, b, c, e) in shapes.near(x0, tol):
        if max(abs(a - x0), abs(b - y0), abs(c - x1), abs(e - y1)) > tol:
            continue
        got = _star(segments, g) if g.kind == "Star" else _arc_slot(segments, g)
        if got is not None:
            return {**doc, **got}
    return doc


def _star(segments, g) -> dict | None:
    n = len(g.data["order"]) // 2
    dims = g.data["dims"]
    ro, ri = dims["outer_radius"], dims["inner_radius"]
    if g.data.get("tip"):
        return _rounded_star(segments, g, n)
    if len(segments) != 2 * n or not all(isinstance(s, Line) for s in segments):
        return None
    P = np.array([s.start for s in segments], dtype=float)
    c = P.mean(axis=0)
    r = np.hypot(*(P - c).T)
    tips = np.flatnonzero(np.abs(r - ro) <= 1e-6 * ro)
    if len(tips) != n or np.count_nonzero(np.abs(r - ri) <= 1e-6 * ro) != n:
        return None
    t = P[tips[0]] - c
    step = 360.0 / n
    ang = (math.degrees(math.atan2(t[1], t[0])) - 90.0) % step
    ang = 0.0 if min(ang, step - ang) < 1e-6 else ang
    return {"kind": "star", "center": _pt(c), "points": n, "outer_radius": _r(ro),
            "inner_radius": _r(ri), "angle": _r(ang)}


def _rounded_star(segments, g, n: int) -> dict | None:
    """A Star with ``tip_radius``: n arcs of that radius whose centers lie ``dc`` from the
    star's center, and 2 n lines; the center the mean of the arcs' centers."""
    dims = g.data["dims"]
    arcs = [s for s in segments if isinstance(s, Arc)]
    lines = [s for s in segments if isinstance(s, Line)]
    rt, (dc, _half) = dims["tip_radius"], g.data["tip"]
    if len(arcs) != n or len(lines) != 2 * n or \
            any(abs(a.radius - rt) > 1e-6 * dims["outer_radius"] for a in arcs):
        return None
    C = np.array([a.center for a in arcs], dtype=float)
    c = C.mean(axis=0)
    if np.any(np.abs(np.hypot(*(C - c).T) - dc) > 1e-6 * dims["outer_radius"]):
        return None
    t = C[int(np.argmax(C[:, 1]))] - c if n else C[0] - c
    step = 360.0 / n
    ang = (math.degrees(math.atan2(t[1], t[0])) - 90.0) % step
    ang = 0.0 if min(ang, step - ang) < 1e-6 else ang
    return {"kind": "star", "center": _pt(c), "points": n,
            "outer_radius": _r(dims["outer_radius"]), "inner_radius": _r(dims["inner_radius"]),
            "tip_radius": _r(rt), "angle": _r(ang)}


def _arc_slot(segments, g) -> dict | None:
    dims = g.data["dims"]
    R, h = dims["radius"], dims["width"] / 2
    if len(segments) != 4 or not all(isinstance(s, Arc) for s in segments):
        return None
    radii = sorted(s.radius for s in segments)
    if max(abs(u - v) for u, v in zip(radii, sorted([R + h, h, R - h, h]))) > 1e-6 * R:
        return None
    outer = max(segments, key=lambda s: s.radius)
    sweep = abs(outer.sweep)
    a1 = outer.start_angle if outer.sweep > 0 else outer.start_angle + outer.sweep
    return {"kind": "arc slot", "center": _pt(outer.center), "radius": _r(R),
            "width": _r(2 * h), "start_angle": _r(math.degrees(a1) % 360.0),
            "sweep": _r(math.degrees(sweep))}


def _right_angles(lines, parallel_pairs: bool = False) -> bool:
    """Four lines, each at right angles to the next."""
    def d(l):
        v = np.subtract(l.end, l.start)
        n = float(np.hypot(*v))
        return v / n if n > 0 else v
    for k in range(4):
        if abs(float(np.dot(d(lines[k]), d(lines[(k + 1) % 4])))) > RIGHT:
            return False
    return True


def _centroid(shape) -> tuple[float, float]:
    sx = sy = a = 0.0
    for P in shape.to_polygons():
        P = np.asarray(P, dtype=float)
        x, y = P[:, 0], P[:, 1]
        xn, yn = np.roll(x, -1), np.roll(y, -1)
        cr = x * yn - xn * y
        a += cr.sum() / 2
        sx += ((x + xn) * cr).sum() / 6
        sy += ((y + yn) * cr).sum() / 6
    return (sx / a, sy / a) if a else (0.0, 0.0)


def symmetries(p: PartOutline, check=None) -> dict:
    """``{"center": [x, y], "mirror_x": bool, "mirror_y": bool, "rotation": n}`` of part
    ``p``: mirror about the horizontal line through its centroid (``mirror_x``: y -> -y) and
    the vertical one (``mirror_y``: x -> -x); ``rotation``: the largest n found such that a
    turn by 360/n degrees maps it onto itself (1: none; 0: any angle, a round part).
    ``check()``: called before each comparison (the deadline; it may raise)."""
    shape = p.shape
    cx, cy = _centroid(shape)
    tol = 2 * CHORD_TOL * p.perimeter + 1e-9
    base = shape.translate((-cx, -cy))
    # A turn by t changes the second moments of area by 2 d |sin t| (d: their anisotropy), a
    # mirror by 2 |Ixy|, and an image within `tol` mm^2 of the shape by at most tol r^2: turns
    # and mirrors that fail this are not tried (one turn of a plate of 4,000 holes by 120
    # degrees was a 22 s boolean no deadline interrupts)
    sxx, syy, sxy, r2 = _moments(base)
    d = math.hypot((sxx - syy) / 2, sxy)
    slack = 2 * tol * r2 + 1e-9 * (abs(sxx) + abs(syy)) + 1e-12

    def may_turn(degrees: float) -> bool:
        return math.sqrt(2) * d * abs(math.sin(math.radians(degrees))) <= slack

    def same(other) -> bool:           # a plain bool: the perimeter may be a NumPy float
        if check is not None:
            check()
        return bool((base - other).area() + (other - base).area() <= tol)

    mirror = 2 * abs(sxy) <= slack
    doc = {"center": _pt((cx, cy)),
           "mirror_x": mirror and same(base.mirror((0.0, 1.0))),
           "mirror_y": mirror and same(base.mirror((1.0, 0.0)))}
    radian = 57.2957795                            # not a turn of any small order
    if may_turn(radian) and same(base.rotate(radian)):
        doc["rotation"] = 0
        return doc
    cands = set(range(2, 13))
    for lp in p.loops:
        m = len(lp.segments)
        cands |= {k for k in range(13, 121) if m % k == 0}
    holes = sum(1 for lp in p.loops if lp.is_hole)
    if holes > 1:
        cands.add(holes)
    doc["rotation"] = next((n for n in sorted(cands, reverse=True)
                            if may_turn(360.0 / n) and same(base.rotate(360.0 / n))), 1)
    return doc


def _moments(shape) -> tuple[float, float, float, float]:
    """The second moments of area of ``shape`` about the origin, ``(Ixx, Iyy, Ixy)`` =
    (integral of x^2, of y^2, of x y) in mm^4 (holes negative), and the largest squared
    distance of a vertex from the origin (mm^2)."""
    sxx = syy = sxy = r2 = 0.0
    for P in shape.to_polygons():
        P = np.asarray(P, dtype=float)
        if not len(P):
            continue
        x, y = P[:, 0], P[:, 1]
        xn, yn = np.roll(x, -1), np.roll(y, -1)
        cr = x * yn - xn * y
        sxx += float((cr * (x * x + x * xn + xn * xn)).sum()) / 12
        syy += float((cr * (y * y + y * yn + yn * yn)).sum()) / 12
        sxy += float((cr * (x * yn + 2 * x * y + 2 * xn * yn + xn * y)).sum()) / 24
        r2 = max(r2, float((x * x + y * y).max()))
    return sxx, syy, sxy, r2


def _text_items(output: Output) -> list[dict]:
    """Each engraved geometry once: a text with its string, other marks by kind; its part
    ("" when none), centre and box size."""
    d = output.drawing
    if d is None:
        return []
    owner: dict = {}
    for name, s in d.part_of.items():          # a split part: its own name, not a piece's
        owner.setdefault(s, name)
    from ...part.part import _part_of
    groups: dict = {}
    for style, item, g in d.strokes:
        if g is None or style == "cut":         # a through-cut is cut, not engraved
            continue
        pts = _item_points(item)
        if pts is None or not len(pts):
            continue
        groups.setdefault(g, []).append(pts)
    out = []
    for g, pts in groups.items():
        P = np.concatenate(pts)
        x0, y0 = P.min(axis=0)
        x1, y1 = P.max(axis=0)
        doc = {"part": _part_of(g, owner), "kind": "text" if g.kind == "Text" else g.kind,
               "name": g.label, "center": _pt(((x0 + x1) / 2, (y0 + y1) / 2)),
               "size": [_r(x1 - x0), _r(y1 - y0)]}
        if g.kind == "Text":
            doc["text"] = g.data.get("text", "")
            if "size" in g.data:
                doc["height"] = _r(g.data["size"])
        out.append(doc)
    return out


def _item_points(item):
    kind = item[0]
    if kind == "line":
        return np.array([item[1], item[2]], dtype=float)
    if kind == "circle":
        (cx, cy), r = item[1], float(item[2])
        return np.array([(cx - r, cy - r), (cx + r, cy + r)], dtype=float)
    if kind == "arc":
        _, c, r, a1, a2 = item
        sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
        t = a1 + np.linspace(0, sweep, 33)
        return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])
    if kind == "poly":
        return np.asarray(item[1], dtype=float).reshape(-1, 2)
    if kind in ("spline", "ellipse_arc"):
        x0, y0, x1, y1 = item[1].box()
        return np.array([(x0, y0), (x1, y1)], dtype=float)
    return None


NOTCH_AREA = 1e-6          # mm^2: a hole reaching this far past its solid's material notches it


def _inside_box(box, outer) -> bool:
    return box[0] >= outer[0] and box[1] >= outer[1] and box[2] <= outer[2] and box[3] <= outer[3]


def notches(output: Output, part, cuts_within: dict | None = None) -> list[dict]:
    """The notches that holes cut into part ``part``'s outline (a :class:`~.part.PartOutline`):
    ``[{"hole", "edge", "width", "depth", "center", "box"}]`` (mm), for every hole of the part
    whose region reaches past the material it cuts (``hole - before`` has area), so that it
    opens the outline instead of making an opening.  Empty without the booleans' result.
    ``cuts_within``: the drawing's cuts by the structures they lie within
    (:func:`~...geometry.model.within_index`), made once for all its parts."""
    d = output.drawing
    s = getattr(d, "part_of", {}).get(part.name) if d is not None else None
    if s is None:
        return []
    if cuts_within is None:
        cuts_within = within_index(d.cuts, lambda c: c.owner)
    x0, y0, x1, y1 = part_box(part)
    out = []
    for c in cuts_within.get(s, ()):
        if c.region.is_empty():
            continue
        shape = d.shapes.get(c.hole)
        if shape is None or (shape - c.before).area() <= NOTCH_AREA:
            continue                            # inside the material: an opening, listed above
        pieces = shape.decompose() if shape.num_contour() > 1 else [shape]
        for piece in pieces:                    # one notch per cut-out (two corners: two)
            if (piece - c.before).area() <= NOTCH_AREA:
                continue                        # this piece is an opening
            region = piece ^ c.region if len(pieces) > 1 else c.region
            if region.is_empty():
                continue
            out.append(_notch(part, c, region, (x0, y0, x1, y1)))
    out.sort(key=lambda n: (-n["center"][1], n["center"][0]))
    return out


def _notch(part, c, region, box) -> dict:
    """One notch of :func:`notches`: the cut ``c``'s ``region`` (one piece) in the part of
    box ``box``, named by the edge it opens onto."""
    x0, y0, x1, y1 = box
    a, b, e, f = region.bounds()
    # the exact box: the part's own outline pieces inside the (polygonal) region's box
    pad = max(0.01, 1e-3 * max(e - a, f - b))
    inner = [g for lp in part.loops for g in lp.segments
             if _inside_box(g.box(), (a - pad, b - pad, e + pad, f + pad))]
    if inner:
        a, b, e, f = _box(inner)
    gaps = {"top": y1 - f, "bottom": b - y0, "left": a - x0, "right": x1 - e}
    edge = min(gaps, key=gaps.get)
    width, depth = (e - a, f - b) if edge in ("top", "bottom") else (f - b, e - a)
    return {"hole": c.hole.path, "edge": edge, "width": _r(width), "depth": _r(depth),
            "center": [_r((a + e) / 2), _r((b + f) / 2)],
            "box": [_r(a), _r(b), _r(e), _r(f)]}


def describe(output: Output, deadline=None) -> dict:
    """The description of ``output`` as JSON-ready data: ``{"units": "mm", "parts": [...],
    "engravings": [...], "count": {"parts", "shapes"}}`` (engravings outside every part;
    ``count``: how many parts and distinct shapes, :func:`.inventory.parts_list`).

    Each part described: ``name``, ``kind``, ``size`` [w, h], ``box`` [x0, y0, x1, y1],
    ``area`` mm^2, ``outline`` (its outer loops' kinds, :func:`loop_shape`), ``openings``
    (each inner loop's kind, centre and size), ``engravings``, ``symmetry``
    (:func:`symmetries`), ``thickness`` (mm) and ``thickness_set``, ``kerf`` (mm or None),
    ``notches`` (:func:`notches`), ``assembled`` (when the program places parts in 3D:
    :func:`_assembled`), ``sinks`` (when it has any: its countersinks and
    counterbores, :func:`.inventory.sinks_of`), ``through_cuts`` (each cut along a curve of a ``cut``
    structure: ``{"name", "kind", "from", "to", "length"}``, mm), ``shape`` (its number in
    the parts list), ``same_shape`` (how many parts have that shape, itself included) and
    ``copies``.  A part of the same shape as one described, with no engravings, notches or
    through-cuts of its own (nor the first) and the same material, is not described again:
    it is one of the first's ``copies``, ``{"name", "box"}`` (its place, mm; and
    ``assembled`` where it is placed in 3D), so the
    description grows with the distinct shapes and one place per copy (6,000 equal circles:
    one part and 5,999 places, where every part used to list every other).  A copy that
    differs so is described in full, with ``copy_of`` naming the first part of its shape.

    ``deadline``: the compile's :class:`~aidl_lang.base.limits.Deadline` (None: no wall-time
    bound), looked at before each part; past it raises :class:`~..part.part.OutputError`
    (its ``budget`` naming the part's structure), like the exact outlines."""
    from ....base.limits import OutOfBudget
    from ...part.part import OutputError
    from .inventory import structure_of
    rows = parts_list(output, deadline)
    try:
        return _describe(output, rows, deadline)
    except OutOfBudget as ex:
        if ex.where is None and output.parts:
            ex.where = structure_of(output, output.parts[0].name)
        raise OutputError(f"the description ran out of time: {ex.what}", ex) from None


def _describe(output: Output, rows: list[dict], deadline) -> dict:
    from .inventory import structure_of
    texts = _text_items(output)
    shapes = _Shapes(output)
    parts = []
    kerfs = getattr(output.drawing, "kerf", None) or {}
    texts_of: dict = {}
    for t in texts:
        texts_of.setdefault(t["part"], []).append(t)
    cuts_within = (within_index(output.drawing.cuts, lambda c: c.owner)
                   if output.drawing is not None else {})
    strokes_of: dict = {}
    for st in output.cuts:
        strokes_of.setdefault(st.part, []).append(st)
    placement = (getattr(output.drawing, "placement", None) or {}) \
        if output.drawing is not None else {}
    first: dict = {}          # shape number -> the first part of it described
    plain: dict = {}          # (shape, material) -> the first described with nothing of its own
    for p, row in zip(output.parts, rows):
        where = structure_of(output, p.name)

        def check(where=where):
            if deadline is not None:
                deadline.check("the description", where)
        check()
        x0, y0, x1, y1 = part_box(p)
        box = [_r(x0), _r(y0), _r(x1), _r(y1)]
        # the thickness as the program states it (1.5875 mm, not 1.588): to 1e-9 mm
        material = (_r(p.thickness if p.thickness is not None else DEFAULT_THICKNESS, 9),
                    p.thickness is not None, _r(kerfs[p.name]) if p.name in kerfs else None)
        engraved = texts_of.get(p.name, [])
        through = _through(strokes_of.get(p.name, ()))
        cut_in = notches(output, p, cuts_within)
        sunk = [_sink(sk) for sk in row.get("sinks", ())]
        placed = _assembled(placement.get(p.name), p, x0, y0, x1, y1)
        own = bool(engraved or through or cut_in or sunk)
        lead = plain.get((row["shape"], material))
        if lead is not None and not own:    # a copy, placed in 3D or not: its row says where
            lead["copies"].append({"name": p.name, "box": box,
                                   **({"assembled": placed} if placed else {})})
            continue
        outer = [_primitive(loop_shape(lp.segments), lp.segments, shapes)
                 for lp in p.loops if not lp.is_hole]
        openings = [_primitive(loop_shape(lp.segments), lp.segments, shapes)
                    for lp in p.loops if lp.is_hole]
        openings.sort(key=lambda o: (-o["center"][1], o["center"][0]))
        doc = {"name": p.name, "kind": p.kind, "size": [_r(x1 - x0), _r(y1 - y0)],
               "box": box, "area": _r(abs(p.area)), "outline": outer, "openings": openings,
               "engravings": engraved, "symmetry": symmetries(p, check),
               "thickness": material[0], "thickness_set": material[1], "kerf": material[2],
               "notches": cut_in, "through_cuts": through,
               "shape": row["shape"], "same_shape": row["copies"], "copies": []}
        if sunk:
            doc["sinks"] = sunk
        if placed:
            doc["assembled"] = placed
        if row["shape"] in first:
            doc["copy_of"] = first[row["shape"]]
        else:
            first[row["shape"]] = p.name
        if not own:
            plain[(row["shape"], material)] = doc
        parts.append(doc)
    return {"units": "mm", "parts": parts, "engravings": texts_of.get("", []),
            "count": {"parts": len(rows), "shapes": len({r["shape"] for r in rows})}}


_AXES = {(1, 0, 0): "right (+x)", (-1, 0, 0): "left (-x)", (0, 1, 0): "back (+y)",
         (0, -1, 0): "front (-y)", (0, 0, 1): "up (+z)", (0, 0, -1): "down (-z)"}


def _direction(v) -> str:
    """A unit vector in words: an axis by its name (``front (-y)``), else its three numbers."""
    r = tuple(_r(c) for c in v)
    return _AXES.get(tuple(int(c) for c in r) if all(c in (-1, 0, 1) for c in r) else None,
                     f"({', '.join(_n(c) for c in r)})")


def _assembled(M, p: PartOutline, x0, y0, x1, y1) -> dict | None:
    """Where a part stands in the assembled product (``Place``; None for a program that places
    nothing): ``top_face`` (where its top face looks, the face its engraving and countersinks
    are on), ``up`` (where its drawing's +y goes) and ``box`` [x0, y0, z0, x1, y1, z1] (mm, the
    corners of its flat box through its thickness, placed: exact for quarter turns)."""
    if M is None:
        return None
    t = p.thickness if p.thickness is not None else DEFAULT_THICKNESS
    corners = np.array([[x, y, z, 1.0] for x in (x0, x1) for y in (y0, y1) for z in (0.0, t)])
    w = (np.asarray(M, dtype=float) @ corners.T).T[:, :3]
    lo, hi = w.min(axis=0), w.max(axis=0)
    return {"top_face": _direction(M[:3, 2]), "up": _direction(M[:3, 1]),
            "box": [_r(c) for c in (*lo, *hi)]}


def _assembled_text(a: dict) -> str:
    """:func:`_assembled`'s data in words."""
    b = a["box"]
    return (f"top face (engraving, countersinks) looks {a['top_face']}, drawing's up goes "
            f"{a['up']}; box x {_n(b[0])}..{_n(b[3])}, y {_n(b[1])}..{_n(b[4])}, z "
            f"{_n(b[2])}..{_n(b[5])} mm")


def _sink(d: dict) -> dict:
    """A countersink or counterbore of the parts list (:func:`.inventory.sinks_of`), its
    numbers rounded as the description's others (1e-3 mm, degrees)."""
    return {k: (_r(v) if isinstance(v, float) else [_r(x) for x in v] if k == "center"
                else v) for k, v in d.items()}


def _through(strokes) -> list[dict]:
    """The through-cuts ``strokes`` (of style ``cut``, one part's): each one's name, the kind
    of its first segment, its ends and length in mm."""
    out = []
    for st in strokes:
        if not st.segments:
            continue
        a = st.segments[0]
        b = st.segments[-1]
        start = getattr(a, "start", None)
        end = getattr(b, "end", None)
        if start is None or end is None:              # a whole circle
            start = end = _segment_point(a)
        out.append({"name": st.source, "kind": type(a).__name__, "from": _pt(start),
                    "to": _pt(end), "length": _r(sum(s.length for s in st.segments))})
    return out


def _segment_point(s):
    c = s.center if hasattr(s, "center") else (0.0, 0.0)
    r = getattr(s, "radius", 0.0)
    return (c[0] + r, c[1])


def _n(v: float) -> str:
    return f"{v:.3f}".rstrip("0").rstrip(".") if abs(v) >= 5e-4 else "0"


def _at(c) -> str:
    return f"({_n(c[0])}, {_n(c[1])})"


def shape_text(s: dict) -> str:
    """One loop of :func:`loop_shape` in words, the way a person names it: ``circle d=6 at
    (10, 5)`` (its diameter), ``slot 14 long, 4 wide``, ``rounded rectangle 40 x 20, corner radius
    3``, ``ellipse with axes 30 x 16``, ``6-point star, outer radius 30, inner 15``, ``arc
    slot radius 20, 6 wide, from 0 to 90 deg`` (lengths in mm)."""
    k = s["kind"]
    ang = f", turned {_n(s['angle'])} deg" if s.get("angle") else ""
    if k == "circle":
        return f"circle d={_n(s['d'])} at {_at(s['center'])}"
    if k == "slot":
        return f"slot {_n(s['l'])} long, {_n(s['w'])} wide{ang} at {_at(s['center'])}"
    if k == "rectangle":
        return f"rectangle {_n(s['w'])} x {_n(s['h'])}{ang} at {_at(s['center'])}"
    if k == "ellipse":
        return f"ellipse with axes {_n(s['w'])} x {_n(s['h'])}{ang} at {_at(s['center'])}"
    if k == "rounded rectangle":
        return f"rounded rectangle {_n(s['w'])} x {_n(s['h'])}, corner radius {_n(s['r'])}" \
               f"{ang} at {_at(s['center'])}"
    if k == "star":
        tips = f", tips rounded {_n(s['tip_radius'])}" if s.get("tip_radius") else ""
        return f"{s['points']}-point star, outer radius {_n(s['outer_radius'])}, inner " \
               f"{_n(s['inner_radius'])}{tips}{ang} at {_at(s['center'])}"
    if k == "arc slot":
        a1 = s["start_angle"]
        return f"arc slot radius {_n(s['radius'])}, {_n(s['width'])} wide, from {_n(a1)} to " \
               f"{_n(a1 + s['sweep'])} deg about {_at(s['center'])}"
    size = f"{_n(s['size'][0])} x {_n(s['size'][1])}"
    if k == "polygon":
        side = f", side {_n(s['side'])}" if s.get("side") else ""
        return f"{s['n']}-gon {size}{side} at {_at(s['center'])}"
    what = ", ".join(f"{s[key]} {key if s[key] != 1 else key[:-1]}" for key in
                     ("lines", "arcs", "curves") if s.get(key))
    return f"outline {size} at {_at(s['center'])} ({what})"


def describe_text(doc: dict) -> str:
    """:func:`describe`'s data as compact text, one line per feature."""
    out = []
    for p in doc["parts"]:
        w, h = p["size"]
        x0, y0, x1, y1 = p["box"]
        out.append(f"part `{p['name']}`" + (" (hole)" if p["kind"] == "hole" else "")
                   + f": {_n(w)} x {_n(h)} mm, from ({_n(x0)}, {_n(y0)}) to ({_n(x1)}, {_n(y1)}),"
                   f" area {_n(round(p['area'], 2))} mm^2")
        if "thickness" in p:
            out.append(f"  material: {p['thickness']:.10g} mm thick"
                       + ("" if p["thickness_set"] else " (no `thickness` stated: the default)")
                       + (f", kerf {_n(p['kerf'])} mm" if p.get("kerf") else ", no kerf"))
        for o in p["outline"]:
            out.append(f"  outline: {shape_text(o)}")
        counts: dict = {}
        for o in p["openings"]:
            counts[o["kind"]] = counts.get(o["kind"], 0) + 1
        if p["openings"]:
            out.append(f"  {len(p['openings'])} opening{'s' if len(p['openings']) != 1 else ''}"
                       " (" + ", ".join(f"{v} {k}{'s' if v != 1 else ''}" for k, v in counts.items())
                       + "):")
        for o in p["openings"]:
            out.append(f"    {shape_text(o)}")
        for nt in p.get("notches", ()):
            out.append(f"  notch in the {nt['edge']} edge: {_n(nt['width'])} wide, "
                       f"{_n(nt['depth'])} deep, at {_at(nt['center'])}, cut by hole "
                       f"`{nt['hole']}` (it breaks through the outline: not an opening)")
        for c in p.get("through_cuts", ()):
            out.append(f"  through-cut: {c['kind']} `{c['name']}` from {_at(c['from'])} to "
                       f"{_at(c['to'])}, {_n(c['length'])} mm (cut along, no width)")
        for c in p.get("sinks", ()):
            how = (f"{_n(c['angle'])} deg cone" if c["kind"] == "countersink" else "flat")
            out.append(f"  {c['kind']}: d={_n(c['diameter'])} head, {how}, {_n(c['depth'])} mm "
                       f"deep, on the d={_n(c['hole_d'])} hole `{c['hole']}` at "
                       f"{_at(c['center'])}")
        for e in p["engravings"]:
            out.append("  engraving: " + _engraving(e))
        if p.get("assembled"):
            out.append("  assembled: " + _assembled_text(p["assembled"]))
        if p.get("copy_of"):
            out.append(f"  the same shape as `{p['copy_of']}` (described again: engravings, "
                       "cuts or material of its own)")
        if p["copies"]:
            k = len(p["copies"])
            out.append(f"  {k} more part{'s' if k != 1 else ''} of this shape (copies, not "
                       "described again), at:")
            for c in p["copies"]:
                x0, y0, x1, y1 = c["box"]
                out.append(f"    `{c['name']}` from ({_n(x0)}, {_n(y0)}) to ({_n(x1)}, {_n(y1)})"
                           + ("; assembled: " + _assembled_text(c["assembled"])
                              if c.get("assembled") else ""))
        out.append("  symmetry: " + _symmetry(p["symmetry"]))
    for e in doc["engravings"]:
        out.append("engraving (no part): " + _engraving(e))
    if not doc["parts"]:
        out.append("no parts")
    elif "count" in doc:
        n, k = doc["count"]["parts"], doc["count"]["shapes"]
        out.append(f"{n} part{'s' if n != 1 else ''}, {k} shape{'s' if k != 1 else ''}")
    return "\n".join(out)


def _engraving(e: dict) -> str:
    size = f"{_n(e['size'][0])} x {_n(e['size'][1])}"
    if e["kind"] == "text":
        high = f" {_n(e['height'])} high" if e.get("height") else ""
        return f"text \"{e['text']}\"{high} at {_at(e['center'])}, {size} mm"
    return f"{e['kind']} `{e['name']}` at {_at(e['center'])}, {size} mm"


def _symmetry(s: dict) -> str:
    c = _at(s["center"])
    said = []
    if s["mirror_y"]:
        said.append(f"mirror about the vertical line x = {_n(s['center'][0])}")
    if s["mirror_x"]:
        said.append(f"mirror about the horizontal line y = {_n(s['center'][1])}")
    if s["rotation"] == 0:
        said.append(f"round about {c} (any rotation)")
    elif s["rotation"] > 1:
        said.append(f"{s['rotation']}-fold rotation about {c}")
    return "; ".join(said) if said else "none found"
