"""The one output model: exact lines, arcs and circles per part, from the booleans' result.

Every face handed to Manifold was an exact outline (:mod:`aidl_lang.geometry.curves`), and the
booleans' :class:`~.exact.Provenance` knows which exact curve each polygon edge came from.
:func:`build` puts each part's polygons back on those curves (docs/outputs.md, "Exact
geometry"): each run of edges on one carrier is one :class:`Line`, :class:`Arc` or
:class:`Circle`, and each vertex where two curves meet is their exact intersection (or the
touching point of a tangent join), so slots, rounded rectangles, fillets and every union or
cut of them come out as the program meant them, to floating-point accuracy.  Ellipses are the
one approximation: a polygon of chords within ``CHORD_TOL``.

The result, :class:`Output`, holds :class:`PartOutline` s (name, kind, loops, thickness, and
the loops tessellated once more for meshes) and engraving strokes (text as one polyline per
pen stroke); every writer (SVG, DXF, PNG, STL/3MF, STEP) reads it.  All lengths are in
millimetres, angles in radians, y up.
"""
from __future__ import annotations

import math
from ..records import dataclass, field

import numpy as np

from ..geometry.curves import Arc, Circle, Line, Loop, Segment, sample_xy
from .booleans import Drawing

__all__ = ["Arc", "Circle", "Line", "Loop", "Segment", "Output", "PartOutline", "Stroke",
           "OutputError", "MissingDependency", "build"]

Point = tuple[float, float]


class OutputError(RuntimeError):
    """A writer cannot produce this file from this part (for example a PNG larger than the
    rasteriser allows); the message says why and what to change."""


class MissingDependency(OutputError):
    """An optional output library is not installed; the message says how to install it."""


@dataclass
class PartOutline:
    """One part: its name (structure path), kind (``solid``, or ``hole`` for a hole with no
    solid to cut), outline loops (outer ones counter-clockwise, holes clockwise) and thickness
    (mm, for 3D outputs)."""
    name: str
    kind: str
    loops: list[Loop]
    thickness: float | None = None

    @property
    def shape(self):
        """A manifold3d CrossSection of the exact loops cut into chords within
        ``CHORD_TOL``, every vertex on its curve (what STL/3MF extrude); made on first use."""
        got = self.__dict__.get("_shape")
        if got is None:
            got = self.__dict__["_shape"] = _mesh_section(self.loops)
        return got

    @property
    def area(self) -> float:
        return sum(lp.area for lp in self.loops)

    @property
    def perimeter(self) -> float:
        return sum(lp.perimeter for lp in self.loops)


@dataclass
class Stroke:
    """Engraving: an open or closed chain of segments (``style`` drawing | open), each
    segment ending where the next starts (a laser runs it without lifting)."""
    segments: list[Segment]
    style: str = "drawing"
    closed: bool = False
    source: str = ""


@dataclass
class Output:
    parts: list[PartOutline] = field(default_factory=list)
    engrave: list[Stroke] = field(default_factory=list)
    title: str = ""
    drawing: Drawing | None = None     # the booleans' result (debug layers, checks)

    @property
    def area(self) -> float:
        """Total area (mm^2) of the solid parts."""
        return sum(p.area for p in self.parts if p.kind == "solid")

    def bounds(self) -> tuple[float, float, float, float]:
        """(x0, y0, x1, y1) in mm: the extent of every loop's and stroke's :meth:`Loop.points`
        (and each open stroke's last end), or (0, 0, 1, 1) when there is nothing."""
        xs: list = []
        ys: list = []
        for p in self.parts:
            for lp in p.loops:
                sample_xy(lp.segments, xs, ys)
        for st in self.engrave:
            sample_xy(st.segments, xs, ys)
            for s in st.segments:
                if not isinstance(s, Circle):
                    e = s.end
                    xs.append(e[0])
                    ys.append(e[1])
        if not xs:
            return (0.0, 0.0, 1.0, 1.0)
        return (min(xs), min(ys), max(xs), max(ys))


# ------------------------------------------------------------------ build
def _t(p) -> Point:
    return (float(p[0]), float(p[1]))


def _stroke(item, exact, style: str, source: str) -> Stroke | None:
    kind = item[0]
    if kind == "line":
        return Stroke([Line(_t(item[1]), _t(item[2]))], style, False, source)
    if kind == "arc":
        _, c, r, a1, a2 = item
        sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
        return Stroke([Arc(_t(c), float(r), float(a1), float(sweep))], style, False, source)
    if kind == "circle":
        return Stroke([Circle(_t(item[1]), float(item[2]))], style, True, source)
    lp = item[2] if len(item) > 2 else exact.recover(item[1])
    return Stroke(list(lp.segments), style, True, source) if lp.segments else None


def _join(strokes: list[Stroke]) -> list[Stroke]:
    """Consecutive open strokes of one source whose ends meet, as one stroke (a text's pen
    strokes: one polyline per stroke of each glyph instead of one line per segment)."""
    out: list[Stroke] = []
    for st in strokes:
        last = out[-1] if out else None
        if (last is not None and not st.closed and not last.closed and last.source == st.source
                and last.style == st.style and st.segments
                and not isinstance(st.segments[0], Circle)
                and not isinstance(last.segments[-1], Circle)
                and math.dist(last.segments[-1].end, st.segments[0].start) <= 1e-12):
            last.segments.extend(st.segments)
            continue
        out.append(Stroke(list(st.segments), st.style, st.closed, st.source))
    for st in out:                  # a run that comes back to its start is a closed stroke
        if len(st.segments) > 2 and not st.closed and \
                math.dist(st.segments[-1].end, st.segments[0].start) <= 1e-12:
            st.closed = True
    return out


def build(drawing: Drawing, title: str = "", thickness=None) -> Output:
    """The exact :class:`Output` of a booleans :class:`Drawing`.  ``thickness`` maps a part's
    name to its thickness in mm (or is one number for all parts); by default the program's
    (``thickness 3 mm``, :attr:`Drawing.thickness`)."""
    from .exact import Provenance
    exact = drawing.exact if drawing.exact is not None else Provenance()
    out = Output(title=title, drawing=drawing)
    if thickness is None:
        thickness = drawing.thickness
    parts = [p for p in drawing.parts if not p.shape.is_empty()]
    for p, loops in zip(parts, exact.loops_of([p.shape for p in parts])):
        if not loops:
            continue
        t = thickness.get(p.name) if isinstance(thickness, dict) else thickness
        out.parts.append(PartOutline(p.name, p.kind, loops, t))
    strokes = []
    for style, item, g in drawing.strokes:
        st = _stroke(item, exact, style, g.label if g is not None else "")
        if st is not None:
            strokes.append(st)
    out.engrave = _join(strokes)
    return out


def _mesh_section(loops: list[Loop]):
    """A CrossSection of exact ``loops`` whose every vertex lies on its curve (for meshes)."""
    import manifold3d as mf
    polys = [lp.points().tolist() for lp in loops]
    polys = [p for p in polys if len(p) >= 3]
    return mf.CrossSection(polys, mf.FillRule.NonZero) if polys else mf.CrossSection()
