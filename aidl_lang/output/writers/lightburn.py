"""LightBurn project writer (``.lbrn2``, LightBurn 1.x and later) for the exact output model
(:class:`~..part.part.Output`): a file LightBurn opens with its layers set up (docs/machines.md,
"LightBurn").

The file is XML, as LightBurn writes it: the root ``<LightBurnProject AppVersion=...
FormatVersion="1" MaterialHeight="0" MirrorX="False" MirrorY="False">``, the optimisation
preferences (``<UIPrefs>``: order by layer priority, inner shapes first), then one
``<CutSetting type="Cut">`` per operation the drawing uses (:data:`LAYERS`: ``engrave``
blue C01, ``score`` green C03, ``cut_inner`` orange C05, ``cut_outer`` red C02; LightBurn's
layers are its 30 palette colours, index 0-29), each with ``<index>``, ``<name>``,
``<maxPower>`` / ``<maxPower2>`` (percent), ``<speed>`` (**mm/s**: LightBurn stores speeds in
mm/s whatever unit its window shows; the machine profile's mm/min / 60), ``<numPasses>`` and
``<priority>`` (0-3 in the order above, so that "order by priority" runs engraving first and
inner cuts before outer ones), all from the machine profile; the areas engraved filled
(``Text(..., font=, fill=true)``, issue 112) are the layer ``fill`` (black C00, priority 0) of
a ``<CutSetting type="Scan">``, its line ``<interval>`` (mm) the profile's ``fill.interval``
and ``<bidir Value="1"/>`` (lines run both ways), its shapes the areas' closed loops (the
letters and their counters: LightBurn fills what they enclose)
(:mod:`~..fabrication.machine`, ``--machine FILE``; the built-in laser profile without one).

Then the shapes, in the cut order of :func:`~..fabrication.toolpath.plan` (engraving first, each part's
inner loops before its outline): engraving outside every part first, at the top level, then
one ``<Shape Type="Group">`` per part (in the order of the parts' first cuts) holding that
part's shapes in plan order (its engraving, its inner loops, its outline); a comment
``<!-- part NAME -->`` before the group names the part (LightBurn's groups hold no name).
LightBurn's optimiser orders the job in the end: the preferences written ask it for layer
priority order and inner shapes first, which is the plan's order.  Each path is

* a whole circle: ``<Shape Type="Ellipse" Rx=r Ry=r>`` with ``<XForm>1 0 0 1 cx cy</XForm>``
  (exact);
* a whole ellipse: ``Type="Ellipse"`` with ``Rx``, ``Ry`` and the rotation in its XForm
  ``cos sin -sin cos cx cy`` (exact);
* anything else: ``<Shape Type="Path" VertID=.. PrimID=..>`` with an identity XForm, its
  vertices in ``<VertList>`` (``V x y`` then ``c0x X c0y Y`` the control point leaving the
  vertex, ``c1x X c1y Y`` the one entering it, ``c0x1`` / ``c1x1`` for none, as LightBurn
  writes them) and its primitives in ``<PrimList>`` (``L i j`` a line, ``B i j`` a cubic
  Bézier from vertex i's c0 to vertex j's c1; a closed path's last primitive returns to
  vertex 0).  Lines are exact; spline pieces are their own cubic Bézier spans (exact);
  **arcs** are cubic Béziers (the standard construction, control arms ``4/3 tan(phi/4) r``,
  which meets the arc at both ends and the middle) in pieces small enough that every point of
  every piece is within :data:`BEZIER_TOL` = 1e-4 mm of the arc (the radial error of a piece
  of sweep phi is below ``r * 4/27 sin^6(phi/4) / cos^2(phi/4)``); elliptical arcs are the
  same Béziers of the unit circle mapped by the ellipse's affine map, their pieces counted
  for the major semi-axis, so within BEZIER_TOL of the ellipse too (:mod:`.beziers`, shared
  with the PDF writer).

Coordinates are millimetres, y up (LightBurn's workspace y points up, as ours), written to
:data:`DIGITS` decimals (1e-9 mm).  A cutting layout (``--layout sheet``) keeps the sheet's
coordinates.  Reference: LightBurn's own files (its ``.lbrn2`` is XML with these elements; the
format is not published).
"""
from __future__ import annotations

import math
from xml.sax.saxutils import escape, quoteattr

from ..fabrication import machine as machine_mod
from ..part.part import Circle, EllipticArc, Line, Output
from . import beziers

APP_VERSION = "1.7.00"
FORMAT_VERSION = "1"
DIGITS = 9                 # decimals of a mm: 1e-9 mm
BEZIER_TOL = 1e-4          # mm: the largest distance of an arc's Bézier from the arc
# operation -> (LightBurn layer index = palette colour, layer name, priority)
LAYERS = {
    "engrave": (1, "engrave", 0),        # C01 blue
    "score": (3, "score", 1),            # C03 green
    "cut_inner": (5, "cut inner", 2),    # C05 orange
    "cut_outer": (2, "cut outer", 3),    # C02 red
    "fill": (0, "fill", 0),              # C00 black: a Scan layer (areas engraved filled)
}
SPEED_DIVISOR = 60.0       # the profile's mm/min over LightBurn's mm/s


def _f(v: float) -> str:
    """A number to :data:`DIGITS` decimals without trailing zeros (``12.5``, ``0``)."""
    s = f"{v:.{DIGITS}f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def pieces(segments) -> list:
    """A chain of exact segments as LightBurn primitives: ``("L", p, q)`` or ``("B", p, c0,
    c1, q)`` (a Circle inside a chain as its Béziers from angle 0)."""
    out = []
    for s in segments:
        if isinstance(s, Line):
            out.append(("L", tuple(s.start), tuple(s.end)))
            continue
        out += [("B",) + tuple(b) for b in beziers.segment_beziers(s, BEZIER_TOL)]
    return out


class _Doc:
    def __init__(self):
        self.lines: list[str] = []
        self.vert_id = 0

    def add(self, depth: int, text: str) -> None:
        self.lines.append("    " * depth + text)


def _path(doc: _Doc, depth: int, index: int, segments, closed: bool) -> None:
    """One ``Path`` shape of a chain of segments."""
    prims = pieces(segments)
    if not prims:
        return
    verts: list[list] = []        # [point, c0 or None, c1 or None]
    plist = []
    verts.append([prims[0][1], None, None])
    for n, pr in enumerate(prims):
        last = n == len(prims) - 1
        j = 0 if (closed and last) else len(verts)
        i = len(verts) - 1
        if pr[0] == "L":
            plist.append(f"L{i} {j}")
            if j:
                verts.append([pr[2], None, None])
        else:
            _, p, c0, c1, q = pr
            verts[i][1] = c0
            if j:
                verts.append([q, None, c1])
            else:
                verts[0][2] = c1
            plist.append(f"B{i} {j}")
    vl = []
    for p, c0, c1 in verts:
        v = f"V{_f(p[0])} {_f(p[1])}"
        v += f"c0x{_f(c0[0])}c0y{_f(c0[1])}" if c0 is not None else "c0x1"
        v += f"c1x{_f(c1[0])}c1y{_f(c1[1])}" if c1 is not None else "c1x1"
        vl.append(v)
    vid = doc.vert_id
    doc.vert_id += 1
    doc.add(depth, f'<Shape Type="Path" CutIndex="{index}" VertID="{vid}" PrimID="{vid}">')
    doc.add(depth + 1, "<XForm>1 0 0 1 0 0</XForm>")
    doc.add(depth + 1, f"<VertList>{''.join(vl)}</VertList>")
    doc.add(depth + 1, f"<PrimList>{''.join(plist)}</PrimList>")
    doc.add(depth, "</Shape>")


def _shape(doc: _Doc, depth: int, cut) -> None:
    """One cut (:class:`~..fabrication.toolpath.Cut`) as its LightBurn shape."""
    index = LAYERS[cut.operation][0]
    segs = cut.segments
    if len(segs) == 1 and isinstance(segs[0], Circle):
        c = segs[0]
        doc.add(depth, f'<Shape Type="Ellipse" CutIndex="{index}" Rx="{_f(c.radius)}" '
                       f'Ry="{_f(c.radius)}">')
        doc.add(depth + 1, f"<XForm>1 0 0 1 {_f(c.center[0])} {_f(c.center[1])}</XForm>")
        doc.add(depth, "</Shape>")
        return
    if len(segs) == 1 and isinstance(segs[0], EllipticArc) and segs[0].whole:
        e = segs[0].curve
        cr, sr = math.cos(e.rotation), math.sin(e.rotation)
        doc.add(depth, f'<Shape Type="Ellipse" CutIndex="{index}" Rx="{_f(e.rx)}" '
                       f'Ry="{_f(e.ry)}">')
        doc.add(depth + 1, f"<XForm>{_f(cr)} {_f(sr)} {_f(-sr)} {_f(cr)} "
                           f"{_f(e.center[0])} {_f(e.center[1])}</XForm>")
        doc.add(depth, "</Shape>")
        return
    _path(doc, depth, index, segs, cut.closed)


def _machine(options):
    """The machine profile of ``options.machine`` (:func:`~..fabrication.machine.resolve`: a profile, a
    kind, a TOML path or a table; None: the built-in laser profile)."""
    return machine_mod.resolve(getattr(options, "machine", None), "laser")


def to_lbrn2(output: Output, options=None) -> str:
    """The ``.lbrn2`` text of ``output`` (see the module docstring); the layers' settings
    from ``options.machine`` (a :class:`~..fabrication.machine.Machine`) or the built-in laser profile.
    (An empty drawing is refused before, by :func:`~aidl_lang.output.writers.encode`.)"""
    from ..fabrication.toolpath import plan
    m = _machine(options)
    cuts = plan(output)
    doc = _Doc()
    doc.lines.append('<?xml version="1.0" encoding="UTF-8"?>')
    doc.add(0, f'<LightBurnProject AppVersion="{APP_VERSION}" FormatVersion="{FORMAT_VERSION}" '
               'MaterialHeight="0" MirrorX="False" MirrorY="False">')
    if output.title:
        doc.add(1, f"<!-- {escape(output.title).replace('--', '- -')} -->")
    doc.add(1, "<UIPrefs>")
    for key, value in (("Optimize_ByLayer", 0), ("Optimize_ByGroup", -1),
                       ("Optimize_ByPriority", 1), ("Optimize_WhichDirection", 0),
                       ("Optimize_InnerToOuter", 1), ("Optimize_ByDirection", 0),
                       ("Optimize_ReduceTravel", 1), ("Optimize_HideBacklash", 0),
                       ("Optimize_ReduceDirChanges", 0), ("Optimize_ChooseCorners", 0),
                       ("Optimize_AllowReverse", 1), ("Optimize_RemoveOverlaps", 0),
                       ("Optimize_OptimalEntryPoint", 0), ("Optimize_OverlapDist", 0.025)):
        doc.add(2, f'<{key} Value="{value}"/>')
    doc.add(1, "</UIPrefs>")
    used = [op for op in LAYERS if any(c.operation == op for c in cuts)]
    for op in used:
        index, name, priority = LAYERS[op]
        o = m.operation(op)
        doc.add(1, f'<CutSetting type="{"Scan" if op == "fill" else "Cut"}">')
        doc.add(2, f'<index Value="{index}"/>')
        doc.add(2, f"<name Value={quoteattr(name)}/>")
        doc.add(2, f'<maxPower Value="{_f(o.power)}"/>')
        doc.add(2, f'<maxPower2 Value="{_f(o.power)}"/>')
        doc.add(2, f'<speed Value="{_f(o.speed / SPEED_DIVISOR)}"/>')   # mm/min -> mm/s
        doc.add(2, f'<numPasses Value="{max(1, int(o.passes))}"/>')
        doc.add(2, f'<priority Value="{priority}"/>')
        if op == "fill":            # LightBurn fills the layer's closed shapes: its lines
            doc.add(2, f'<interval Value="{_f(o.interval)}"/>')
            doc.add(2, '<bidir Value="1"/>')
        doc.add(1, "</CutSetting>")
    # the parts in the order their first cut comes; each part's shapes in plan order
    loose = [c for c in cuts if not c.part]
    order: list[str] = []
    by_part: dict = {}
    for c in cuts:
        if c.part:
            by_part.setdefault(c.part, []).append(c)
    for c in cuts:
        if c.part and c.operation.startswith("cut") and c.part not in order:
            order.append(c.part)
    order += [p for p in by_part if p not in order]       # parts with engraving only
    for c in loose:
        _shape(doc, 1, c)
    for part in order:
        doc.add(1, f"<!-- part {escape(part).replace('--', '- -')} -->")
        doc.add(1, '<Shape Type="Group">')
        doc.add(2, "<XForm>1 0 0 1 0 0</XForm>")
        doc.add(2, "<Children>")
        for c in by_part[part]:
            _shape(doc, 3, c)
        doc.add(2, "</Children>")
        doc.add(1, "</Shape>")
    doc.add(1, '<Notes ShowOnLoad="0" Notes=""/>')
    doc.add(0, "</LightBurnProject>")
    return "\n".join(doc.lines) + "\n"


def write(output: Output, options) -> bytes:
    """The registry's entry (:data:`~.FORMATS`): :func:`to_lbrn2`, UTF-8."""
    return to_lbrn2(output, options).encode()
