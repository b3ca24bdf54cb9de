"""The unit of a drawing as ``aidl import`` writes it (docs/import.md, "Units").

In: :class:`~.model.Drawing` s read in millimetres.  Out: whether a drawing that gives no
unit has the numbers of an inch drawing (:func:`fits_inches`, said in its ``W0130`` by
:func:`say_inches`), the unit its program is written in (:func:`written_unit`), and its
structures scaled into that unit (:func:`scaled`, :func:`in_unit`: ``units in`` with the
file's inch numbers, not their millimetres) once they are made in mm."""
from __future__ import annotations

import contextvars
from dataclasses import replace

from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Spline
from ...geometry.shapes.ellipse import EllipseCurve
from ...geometry.shapes.spline import CubicSpline
from ..model import Drawing, Note, Outline, Path

# the unit the program is written in (`units in` for a drawing read in inches: its numbers
# are the file's, in_unit); set by program.import_drawing around its writer
UNIT: "contextvars.ContextVar[str]" = contextvars.ContextVar("aidl_import_unit", default="mm")
INCH_BOX = 50.0         # a drawing whose larger side is above this many units is no inch one
NO_UNIT = "gives no unit ("     # the reader's W0130 of a drawing without a unit (dxf._dxf_unit)


def _whole(v: float, step: float) -> bool:
    """Whether ``v`` is a whole multiple of ``step`` (to 1e-6 of a step)."""
    q = v / step
    return abs(q - round(q)) <= 1e-6


def _sizes(drawings) -> tuple[list[float], tuple]:
    """The distinct sizes of ``drawings`` (file units): every circle's diameter and every
    arc's radius; and the box of all of them ``(x0, y0, x1, y1)`` (None when empty)."""
    sizes, boxes = set(), []
    for d in drawings:
        b = d.box()
        if b is not None:
            boxes.append(b)
        for c in d.circles:
            sizes.add(round(2 * c.radius, 9))
        for o in list(d.outlines) + list(d.paths):
            for s in o.segments:
                if isinstance(s, Arc):
                    sizes.add(round(s.radius, 9))
    if not boxes:
        return [], None
    box = (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes),
           max(b[3] for b in boxes))
    return sorted(sizes), box


def fits_inches(drawings) -> tuple[int, int] | None:
    """Whether ``drawings`` (the layers of one drawing read as millimetres because it gives
    no unit) have an inch drawing's numbers: ``(sizes round in inches, sizes)`` when so,
    else None.  The test (docs/import.md, "Units"): the box's larger side is at most
    :data:`INCH_BOX` units (50 mm is a small part, 50 in a large one), and of its sizes (the
    box's width and height, every circle's diameter and arc's radius, each once) more are
    *round in inches* (a multiple of 1/64, or a whole thousandth below 1: ``0.125``,
    ``0.197``) than *round in millimetres* (a multiple of 0.1 of at least 0.5: ``3.2``,
    ``120``), and at least 3; a size may be both (``4``, ``0.5``)."""
    sizes, box = _sizes(drawings)
    if box is None:
        return None
    w, h = box[2] - box[0], box[3] - box[1]
    if max(w, h) > INCH_BOX or max(w, h) <= 0:
        return None
    every = sizes + [round(w, 9), round(h, 9)]
    inch = sum(1 for s in every if s > 0 and (_whole(s, 1 / 64) or (s < 1 and _whole(s, 1e-3))))
    mm = sum(1 for s in every if s >= 0.5 and _whole(s, 0.1))
    return (inch, len(every)) if inch > mm and inch >= 3 else None


def say_inches(notes: list, drawings) -> None:
    """The reader's ``W0130`` of a drawing that gives no unit (in ``notes``) told, when
    :func:`fits_inches` of ``drawings`` says so, that its numbers fit inches, its fix
    ``--units in`` (``units="in"``)."""
    for k, n in enumerate(notes):
        if n.code == "W0130" and NO_UNIT in n.message and "fit inches" not in n.message:
            got = fits_inches(drawings)
            if got is None:
                return
            inch, total = got
            notes[k] = Note("W0130", n.message + f"; but its numbers fit inches better: "
                                                 f"{inch} of its {total} sizes are round in "
                                                 f"inches and it is {_box_text(drawings)} "
                                                 f"(as millimetres, a small part)",
                            "import it with --units in (Drawing2D: units=\"in\") if it was "
                            "drawn in inches; --units mm says it was not")
            return


def _box_text(drawings) -> str:
    _, b = _sizes(drawings)
    return f"{b[2] - b[0]:.6g} x {b[3] - b[1]:.6g} units"


def scaled(d: Drawing, f: float) -> Drawing:
    """``d`` with every length times ``f`` (its pieces, circles, ellipses, texts' places and
    heights, its engraving): a drawing read in mm written in another unit (``f = 1 / 25.4``
    for inches).  Angles are kept."""
    def pt(p):
        return (p[0] * f, p[1] * f)

    def seg(s):
        if isinstance(s, Line):
            return Line(pt(s.start), pt(s.end))
        if isinstance(s, Arc):
            return Arc(pt(s.center), s.radius * f, s.start_angle, s.sweep)
        if isinstance(s, Circle):
            return Circle(pt(s.center), s.radius * f, s.ccw)
        if isinstance(s, Spline):
            c = s.curve
            return Spline(CubicSpline(tuple(pt(p) for p in c.ctrl), tuple(h * f for h in c.h),
                                      c.closed), s.u0, s.u1)
        if isinstance(s, EllipticArc):
            e = s.curve
            return EllipticArc(EllipseCurve(pt(e.center), e.rx * f, e.ry * f, e.rotation),
                               s.start_param, s.sweep)
        raise TypeError(f"no scaling for {type(s).__name__}")
    return replace(
        d, outlines=[Outline([seg(s) for s in o.segments], o.source) for o in d.outlines],
        circles=[seg(c) for c in d.circles],
        ellipses=[(cx * f, cy * f, rx * f, ry * f, rot) for cx, cy, rx, ry, rot in d.ellipses],
        paths=[Path([seg(s) for s in p.segments], p.source,
                    None if p.crossing is None else pt(p.crossing)) for p in d.paths],
        texts=[(t, pt(p), h * f, rot, *rest) for t, p, h, rot, *rest in d.texts],
        engrave=None if d.engrave is None else scaled(d.engrave, f))


def written_unit(drawings) -> tuple[str, float]:
    """The unit a program of ``drawings`` is written in and its millimetres: ``in`` (25.4)
    when the drawing was read in inches (``$INSUNITS`` 1, ``--units in``), else ``mm``."""
    units = {d.unit for d in drawings}
    if units and units <= {"in", "inch"}:
        return "in", 25.4
    return "mm", 1.0


def in_unit(items: list) -> list:
    """The structures ``(kind, name, drawing, ...)`` a writer makes of a drawing's layers
    (in mm), each drawing :func:`scaled` into the unit the program is written in
    (:data:`UNIT`: ``in``, 1 / 25.4; ``mm``: as they are)."""
    from ..model import UNIT_MM
    per = UNIT_MM[UNIT.get()]
    if per == 1.0:
        return items
    return [(kind, name, scaled(d, 1 / per), *rest) for kind, name, d, *rest in items]
