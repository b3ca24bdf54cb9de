"""The exact extent of an output: the bounding box of its lines, arcs and circles computed from
the curves themselves (an arc's box includes each axis extreme its sweep passes), not from
sampled chords.  The SVG page (``--margin 0`` makes it exactly this box) and the DXF header's
``$EXTMIN`` / ``$EXTMAX`` use it."""
from __future__ import annotations

import math

from .part import Arc, Circle, EllipticArc, Line, Output, Spline


def _segment_box(s) -> tuple[float, float, float, float]:
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        return min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)
    if isinstance(s, (Spline, EllipticArc)):
        return s.box()
    cx, cy = s.center
    r = s.radius
    if isinstance(s, Circle) or abs(s.sweep) >= 2 * math.pi:
        return cx - r, cy - r, cx + r, cy + r
    (sx, sy), (ex, ey) = s.start, s.end
    x0, x1 = min(sx, ex), max(sx, ex)
    y0, y1 = min(sy, ey), max(sy, ey)
    lo = s.start_angle
    hi = lo + s.sweep                            # its end angle
    if hi < lo:
        lo, hi = hi, lo
    k = math.ceil(lo / (math.pi / 2))
    while k * math.pi / 2 <= hi:                 # each multiple of 90 degrees the arc passes
        q = k % 4
        if q == 0:
            x1 = cx + r
        elif q == 1:
            y1 = cy + r
        elif q == 2:
            x0 = cx - r
        else:
            y0 = cy - r
        k += 1
    return x0, y0, x1, y1


def extent(output: Output) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) in mm: the exact bounding box of every part loop and engraving stroke
    of ``output``; (0, 0, 1, 1) when it has neither (as :meth:`~.part.Output.bounds`).  An
    output with a fixed :attr:`~.part.Output.page` (a cutting layout's sheet) gives the page."""
    if output.page is not None:
        return tuple(float(v) for v in output.page)
    boxes = [_segment_box(s) for segs in [lp.segments for p in output.parts for lp in p.loops]
             + [st.segments for st in output.engrave] for s in segs]
    if not boxes:
        return (0.0, 0.0, 1.0, 1.0)
    x0, y0, x1, y1 = zip(*boxes)
    return (min(x0), min(y0), max(x1), max(y1))
