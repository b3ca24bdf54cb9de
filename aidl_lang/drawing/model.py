"""The drawing model every reader fills: :class:`Drawing` (outlines, circles, ellipses, open
paths, texts, notes; mm, y up), :class:`Outline`, :class:`Path`, :class:`Note`, and the error
:class:`DrawingError`; with what the DXF and SVG readers share: the units (:data:`UNIT_MM`),
the number checks (:func:`_mm`, :func:`_finite`, :func:`_check_made`; :func:`_range_error`:
``E0130`` naming the entity), the options of one :func:`~.read.read_drawing` call
(:class:`_Options`, in a context variable) and the cubic Bézier spline piece
(:func:`bezier_spline`).  Nothing here reads a file: :mod:`.dxf` and :mod:`.svg` do, and
:mod:`.chain` joins their pieces into outlines and paths."""
from __future__ import annotations

import contextvars
import math
from dataclasses import dataclass, field

from ..geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Loop, Spline
from ..geometry.shapes.spline import CubicSpline
from ..base.limits import MAX_EXTENT

JOIN_TOL = 1e-6          # mm: pieces whose ends are this close chain into one
MAX_ENTITIES = 120_000   # entities (DXF) or shapes (SVG) read from one drawing
CLOSE_TOL = 0.05         # mm: the default closing tolerance (close_tolerance=, --close-tolerance)
GAP_NOTE = 0.5           # mm: an open chain whose ends are this close was probably meant closed
UNIT_MM = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "inch": 25.4, "ft": 304.8,
           "pt": 25.4 / 72, "px": 25.4 / 96}


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


class _Skip(Exception):
    """An entity left out: ``what`` (SVG: its kind; DXF: the reason), ``kind`` (DXF: the
    entity type when not the entity's own) and ``cls``, the class of the reason (``plane``,
    ``number``, ``exact``, ``text``, ``spline``: DXF notes are grouped and given a fix by it);
    ``named``: the note names the entity (a defect of this one, not of its kind)."""

    def __init__(self, what: str, kind: str | None = None, cls: str = "exact",
                 named: bool = False) -> None:
        self.what, self.kind, self.cls, self.named = what, kind, cls, named


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
    # mm: one unit of the last decimal the file writes its numbers to (an SVG whose centres
    # carry 6 decimals in a mm viewBox: 1e-6), 0 when it writes them to a float's own
    # precision; `aidl import --infer` takes what is equal within it as equal (issue 114)
    precision: float = 0.0

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
    """The exact ``(x0, y0, x1, y1)`` of ``segs`` (each segment's ``box()``)."""
    bs = [x.box() for x in segs]
    return (min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
            max(b[3] for b in bs))


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


def _lerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t)


def _plural(n: int, word: str) -> str:
    """``1 entity``, ``2 entities``, ``3 HATCH boundaries``."""
    if n == 1:
        return f"{n} {word}"
    return f"{n} {word[:-1]}ies" if word.endswith("y") else f"{n} {word}s"


@dataclass
class _Options:
    """What :func:`read_drawing` asks of the readers beyond the selection: the closing
    tolerance (mm), the wall-time :class:`~aidl_lang.base.limits.Deadline` (or None), the role
    filter ``keep(layer, rgb, aci)`` (or None: everything), the shape budget, and whether a
    loop that crosses itself is split at its crossings (``split_crossings``: on a cut role,
    where a laser cuts every line) instead of kept as a stroke."""
    close_tol: float = CLOSE_TOL
    deadline: object = None
    keep: object = None
    max_shapes: int = MAX_ENTITIES
    split_crossings: bool = False


_OPTS: "contextvars.ContextVar[_Options]" = contextvars.ContextVar("aidl_drawing_opts",
                                                                  default=_Options())
