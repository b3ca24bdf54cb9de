"""DXF writer (``ezdxf``) for the exact output model (:class:`~.part.Output`).

What laser, waterjet and CNC software imports: a DXF R2010 file in millimetres (header
``$INSUNITS`` = 4, ``$MEASUREMENT`` = 1).  Each closed outline loop is a ``CIRCLE`` when it is
a circle and otherwise a closed ``LWPOLYLINE`` whose arcs are bulges (bulge = tan(sweep / 4);
arcs over 180 degrees are split in two).  Engraving (drawings, text strokes, unclosed curves)
is ``LINE``, ``ARC``, ``CIRCLE`` and ``LWPOLYLINE`` entities.

Layers: ``CUT`` (red) for the outlines of a single part, ``ENGRAVE`` (blue) for engraving; in an
assembly with several parts, each part's outlines are on their own layer ``CUT-<part>``
(see :func:`layer_of`), so each part can be selected, nested or hidden on its own.
"""
from __future__ import annotations

import io
import math

from .part import Arc, Circle, Line, Output, PartOutline

CUT, ENGRAVE = "CUT", "ENGRAVE"
_BAD = '<>/\\":;?*|=`'


def layer_of(part: PartOutline, output: Output) -> str:
    """The DXF layer of a part's outlines: ``CUT`` for a lone part, else ``CUT-<path>``."""
    if len(output.parts) <= 1:
        return CUT
    return "CUT-" + "".join("_" if c in _BAD else c for c in part.name)


def _bulge_points(segments):
    """(x, y, bulge) vertices of a closed chain of lines and arcs."""
    pts = []
    for s in segments:
        if isinstance(s, Line):
            pts.append((s.start[0], s.start[1], 0.0))
        else:
            k = 1 if abs(s.sweep) <= math.pi else 2
            for i in range(k):
                part = Arc(s.center, s.radius, s.start_angle + s.sweep * i / k, s.sweep / k)
                x, y = part.start
                pts.append((x, y, math.tan(part.sweep / 4)))
    return pts


def to_dxf_document(output: Output):
    """An ``ezdxf`` document of ``output`` (see the module docstring for layers and units)."""
    import ezdxf
    from ezdxf import units
    doc = ezdxf.new("R2010", setup=False)
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1
    doc.layers.add(CUT, color=1)
    doc.layers.add(ENGRAVE, color=5)
    msp = doc.modelspace()
    for p in output.parts:
        layer = layer_of(p, output)
        if layer not in doc.layers:
            doc.layers.add(layer, color=1)
        for lp in p.loops:
            segs = lp.segments
            if len(segs) == 1 and isinstance(segs[0], Circle):
                msp.add_circle(segs[0].center, segs[0].radius, dxfattribs={"layer": layer})
                continue
            msp.add_lwpolyline(_bulge_points(segs), format="xyb", close=True,
                               dxfattribs={"layer": layer})
    for st in output.engrave:
        att = {"layer": ENGRAVE}
        if st.closed and not (len(st.segments) == 1 and isinstance(st.segments[0], Circle)):
            msp.add_lwpolyline(_bulge_points(st.segments), format="xyb", close=True,
                               dxfattribs=att)
            continue
        for s in st.segments:
            if isinstance(s, Line):
                msp.add_line(s.start, s.end, dxfattribs=att)
            elif isinstance(s, Circle):
                msp.add_circle(s.center, s.radius, dxfattribs=att)
            else:                   # DXF arcs run counter-clockwise from start to end angle
                a, b = (s.start_angle, s.end_angle) if s.sweep > 0 else (s.end_angle, s.start_angle)
                msp.add_arc(s.center, s.radius, math.degrees(a), math.degrees(b),
                            dxfattribs=att)
    return doc


def to_dxf(output: Output) -> str:
    """The DXF text of ``output``."""
    buf = io.StringIO()
    to_dxf_document(output).write(buf)
    return buf.getvalue()
