"""SVG writer (``svgwrite``) for the exact output model (:class:`~.part.Output`).

Layers are groups with stable ids: ``cut`` holds one group per part (``part-<path>``), each
part's outline loops as exact ``L`` / ``A`` / ``C`` path commands (``C``: a spline's cubic
Bézier spans; every arc in ``A`` pieces of at most a quarter turn, a full circle four of them
in the preview style, a ``<circle>`` in the laser style; numbers to 1e-9 mm, :data:`DIGITS`); ``engrave`` holds drawings, text and
unclosed curves.  Debug layers appear only when asked for (``show``): ``holes`` (each hole's
declared outline, dashed), ``bboxes`` (every structure's bounding box), ``construction``
(construction geometry).  ``fill`` (when there is one, under ``engrave``) holds the areas
engraved filled (``Text(..., font=, fill=true)``, issue 112): one path per area, its loops
(the letters and their counters) one ``d``, filled black ``#000000`` in the laser style (no
stroke: a laser program's fill/scan layer) and blue in the preview.

Styles: ``preview`` (default) fills solids light grey for readability, with a thin dark stroke;
``laser`` is stroke-only, hairlines 0.01 mm wide (:data:`HAIRLINE`, in the mm user units of
the viewBox) in red ``#ff0000`` for cuts and blue ``#0000ff`` for engraving, one element per
loop and one path per stroke — what laser-cutter software (LightBurn, Inkscape, VisiCut)
imports as cut and engrave paths.
Either way the geometry is exact.  Units: width and height in mm, the viewBox in mm; the
model's y points up and is flipped for the page (y_svg = -y).
"""
from __future__ import annotations

import math

import numpy as np

from ..part.extent import extent
from ..part.edges.shared import cut_once, loop_paths
from ..part.part import (PALETTE, Arc, Circle, EllipticArc, Line, Loop, Output, OutputError, Spline,
                    build, fill_regions)

SHOW = ("holes", "bboxes", "construction")
# the engrave layers of the heads of countersinks and counterbores (issue 102): their own
# group (``id``), colour and, in the DXF, layer, so a laser can engrave or skip them
SINK_STYLES = ("countersink", "counterbore")
STYLES = ("preview", "laser")
CHAIN_TOL = 1e-6     # mm: a segment starting this close to the pen continues the subpath
DIGITS = 9           # decimals of a mm written for lines, arcs and sizes: 1e-9 mm
HAIRLINE = 0.01      # mm: the laser style's stroke width, in user units (the viewBox is in mm)
# each part of an assembly is drawn in its colour (:data:`~..part.part.PALETTE`) over a fill of
# the same colour at PART_FILL_OPACITY, so overlapping parts stay visible
PART_FILL_OPACITY = 0.18


_FMT = f"%.{DIGITS}f"


def _f(v: float) -> str:
    """A coordinate or length to :data:`DIGITS` decimals of a mm (1e-9 mm), without trailing
    zeros (``12.5``, ``0``, ``-3.000000001``)."""
    s = (_FMT % v).rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _pt(p) -> str:
    return f"{_f(p[0])},{_f(-p[1])}"


def _f10(v: float) -> str:
    s = f"{v:.10f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _pt10(p) -> str:
    """A spline's point, to 1e-10 mm: the curve a reader draws from the control points is
    the program's to 1e-9 mm (lines and arcs are written to 1e-9 mm, :func:`_pt`)."""
    return f"{_f10(p[0])},{_f10(-p[1])}"


def _arc_cmd(a: Arc) -> str:
    """SVG ``A`` commands of an arc: equal pieces of at most a quarter turn.  A reader finds
    an ``A``'s centre from its end points and radius, each rounded to 5e-10 mm (:data:`DIGITS`):
    for a piece of sweep t the centre moves by about 5e-10 * (1 + sin(t/2)) / cos(t/2) mm,
    1.2e-9 at a quarter turn but without bound towards a half turn (end points nearly
    opposite: a half circle 1e-6 rad short of its half turn was read 5e-7 mm off), and a
    whole turn drawn as one ``A`` is nothing at all (the end equals the start)."""
    r = _f(a.radius)
    sweep_flag = 0 if a.sweep > 0 else 1          # y is flipped: model ccw is SVG's negative
    n = max(1, math.ceil(abs(a.sweep) / (math.pi / 2) - 1e-9))
    if n == 1:                                    # its end, as a.at(start + 1 * sweep) is
        return f"A{r},{r} 0 0 {sweep_flag} {_pt(a.end)}"
    step = a.sweep / n
    return "".join(f"A{r},{r} 0 0 {sweep_flag} {_pt(a.at(a.start_angle + (k + 1) * step))}"
                   for k in range(n))


def _ellipse_cmd(s: EllipticArc) -> str:
    """SVG ``A rx ry rotation`` commands of an elliptical arc: equal pieces of at most a
    quarter turn of its parameter (as :func:`_arc_cmd`), the rotation in degrees, y flipped."""
    e = s.curve
    rx, ry = _f(e.rx), _f(e.ry)
    rot = _f(-math.degrees(e.rotation))
    sweep_flag = 0 if s.sweep > 0 else 1
    n = max(1, math.ceil(abs(s.sweep) / (math.pi / 2) - 1e-9))
    step = s.sweep / n
    return "".join(f"A{rx},{ry} {rot} 0 {sweep_flag} {_pt(e.at(s.start_param + (k + 1) * step))}"
                   for k in range(n))


def segments_d(segments, closed: bool) -> str:
    """Path data of a chain of exact segments (a Circle as four quarter arcs): one subpath per
    run of segments each starting within :data:`CHAIN_TOL` (mm) of the previous
    one's end, so a gap is a move, never a drawn line."""
    out = []
    here = None                       # the pen's position, None after a circle or at the start
    for s in segments:
        if isinstance(s, Circle):
            whole = Arc(s.center, s.radius, 0.0, 2 * math.pi if s.ccw else -2 * math.pi)
            out.append(f"M{_pt(whole.start)}{_arc_cmd(whole)}Z")    # four quarter arcs
            here = None
            continue
        if here is None or math.dist(here, s.start) > CHAIN_TOL:
            out.append(f"M{_pt10(s.start) if isinstance(s, Spline) else _pt(s.start)}")
        if isinstance(s, Spline):         # each span one cubic Bézier: the curve itself
            out += [f"C{_pt10(b[1])} {_pt10(b[2])} {_pt10(b[3])}" for b in s.spans]
        else:
            out.append(f"L{_pt(s.end)}" if isinstance(s, Line) else
                       _ellipse_cmd(s) if isinstance(s, EllipticArc) else _arc_cmd(s))
        here = s.end
    if closed and segments and not isinstance(segments[-1], Circle):
        out.append("Z")
    return "".join(out)


def to_svg(output, title: str = "", show=(), style: str = "preview",
           margin: float | None = None, hairline: float = HAIRLINE,
           stroke: float | None = None) -> str:
    """The SVG text of ``output`` (an :class:`Output`, or a booleans ``Drawing``, which is
    converted with :func:`~.part.build`).  ``show``: debug layers from :data:`SHOW`.

    The page is the exact extent of the drawing (:func:`~.extent.extent`) plus ``margin`` mm
    on every side; ``None`` (the default) is 5 % of the larger side, at least 1 mm, and ``0``
    makes the page exactly the bounding box.  Raises :class:`ValueError` for an unknown layer
    and :class:`~.part.OutputError` for a negative or non-finite margin.  ``hairline``: the
    laser style's stroke width in mm (:data:`HAIRLINE`; a raster output passes one pixel's
    width, so the cuts show).  ``stroke``: the preview's line width in mm (None: the page's
    longer side / 500; a large raster passes a few pixels' width, so a 1 mm gap between two
    lines is not drawn shut)."""
    import svgwrite
    if not isinstance(output, Output):
        output = build(output, title)
    bad = set(show) - set(SHOW)
    if bad:
        raise ValueError(f"unknown layer(s) to show: {', '.join(sorted(bad))}; "
                         f"known: {', '.join(SHOW)}")
    d0 = output.drawing
    if margin is not None and not 0 <= margin < math.inf:
        raise OutputError(f"the SVG margin must be a length of 0 mm or more, got {margin}")
    if margin is None and output.page is not None:
        margin = 0.0                 # a sheet: the page is the sheet
    x0, y0, x1, y1 = extent(output)
    if "construction" in show and d0 is not None:
        for _, item, _ in d0.construction:
            pts = _item_points(item)
            if len(pts):
                x0, y0 = min(x0, pts[:, 0].min()), min(y0, pts[:, 1].min())
                x1, y1 = max(x1, pts[:, 0].max()), max(y1, pts[:, 1].max())
    w, h = max(x1 - x0, 1e-3), max(y1 - y0, 1e-3)
    if margin is None:
        margin = max(0.05 * max(w, h), 1.0)
    vx, vy = x0 - margin, -(y1 + margin)
    vw, vh = w + 2 * margin, h + 2 * margin
    sw = max(vw, vh) / 500.0 if stroke is None else stroke
    d = svgwrite.Drawing(size=(f"{_f(vw)}mm", f"{_f(vh)}mm"), profile="full",
                         debug=False)   # no per-attribute validation: 2-3x faster, same text
    d.viewbox(_f(vx), _f(vy), _f(vw), _f(vh))
    if title or output.title:
        d.set_desc(title=title or output.title)
    laser = style == "laser"
    if laser:
        # a true hairline: 0.01 user units = 0.01 mm ("0.01mm" would be 0.01 CSS mm in user
        # units, i.e. 3.78 times wider on this page)
        cut = d.g(id="cut", fill="none", stroke="#ff0000", stroke_width=_f(hairline))
    else:
        cut = d.g(id="cut", fill="#cfd8dc", stroke="#263238", stroke_width=_f(sw),
                  fill_rule="evenodd")
    if output.page is not None and not laser:      # the sheet's edge (never in the laser style)
        px0, py0, px1, py1 = output.page
        gs = d.g(id="sheet", fill="none", stroke="#90a4ae", stroke_width=_f(sw))
        gs.add(d.rect(insert=(_f(px0), _f(-py1)), size=(_f(px1 - px0), _f(py1 - py0))))
        d.add(gs)
    solids = [p for p in output.parts if p.kind == "solid"]
    colour = {p.name: PALETTE[i % len(PALETTE)] for i, p in enumerate(solids)} \
        if len(solids) > 1 and not laser else {}
    once = cut_once(output) if laser else {}    # pieces of one cut part: shared edges once
    # the holes declared in an assembly (W0109) cut nothing: the preview draws them dashed
    # where they lie, no cutting file has them
    drawn = output.parts if laser else output.parts + getattr(output, "stray", [])
    for i, p in enumerate(drawn):
        g = d.g(id=_id(p.name), **({"class_": p.kind}))
        if len(drawn) > 1:
            g.set_desc(title=p.name)           # the part's name on hover
        if p.kind == "hole" and not laser:
            g.update({"fill": "none", "stroke": "#c62828",
                      "stroke_dasharray": f"{_f(4 * sw)},{_f(2 * sw)}"})
        elif p.name in colour:
            g.update({"fill": colour[p.name], "fill_opacity": _f(PART_FILL_OPACITY),
                      "stroke": colour[p.name]})
        if laser:
            for k, lp in enumerate(p.loops):
                for segs, closed in loop_paths(once, i, k, lp):
                    g.add(_element(d, segs, closed))
        else:
            g.add(d.path(d=" ".join(segments_d(lp.segments, True) for lp in p.loops)))
        cut.add(g)
    for st in output.cuts:          # through-cuts: cut as the outlines are, zero width
        e = _element(d, st.segments, st.closed)
        e.update({"fill": "none", "class_": "through-cut"})
        cut.add(e)
    d.add(cut)
    fills = fill_regions(output.engrave)
    if fills:       # areas engraved filled (issue 112): one path per area, above the cuts
        gf = d.g(id="fill", fill="#000000" if laser else "#1565c0", stroke="none",
                 fill_rule="nonzero", **({} if laser else {"fill_opacity": "0.85"}))
        for src, _, loops in fills:
            e = d.path(d="".join(segments_d(segs, True) for segs in loops))
            e.set_desc(title=src)
            gf.add(e)
        d.add(gf)
    eng = d.g(id="engrave", fill="none", stroke="#0000ff" if laser else "#1565c0",
              stroke_width=_f(hairline if laser else sw), stroke_linecap="round",
              stroke_linejoin="round")
    sinks: dict = {}
    for st in output.engrave:
        if st.style in ("cut", "fill"):
            continue
        e = _element(d, st.segments, st.closed)
        if st.style in SINK_STYLES:         # a countersink's head: an engrave layer of its own
            sinks.setdefault(st.style, []).append(e)
            continue
        if st.style == "open" and not laser:
            e.update({"stroke": "#ef6c00"})
        eng.add(e)
    d.add(eng)
    for style in SINK_STYLES:
        if style in sinks:
            gk = d.g(id=style, fill="none", stroke="#00a000" if laser else "#2e7d32",
                     stroke_width=_f(hairline if laser else sw))
            for e in sinks[style]:
                gk.add(e)
            d.add(gk)
    if d0 is not None and "holes" in show and d0.hole_outlines:
        gh = d.g(id="holes", fill="none", stroke="#c62828", stroke_width=_f(sw * 0.8),
                 stroke_dasharray=f"{_f(4 * sw)},{_f(2 * sw)}")
        for pl in d0.hole_outlines:
            gh.add(d.path(d=_poly_d(np.asarray(pl), True)))
        d.add(gh)
    if d0 is not None and "bboxes" in show:
        gb = d.g(id="bboxes", fill="none", stroke="#6a1b9a", stroke_width=_f(sw * 0.6),
                 stroke_dasharray=f"{_f(2 * sw)},{_f(2 * sw)}")
        for s, shp in d0.shapes.items():
            if shp.is_empty():
                continue
            bx0, by0, bx1, by1 = shp.bounds()
            r = d.rect(insert=(_f(bx0), _f(-by1)), size=(_f(bx1 - bx0), _f(by1 - by0)))
            r.set_desc(title=s.path)
            gb.add(r)
        d.add(gb)
    if d0 is not None and "construction" in show and d0.construction:
        gc = d.g(id="construction", fill="none", stroke="#9e9e9e", stroke_width=_f(sw * 0.6),
                 stroke_dasharray=f"{_f(sw)},{_f(sw)}")
        for _, item, _ in d0.construction:
            gc.add(d.path(d=_poly_d(_item_points(item), item[0] in ("circle", "poly"))))
        d.add(gc)
    return d.tostring()


def _element(d, segments, closed: bool):
    if len(segments) == 1 and isinstance(segments[0], Circle):
        c = segments[0]
        return d.circle(center=(_f(c.center[0]), _f(-c.center[1])), r=_f(c.radius))
    return d.path(d=segments_d(segments, closed))


def _item_points(item) -> np.ndarray:
    kind = item[0]
    if kind == "line":
        return np.array([item[1], item[2]], dtype=float)
    if kind == "poly":
        return np.asarray(item[1], dtype=float)
    if kind in ("spline", "ellipse_arc"):
        return np.vstack([Loop([item[1]]).points(), [item[1].end]])
    if kind == "circle":
        seg = Circle(tuple(item[1]), float(item[2]))
    else:
        _, c, r, a1, a2 = item
        seg = Arc(tuple(c), float(r), float(a1), float((a2 - a1) % (2 * math.pi) or 2 * math.pi))
        return np.vstack([Loop([seg]).points(), [seg.end]])
    return Loop([seg]).points()


def _poly_d(pl: np.ndarray, close: bool) -> str:
    if len(pl) == 0:
        return ""
    return "M" + " ".join(_pt(p) for p in pl) + ("Z" if close else "")


def _id(name: str) -> str:
    return "part-" + "".join(c if c.isalnum() or c in "-_" else "_" for c in name)


def write(output: Output, options) -> bytes:
    """The registry's entry (:data:`~.FORMATS`): :func:`to_svg` with the
    :class:`~.Options` ``show``, ``style`` and ``margin``, UTF-8."""
    return to_svg(output, show=options.show, style=options.style,
                  margin=options.margin).encode()
