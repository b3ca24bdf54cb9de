"""DXF writer (``ezdxf``) for the exact output model (:class:`~.part.Output`).

What laser, waterjet and CNC software imports: a DXF R2010 file in millimetres (header
``$INSUNITS`` = 4, ``$MEASUREMENT`` = 1).  Each closed outline loop is a ``CIRCLE`` when it is
a circle and otherwise a closed ``LWPOLYLINE`` whose arcs are bulges (bulge = tan(sweep / 4);
one bulge per arc, a half circle or 359 degrees alike, up to :data:`MAX_BULGE_SWEEP`).
Engraving (drawings, text strokes, unclosed curves) is written so that a laser runs each stroke in one go: a closed stroke is a closed
``LWPOLYLINE``; an open stroke whose segments are chained (each starting where the one before
ends, within :data:`CHAIN_TOL`) is ONE open ``LWPOLYLINE`` with bulges; a lone line, arc or
circle is a ``LINE``, ``ARC`` or ``CIRCLE`` (a stroke with gaps is cut into its chains).

A loop or stroke that holds a spline or an ellipse cannot be one ``LWPOLYLINE`` (it has no
cubic or elliptical segments): it is written segment by segment, each elliptical arc as an
``ELLIPSE`` entity (centre, major axis, ratio, start and end parameter), each spline piece as
a ``SPLINE`` entity (degree 3,
clamped, its knots the chord-length parameters with triple interior knots: every span one
Bézier piece, control points to the last bit), each line as a ``LINE`` and each arc as an
``ARC``, ends meeting exactly, so CAM software joins them into one contour.

The header's ``$EXTMIN`` / ``$EXTMAX`` are the drawing's exact extent
(:func:`~.extent.extent`, z = 0), also when a corner is at the origin (a cutting sheet).

Layers: ``CUT`` (red) for the outlines of a single part, ``ENGRAVE`` (blue) for engraving; in an
assembly with several parts, each part's outlines are on their own layer ``CUT-<part>``
(see :func:`layer_of`), so each part can be selected, nested or hidden on its own.  A
through-cut (a ``cut`` structure's curve) is written as engraving is (one entity or polyline
per path, exact) on its part's cut layer.  An area engraved filled (``Text(..., font=,
fill=true)``, issue 112) is a solid ``HATCH`` on layer ``FILL`` (blue), its boundary the
letters' loops as edge paths: lines, and each spline piece a spline edge (the font's curves,
exact; arcs as Bézier spline edges within :data:`HATCH_ARC_TOL`), see :func:`_hatch`.
"""
from __future__ import annotations

import io
import math

from ..part.extent import extent
from ..part.part import (Arc, Circle, EllipticArc, Line, Loop, Output, PartOutline, Spline,
                         fill_regions)
from ..part.edges.shared import cut_once

CUT, ENGRAVE, FILL = "CUT", "ENGRAVE", "FILL"
HATCH_ARC_TOL = 1e-4     # mm: an arc's Bézier pieces in a HATCH boundary, from the arc
CHAIN_TOL = 1e-6     # mm: a segment continues the chain when it starts this close to its end
_BAD = '<>/\\":;?*|=`'
# radians: the largest sweep written as one bulge.  A reader finds an arc's centre from its
# chord and bulge; near a whole turn the chord shrinks like (2 pi - sweep) * r, and the
# centre's error grows like 1e-16 * |coordinates| / (2 pi - sweep): 1e-3 rad short of a turn
# keeps it below 1e-9 mm up to 10 m.  A half circle, or 359 degrees, is one arc.
MAX_BULGE_SWEEP = 2 * math.pi - 1e-3


def layer_of(part: PartOutline, output: Output) -> str:
    """The DXF layer of a part's outlines: ``CUT`` for a lone part, else ``CUT-<path>``."""
    if len(output.parts) <= 1:
        return CUT
    return "CUT-" + "".join("_" if c in _BAD else c for c in part.name)


def _chains(segments) -> list[list]:
    """``segments`` cut into maximal chains: runs of lines and arcs each starting within
    :data:`CHAIN_TOL` of the previous one's end; a circle is a chain of its own."""
    chains: list[list] = []
    for s in segments:
        last = chains[-1][-1] if chains else None
        if (last is not None and not isinstance(s, Circle) and not isinstance(last, Circle)
                and math.dist(last.end, s.start) <= CHAIN_TOL):
            chains[-1].append(s)
        else:
            chains.append([s])
    return chains


def _bulge_points(segments, closed: bool = True):
    """(x, y, bulge) vertices of a chain of lines and arcs (bulge = tan(sweep / 4)): each arc
    one vertex, up to :data:`MAX_BULGE_SWEEP`; an arc closer to a whole turn is split in two
    halves.  An open chain ends with its last segment's end point."""
    pts = []
    for s in segments:
        if isinstance(s, Line):
            pts.append((s.start[0], s.start[1], 0.0))
        else:
            k = 1 if abs(s.sweep) <= MAX_BULGE_SWEEP else 2
            for i in range(k):
                part = Arc(s.center, s.radius, s.start_angle + s.sweep * i / k, s.sweep / k)
                x, y = part.start
                pts.append((x, y, math.tan(part.sweep / 4)))
    if not closed and segments:
        x, y = segments[-1].end
        pts.append((x, y, 0.0))
    return pts


def _pieces(msp, segments, att) -> None:
    """Each segment of a chain holding a spline as its own entity (see the module docstring)."""
    for s in segments:
        if isinstance(s, EllipticArc):
            _ellipse(msp, s, att)
        elif isinstance(s, Spline):
            deg, knots, ctrl = s.bspline()
            msp.add_open_spline([(x, y, 0.0) for x, y in ctrl], degree=deg, knots=knots,
                                dxfattribs=att)
        elif isinstance(s, Line):
            msp.add_line(s.start, s.end, dxfattribs=att)
        elif isinstance(s, Circle):
            msp.add_circle(s.center, s.radius, dxfattribs=att)
        else:
            a, b = (s.start_angle, s.end_angle) if s.sweep > 0 else (s.end_angle, s.start_angle)
            msp.add_arc(s.center, s.radius, math.degrees(a), math.degrees(b), dxfattribs=att)


def _ellipse(msp, s: EllipticArc, att) -> None:
    """An ``ELLIPSE`` entity: centre, major axis (the vector to the end of the major
    semi-axis), ratio ry / rx, and the parameters (eccentric anomaly, radians) it runs
    counter-clockwise between; a whole ellipse 0 to 2 pi."""
    e = s.curve
    axis = (e.rx * math.cos(e.rotation), e.rx * math.sin(e.rotation), 0.0)
    if s.whole:
        a, b = 0.0, 2 * math.pi
    else:
        a, b = (s.start_param, s.end_param) if s.sweep > 0 else (s.end_param, s.start_param)
        k = math.floor(a / (2 * math.pi))
        a, b = a - 2 * math.pi * k, b - 2 * math.pi * k
    msp.add_ellipse((e.center[0], e.center[1], 0.0), axis, e.ry / e.rx, a, b,
                    dxfattribs=att)


def _exploded(segs) -> bool:
    """A chain that cannot be one ``LWPOLYLINE``: it holds a spline or an ellipse."""
    return any(isinstance(g, (Spline, EllipticArc)) for g in segs)


def to_dxf_document(output: Output):
    """An ``ezdxf`` document of ``output`` (see the module docstring for layers and units)."""
    import ezdxf
    from ezdxf import units
    doc = ezdxf.new("R2010", setup=False)
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1
    doc.layers.add(CUT, color=1)
    doc.layers.add(ENGRAVE, color=5)
    for st in output.engrave:                 # a countersink's heads: a layer of their own
        if st.style in ("countersink", "counterbore") and st.style.upper() not in doc.layers:
            doc.layers.add(st.style.upper(), color=3)
    msp = doc.modelspace()
    x0, y0, x1, y1 = extent(output)
    msp.reset_extents((x0, y0, 0.0), (x1, y1, 0.0))
    # ezdxf copies the modelspace's extents to the header only when neither corner is the
    # point (0, 0, 0), which it takes for "unset": a drawing cornered at the origin (every
    # cutting sheet) kept +-1e20; set them here, and ezdxf leaves them (or rewrites the same)
    doc.header["$EXTMIN"] = (x0, y0, 0.0)
    doc.header["$EXTMAX"] = (x1, y1, 0.0)
    once = cut_once(output)      # pieces of one cut part: each shared edge once
    for i, p in enumerate(output.parts):
        layer = layer_of(p, output)
        if layer not in doc.layers:
            doc.layers.add(layer, color=1)
        for k, lp in enumerate(p.loops):
            if (i, k) in once:
                for segs, closed in once[(i, k)]:
                    _path(msp, segs, closed, {"layer": layer})
                continue
            segs = lp.segments
            if len(segs) == 1 and isinstance(segs[0], Circle):
                msp.add_circle(segs[0].center, segs[0].radius, dxfattribs={"layer": layer})
                continue
            if _exploded(segs):
                _pieces(msp, segs, {"layer": layer})
                continue
            msp.add_lwpolyline(_bulge_points(segs), format="xyb", close=True,
                               dxfattribs={"layer": layer})
    layers = {p.name: layer_of(p, output) for p in output.parts}
    fills = fill_regions(output.engrave)
    if fills:
        doc.layers.add(FILL, color=5)
        for _, _, loops in fills:
            _hatch(msp, loops)
    for st in output.engrave:
        if st.style == "fill":
            continue
        # a through-cut on its part's cut layer (CUT when it cuts no part)
        att = {"layer": layers.get(st.part, CUT) if st.style == "cut" else
               st.style.upper() if st.style in ("countersink", "counterbore") else ENGRAVE}
        _path(msp, st.segments, st.closed, att)
    return doc


def _hatch(msp, loops) -> None:
    """One solid ``HATCH`` on layer :data:`FILL` of an area engraved filled
    (:func:`~..part.part.fill_regions`): one edge boundary path per loop (an outer loop flagged
    external, a counter inside it a plain path: the area by the DXF's odd parity), a line a
    line edge, a spline piece a spline edge (its own degree-3 B-spline, exact), an arc or an
    elliptical arc spline edges of its Bézier pieces within :data:`HATCH_ARC_TOL`."""
    from . import beziers
    h = msp.add_hatch(color=5, dxfattribs={"layer": FILL})
    h.set_solid_fill(color=5, style=0)
    for segs in loops:
        outer = Loop(list(segs)).area > 0
        ep = h.paths.add_edge_path(flags=1 if outer else 0)
        for g in segs:
            if isinstance(g, Line):
                ep.add_line(g.start, g.end)
                continue
            if isinstance(g, Spline):
                deg, knots, ctrl = g.bspline()
                ep.add_spline(control_points=[(x, y) for x, y in ctrl],
                              knot_values=list(knots), degree=deg)
                continue
            for b in beziers.segment_beziers(g, HATCH_ARC_TOL):
                ep.add_spline(control_points=[tuple(map(float, q)) for q in b],
                              knot_values=[0, 0, 0, 0, 1, 1, 1, 1], degree=3)


def _path(msp, segments, closed: bool, att) -> None:
    """One stroke's or one outline stretch's entities: a chain with a spline or an ellipse
    exploded, a closed chain one closed ``LWPOLYLINE``, an open one an open ``LWPOLYLINE``
    per run (one ``LINE``, ``ARC`` or ``CIRCLE`` when it is one segment)."""
    if _exploded(segments):
        _pieces(msp, segments, att)
        return
    if closed and not (len(segments) == 1 and isinstance(segments[0], Circle)):
        msp.add_lwpolyline(_bulge_points(segments), format="xyb", close=True, dxfattribs=att)
        return
    for chain in _chains(segments):
        if len(chain) > 1:          # one polyline: the laser does not stop at each joint
            msp.add_lwpolyline(_bulge_points(chain, closed=False), format="xyb",
                               close=False, dxfattribs=att)
            continue
        (s,) = chain
        if isinstance(s, Line):
            msp.add_line(s.start, s.end, dxfattribs=att)
        elif isinstance(s, Circle):
            msp.add_circle(s.center, s.radius, dxfattribs=att)
        else:                   # DXF arcs run counter-clockwise from start to end angle
            a, b = (s.start_angle, s.end_angle) if s.sweep > 0 else (s.end_angle, s.start_angle)
            msp.add_arc(s.center, s.radius, math.degrees(a), math.degrees(b), dxfattribs=att)


def to_dxf(output: Output) -> str:
    """The DXF text of ``output``."""
    buf = io.StringIO()
    to_dxf_document(output).write(buf)
    return buf.getvalue()


def write(output: Output, options) -> bytes:
    """The registry's entry (:data:`~.FORMATS`): :func:`to_dxf`, UTF-8."""
    return to_dxf(output).encode()
