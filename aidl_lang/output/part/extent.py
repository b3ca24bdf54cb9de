"""The exact extent of an output: the bounding box of its lines, arcs and circles computed from
the curves themselves (each segment's ``box()``, geometry/shapes/curves.py: an arc's box includes
each axis extreme its sweep passes), not from sampled chords.  The SVG page (``--margin 0``
makes it exactly this box) and the DXF header's ``$EXTMIN`` / ``$EXTMAX`` use it."""
from __future__ import annotations

from .part import Output


def extent(output: Output) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) in mm: the exact bounding box of every part loop and engraving stroke
    of ``output``; (0, 0, 1, 1) when it has neither (as :meth:`~.part.Output.bounds`).  An
    output with a fixed :attr:`~.part.Output.page` (a cutting layout's sheet) gives the page."""
    if output.page is not None:
        return tuple(float(v) for v in output.page)
    boxes = [s.box() for segs in [lp.segments for p in output.parts for lp in p.loops]
             + [st.segments for st in output.engrave] for s in segs]
    if not boxes:
        return (0.0, 0.0, 1.0, 1.0)
    x0, y0, x1, y1 = zip(*boxes)
    return (min(x0), min(y0), max(x1), max(y1))
