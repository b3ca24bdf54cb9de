"""Reading a DXF (``ezdxf``) or SVG (``svgelements``) drawing as exact curves.

:func:`read_drawing` turns the bytes of a drawing into a :class:`Drawing` in millimetres with
the y axis up: its closed **outlines** (loops of :class:`~aidl_lang.geometry.curves.Line`,
``Arc`` and ``Spline`` pieces, counter-clockwise, largest area first), its **circles**, its
full **ellipses** ``(cx, cy, rx, ry, rotation)`` and its open **paths**.  Nothing is
approximated: a DXF ``LINE``, ``ARC``, ``CIRCLE``, ``LWPOLYLINE``/``POLYLINE`` (bulges are
arcs), ``SPLINE`` (non-rational, degree 1 to 3: its Bézier pieces, raised to cubics),
``ELLIPSE`` (whole, or a partial one as an exact ``EllipticArc``), ``HATCH`` boundary paths
(closed loops), ``INSERT``/``MINSERT`` blocks placed (every copy, under the entity budget:
``E0304``), ASCII or binary; an SVG path's lines,
circular and elliptical arcs, cubic and quadratic Béziers, and its
``rect``, ``circle``, ``ellipse``, ``polygon``, ``polyline`` and ``line`` elements.  What has
no exact form here (a rational spline, dimensions, images), a DXF entity not in the XY plane
(extrusion neither +Z nor -Z, or points at different z) and one whose numbers give no shape
(radius <= 0, zero length, inf, nan, beyond 1e15 mm) is skipped and counted in a
:class:`Note` (``W0130``, DXF: by type and layer).  Text (DXF ``TEXT``/``MTEXT``, SVG
``<text>``) is read into the drawing's ``texts``; an SVG path whose data holds a word that is
no number (``inf``, ``nan``) is read up to it and counted with its place.

Loose pieces are joined end to end (within :data:`JOIN_TOL`) into chains: a chain that comes
back to its start is an outline, otherwise a path; a chain whose end runs past its start,
crossing it, is closed at the crossing (:func:`_overshoot`), and a loop's small loops where it
crosses itself are cut off (:func:`_trim_small_loops`).  A loop that crosses itself, a selection
that finds nothing and a file past :data:`MAX_ENTITIES` raise :class:`DrawingError` (its
``code``, ``message`` and ``hint``: the caller places it at the call).

Every number read is checked before it is used: a coordinate, radius, semi-axis or text
height (in mm, after the unit) that is not finite (``inf``, ``nan``) or beyond
:data:`~aidl_lang.limits.MAX_EXTENT` (1e6 mm, the model extent of a program), and a number
derived from them (the centre and radius of a DXF bulge, a spline's steps), is ``E0130``
naming the entity (DXF: its kind, handle and line; SVG: the element and its id).

Units: DXF ``$INSUNITS`` (0, unitless, is read as millimetres with a note), the SVG's
``width``/``height`` against its ``viewBox`` (CSS units: 96 px to the inch); ``units=``
overrides them (for SVG: one user unit of the ``viewBox`` is one ``units``).
"""
from __future__ import annotations

import contextvars
import io
import math
from dataclasses import dataclass, field

from ..geometry.curves import Arc, Circle, EllipticArc, Line, Loop, Spline, elliptic_arc
from ..geometry.spline import CubicSpline
from ..limits import MAX_EXTENT

JOIN_TOL = 1e-6          # mm: pieces whose ends are this close chain into one
MAX_ENTITIES = 20_000    # entities (DXF) or shapes (SVG) read from one drawing
MAX_CROSSING_CHORDS = 6000   # loops with more chords are not checked for crossing themselves
CLOSE_TOL = 0.05         # mm: the default closing tolerance (close_tolerance=, --close-tolerance)
GAP_NOTE = 0.5           # mm: an open chain whose ends are this close was probably meant closed
UNIT_MM = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "inch": 25.4, "ft": 304.8,
           "pt": 25.4 / 72, "px": 25.4 / 96}


# DXF $INSUNITS: (name, millimetres) exactly (ezdxf's factors are off by 1e-11 for inches)
INSUNITS_MM = {1: ("in", 25.4), 2: ("ft", 304.8), 3: ("mi", 1609344.0), 4: ("mm", 1.0),
               5: ("cm", 10.0), 6: ("m", 1000.0), 7: ("km", 1e6), 8: ("microinch", 25.4e-6),
               9: ("mil", 0.0254), 10: ("yd", 914.4), 11: ("angstrom", 1e-7), 12: ("nm", 1e-6),
               13: ("um", 1e-3), 14: ("dm", 100.0)}


class DrawingError(Exception):
    """A drawing that gives nothing usable: ``code`` (``E0130`` cannot read, or a number not
    finite or beyond the extent; ``E0131`` a loop that crosses itself, ``E0132`` nothing
    selected), ``message`` and ``hint``; ``line``: the line of the drawing's text it is about
    (1-based; a DXF entity's), or None."""

    def __init__(self, code: str, message: str, hint: str = "", line: int | None = None) -> None:
        super().__init__(message)
        self.code, self.message, self.hint, self.line = code, message, hint, line


class _OutOfRange(Exception):
    """A number of the entity being read that is not finite or beyond :data:`MAX_EXTENT`:
    ``what`` it is (``a coordinate``, ``a radius``) and its ``value`` (mm)."""

    def __init__(self, what: str, value: float) -> None:
        super().__init__(what)
        self.what, self.value = what, value


def _mm(v, what: str = "a coordinate") -> float:
    """``v`` as a float when it is finite and within :data:`MAX_EXTENT` (mm); else raises
    :class:`_OutOfRange`."""
    x = float(v)
    if not abs(x) <= MAX_EXTENT:                  # NaN fails too
        raise _OutOfRange(what, x)
    return x


def _finite(v, what: str) -> float:
    """``v`` as a float when it is finite (an angle, a ratio, a parameter step)."""
    x = float(v)
    if not math.isfinite(x):
        raise _OutOfRange(what, x)
    return x


def _check_made(objs) -> None:
    """Check the numbers of what an entity made (segments, circles, ``(cx, cy, rx, ry,
    rotation)`` ellipses, text tuples), derived ones included (a bulge's centre and radius):
    raises :class:`_OutOfRange`."""
    for o in objs:
        if isinstance(o, list):
            _check_made(o)
        elif isinstance(o, Line):
            for v in (*o.start, *o.end):
                _mm(v)
        elif isinstance(o, (Arc, Circle)):
            _mm(o.center[0]), _mm(o.center[1]), _mm(o.radius, "a radius")
            if isinstance(o, Arc):
                _finite(o.start_angle, "an angle"), _finite(o.sweep, "an angle")
        elif isinstance(o, Spline):
            for pt in o.curve.ctrl:
                _mm(pt[0], "a control point"), _mm(pt[1], "a control point")
            for h in o.curve.h:
                _finite(h, "a knot step")
        elif isinstance(o, EllipticArc):
            c = o.curve
            _mm(c.center[0]), _mm(c.center[1])
            _mm(c.rx, "a semi-axis"), _mm(c.ry, "a semi-axis")
            for v in (c.rotation, o.start_param, o.sweep):
                _finite(v, "an angle")
        elif isinstance(o, tuple) and o and isinstance(o[0], str):     # text
            _mm(o[1][0]), _mm(o[1][1]), _mm(o[2], "a text height"), _finite(o[3], "an angle")
        elif isinstance(o, tuple):                                      # an ellipse
            _mm(o[0]), _mm(o[1]), _mm(o[2], "a semi-axis"), _mm(o[3], "a semi-axis")
            _finite(o[4], "an angle")


def _range_error(ex: _OutOfRange, entity: str, name: str, line: int | None = None) -> DrawingError:
    """The ``E0130`` of :class:`_OutOfRange` ``ex`` in ``entity`` (``LINE (handle 2F, line
    30)``, ``<path id="a">``) of the drawing ``name``."""
    v = ex.value
    how = (f"that is not a number ({v})" if v != v else f"that is infinite ({v})"
           if math.isinf(v) else f"of {v:g} mm, beyond the limit of {MAX_EXTENT:g} mm (1 km)")
    return DrawingError("E0130", f"{entity} of `{name}` has {ex.what} {how}",
                        f"coordinates, radii and sizes in a drawing must be finite and within "
                        f"{MAX_EXTENT:g} mm of the origin, as in a program: fix the entity in "
                        "the drawing, or select other layers or ids", line)


def _dxf_line(data: bytes, handle: str | None) -> int | None:
    """The 1-based line of the ASCII DXF ``data`` where the entity of ``handle`` starts (its
    type name; the handle's own line when the type is not just before it), or None."""
    import re
    if not handle or data.startswith(b"AutoCAD Binary DXF"):
        return None
    m = re.search(rb"(?m)^[ \t]*5[ \t]*\r?\n[ \t]*" + re.escape(handle.encode("ascii", "replace"))
                  + rb"[ \t]*\r?$", data)
    if m is None:
        return None
    line = data.count(b"\n", 0, m.start()) + 1
    before = data[:m.start()].splitlines()[-2:]
    return line - 1 if len(before) == 2 and before[0].strip() == b"0" else line


@dataclass
class Note:
    """A warning about the drawing (``W0130``: entities skipped, with their count)."""
    code: str
    message: str
    hint: str = ""


@dataclass
class Outline:
    """A closed loop (counter-clockwise) and where it came from (``source``: entity kinds)."""
    segments: list
    source: str = ""

    @property
    def area(self) -> float:
        return Loop(list(self.segments)).area


@dataclass
class Path:
    """An open chain of segments, start to end."""
    segments: list
    source: str = ""
    crossing: tuple | None = None       # a closed chain that crosses itself there

    @property
    def start(self):
        return self.segments[0].start

    @property
    def end(self):
        return self.segments[-1].end


@dataclass
class Drawing:
    outlines: list = field(default_factory=list)
    circles: list = field(default_factory=list)
    ellipses: list = field(default_factory=list)
    paths: list = field(default_factory=list)
    notes: list = field(default_factory=list)
    unit: str = "mm"
    # DXF TEXT and MTEXT lines (skipped by Drawing2D with a note; `aidl import` writes them
    # as Text engravings): (text, (x, y) mm, height mm, rotation radians, anchor, valign)
    texts: list = field(default_factory=list)
    # DXF: what the file holds (counts by type and layer) and why each kind was left out,
    # for the message of an import that gives nothing
    seen: str = ""
    # what has the role `engrave` (engrave=, roles="laser"), read as a drawing of its own:
    # engraved strokes on the part (Drawing2D: drawn with the texts; `aidl import`: a
    # `drawing engrave` child)
    engrave: "Drawing | None" = None
    # the open paths have the role `cut` (cut=, roles="laser" named it): `aidl import`
    # writes them as through-cuts (a `cut` structure), not engravings
    paths_cut: bool = False

    def box(self) -> tuple[float, float, float, float] | None:
        """The exact ``(x0, y0, x1, y1)`` of everything read (mm), or None when empty."""
        bs = []
        for o in self.outlines:
            bs.append(_segs_box(o.segments))
        for p in self.paths:
            bs.append(_segs_box(p.segments))
        for c in self.circles:
            bs.append((c.center[0] - c.radius, c.center[1] - c.radius,
                       c.center[0] + c.radius, c.center[1] + c.radius))
        for cx, cy, rx, ry, rot in self.ellipses:
            cs, sn = math.cos(rot), math.sin(rot)
            ex, ey = math.hypot(rx * cs, ry * sn), math.hypot(rx * sn, ry * cs)
            bs.append((cx - ex, cy - ey, cx + ex, cy + ey))
        if not bs:
            return None
        return (min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
                max(b[3] for b in bs))

    @property
    def empty(self) -> bool:
        return not (self.outlines or self.circles or self.ellipses or self.paths)


def _segs_box(segs) -> tuple[float, float, float, float]:
    xs, ys = [], []
    for s in segs:
        if isinstance(s, (Spline, EllipticArc)):
            b = s.box()
            xs += [b[0], b[2]]
            ys += [b[1], b[3]]
        elif isinstance(s, Arc):
            xs += [s.start[0], s.end[0]]
            ys += [s.start[1], s.end[1]]
            a0 = min(s.start_angle, s.end_angle)
            for k in range(math.ceil(a0 / (math.pi / 2) - 1e-12), 
                           math.floor(max(s.start_angle, s.end_angle) / (math.pi / 2) + 1e-12) + 1):
                x, y = s.at(k * math.pi / 2)
                xs.append(x)
                ys.append(y)
        else:
            xs += [s.start[0], s.end[0]]
            ys += [s.start[1], s.end[1]]
    return min(xs), min(ys), max(xs), max(ys)


# ------------------------------------------------------------------ segments
def bezier_spline(spans: list, steps: list | None = None) -> Spline:
    """A :class:`Spline` piece of cubic Bézier ``spans`` (each 4 points), ``steps`` their
    parameter steps (the knot differences; default: each span's chord)."""
    ctrl = [tuple(spans[0][0])]
    for b in spans:
        ctrl += [tuple(b[1]), tuple(b[2]), tuple(b[3])]
    if steps is None:
        steps = [math.dist(b[0], b[3]) or 1.0 for b in spans]
    c = CubicSpline(tuple(ctrl), tuple(float(h) for h in steps), False)
    return Spline(c, 0.0, float(c.n))


def _arc_from(p, q, center, sweep) -> Arc:
    r = 0.5 * (math.dist(p, center) + math.dist(q, center))
    a1 = math.atan2(p[1] - center[1], p[0] - center[0])
    return Arc((float(center[0]), float(center[1])), r, a1, sweep)


def _bulge_arc(p, q, b) -> Arc | Line:
    """The arc from ``p`` to ``q`` of DXF bulge ``b`` (tan of a quarter of the sweep; > 0
    counter-clockwise)."""
    if abs(b) < 1e-15 or p == q:
        return Line(p, q)
    sweep = 4 * math.atan(b)
    d = math.dist(p, q)
    r = d / (2 * abs(math.sin(sweep / 2)))
    mx, my = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
    ux, uy = (q[0] - p[0]) / d, (q[1] - p[1]) / d
    # the centre is on the left of p->q for a counter-clockwise arc under 180 degrees, on the
    # right over 180 (cos of half the sweep < 0); mirrored for a clockwise one
    h = r * math.cos(sweep / 2) * (1.0 if sweep > 0 else -1.0)
    c = (mx - uy * h, my + ux * h)
    return Arc(c, r, math.atan2(p[1] - c[1], p[0] - c[0]), sweep)


# ------------------------------------------------------------------ chains
def _meet(a, b) -> tuple[list, list]:
    """``a`` and ``b`` (segments, ``a.end`` near ``b.start``) made to meet exactly: the end
    of ``a`` (else the start of ``b``) is moved onto the other when it is a Line over ten
    times longer than the gap (its direction turns by less than 0.1 rad), else a tiny Line
    bridges the gap; an arc's
    or a curve's own numbers are never changed (their exactness is kept)."""
    g = math.dist(a.end, b.start)
    if g == 0.0:
        return [a], [b]
    if isinstance(a, Line) and math.dist(a.start, a.end) > 10 * g:
        return [Line(a.start, b.start)], [b]
    if isinstance(b, Line) and math.dist(b.start, b.end) > 10 * g:
        return [a], [Line(a.end, b.end)]
    return [a, Line(a.end, b.start)], [b]


def _seg_key(s, q: float = 1e-6):
    """A key equal for two segments that are the same curve, run either way (ends rounded
    to ``q`` mm): lines, arcs and spline pieces; None for others."""
    def r(p):
        return (round(p[0] / q), round(p[1] / q))
    if isinstance(s, Line):
        return ("L", frozenset((r(s.start), r(s.end))))
    if isinstance(s, Arc):
        return ("A", r(s.center), round(s.radius / q), frozenset((r(s.start), r(s.end))),
                r(s.at(s.start_angle + s.sweep / 2)))
    if isinstance(s, Spline):
        pts = tuple(r(p) for b in s.spans for p in b)
        return ("S", min(pts, pts[::-1]))
    return None


def _dedupe(pieces: list, loops: list) -> tuple[list, list, int]:
    """``pieces`` and ``loops`` without the duplicates a drawing program leaves (the same
    line drawn twice, a path drawn over another): a piece or loop every segment of which is
    already drawn is left out.  Returns them and the count of segments removed."""
    seen: set = set()
    removed = 0

    def dup(segs) -> bool:
        keys = [_seg_key(x) for x in segs]
        if keys and all(k is not None and k in seen for k in keys):
            return True
        seen.update(k for k in keys if k is not None)
        return False
    out_loops = []
    for segs, src in loops:
        if dup(segs):
            removed += len(segs)
        else:
            out_loops.append((segs, src))
    out_pieces = []
    for p in pieces:
        if dup(p):
            removed += len(p)
        else:
            out_pieces.append(p)
    return out_pieces, out_loops, removed


def _chain(pieces: list, tol: float = JOIN_TOL, gaps: list | None = None,
           deadline=None) -> tuple[list, list]:
    """Join open pieces (lists of segments) end to end: ``(closed chains, open chains)``.
    The pieces' ends are kept in a grid of cells ``tol`` wide, so each step finds its
    neighbours in the 3 x 3 cells around an end: linear in the pieces (20 000 loose lines join
    in well under a second), where scanning them all at every step was quadratic.

    ``tol`` above :data:`JOIN_TOL` (the closing tolerance): ends that far apart are made to
    meet exactly (:func:`_meet`) and each gap so closed is appended to ``gaps`` as ``(gap mm,
    where)``.  ``deadline``: a :class:`~aidl_lang.limits.Deadline`, checked as it goes."""
    from ..geometry.curves import reverse
    pieces = [list(p) for p in pieces]
    used = [False] * len(pieces)
    grid: dict = {}

    def cell(p):
        return (math.floor(p[0] / tol), math.floor(p[1] / tol))

    def join(left: list, right: list) -> list:
        """``left + right``, their meeting ends made exact (the gap noted) when apart."""
        g = math.dist(left[-1].end, right[0].start)
        if g == 0.0 or tol <= JOIN_TOL or g <= JOIN_TOL:
            return left + right
        if gaps is not None:
            gaps.append((g, left[-1].end))
        a, b = _meet(left[-1], right[0])
        return left[:-1] + a + b + right[1:]

    for i, p in enumerate(pieces):
        for q in (p[0].start, p[-1].end):
            grid.setdefault(cell(q), []).append(i)

    def near(q):
        cx, cy = cell(q)
        out = []
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                out += [i for i in grid.get((cx + dx, cy + dy), ()) if not used[i]]
        return sorted(set(out))

    closed, paths = [], []
    for i0 in range(len(pieces)):
        if used[i0]:
            continue
        if deadline is not None and i0 % 256 == 0:
            deadline.check("joining the drawing's pieces")
        used[i0] = True
        cur = list(pieces[i0])
        for forward in (True, False):
            while math.dist(cur[0].start, cur[-1].end) > tol:
                end = cur[-1].end if forward else cur[0].start
                for i in near(end):
                    p = pieces[i]
                    if forward and math.dist(p[0].start, end) <= tol:
                        cur = join(cur, p)
                    elif forward and math.dist(p[-1].end, end) <= tol:
                        cur = join(cur, [reverse(s) for s in reversed(p)])
                    elif not forward and math.dist(p[-1].end, end) <= tol:
                        cur = join(p, cur)
                    elif not forward and math.dist(p[0].start, end) <= tol:
                        cur = join([reverse(s) for s in reversed(p)], cur)
                    else:
                        continue
                    used[i] = True
                    break
                else:
                    break
        g = math.dist(cur[0].start, cur[-1].end)
        if g <= tol:
            if g > JOIN_TOL:            # closed across the gap: its ends made one point
                if gaps is not None:
                    gaps.append((g, cur[-1].end))
                if len(cur) == 1:
                    cur = cur + [Line(cur[-1].end, cur[0].start)]
                else:
                    a, b = _meet(cur[-1], cur[0])
                    cur = b + cur[1:-1] + a
            closed.append(cur)
        else:
            paths.append(cur)
    return closed, paths


def _crossing(segs) -> tuple[float, float] | None:
    """A point where the closed loop ``segs`` crosses itself, or None (on its chords within
    0.005 mm of the curves)."""
    import numpy as np
    pts = Loop(list(segs)).points()
    P = np.asarray(pts, dtype=float)
    n = len(P)
    if n < 4 or n > MAX_CROSSING_CHORDS:
        return None
    A, B = P, np.roll(P, -1, axis=0)
    for i in range(n - 2):
        j0, j1 = i + 2, n if i > 0 else n - 1
        if j0 >= j1:
            continue
        a, b = A[i], B[i]
        c, d = A[j0:j1], B[j0:j1]
        def orient(p, q, r):
            return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])
        o1 = orient(a, b, c)
        o2 = orient(a, b, d)
        o3 = orient(c, d, a)
        o4 = orient(c, d, b)
        hit = (o1 * o2 < 0) & (o3 * o4 < 0)
        if hit.any():
            k = int(np.argmax(hit))
            t = o1[k] / (o1[k] - o2[k])
            x, y = c[k] + t * (d[k] - c[k])
            return float(x), float(y)
    return None


OVERSHOOT = 0.5          # mm: a path whose end runs this far past its start is closed there


def _piece_length(s) -> float:
    return s.length if not isinstance(s, Circle) else 2 * math.pi * s.radius


def _split_at(s, x) -> tuple | None:
    """Segment ``s`` cut at its point ``x``: ``(s from its start to x, s from x to its
    end)``, each on ``s``'s own carrier (:func:`~aidl_lang.geometry.curves.with_ends`:
    exact, a line stays a line, an arc an arc, a curve the same curve); None when ``x`` is
    not on ``s`` between its ends (their lengths do not add up to its own)."""
    from ..geometry.curves import with_ends
    try:
        a, b = with_ends(s, s.start, x), with_ends(s, x, s.end)
        la, lb, l0 = _piece_length(a), _piece_length(b), _piece_length(s)
    except Exception:
        return None
    if abs(la + lb - l0) > 1e-9 * max(1.0, l0):
        return None
    return a, b


def _overshoot(segs: list, bound: float):
    """The closed loop of the open chain ``segs`` whose end crosses its own start (a path
    drawn past its start so that the beam closes it, as Boxes.py's D-bores end 0.1 mm past
    theirs): ``(loop, overshoot mm, crossing)``, the loop running from the crossing to the
    crossing with the bits before and after it trimmed, or None.  The trimmed bits each run
    at most ``bound`` mm along the chain; the crossing is exact on both pieces' carriers
    (:func:`~aidl_lang.geometry.curves.crossings`)."""
    from ..geometry.curves import carrier, crossings
    if bound <= 0 or len(segs) < 2 or math.dist(segs[0].start, segs[-1].end) > 2 * bound:
        return None
    heads, run = [], 0.0            # the pieces whose start lies within bound of the start
    for i, sg in enumerate(segs):
        if run > bound:
            break
        heads.append((i, run))
        run += _piece_length(sg)
    tails, run = [], 0.0
    for j in range(len(segs) - 1, -1, -1):
        if run > bound:
            break
        tails.append((j, run))
        run += _piece_length(segs[j])
    best = None
    for i, before in heads:
        for j, after in tails:
            if j <= i:
                continue
            a, b = segs[i], segs[j]
            try:
                pts = crossings(carrier(a), carrier(b))
            except Exception:
                continue
            for x in pts:
                sa, sb = _split_at(a, x), _split_at(b, x)
                if sa is None or sb is None:
                    continue
                cut_head = before + _piece_length(sa[0])
                cut_tail = after + _piece_length(sb[1])
                if cut_head > bound or cut_tail > bound or _piece_length(sa[1]) <= JOIN_TOL \
                        or _piece_length(sb[0]) <= JOIN_TOL:
                    continue
                if best is None or cut_head + cut_tail < best[0]:
                    loop = [sa[1]] + segs[i + 1:j] + [sb[0]]
                    if j == i + 1 and len(loop) == 2 and _piece_length(loop[0]) + \
                            _piece_length(loop[1]) <= 4 * JOIN_TOL:
                        continue
                    best = (cut_head + cut_tail, loop, cut_tail, x)
    if best is None:
        return None
    return best[1], best[2], best[3]


def _box_of(s) -> tuple:
    if isinstance(s, Line):
        return (min(s.start[0], s.end[0]), min(s.start[1], s.end[1]),
                max(s.start[0], s.end[0]), max(s.start[1], s.end[1]))
    return _segs_box([s])


def _trim_small_loops(segs: list, bound: float, closed: bool) -> tuple[list, int]:
    """``segs`` (a chain; ``closed``: a loop) without the small loops it makes where it
    crosses itself and comes back within ``bound`` mm along itself: the pieces between the
    crossing and its return are cut out, the two crossing pieces cut at the crossing on
    their own carriers (exact).  A laser cuts such a loop off as a crumb, so the part's edge
    is the chain without it: Boxes.py draws one at each inner corner with its default
    ``inner_corners="loop"`` and a burn (kerf) correction, and its D-bores' flat crosses
    their arc so.  Returns the chain and the number of loops cut out."""
    from ..geometry.curves import carrier, crossings
    n_cut = 0
    out = list(segs)
    i = 0
    while i < len(out) - 2:
        a = out[i]
        ba = _box_of(a)
        run = 0.0
        hit = None
        for j in range(i + 2, len(out) - (1 if closed and i == 0 else 0)):
            run += _piece_length(out[j - 1])
            if run > bound:
                break
            b = out[j]
            bb = _box_of(b)
            if bb[0] > ba[2] + 1e-9 or ba[0] > bb[2] + 1e-9 or bb[1] > ba[3] + 1e-9 or \
                    ba[1] > bb[3] + 1e-9:
                continue
            try:
                pts = crossings(carrier(a), carrier(b))
            except Exception:
                continue
            for x in pts:
                sa, sb = _split_at(a, x), _split_at(b, x)
                if sa is None or sb is None or _piece_length(sa[0]) <= JOIN_TOL or \
                        _piece_length(sb[1]) <= JOIN_TOL:
                    continue
                if run + _piece_length(sa[1]) + _piece_length(sb[0]) <= bound:
                    hit = (j, sa[0], sb[1])
                    break
            if hit is not None:
                break
        if hit is None:
            i += 1
            continue
        j, head, tail = hit
        out = out[:i] + [head, tail] + out[j + 1:]
        n_cut += 1
    return out, n_cut


@dataclass
class _Options:
    """What :func:`read_drawing` asks of the readers beyond the selection: the closing
    tolerance (mm), the wall-time :class:`~aidl_lang.limits.Deadline` (or None), the role
    filter ``keep(layer, rgb, aci)`` (or None: everything) and the shape budget."""
    close_tol: float = CLOSE_TOL
    deadline: object = None
    keep: object = None
    max_shapes: int = MAX_ENTITIES


_OPTS: "contextvars.ContextVar[_Options]" = contextvars.ContextVar("aidl_drawing_opts",
                                                                  default=_Options())


DEGENERATE_ABS = JOIN_TOL    # mm: a piece all of whose points lie this close to its start
DEGENERATE_REL = 1e-8       # ... or this share of the drawing's largest coordinate is dropped


def degenerate_tol(pieces, loops, circles, ellipses) -> float:
    """The size (mm) at or below which a piece of the drawing is one point and is dropped
    (:func:`_drop_degenerate`): ``max(DEGENERATE_ABS, DEGENERATE_REL * c)``, ``c`` the largest
    absolute coordinate of the pieces' ends, circles' and ellipses' centres.  The compiler
    calls two points one when they are within ``1e-9 * max(1 mm, the largest coordinate of
    the statement)`` (``Bezier`` and ``Spline``: E0108 "is one point",
    :func:`aidl_lang.geometry.spline.check_points`), so a piece kept here stays ten times
    past what it refuses, after the writer's shortest-decimal rounding (1e-12 mm); and
    :data:`JOIN_TOL` is where two ends are one point for the chaining."""
    c = 0.0
    for segs in list(pieces) + [segs for segs, _src in loops]:
        for s in segs:
            for p in (s.start, s.end):
                c = max(c, abs(p[0]), abs(p[1]))
    for x in circles:
        c = max(c, abs(x.center[0]), abs(x.center[1]))
    for e in ellipses:
        c = max(c, abs(e[0]), abs(e[1]))
    return max(DEGENERATE_ABS, DEGENERATE_REL * c)


def _reach(s) -> float:
    """An upper bound (mm) of how far segment ``s`` gets from its start."""
    if isinstance(s, Line):
        return math.dist(s.start, s.end)
    if isinstance(s, Arc):
        return s.radius * min(2.0, abs(s.sweep))
    if isinstance(s, Circle):
        return 2 * s.radius
    b = s.box()                                  # Spline, EllipticArc: the exact box
    return math.hypot(b[2] - b[0], b[3] - b[1])


def _span_reach(b) -> float:
    return max(math.dist(b[0], q) for q in b[1:])


def _drop_in(segs: list, tol: float, dropped: dict) -> list:
    """``segs`` without the pieces that are one point (within ``tol``), each counted in
    ``dropped`` by kind; a spline piece loses only its spans that are one point (the next span
    starts where the previous ends: the Bezier chain the writer writes shares them)."""
    out = []
    for s in segs:
        if isinstance(s, Spline):
            spans = s.spans
            keep = [i for i, b in enumerate(spans) if _span_reach(b) > tol]
            if len(keep) < len(spans):
                dropped["Bézier piece"] = dropped.get("Bézier piece", 0) + len(spans) - len(keep)
                if not keep:
                    continue
                from ..geometry.curves import _span_steps
                h = _span_steps(s)
                kept = [list(spans[i]) for i in keep]
                for j in range(1, len(kept)):        # each span starts where the last ended
                    kept[j][0] = kept[j - 1][3]
                s = bezier_spline(kept, [h[i] for i in keep] if len(h) == len(spans) else None)
            out.append(s)
        elif _reach(s) <= tol:
            kind = {Line: "line", Arc: "arc", EllipticArc: "elliptical arc",
                    Circle: "circle"}.get(type(s), "piece")
            dropped[kind] = dropped.get(kind, 0) + 1
        else:
            out.append(s)
    return out


def _drop_degenerate(pieces, loops, circles, ellipses, notes, name, hatch_circles=()):
    """The pieces, loops, circles and ellipses of a drawing without what is one point: a
    line, arc, Bézier span or elliptical arc all of whose points lie within
    :func:`degenerate_tol` of its start, a circle or ellipse of a radius or semi-axis within
    it (a Boxes.py ``C x,y x,y x,y``, a DXF spline's repeated knot, a LINE from a point to
    itself).  The compiler refuses some of them (``Bezier``: E0108 "is one point") and the
    others draw nothing; one ``W0130`` note counts them by kind."""
    tol = degenerate_tol(pieces, loops, list(circles) + list(hatch_circles), ellipses)
    dropped: dict = {}
    pieces = [q for q in (_drop_in(p, tol, dropped) for p in pieces) if q]
    loops = [(q, src) for q, src in ((_drop_in(p, tol, dropped), src) for p, src in loops) if q]
    keep_c = [c for c in circles if c.radius > tol]
    keep_h = [c for c in hatch_circles if c.radius > tol]
    if len(keep_c) + len(keep_h) < len(circles) + len(hatch_circles):
        dropped["circle"] = dropped.get("circle", 0) + len(circles) + len(hatch_circles) \
            - len(keep_c) - len(keep_h)
    keep_e = [e for e in ellipses if min(e[2], e[3]) > tol]
    if len(keep_e) < len(ellipses):
        dropped["ellipse"] = len(ellipses) - len(keep_e)
    if dropped:
        n = sum(dropped.values())
        what = ", ".join(_plural(v, w) for w, v in sorted(dropped.items()))
        notes.append(Note("W0130", f"{n} piece{'s' if n != 1 else ''} of `{name}` dropped: "
                                   f"zero length, all {'its' if n == 1 else 'their'} points "
                                   f"within {tol:.3g} mm of one point ({what})",
                          "nothing is lost: they draw nothing; delete them in the drawing "
                          "program to silence this"))
    return pieces, loops, keep_c, keep_e, keep_h


def _finish(pieces, loops, circles, ellipses, notes, unit, name,
            hatch_circles: list | None = None) -> Drawing:
    """The :class:`Drawing` of the pieces read: pieces that are one point dropped
    (:func:`_drop_degenerate`; ``hatch_circles``, a DXF's, are filtered in place), duplicates
    removed, chained, gaps within the closing tolerance closed, loops sorted into outlines and
    paths."""
    opts = _OPTS.get()
    pieces, loops, circles, ellipses, kept = _drop_degenerate(
        pieces, loops, circles, ellipses, notes, name, hatch_circles or ())
    if hatch_circles:
        hatch_circles[:] = kept
    pieces, loops, dups = _dedupe(pieces, loops)
    if dups:
        notes.append(Note("W0130", f"{dups} duplicate segment{'s' if dups > 1 else ''} of "
                                   f"`{name}` removed (drawn twice, over one another)",
                          "delete the duplicates in the drawing program to silence this"))
    closed, open_ = _chain(pieces, deadline=opts.deadline)
    if open_ and opts.close_tol > 0:
        # a path whose end runs past its start, crossing it: closed at the crossing (before
        # the gaps below, which would close it across the overshoot into a loop that
        # crosses itself)
        shot, keep_open = [], []
        for segs in open_:
            o = _overshoot(segs, max(opts.close_tol, OVERSHOOT))
            if o is None:
                keep_open.append(segs)
            else:
                closed.append(o[0])
                shot.append((o[1], o[2]))
        open_ = keep_open
        if shot:
            g, at = max(shot)
            notes.append(Note("W0130", f"{len(shot)} path{'s' if len(shot) > 1 else ''} of "
                                       f"`{name}` closed where {'its' if len(shot) == 1 else 'their'} "
                                       f"end crosses {'its' if len(shot) == 1 else 'their'} start "
                                       f"(the overshoot trimmed: the largest {g:.3g} mm, at "
                                       f"({at[0]:.6g}, {at[1]:.6g}) mm)",
                              "give close_tolerance=0 (`aidl import --close-tolerance 0`) to "
                              "keep them as drawn"))
    if open_ and opts.close_tol > JOIN_TOL:
        gaps: list = []
        more, open_ = _chain(open_, opts.close_tol, gaps, opts.deadline)
        closed += more
        if gaps:
            g, at = max(gaps)
            notes.append(Note("W0130", f"{len(gaps)} gap{'s' if len(gaps) > 1 else ''} of "
                                       f"`{name}` closed (the largest {g:.3g} mm, at "
                                       f"({at[0]:.6g}, {at[1]:.6g}) mm): ends within the "
                                       f"closing tolerance of {opts.close_tol:g} mm made one "
                                       f"point", "give close_tolerance=0 (`aidl import "
                                                 "--close-tolerance 0`) to keep them open"))
    d = Drawing(circles=circles, ellipses=ellipses, notes=notes, unit=unit)
    crumbs = 0
    for segs, src in [(c, "") for c in closed] + loops:
        if len(segs) == 1 and isinstance(segs[0], Circle):
            d.circles.append(segs[0])
            continue
        hit = _crossing(segs)
        if hit is not None and opts.close_tol > 0:
            # small loops where it crosses itself (a kerf-corrected inner corner) cut off
            trimmed, k = _trim_small_loops(segs, max(opts.close_tol, OVERSHOOT), True)
            if k and _crossing(trimmed) is None:
                segs, hit = trimmed, None
                crumbs += k
        if hit is not None:          # kept as a stroke; an error where an outline is needed
            d.paths.append(Path(list(segs), "crosses itself", crossing=hit))
            continue
        o = Outline(list(segs), src)
        if o.area < 0:
            from ..geometry.curves import reverse
            o.segments = [reverse(s) for s in reversed(o.segments)]
        d.outlines.append(o)
    d.outlines.sort(key=lambda o: -abs(o.area))
    if crumbs:
        notes.append(Note("W0130", f"{crumbs} small loop{'s' if crumbs > 1 else ''} of `{name}` "
                                   f"cut off where an outline crosses itself and comes back "
                                   f"within {max(opts.close_tol, OVERSHOOT):g} mm (a kerf-"
                                   f"corrected inner corner drawn as a loop): the outline "
                                   f"runs through the crossing",
                          "give close_tolerance=0 (`aidl import --close-tolerance 0`) to "
                          "keep them as drawn"))
    for segs in open_:
        d.paths.append(Path(list(segs)))
    d.circles = [Circle(c.center, c.radius) for c in d.circles]
    d.circles.sort(key=lambda c: (-c.radius, c.center[0], c.center[1]))
    return d


def open_gaps(d: Drawing) -> list[tuple[float, tuple[float, float]]]:
    """``(gap in mm, where)`` of each open path (its end to its start)."""
    return [(math.dist(p.start, p.end), p.end) for p in d.paths]


# ------------------------------------------------------------------ DXF
_SKIP_QUIET = {"POINT", "VIEWPORT", "ATTDEF", "ATTRIB", "SEQEND", "VERTEX"}


MAX_BLOCK_DEPTH = 16     # blocks inside blocks (INSERT in a block definition), as templates
GARBAGE = 1e15           # mm: a number past this (or inf, nan) is noise: the entity is skipped
FLAT_TOL = 1e-9          # mm: z values this close lie in one plane parallel to XY


class _EzdxfLog:
    """ezdxf's own log lines (``Found non-unique entity handle #C, ...``) while a drawing is
    read: kept in ``lines`` for a ``W0130`` note instead of reaching the terminal."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def __enter__(self):
        import logging

        class H(logging.Handler):
            def emit(h, record) -> None:
                try:
                    msg = record.getMessage()
                except Exception:
                    msg = str(record.msg)
                if len(self.lines) < 1000:
                    self.lines.append(msg)
        self.log = logging.getLogger("ezdxf")
        self.handler = H(logging.WARNING)         # its INFO lines were never shown
        self.saved = self.log.propagate
        self.log.addHandler(self.handler)
        self.log.propagate = False
        return self

    def __exit__(self, *exc) -> None:
        self.log.removeHandler(self.handler)
        self.log.propagate = self.saved


def _open_dxf(data: bytes, name: str):
    """The ezdxf document of the DXF ``data`` (ASCII or binary, read from these bytes: the
    file is opened once): ezdxf's normal loader, its recover mode when that fails.  Raises
    :class:`DrawingError` ``E0130``."""
    doc = _fast_dxf(data)
    if doc is not None:
        return doc
    try:
        if data.startswith(b"AutoCAD Binary DXF"):
            from ezdxf.document import Drawing as _Doc
            from ezdxf.lldxf.tagger import binary_tags_loader
            return _Doc.load(binary_tags_loader(data, errors="surrogateescape"))
        from ezdxf import recover
        return recover.read(io.BytesIO(data))[0]      # damaged: recover mode (slower)
    except Exception as ex:          # ezdxf raises DXFStructureError and others on garbage
        raise DrawingError("E0130", f"`{name}` is not a readable DXF file ({type(ex).__name__})",
                           "export it again as DXF R12 or later (ASCII or binary)") from None


def _plural(n: int, word: str) -> str:
    """``1 entity``, ``2 entities``, ``3 HATCH boundaries``."""
    if n == 1:
        return f"{n} {word}"
    return f"{n} {word[:-1]}ies" if word.endswith("y") else f"{n} {word}s"


def _layers_text(by_layer: dict) -> str:
    """``layer `0``` or ``layers `A` (20), `B` (10)``."""
    items = sorted(by_layer.items(), key=lambda kv: (-kv[1], kv[0]))
    if len(items) == 1:
        return f"layer `{items[0][0]}`"
    shown = ", ".join(f"`{ly}` ({n})" for ly, n in items[:6])
    return f"layers {shown}" + (f" and {len(items) - 6} more" if len(items) > 6 else "")


_REASON_HINT = {
    "plane": "turn the drawing into the XY plane (the world UCS) in the drawing program, "
             "or select other layers",
    "number": "fix the entity in the drawing program (it has no size or a broken number)",
    "width": "widths are not cut: draw a wide line as an outline if it is one",
    "text": "write the text with Text(...) in a `drawing`",
    "z": "the drawing is read in the XY plane: z only places it in 3D",
    "exact": "convert it to lines, arcs or splines in the drawing program, or select other "
             "layers",
    "hatch": "",
}


def _read_dxf(data: bytes, name: str, layer, color, unit: str | None) -> Drawing:
    with _EzdxfLog() as log:
        d = _read_dxf_doc(data, name, layer, color, unit, log)
    return d


def _read_dxf_doc(data: bytes, name: str, layer, color, unit: str | None, log) -> Drawing:
    doc = _open_dxf(data, name)
    notes: list[Note] = []
    if unit is None:
        code = int(doc.header.get("$INSUNITS", 0) or 0)
        if code == 0:
            scale, unit = 1.0, "mm"
            notes.append(Note("W0130", f"`{name}` gives no unit ($INSUNITS = 0): read as "
                                       f"millimetres", 'give units="in" (or another unit) '
                                                       "to read it in another unit"))
        else:
            if code not in INSUNITS_MM:
                raise DrawingError("E0130", f"`{name}` has an unknown unit ($INSUNITS = {code})",
                                   'give units="mm" (or another unit)')
            unit, scale = INSUNITS_MM[code]
    else:
        scale = UNIT_MM[unit]
    layers = None if layer is None else {s.lower() for s in
                                         ([layer] if isinstance(layer, str) else layer)}
    colors = None if color is None else set([color] if isinstance(color, (int, float))
                                             else color)
    msp = doc.modelspace()
    if layers is not None:
        known = {ly.dxf.name.lower() for ly in doc.layers}
        missing = [ly for ly in ([layer] if isinstance(layer, str) else layer)
                   if ly.lower() not in known]
        if missing and not any(e.dxf.layer.lower() in layers for e in msp):
            from ..diagnostics import did_you_mean
            sugg = did_you_mean(missing[0], [ly.dxf.name for ly in doc.layers])
            raise DrawingError("E0132", f"`{name}` has no layer `{missing[0]}`",
                               ("did you mean " + ", ".join(f"`{s}`" for s in sugg) + "?")
                               if sugg else "layers: " + ", ".join(
                                   sorted(ly.dxf.name for ly in doc.layers))[:300])
    pieces, loops, circles, ellipses, texts = [], [], [], [], []
    hatch_circles: list = []
    # (kind, reason, reason class) -> {layer: count}; what was seen: (type, layer) -> count
    skipped: dict = {}
    seen: dict = {}
    widths: dict = {}
    zs: dict = {}                    # entity type -> [z, ...] of entities read at z != 0
    count = 0
    cur_layer = ["0"]

    def skip(kind: str, reason: str, cls: str) -> None:
        by = skipped.setdefault((kind, reason, cls), {})
        by[cur_layer[0]] = by.get(cur_layer[0], 0) + 1

    def P(v):
        return (_mm(float(v[0]) * scale), _mm(float(v[1]) * scale))

    def aci(e, inherited) -> int:
        c = e.dxf.get("color", 256)
        if c == 0 and inherited is not None:          # BYBLOCK: the insert's colour
            return inherited
        if c == 256:
            try:
                c = doc.layers.get(e.dxf.layer).dxf.color
            except Exception:
                c = 7
        return abs(int(c))

    def where(e) -> tuple[str, int | None]:
        handle = e.dxf.get("handle", None)
        line = _dxf_line(data, handle)
        return ", ".join(x for x in (f"handle {handle}" if handle else "",
                                     f"line {line}" if line else "") if x), line

    sizes: dict = {}

    def block_size(bname: str, stack: tuple) -> int:
        """The entities block ``bname`` expands to, its nested blocks and arrays included
        (each copy counted); a block that inserts itself or nests past MAX_BLOCK_DEPTH
        raises _Deep."""
        if bname in sizes:
            return sizes[bname]
        if bname in stack or len(stack) >= MAX_BLOCK_DEPTH:
            raise _Deep(stack + (bname,))
        blk = doc.blocks.get(bname)
        n = 0
        if blk is not None:
            for x in blk:
                if x.dxftype() == "INSERT":
                    n += _copies(x) * max(1, block_size(x.dxf.name, stack + (bname,)))
                else:
                    n += 1
        sizes[bname] = n
        return n

    def expand(e, depth: int, top, eff_layer: str, eff_color) -> None:
        nonlocal count
        rows, cols = int(e.dxf.get("row_count", 1) or 1), int(e.dxf.get("column_count", 1) or 1)
        arr = rows * cols > 1
        label_top, line = where(top)
        kind = "MINSERT" if arr else "INSERT"
        at = f" ({label_top})" if label_top else ""
        head = (f"{kind}{at}" if top is e else
                f"INSERT{at}, through its {kind} of block `{e.dxf.name}`,")
        try:
            size = block_size(e.dxf.name, ())
            n = _copies(e) * max(1, size)            # each copy counts, even an empty one
        except _Deep as ex:
            chain = " > ".join(f"`{b}`" for b in ex.chain[:MAX_BLOCK_DEPTH + 1])
            cyc = ex.chain[-1] in ex.chain[:-1]
            raise DrawingError("E0304", f"{head} of `{name}` " + (
                f"places block `{ex.chain[-1]}`, which inserts itself ({chain}): it never ends"
                if cyc else f"nests blocks more than {MAX_BLOCK_DEPTH} deep ({chain})"),
                "remove the INSERT of the block from its own definition" if cyc else
                "explode some of the blocks in the drawing program", line) from None
        if depth + 1 > MAX_BLOCK_DEPTH:
            raise DrawingError("E0304", f"{head} of `{name}` nests blocks more than "
                                        f"{MAX_BLOCK_DEPTH} deep", "explode some of the blocks "
                                                                   "in the drawing program", line)
        if count + n > MAX_ENTITIES:
            each = f" ({_plural(size, 'entity')} each)"
            grid = f"an array of {rows} x {cols} copies of block `{e.dxf.name}`{each}" if arr \
                else f"block `{e.dxf.name}`"
            raise DrawingError("E0304", f"{head} of `{name}` is {grid}: "
                                        f"{n:,} entities in all, "
                                        f"more than the {MAX_ENTITIES:,} entities one drawing "
                                        f"may give",
                               "draw one copy and repeat it with a `for` loop in the program, "
                               "or select other layers", line)
        if rows * cols > 1:
            inserts = list(e.multi_insert())
            count += rows * cols - len(inserts)          # copies at one place: counted
        else:
            inserts = [e]

        def cb(x, reason) -> None:
            skip(x.dxftype(), f"cannot be placed by its INSERT ({reason})", "exact")
        for ins in inserts:
            try:
                ents = list(ins.virtual_entities(skipped_entity_callback=cb))
            except DrawingError:
                raise
            except Exception as ex:
                cur_layer[0] = eff_layer
                skip(kind, f"its block `{e.dxf.name}` cannot be placed ({type(ex).__name__})",
                     "exact")
                continue
            walk(ents, depth + 1, top, eff_layer, eff_color)

    def walk(entities, depth: int, top=None, inh_layer=None, inh_color=None) -> None:
        nonlocal count
        for e in entities:
            count += 1
            if count > MAX_ENTITIES:
                raise DrawingError("E0130", f"`{name}` has more than {MAX_ENTITIES} entities",
                                   "select fewer with layer= or split the drawing")
            t = e.dxftype()
            ly = e.dxf.get("layer", "0")
            if ly == "0" and inh_layer is not None:         # layer 0 in a block: the insert's
                ly = inh_layer
            if t == "INSERT":
                expand(e, depth, top or e, ly, aci(e, inh_color))
                continue
            if layers is not None and ly.lower() not in layers:
                continue
            if colors is not None and aci(e, inh_color) not in colors:
                continue
            if t in _SKIP_QUIET:
                continue
            cur_layer[0] = ly
            seen[(t, ly)] = seen.get((t, ly), 0) + 1
            if _OPTS.get().keep is not None and not _OPTS.get().keep(
                    [ly], _dxf_rgb(e, aci(e, inh_color)), aci(e, inh_color)):
                continue            # roles (cut=, engrave=, ignore=): another role's entity
                                    # (in a block: the insert's layer and colour, as above)
            made = (len(pieces), len(loops), len(circles), len(ellipses), len(texts),
                    len(hatch_circles))
            try:
                one(e, t)
                _check_made(pieces[made[0]:] + [seg for seg, _ in loops[made[1]:]]
                            + circles[made[2]:] + ellipses[made[3]:] + texts[made[4]:]
                            + hatch_circles[made[5]:])
            except _Skip as s:
                skip(s.kind or t, s.what, s.cls)
            except _OutOfRange as ex:
                del pieces[made[0]:], loops[made[1]:], circles[made[2]:]
                del ellipses[made[3]:], texts[made[4]:], hatch_circles[made[5]:]
                v = ex.value
                if not math.isfinite(v) or abs(v) > GARBAGE:
                    skip(t, f"{ex.what} that is " + ("not a number" if v != v else "infinite"
                                                      if math.isinf(v) else
                                                      f"beyond {GARBAGE:g} mm"), "number")
                    continue
                w, line = where(top or e)
                label = t + (f" (in the block of INSERT {w})" if top is not None and w
                             else f" ({w})" if w else "")
                raise _range_error(ex, label, name, line) from None

    def ocs_z(e, t: str) -> bool:
        """Whether the OCS entity ``e`` lies in the drawing plane (extrusion +Z or -Z), True
        for -Z (its OCS x axis is the world's -x: ezdxf's arbitrary axis algorithm); else
        raises _Skip."""
        ext = tuple(float(v) for v in e.dxf.get("extrusion", (0, 0, 1))) \
            if e.dxf.hasattr("extrusion") else (0.0, 0.0, 1.0)
        if not all(math.isfinite(v) for v in ext):
            raise _Skip("an extrusion that is not a number", cls="number")
        n = math.sqrt(sum(v * v for v in ext))
        if n == 0 or abs(ext[0]) > 1e-12 * n or abs(ext[1]) > 1e-12 * n:
            raise _Skip("not in the drawing plane: the extrusion (normal) is not +Z or -Z "
                        "(drawn in a tilted UCS)", cls="plane")
        return ext[2] < 0

    def at_z(t: str, z: float, flip: bool = False) -> None:
        z = float(z) * scale * (-1.0 if flip else 1.0)
        if not math.isfinite(z) or abs(z) > GARBAGE:
            raise _OutOfRange("a z coordinate", z)
        if abs(z) > FLAT_TOL:
            zs.setdefault(t, []).append(z)

    def flat(t: str, vs) -> None:
        """WCS points ``vs`` must share one z (a plane parallel to XY)."""
        z = [float(v[2]) * scale for v in vs]
        if not z:
            return
        for v in z:
            if not math.isfinite(v) or abs(v) > GARBAGE:
                raise _OutOfRange("a z coordinate", v)
        if max(z) - min(z) > FLAT_TOL:
            raise _Skip("not in the drawing plane: its points lie at different z",
                        cls="plane")
        at_z(t, z[0] / scale)

    def polyline(t, vs, closed) -> list | None:
        """The segments of ``vs`` ((x, y) mm, bulge), or None (all at one point)."""
        segs = []
        n = len(vs)
        for i in range(n if closed else n - 1):
            (p, b), (q, _) = vs[i], vs[(i + 1) % n]
            if math.dist(p, q) <= 1e-12:
                continue
            segs.append(_bulge_arc(p, q, b))
        return segs or None

    def one(e, t) -> None:
        if t == "LINE":
            flat(t, (e.dxf.start, e.dxf.end))
            a, b = P(e.dxf.start), P(e.dxf.end)
            if math.dist(a, b) <= 1e-12:
                raise _Skip("zero length", cls="number")
            pieces.append([Line(a, b)])
        elif t in ("CIRCLE", "ARC"):
            flip = ocs_z(e, t)
            c = P(e.dxf.center)
            at_z(t, e.dxf.center[2], flip)
            r = _mm(float(e.dxf.radius) * scale, "a radius")
            if r <= 0:
                raise _Skip("a radius not above 0", cls="number")
            if flip:
                c = (-c[0], c[1])
            if t == "CIRCLE":
                circles.append(Circle(c, r))
                return
            a1 = math.radians(_finite(e.dxf.start_angle, "an angle"))
            a2 = math.radians(_finite(e.dxf.end_angle, "an angle"))
            sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
            pieces.append([Arc(c, r, math.pi - a1, -sweep) if flip else Arc(c, r, a1, sweep)])
        elif t == "LWPOLYLINE":
            flip = ocs_z(e, t)
            at_z(t, e.dxf.get("elevation", 0.0), flip)
            vs = [(P((x, y)), _finite(b, "a bulge")) for x, y, b in e.get_points("xyb")]
            if e.has_width:
                widths[(t, cur_layer[0])] = widths.get((t, cur_layer[0]), 0) + 1
            add_poly(t, vs, e.closed, flip)
        elif t == "POLYLINE":
            if e.is_polygon_mesh or e.is_poly_face_mesh:
                raise _Skip("a mesh (3D faces): no outline here", cls="exact")
            if e.is_3d_polyline:         # world coordinates, no bulges
                locs = [v.dxf.location for v in e.vertices]
                flat(t, locs)
                vs = [(P(v), 0.0) for v in locs]
                flip = False
            else:
                flip = ocs_z(e, t)
                at_z(t, e.dxf.get("elevation", (0, 0, 0))[2], flip)
                vs = [(P(v.dxf.location), _finite(v.dxf.get("bulge", 0.0), "a bulge"))
                      for v in e.vertices]
                if e.has_width:
                    widths[(t, cur_layer[0])] = widths.get((t, cur_layer[0]), 0) + 1
            add_poly(t, vs, e.is_closed, flip)
        elif t == "SPLINE":
            flat(t, list(e.control_points) or list(e.fit_points))
            for v in e.control_points:       # before ezdxf's tools compute with them
                P(v)
            for k in (*e.knots, *e.weights):
                _finite(k, "a knot or weight")
            pieces.append([_dxf_spline(e, P)])
        elif t == "ELLIPSE":
            # center and major axis are in world coordinates (not the OCS of ARC and
            # CIRCLE); the extrusion only turns the parameter: the minor axis is
            # extrusion x major axis, so an extrusion down runs the parameter clockwise
            flip = ocs_z(e, t)
            if abs(float(e.dxf.major_axis[2]) * scale) > FLAT_TOL:
                raise _Skip("not in the drawing plane: its major axis leaves the XY plane",
                            cls="plane")
            at_z(t, e.dxf.center[2])
            s0 = _finite(e.dxf.start_param, "an angle")
            s1 = _finite(e.dxf.end_param, "an angle")
            c = P(e.dxf.center)
            mx = _mm(float(e.dxf.major_axis[0]) * scale, "a semi-axis")
            my = _mm(float(e.dxf.major_axis[1]) * scale, "a semi-axis")
            rx = _mm(math.hypot(mx, my), "a semi-axis")
            ratio = _finite(e.dxf.ratio, "an axis ratio")
            ry = _mm(rx * ratio, "a semi-axis")
            if rx <= 0 or ry <= 0:
                raise _Skip("a semi-axis not above 0", cls="number")
            rot = math.atan2(my, mx)
            sweep = (s1 - s0) % (2 * math.pi)
            if sweep < 1e-9 or sweep > 2 * math.pi - 1e-9:
                ellipses.append((c[0], c[1], rx, ry, rot))
                return
            nx, ny = (-my * ratio, mx * ratio) if not flip else (my * ratio, -mx * ratio)

            def at(tp):
                cs, sn = math.cos(tp), math.sin(tp)
                return (c[0] + mx * cs + nx * sn, c[1] + my * cs + ny * sn)
            pieces.append([elliptic_arc(c, rx, ry, rot, at(s0), at(s0 + sweep / 2),
                                        at(s0 + sweep))])
        elif t == "HATCH":
            hatch(e)
        elif t in ("TEXT", "MTEXT"):
            if t == "TEXT" or e.dxf.hasattr("extrusion"):
                if ocs_z(e, t):                  # mirrored text: not read
                    raise _Skip("mirrored (extrusion down): not read", cls="text")
            texts.extend(_dxf_text(e, t, P, scale))
        else:
            raise _Skip("no exact form here", cls="exact")

    def add_poly(t, vs, closed, flip) -> None:
        if flip:
            vs = [((-p[0], p[1]), -b) for p, b in vs]
        segs = polyline(t, vs, closed)
        if segs is None:
            raise _Skip("zero length (all its vertices at one point)", cls="number")
        if closed or math.dist(segs[0].start, segs[-1].end) <= JOIN_TOL:
            loops.append((segs, t))
        else:
            pieces.append(segs)

    def hatch(e) -> None:
        """A HATCH's boundary paths (polyline paths with bulges; edge paths of lines, arcs,
        ellipses and splines), each a closed loop: an island is a loop inside another, so it
        becomes a hole as any inner loop does."""
        ocs_z(e, "HATCH")
        l0 = len(loops)
        for path in _hatch_paths(e):
            n0 = len(pieces)
            for x in path:
                xt = x.dxftype()
                if xt == "ARC" and len(path) == 1 and \
                        (float(x.dxf.end_angle) - float(x.dxf.start_angle)) % 360.0 == 0.0:
                    flip = ocs_z(x, xt)                  # a full-circle edge: a circle
                    c = P(x.dxf.center)
                    r = _mm(float(x.dxf.radius) * scale, "a radius")
                    if r <= 0:
                        raise _Skip("a boundary radius not above 0", cls="number")
                    hatch_circles.append(Circle((-c[0], c[1]) if flip else c, r))
                    continue
                try:
                    one(x, xt)
                except _Skip as s:
                    raise _Skip(f"a boundary {xt}: {s.what}", cls=s.cls) from None
            mine = pieces[n0:]
            del pieces[n0:]
            closed, open_ = _chain(mine)
            loops.extend((c, "HATCH") for c in closed)
            pieces.extend(open_)
        loops[l0:] = [(segs, "HATCH") for segs, _ in loops[l0:]]

    texts_ref = texts
    walk(list(msp), 0)
    return _dxf_finish(pieces, loops, circles, ellipses, hatch_circles, texts_ref, notes,
                       skipped, seen, widths, zs, log, unit, name)


def _hatch_paths(e) -> list:
    """The boundary paths of HATCH ``e`` as virtual entities, one list a path: a polyline
    path an LWPOLYLINE (with its bulges), an edge path its LINE, ARC, ELLIPSE and SPLINE
    edges, in the hatch's plane (ezdxf's ``virtual_boundary_path_entities``, whose polyline
    paths fail in ezdxf 1.4)."""
    from ezdxf.entities import LWPolyline
    from ezdxf.entities.boundary_paths import EdgePath, PolylinePath
    from ezdxf.explode import _virtual_edge_path
    attribs = {"layer": e.dxf.get("layer", "0")}
    elevation = float(e.dxf.elevation.z)
    ocs = e.ocs()
    out = []
    for path in e.paths:
        if isinstance(path, PolylinePath):
            p = LWPolyline.new(dxfattribs=dict(attribs))
            p.append_points(path.vertices, format="xyb")
            p.dxf.extrusion = ocs.uz
            p.dxf.elevation = elevation
            p.closed = path.is_closed
            out.append([p])
        elif isinstance(path, EdgePath):
            out.append(_virtual_edge_path(path, dict(attribs), ocs, elevation))
    return out


class _Deep(Exception):
    def __init__(self, chain: tuple) -> None:
        self.chain = chain


def _copies(e) -> int:
    """The copies an INSERT places: rows x columns of a MINSERT, else 1."""
    try:
        return max(1, int(e.dxf.get("row_count", 1) or 1)) * \
            max(1, int(e.dxf.get("column_count", 1) or 1))
    except (TypeError, ValueError):
        return 1


def _loop_key(segs) -> tuple:
    """A loop's segments as a set of rounded starts and kinds (the same loop whatever its
    direction and first segment)."""
    from ..geometry.curves import reverse
    a = sorted((type(s).__name__, round(s.start[0], 6), round(s.start[1], 6),
                round(s.end[0], 6), round(s.end[1], 6)) for s in segs)
    b = sorted((type(s).__name__, round(r.start[0], 6), round(r.start[1], 6),
                round(r.end[0], 6), round(r.end[1], 6)) for s in segs for r in [reverse(s)])
    return tuple(min(a, b))


def _dxf_finish(pieces, loops, circles, ellipses, hatch_circles, texts, notes, skipped, seen,
                widths, zs, log, unit, name) -> Drawing:
    """The drawing of what was read, a HATCH boundary that repeats an outline drawn by other
    entities read once, and the notes: skipped entities by kind, reason and layer (numbers
    that are no size in one note), widths ignored, z left out, ezdxf's own log lines."""
    d = _finish(pieces, loops, circles, ellipses, notes, unit, name, hatch_circles)
    drawn = {_loop_key(o.segments) for o in d.outlines if o.source != "HATCH"}
    keep, dup = [], 0
    for o in d.outlines:
        if o.source == "HATCH":
            k = _loop_key(o.segments)
            if k in drawn:
                dup += 1
                continue
            drawn.add(k)
        keep.append(o)
    d.outlines = keep
    have = {(round(c.center[0], 6), round(c.center[1], 6), round(c.radius, 6)) for c in d.circles}
    for c in hatch_circles:
        k = (round(c.center[0], 6), round(c.center[1], 6), round(c.radius, 6))
        if k in have:
            dup += 1
            continue
        have.add(k)
        d.circles.append(Circle(c.center, c.radius))
    d.circles.sort(key=lambda c: (-c.radius, c.center[0], c.center[1]))
    d.texts = texts
    if dup:
        notes.append(Note("W0130", f"{_plural(dup, 'HATCH boundary')} of `{name}` "
                                   f"repeat{'s' if dup == 1 else ''} an outline drawn by other "
                                   "entities: read once", ""))
    bad = []
    for (kind, reason, cls), by in sorted(skipped.items()):
        n = sum(by.values())
        if cls == "number":
            bad.append((n, kind, reason, by))
            continue
        word = "entity" if n == 1 else "entities"
        notes.append(Note("W0130", f"{n} {kind} {word} of `{name}` skipped ({_layers_text(by)})"
                                   f": {reason}", _REASON_HINT.get(cls, "")))
    if bad:
        total = sum(b[0] for b in bad)
        parts = "; ".join(f"{n} {kind} with {reason} ({_layers_text(by)})"
                          if not reason.startswith(("zero", "a boundary")) else
                          f"{n} {kind} of {reason} ({_layers_text(by)})"
                          for n, kind, reason, by in bad)
        notes.append(Note("W0130", f"{total} {'entity' if total == 1 else 'entities'} of "
                                   f"`{name}` skipped for numbers that give no shape: {parts}",
                          _REASON_HINT["number"]))
    if widths:
        n = sum(widths.values())
        by: dict = {}
        kinds = sorted({k for k, _ in widths})
        for (k, ly), m in widths.items():
            by[ly] = by.get(ly, 0) + m
        notes.append(Note("W0130", f"{n} {'/'.join(kinds)} {'entity' if n == 1 else 'entities'}"
                                   f" of `{name}` ({_layers_text(by)}) {'has' if n == 1 else 'have'} widths: read as "
                                   "their centre lines, the widths ignored",
                          _REASON_HINT["width"]))
    if zs:
        allz = [z for v in zs.values() for z in v]
        rng = f"z = {allz[0]:g}" if max(allz) - min(allz) <= FLAT_TOL else \
            f"z from {min(allz):g} to {max(allz):g}"
        kinds = ", ".join(f"{len(v)} {k}" for k, v in sorted(zs.items()))
        notes.append(Note("W0130", f"{len(allz)} {'entity' if len(allz) == 1 else 'entities'}"
                                   f" of `{name}` ({kinds}) {'lies' if len(allz) == 1 else 'lie'} off the XY plane ({rng} mm): "
                                   "read in the XY plane", _REASON_HINT["z"]))
    if log.lines:
        first = log.lines[0].strip()
        more = f" (and {len(log.lines) - 1} more)" if len(log.lines) > 1 else ""
        notes.append(Note("W0130", f"ezdxf, reading `{name}`, said: \"{first}\"{more}",
                          "the file was read as ezdxf repaired it: check the import, or save "
                          "the drawing again from its program"))
    # what was seen and why each kind was left out: the message of an empty import
    kinds: dict = {}
    for (t, ly), n in seen.items():
        kinds.setdefault(t, {})[ly] = n
    held = ", ".join(f"{sum(by.values())} {t} ({_layers_text(by)})"
                     for t, by in sorted(kinds.items()))
    why = "; ".join(f"{sum(by.values())} {kind}: {reason}"
                    for (kind, reason, _c), by in sorted(skipped.items()))
    d.seen = (f"it holds {held}" if held else "it holds no drawable entities") + \
        (f", left out: {why}" if why else "")
    return d


def _dxf_rgb(e, aci: int) -> tuple | None:
    """The RGB colour of DXF entity ``e``: its true colour (group 420), else that of its ACI
    ``aci`` (7, white on a dark screen, black on paper: black)."""
    try:
        tc = e.dxf.get("true_color", None)
        if tc is not None:
            return ((tc >> 16) & 255, (tc >> 8) & 255, tc & 255)
        if aci in (0, 7, 256):
            return (0, 0, 0)
        from ezdxf.colors import aci2rgb
        return tuple(aci2rgb(aci))
    except Exception:
        return None


# TEXT halign (0 left, 1 center, 2 right; 3-5 aligned/middle/fit: centred) and valign
# (0 baseline, 1 bottom, 2 middle, 3 top); MTEXT attachment 1-9 (top/middle/bottom x
# left/center/right): as Text's anchor and valign
_HALIGN = {0: "start", 1: "middle", 2: "end", 3: "middle", 4: "middle", 5: "middle"}
_VALIGN = {0: "baseline", 1: "bottom", 2: "middle", 3: "top"}


def _dxf_text(e, t: str, P, scale: float) -> list:
    """The lines of a TEXT or MTEXT entity as ``(text, position, height, rotation, anchor,
    valign)`` in mm and radians: the insertion (or alignment) point, the height as the cap
    height, MTEXT's lines one below the other (5/3 of the height apart, times its line
    spacing factor)."""
    import math as m
    if t == "TEXT":
        text = e.dxf.get("text", "")
        h = float(e.dxf.get("height", 2.5)) * scale
        rot = m.radians(float(e.dxf.get("rotation", 0.0)))
        ha, va = int(e.dxf.get("halign", 0)), int(e.dxf.get("valign", 0))
        at = e.dxf.insert if (ha, va) == (0, 0) or not e.dxf.hasattr("align_point") \
            else e.dxf.align_point
        return [(text, P(at), h, rot, _HALIGN.get(ha, "start"), _VALIGN.get(va, "baseline"))] \
            if text.strip() else []
    try:
        lines = e.plain_text().splitlines()
    except Exception:
        lines = [e.text]
    h = float(e.dxf.get("char_height", 2.5)) * scale
    try:
        rot = m.radians(float(e.get_rotation()))
    except Exception:
        rot = m.radians(float(e.dxf.get("rotation", 0.0)))
    ap = int(e.dxf.get("attachment_point", 1))
    anchor = ("start", "middle", "end")[(ap - 1) % 3]
    valign = ("top", "middle", "bottom")[(ap - 1) // 3] if len(lines) == 1 else "top"
    step = 5 / 3 * h * float(e.dxf.get("line_spacing_factor", 1.0))
    x0, y0 = P(e.dxf.insert)
    out = []
    for i, line in enumerate(lines):
        if line.strip():
            out.append((line, (x0 + m.sin(rot) * step * i, y0 - m.cos(rot) * step * i), h,
                        rot, anchor, valign))
    return out


def _fast_dxf(data: bytes):
    """An ASCII DXF read by ezdxf's normal loader (several times faster than its recover
    mode), or None when that fails or the file is binary."""
    import ezdxf
    if data.startswith(b"AutoCAD Binary DXF"):
        return None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        text = data.decode("cp1252", errors="replace")
    try:
        return ezdxf.read(io.StringIO(text))
    except Exception:
        return None


class _Skip(Exception):
    """An entity left out: ``what`` (SVG: its kind; DXF: the reason), ``kind`` (DXF: the
    entity type when not the entity's own) and ``cls``, the class of the reason (``plane``,
    ``number``, ``exact``, ``text``: DXF notes are grouped and given a fix by it)."""

    def __init__(self, what: str, kind: str | None = None, cls: str = "exact") -> None:
        self.what, self.kind, self.cls = what, kind, cls


def _skip_notes(skipped: dict, notes: list, name: str) -> None:
    for what, n in sorted(skipped.items()):
        if what in ("TEXT", "MTEXT", "text"):
            notes.append(Note("W0130", f"{n} {what} {'entity' if n == 1 else 'entities'} of "
                                       f"`{name}` skipped: text is not imported",
                              "write the text with Text(...) in a `drawing`"))
        else:
            notes.append(Note("W0130", f"{n} {what} {'entity' if n == 1 else 'entities'} of "
                                       f"`{name}` skipped: no exact form here",
                              "convert it to lines, arcs or splines in the drawing program, "
                              "or select other layers"))


def _dxf_spline(e, P) -> Spline:
    bs = e.construction_tool()
    if bs.is_rational:
        w = list(bs.weights())
        if max(w) - min(w) > 1e-12 * max(w):
            raise _Skip("rational: no exact form here")
    deg = bs.degree
    if deg > 3:
        raise _Skip(f"degree {deg}: no exact form here")
    knots = list(bs.knots())
    spans = []
    for ctrl in bs.bezier_decomposition():
        pts = [P(v) for v in ctrl]
        if deg == 1:
            a, b = pts
            pts = [a, _lerp(a, b, 1 / 3), _lerp(a, b, 2 / 3), b]
        elif deg == 2:
            a, b, c = pts
            pts = [a, _lerp(a, b, 2 / 3), _lerp(c, b, 2 / 3), c]
        spans.append(pts)
    distinct = []
    for k in knots[deg:len(knots) - deg]:
        if not distinct or k - distinct[-1] > 1e-15 * max(1.0, abs(k)):
            distinct.append(k)
    steps = [b - a for a, b in zip(distinct, distinct[1:])]
    if len(steps) != len(spans) or min(steps, default=0) <= 0:
        steps = None
    return bezier_spline(spans, steps)


def _lerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t)


# ------------------------------------------------------------------ SVG
def _read_svg(data: bytes, name: str, layer, color, ident, unit: str | None) -> Drawing:
    import svgelements as S
    try:
        svg = S.SVG.parse(io.BytesIO(data), reify=True, ppi=96.0)
    except Exception as ex:
        raise DrawingError("E0130", f"`{name}` is not a readable SVG file ({type(ex).__name__})",
                           "save it as plain SVG") from None
    notes: list[Note] = []
    # svgelements gives px (its mm-to-px factor is rounded): undo its viewBox scale k (px per
    # user unit) and apply the exact mm per user unit from the width attribute and viewBox
    vb = getattr(svg, "viewbox", None)
    k = (float(svg.width) / vb.width) if vb is not None and vb.width and svg.width else 1.0
    if unit is not None:
        mm_per_user = UNIT_MM[unit]
    else:
        unit = "mm"
        mm_per_user = _css_mm(svg.values.get("width"), vb.width if vb is not None else None)
        if mm_per_user is None:
            mm_per_user = k * 25.4 / 96
    scale = mm_per_user / k
    roots = [svg]
    for sel, what in ((ident, "id"), (layer, "layer")):
        if sel is None:
            continue
        wanted = [sel] if isinstance(sel, str) else list(sel)
        found = []
        for w in wanted:
            el = svg.get_element_by_id(w)
            if el is None:
                for g in svg.elements(lambda x: isinstance(x, S.Group)):
                    if w in (g.values.get("inkscape:label"), g.values.get(
                            "{http://www.inkscape.org/namespaces/inkscape}label"), g.id):
                        el = g
                        break
            if el is None:
                ids = sorted({x.id for x in svg.elements() if getattr(x, "id", None)})
                from ..diagnostics import did_you_mean
                sugg = did_you_mean(w, ids)
                raise DrawingError("E0132", f"`{name}` has no element or group with {what} "
                                            f"`{w}`",
                                   ("did you mean " + ", ".join(f"`{s}`" for s in sugg) + "?")
                                   if sugg else "ids: " + ", ".join(ids)[:300])
            found.append(el)
        roots = found
    pieces, loops, circles, ellipses = [], [], [], []
    texts: list = []
    lost_text: list = []            # "`the words` (why)", each a text not written
    skipped: dict[str, int] = {}
    count = 0

    def P(p):
        return (_mm(float(p[0]) * scale), _mm(-float(p[1]) * scale))

    def colour_ok(el) -> bool:
        if color is None:
            return True
        want = {c.lower() for c in ([color] if isinstance(color, str) else color)}
        have = set()
        for attr in ("stroke", "fill"):
            v = getattr(el, attr, None)
            if v is not None and getattr(v, "value", None) is not None:
                have.add(S.Color(v).hex.lower()[:7])
        return bool({S.Color(w).hex.lower()[:7] for w in want} & have)

    opts = _OPTS.get()

    def names_of(g) -> list:
        return [v for v in (getattr(g, "id", None), g.values.get("inkscape:label"), g.values.get(
            "{http://www.inkscape.org/namespaces/inkscape}label")) if v]

    def walk(node, names):
        """The shapes under ``node`` with the names (ids, Inkscape labels) of the groups
        they are in."""
        yield node, names
        if isinstance(node, (S.Group, S.Use)):
            inner = names + names_of(node)
            for ch in node:
                yield from walk(ch, inner)

    seen = set()
    for root in roots:
        for el, names in walk(root, []):
            if id(el) in seen:
                continue
            seen.add(id(el))
            if opts.deadline is not None and len(seen) % 512 == 0:
                opts.deadline.check("reading the drawing")
            if opts.keep is not None and isinstance(el, (S.Shape, S.Text)):
                c = getattr(el, "stroke", None)
                if c is None or getattr(c, "value", None) is None:
                    c = getattr(el, "fill", None)
                rgb = (c.red, c.green, c.blue) if c is not None and \
                    getattr(c, "value", None) is not None else None
                if not opts.keep(names + names_of(el), rgb, None):
                    continue
            if isinstance(el, S.Text):
                if el.values.get("visibility") in ("hidden", "collapse") or \
                        el.values.get("display") == "none" or not colour_ok(el):
                    continue
                got = _svg_text(el, P, scale)
                if isinstance(got, str):
                    lost_text.append(got)
                elif got is not None:
                    texts.append(got)
                continue
            if not isinstance(el, S.Shape):
                continue
            if el.values.get("visibility") in ("hidden", "collapse") or \
                    el.values.get("display") == "none":
                continue
            if not colour_ok(el):
                continue
            if isinstance(el, (S.Polyline, S.Polygon)) and isinstance(
                    el.values.get("points"), str) and _path_data_error(
                    el.values["points"].replace("M", "?").replace("m", "?")) is not None:
                continue        # svgelements would pair the numbers after it wrongly: noted
            count += 1
            if count > opts.max_shapes:
                raise DrawingError("E0130", f"`{name}` has more than {opts.max_shapes} shapes",
                                   "select fewer with id= or split the drawing")
            try:
                _svg_element(S, el, P, scale, pieces, loops, circles, ellipses, skipped)
            except _OutOfRange as ex:
                tag = type(el).__name__.lower()
                ident_ = getattr(el, "id", None)
                raise _range_error(ex, f"<{tag}>" + (f" (id `{ident_}`)" if ident_ else ""),
                                   name) from None
    _skip_notes(skipped, notes, name)
    if lost_text:
        n = len(lost_text)
        notes.append(Note("W0130", f"{n} text{'s' if n != 1 else ''} of `{name}` not "
                                   f"imported: " + "; ".join(lost_text[:8])
                                   + (f"; and {n - 8} more" if n > 8 else ""),
                          "write them with Text(...) in a `drawing` of the part"))
    d = _finish(pieces, loops, circles, ellipses, notes, unit, name)
    d.texts = texts
    return d


# SVG text-anchor and dominant-baseline as Text's anchor and valign (Boxes.py writes
# text-anchor="left", which CSS does not know, for the start)
_SVG_ANCHOR = {"start": "start", "left": "start", "middle": "middle", "center": "middle",
               "end": "end", "right": "end"}
_SVG_BASELINE = {"hanging": "top", "text-before-edge": "top", "middle": "middle",
                 "central": "middle", "text-after-edge": "bottom", "ideographic": "bottom",
                 "alphabetic": "baseline", "auto": "baseline", "baseline": "baseline"}
CAP_HEIGHT_EM = 0.7      # the cap height of a sans-serif font in em (Helvetica, Arial 0.72)


def _svg_text(el, P, scale: float):
    """An SVG ``<text>`` as ``(text, position mm, cap height mm, rotation rad, anchor,
    valign)`` (:class:`Drawing`'s ``texts``), a string saying why it is not written (a
    mirrored or skewed transform, no size), or None when it has no words.  Its size is
    its ``font-size`` times :data:`CAP_HEIGHT_EM` (Text's size is the cap height: the
    single-stroke font stands in for the file's font, so the words and where they stand
    come through, not the letter shapes); ``text-anchor`` and ``dominant-baseline`` give
    ``anchor`` and ``valign`` (:data:`_SVG_ANCHOR`, :data:`_SVG_BASELINE`)."""
    words = " ".join((el.text or "").split())
    if not words:
        return None
    shown = words if len(words) <= 40 else words[:37] + "..."
    m = el.transform
    a, b, c, d = float(m.a), float(m.b), float(m.c), float(m.d)
    det = a * d - b * c
    if not all(math.isfinite(v) for v in (a, b, c, d)) or abs(det) < 1e-12:
        return f"`{shown}` (its transform has no size)"
    if det < 0:
        return f"`{shown}` (mirrored)"
    sx, sy = math.hypot(a, b), math.hypot(c, d)
    if abs(a * c + b * d) > 1e-9 * sx * sy or abs(sx - sy) > 1e-9 * max(sx, sy):
        return f"`{shown}` (skewed or stretched)"
    try:
        fs = float(el.font_size)
    except (TypeError, ValueError):
        fs = float("nan")
    if not math.isfinite(fs) or fs <= 0:
        return f"`{shown}` (no font size)"
    x, y = float(el.x or 0.0), float(el.y or 0.0)
    at = P(m.point_in_matrix_space((x, y)))
    size = _mm(fs * sx * scale * CAP_HEIGHT_EM, "a text height")
    rot = -math.atan2(b, a)          # the SVG's y axis points down
    anchor = _SVG_ANCHOR.get(str(el.values.get("text-anchor", "start")).strip().lower(),
                             "start")
    valign = _SVG_BASELINE.get(str(el.values.get("dominant-baseline", "auto")).strip().lower(),
                               "baseline")
    return (words, at, size, rot, anchor, valign)


_PATH_TOKEN = None


def _path_data_error(d: str) -> tuple[int, str] | None:
    """Where the SVG path data ``d`` stops being readable (SVG 1.1 section 8.3.9: command
    letters, numbers, whitespace and commas): ``(character offset, the word there)``, or
    None.  svgelements stops reading a path at such a word (``inf``, ``nan``, ``1,5e``) and
    drops the rest of it without a word; the caller counts it (``W0130``)."""
    import re
    global _PATH_TOKEN
    if _PATH_TOKEN is None:
        _PATH_TOKEN = re.compile(r"[\s,]+|[MmZzLlHhVvCcSsQqTtAa]|"
                                 r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
    i, n = 0, len(d)
    while i < n:
        m = _PATH_TOKEN.match(d, i)
        if m is None or m.end() == i:
            word = re.match(r"[^\s,]{1,20}", d[i:])
            return i, word.group(0) if word else d[i:i + 1]
        i = m.end()
    return None


def _svg_prescan(data: bytes, name: str, limit: int) -> list:
    """Count what the SVG ``data`` draws before svgelements reads it, with the standard
    library's expat parser (no entity expansion, no network): a file that declares XML
    entities (``<!ENTITY``: the "billion laughs") is refused, and each ``<use>`` counts as
    the elements it copies, nested ``<use>`` multiplied out, so a few kilobytes of nested
    references that would expand to millions of shapes are refused (``E0304``, at the
    ``<use>`` that copies the most) before they are expanded; more than ``limit`` elements
    drawn is ``E0130``.  A file expat cannot parse is left to svgelements (its message).

    Returns the paths (``d``) and polylines or polygons (``points``) whose data holds a word
    that is no number or command (:func:`_path_data_error`: ``inf``, ``nan``): ``(tag, id or
    None, line, offset, word, characters left out)`` each, for the ``W0130`` note of
    :func:`read_drawing`."""
    import xml.parsers.expat as X
    tags: list = []         # per element: local tag, id, href, line
    kids: list = []
    stack: list = []
    ids: dict = {}
    bad_data: list = []

    class _Refused(Exception):
        pass

    def start(tag, attrs):
        local = tag.rsplit("}", 1)[-1].rsplit(":", 1)[-1]
        href = attrs.get("href") or attrs.get("http://www.w3.org/1999/xlink}href") or \
            attrs.get("xlink:href")
        i = len(tags)
        tags.append((local, attrs.get("id"), href, p.CurrentLineNumber))
        kids.append([])
        if stack:
            kids[stack[-1]].append(i)
        if attrs.get("id") is not None:
            ids.setdefault(attrs["id"], i)
        data_attr = "d" if local == "path" else "points" if local in ("polyline", "polygon") \
            else None
        if data_attr is not None and attrs.get(data_attr):
            text = attrs[data_attr]
            err = _path_data_error(text if data_attr == "d" else
                                   text.replace("M", "?").replace("m", "?"))
            if err is not None:
                bad_data.append((local, attrs.get("id"), p.CurrentLineNumber, err[0], err[1],
                                 len(text) - err[0]))
        stack.append(i)
        if len(stack) > 500:
            raise DrawingError("E0130", f"`{name}` nests its elements more than 500 deep",
                               "save it again as plain SVG with fewer nested groups",
                               p.CurrentLineNumber)
        if len(tags) > 50 * limit + 1000:
            raise _Refused()

    def end(tag):
        stack.pop()

    def entity(*a):
        raise DrawingError("E0130", f"`{name}` declares XML entities (<!ENTITY ...>): not read",
                           "save it again as plain SVG (Inkscape: Save As, Plain SVG)",
                           p.CurrentLineNumber)
    p = X.ParserCreate(namespace_separator="}")
    p.StartElementHandler, p.EndElementHandler = start, end
    p.EntityDeclHandler = entity
    try:
        p.Parse(data, True)
    except DrawingError:
        raise
    except _Refused:
        raise DrawingError("E0130", f"`{name}` has more than {limit} shapes",
                           "select fewer with id= or split the drawing") from None
    except Exception:
        return []               # not XML: svgelements says so
    cap = 10 * limit + 1
    weight: dict = {}
    busy: set = set()

    def w(i: int) -> int:
        if i in weight:
            return weight[i]
        if i in busy:
            local, ident, _href, line = tags[i]
            raise DrawingError("E0130", f"<{local}>" + (f" (id `{ident}`)" if ident else "")
                               + f" of `{name}` refers to itself through <use>",
                               "remove the circular <use> reference", line)
        busy.add(i)
        local, _ident, href, _line = tags[i]
        n = 1 if local in ("path", "rect", "circle", "ellipse", "line", "polyline",
                           "polygon", "text") else 0
        for k in kids[i]:
            n = min(cap, n + w(k))
        if local == "use" and href and href.startswith("#") and href[1:] in ids:
            n = min(cap, n + w(ids[href[1:]]))
        busy.discard(i)
        weight[i] = n
        return n
    import sys
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, 20000))
    try:
        total = w(0) if tags else 0
    except RecursionError:
        raise DrawingError("E0130", f"`{name}` nests its elements too deeply",
                           "save it again as plain SVG with fewer nested groups") from None
    finally:
        sys.setrecursionlimit(old)
    if total > limit:
        uses = [i for i, t in enumerate(tags) if t[0] == "use"]
        if uses:
            i = max(uses, key=lambda i: (weight.get(i, 0), -i))
            local, ident, href, line = tags[i]
            more = "more than " if weight[i] >= cap else ""
            raise DrawingError("E0304", f"<use>" + (f" (id `{ident}`)" if ident else "")
                               + f" of `{name}` copies `{href}` into {more}{weight[i]} shapes "
                                 f"(nested <use> references): the drawing would hold more than "
                                 f"the {limit} shapes an import may read",
                               "replace the nested <use> copies by the shapes they copy "
                               "(Inkscape: Edit > Clone > Unlink Clone), or draw fewer",
                               line)
        raise DrawingError("E0130", f"`{name}` has more than {limit} shapes",
                           "select fewer with id= or split the drawing")
    return bad_data


def _bad_data_note(bad: list, name: str) -> Note:
    """The ``W0130`` note of the paths whose data stops at a word that is no number
    (:func:`_svg_prescan`), each with its place."""
    where = "; ".join(f"<{tag}>" + (f" (id `{i}`)" if i else "") + f" at line {ln}, "
                      f"character {off + 1}: `{w}` (" + (f"{left} characters left out"
                                                         if tag == "path" else
                                                         "the whole shape left out") + ")"
                      for tag, i, ln, off, w, left in bad[:5])
    more = f"; and {len(bad) - 5} more" if len(bad) > 5 else ""
    n = len(bad)
    return Note("W0130", f"{n} path{'s' if n != 1 else ''} of `{name}` "
                         f"{'holds' if n == 1 else 'hold'} a number that cannot be read: a "
                         f"path's data is read up to it: {where}{more}",
                "write a finite number there (inf and nan are no coordinates), or save the "
                "drawing again from its program")


def _svg_element(S, el, P, scale, pieces, loops, circles, ellipses, skipped) -> None:
    """Read the shape ``el`` into the lists; its numbers checked (:func:`_check_made`: raises
    :class:`_OutOfRange`)."""
    made = (len(pieces), len(loops), len(circles), len(ellipses))
    if isinstance(el, (S.Circle, S.Ellipse)) and not isinstance(el, S.Path):
        # the implicit values: centre, semi-axes and turn after the element's
        # transform (a turned ellipse keeps its own cx, cy, rx, ry and a matrix)
        c = P(el.implicit_center)
        rx = _mm(float(el.implicit_rx) * scale, "a radius")
        ry = _mm(float(el.implicit_ry) * scale, "a radius")
        rot = -_finite(el.rotation, "an angle") if el.rotation else 0.0
        if rx <= 0 or ry <= 0:
            return
        if abs(rx - ry) <= 1e-12 * max(rx, ry):
            circles.append(Circle(c, rx))
        else:
            ellipses.append((c[0], c[1], rx, ry, rot))
    else:
        _svg_path(S, S.Path(el), P, pieces, loops, skipped)
    _check_made(pieces[made[0]:] + [seg for seg, _ in loops[made[1]:]] + circles[made[2]:]
                + ellipses[made[3]:])


def _css_mm(width, vb_width) -> float | None:
    """Millimetres per user unit from the root ``width`` (a CSS length: mm, cm, in, pt, pc,
    px or a bare number, px) over the ``viewBox`` width (none: one user unit is one px)."""
    import re
    if width is None:
        return (25.4 / 96) if vb_width is None else None
    m = re.fullmatch(r"\s*([0-9.eE+-]+)\s*(mm|cm|in|pt|pc|px|)\s*", str(width))
    if not m:
        return None
    try:
        w = float(m.group(1))
    except ValueError:
        return None
    per = {"mm": 1.0, "cm": 10.0, "in": 25.4, "pt": 25.4 / 72, "pc": 25.4 / 6, "px": 25.4 / 96,
           "": 25.4 / 96}[m.group(2)]
    return w * per / vb_width if vb_width else per


def _svg_path(S, path, P, pieces, loops, skipped) -> None:
    cur: list = []

    def flush(closed: bool) -> None:
        nonlocal cur
        if cur:
            if closed or math.dist(cur[0].start, cur[-1].end) <= JOIN_TOL:
                loops.append((cur, "path"))
            else:
                pieces.append(cur)
        cur = []

    for seg in path:
        if isinstance(seg, S.Move):
            flush(False)
            continue
        if isinstance(seg, S.Close):
            if cur and math.dist(cur[-1].end, cur[0].start) > JOIN_TOL:
                cur.append(Line(cur[-1].end, cur[0].start))
            flush(True)
            continue
        a, b = P(seg.start), P(seg.end)
        if isinstance(seg, S.Line):
            cur.append(Line(a, b))          # one of zero length: dropped and counted later
        elif isinstance(seg, S.CubicBezier):
            cur.append(bezier_spline([[a, P(seg.control1), P(seg.control2), b]]))
        elif isinstance(seg, S.QuadraticBezier):
            c = P(seg.control)
            cur.append(bezier_spline([[a, _lerp(a, c, 2 / 3), _lerp(b, c, 2 / 3), b]]))
        elif isinstance(seg, S.Arc):
            if not seg.is_circular():
                # an elliptical arc: its ellipse in the drawing's frame (P maps the user
                # units to mm and turns y over: the x axis's image gives the rotation) and
                # the exact arc from its start through its middle to its end
                c = P(seg.center)
                rot = float(seg.get_rotation())
                rx, ry = float(seg.rx), float(seg.ry)
                ux = P((seg.center.x + rx * math.cos(rot), seg.center.y + rx * math.sin(rot)))
                vy = P((seg.center.x - ry * math.sin(rot), seg.center.y + ry * math.cos(rot)))
                rxm, rym = math.dist(c, ux), math.dist(c, vy)
                if rxm <= 1e-12 or rym <= 1e-12 or math.dist(a, b) <= 1e-12:
                    skipped["elliptical arc"] = skipped.get("elliptical arc", 0) + 1
                    continue
                cur.append(elliptic_arc(c, rxm, rym, math.atan2(ux[1] - c[1], ux[0] - c[0]),
                                        a, P(seg.point(0.5)), b))
                continue
            c = P(seg.center)
            sweep = -float(seg.sweep)          # the y axis turns over
            cur.append(_arc_from(a, b, c, sweep))
        else:
            skipped[type(seg).__name__] = skipped.get(type(seg).__name__, 0) + 1
    flush(False)


# ------------------------------------------------------------------ roles
# roles="laser": the colours Boxes.py (boxes/Color.py: OUTER_CUT black, INNER_CUT blue,
# ANNOTATIONS red, ETCHING green, ETCHING_DEEP cyan) and the laser programs that read its
# SVGs use (docs/import.md)
ROLE_PRESETS = {"laser": {"cut": ["#000000", "#0000ff"], "engrave": ["#00ff00", "#00ffff"],
                          "ignore": ["#ff0000"]}}
ROLES = ("cut", "engrave", "ignore")


def _colour(v):
    """``v`` (a CSS colour name, ``#rgb``/``#rrggbb``, ``rgb(...)``; or an ACI number) as
    ``("rgb", (r, g, b))`` or ``("aci", n)``; None when ``v`` is no colour (a layer name)."""
    if isinstance(v, bool):
        return None
    if isinstance(v, (int, float)) and float(v).is_integer():
        return ("aci", int(v))
    if not isinstance(v, str):
        return None
    import re
    import svgelements as S
    t = v.strip().lower()
    if re.fullmatch(r"#[0-9a-f]{3}|#[0-9a-f]{6}", t) or re.fullmatch(r"rgb\(.*\)", t) or \
            t == "black" or S.Color.parse_color_lookup(t) != 255:
        c = S.Color(t)
        return ("rgb", (c.red, c.green, c.blue))
    return None


def _role_of(cut, engrave, ignore, roles, where: str = ""):
    """The role of a shape from ``cut=``, ``engrave=``, ``ignore=`` (each a layer name, a
    colour or an ACI number, or a list of them) and the preset ``roles=``: a function
    ``(layer names, rgb, aci) -> "cut" | "engrave" | "ignore"``, or None when none is
    given (everything is cut, as before).  A shape no role names is cut when ``cut=`` is not
    given, else ignored.  Raises :class:`DrawingError` (``E0130``) for an unknown preset."""
    given = {"cut": cut, "engrave": engrave, "ignore": ignore}
    if roles is not None:
        if not isinstance(roles, str) or roles.lower() not in ROLE_PRESETS:
            raise DrawingError("E0130", f"unknown roles preset {roles!r}",
                               "roles=\"laser\" (Boxes.py's colours: black and blue cut, "
                               "green engrave, red annotations ignored), or give cut=, "
                               "engrave= and ignore= by layer or colour")
        for k, v in ROLE_PRESETS[roles.lower()].items():
            if given[k] is None:
                given[k] = v
    if all(v is None for v in given.values()):
        return None
    sel = {}
    for k, v in given.items():
        vs = [] if v is None else [v] if isinstance(v, (str, int, float)) else list(v)
        sel[k] = [(str(x).lower(), _colour(x)) for x in vs]

    def close(a, b) -> bool:
        return a is not None and b is not None and all(abs(x - y) <= 2 for x, y in zip(a, b))

    def role(layers, rgb, aci) -> str:
        low = [n.lower() for n in layers]
        for k in ("ignore", "engrave", "cut"):
            for text, col in sel[k]:
                if text in low:
                    return k
                if col is not None and col[0] == "aci" and aci is not None and col[1] == aci:
                    return k
                if col is not None and col[0] == "rgb" and close(col[1], rgb):
                    return k
                if col is not None and col[0] == "aci" and aci is None and rgb is not None:
                    from ezdxf.colors import aci2rgb
                    if close(tuple(aci2rgb(col[1])) if col[1] not in (0, 7) else (0, 0, 0),
                             rgb):
                        return k
        return "cut" if given["cut"] is None else "ignore"
    return role


def _colour_name(rgb) -> str:
    if rgb is None:
        return "no colour"
    names = {(0, 0, 0): "black", (255, 0, 0): "red", (0, 0, 255): "blue", (0, 255, 0): "green",
             (255, 255, 255): "white"}
    return names.get(tuple(rgb), "#%02x%02x%02x" % tuple(rgb))


# ------------------------------------------------------------------ entry
def read_drawing(data: bytes, name: str, layer=None, color=None, ident=None,
                 unit: str | None = None, keep_text: bool = False,
                 close_tolerance: float | None = None, cut=None, engrave=None, ignore=None,
                 roles=None, deadline=None, max_shapes: int | None = None) -> Drawing:
    """The drawing in ``data`` (``name``: its path as written, for messages; ``.dxf`` or
    ``.svg`` decides the reader).  ``layer``: DXF layer name(s) or SVG group id / Inkscape
    layer label(s); ``color``: DXF ACI number(s) or SVG colour(s); ``ident``: SVG element or
    group id(s); ``unit``: overrides the file's unit; ``keep_text``: a selection that holds
    only DXF text is not empty (``aidl import`` writes it).  ``close_tolerance``: chains
    whose ends meet within it (mm; default :data:`CLOSE_TOL`) are closed exactly.
    ``cut``/``engrave``/``ignore``/``roles``: the role of each shape by layer or colour
    (:func:`_role_of`): what is cut is the drawing, what is engraved its ``engrave``
    drawing, the rest left out (counted in a note).  ``deadline``: a
    :class:`~aidl_lang.limits.Deadline` the reading is held to (``E0304``, raised as
    :class:`~aidl_lang.limits.OutOfBudget`); ``max_shapes``: the shape limit (default
    :data:`MAX_ENTITIES`).  Raises :class:`DrawingError`."""
    if unit is not None and unit not in UNIT_MM:
        raise DrawingError("E0130", f"unknown unit `{unit}`",
                           "units: " + ", ".join(UNIT_MM))
    tol = CLOSE_TOL if close_tolerance is None else close_tolerance
    try:
        tol = float(tol)
    except (TypeError, ValueError):
        tol = float("nan")
    if not 0 <= tol <= 10:
        raise DrawingError("E0130", f"close_tolerance must be between 0 and 10 mm, not "
                                    f"{close_tolerance!r}",
                           f"the default is {CLOSE_TOL:g} mm; 0 closes only what meets")
    bad_data = []
    if name.lower().endswith(".svg"):
        bad_data = _svg_prescan(data, name, max_shapes or MAX_ENTITIES)
    role = _role_of(cut, engrave, ignore, roles)
    base = _Options(tol, deadline, None, max_shapes or MAX_ENTITIES)
    if role is None:
        token = _OPTS.set(base)
        try:
            d = _read_one(data, name, layer, color, ident, unit, keep_text)
        finally:
            _OPTS.reset(token)
        if bad_data:
            d.notes.append(_bad_data_note(bad_data, name))
        return d
    ignored: dict = {}
    # what `ignore=` itself names is left out as asked, unsaid (a warning on a design exactly
    # as meant is noise a model obeys); what a preset or an unnamed colour leaves out is counted
    named = _role_of(None, None, ignore, None) if ignore is not None else None

    def keep_for(want):
        def keep(layers, rgb, aci) -> bool:
            r = role(layers, rgb, aci)
            if want == "cut" and r == "ignore" and (
                    named is None or named(layers, rgb, aci) != "ignore"):
                what = (f"layer `{layers[0]}`" if layers and name.lower().endswith(".dxf")
                        else _colour_name(rgb))
                ignored[what] = ignored.get(what, 0) + 1
            return r == want
        return keep
    out = []
    for want in ("cut", "engrave"):
        token = _OPTS.set(_Options(tol, deadline, keep_for(want), base.max_shapes))
        try:
            out.append(_read_one(data, name, layer, color, ident, unit, keep_text,
                                 allow_empty=True))
        finally:
            _OPTS.reset(token)
    d, e = out
    d.paths_cut = True
    if not e.empty or e.texts:
        d.engrave = e
        d.notes += [n for n in e.notes if n.message not in {m.message for m in d.notes}]
    if bad_data:
        d.notes.append(_bad_data_note(bad_data, name))
    if ignored:
        n = sum(ignored.values())
        d.notes.append(Note("W0130", f"{n} shape{'s' if n > 1 else ''} of `{name}` left out by "
                                     f"their role: " + ", ".join(
                                         f"{k} ({v})" for k, v in sorted(ignored.items())),
                            "give cut=, engrave= or ignore= (by layer or colour) to choose"))
    if d.empty and d.engrave is None and not (keep_text and d.texts):
        raise DrawingError("E0132", f"nothing to cut or engrave in `{name}` with these roles",
                           "name the layers or colours that hold the parts with cut= (or "
                           "roles=\"laser\": black and blue cut, green engraved)")
    return d


def _read_one(data: bytes, name: str, layer, color, ident, unit, keep_text,
              allow_empty: bool = False) -> Drawing:
    low = name.lower()
    if low.endswith(".dxf"):
        if ident is not None:
            raise DrawingError("E0130", "id= selects SVG elements; a DXF selects by layer= "
                                        "and color=", "give layer= for a DXF")
        d = _read_dxf(data, name, layer, color, unit)
    elif low.endswith(".svg"):
        d = _read_svg(data, name, layer, color, ident, unit)
    else:
        raise DrawingError("E0130", f"`{name}` is neither a .dxf nor a .svg file",
                           "give a DXF or SVG drawing")
    if allow_empty:
        return d
    if d.empty and not (keep_text and d.texts):      # `aidl import` keeps a text layer
        what = (f" on layer {layer!r}" if layer is not None else "") + \
               (f" with id {ident!r}" if ident is not None else "") + \
               (f" of colour {color!r}" if color is not None else "")
        raise DrawingError("E0132", f"nothing to import from `{name}`{what}"
                           + (f": {d.seen}" if d.seen else ""),
                           "select a layer, colour or id that holds lines, arcs, circles or "
                           "splines" + ("; or fix what was left out in the drawing program"
                                        if d.seen and "left out" in d.seen else ""))
    return d
