"""The booleans' result records (:mod:`.booleans` makes them): a :class:`Part` (one solid
part's final shape), a :class:`Cut` (a hole or cut and the part it cuts), a :class:`Through`
(a through-cut along an open curve) and the :class:`Drawing` of a whole model, which the
checks, the exact outlines and the writers read."""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ....geometry.core.model import Geometry, Structure
from ....base.records import Compared
from ..edges.exact import Provenance
from .hole_outlines import HoleOutlines


class Part(Compared):
    """One part of the booleans' result: its structure's final shape (mm)."""
    __slots__ = ("name", "kind", "shape")

    def __init__(self, name: str, kind: str, shape: mf.CrossSection):
        self.name = name
        self.kind = kind  # solid | hole (a hole with no solid to cut)
        self.shape = shape


class Cut(Compared):
    """A hole child ``hole`` of the solid ``owner``: ``region`` is what it removed (mm)."""
    __slots__ = ("hole", "owner", "before", "region")

    def __init__(self, hole: Structure, owner: Structure, before: mf.CrossSection,
                 region: mf.CrossSection):
        self.hole = hole
        self.owner = owner
        self.before = before  # the owner's shape before its holes
        self.region = region  # before ∩ hole


class Through(Compared):
    """A through-cut: an open curve ``geometry`` of a ``cut`` structure, cut along as written
    (zero width) through ``part`` (the part's structure): its exact ``segments`` (mm) and
    ``band``, the strip :data:`SLIT_HALF` either side of it (the analysis' stand-in for the
    zero-width cut); ``inside``: the band's area inside the part before any through-cut
    (0: the cut is off the material); ``on_outline``: it lies along the part's outline;
    ``along``: the indices of its ``units`` (its segments, an open Spline's spans) that lie
    along the outline."""
    __slots__ = ("geometry", "part", "segments", "band", "inside", "on_outline", "along",
                 "units")

    def __init__(self, geometry: Geometry, part: Structure, segments: list,
                 band: mf.CrossSection, inside: float = 0.0, on_outline: bool = False,
                 along: tuple = (), units: list | None = None):
        self.geometry = geometry
        self.part = part
        self.segments = segments
        self.band = band
        self.inside = inside
        # True: it runs along the part's outline (a hole's included) from end to end, the
        # material on one side only: it adds nothing (not drawn, W0522)
        self.on_outline = on_outline
        # the segments (indices into ``segments``) that each lie along the outline: each adds
        # nothing (not drawn, W0522), whatever the curve (a Polyline's first side, say)
        self.along = along
        # the pieces judged one by one: its segments, an open Spline's (Bezier's) by span
        self.units = segments if units is None else units


class SinkAt(Compared):
    """A countersink or counterbore at one round hole (issue 102): ``kind`` (countersink |
    counterbore), ``part`` (the part's name), ``hole`` (the hole's Circle, its label),
    ``center`` (x, y mm, sheet frame), ``hole_d`` and ``diameter`` (the hole's and the
    head's, mm), ``angle`` (a countersink's included angle, radians), ``depth`` (a
    counterbore's, mm); ``span``: the call."""
    __slots__ = ("kind", "part", "hole", "center", "hole_d", "diameter", "angle", "depth",
                 "span")

    def __init__(self, kind, part, hole, center, hole_d, diameter, angle, depth, span):
        self.kind, self.part, self.hole, self.center = kind, part, hole, tuple(center)
        self.hole_d, self.diameter, self.angle, self.depth = hole_d, diameter, angle, depth
        self.span = span

    def cone_depth(self) -> float:
        """How deep the head goes (mm): a countersink's cone from the head's diameter down
        to the hole's (``(D - d) / 2 / tan(angle / 2)``), a counterbore's depth."""
        if self.kind == "counterbore":
            return float(self.depth)
        return max(0.0, (self.diameter - self.hole_d) / 2 / math.tan(self.angle / 2))


class SinkCall:
    """Where an ``E0503`` of the booleans is said (:mod:`.sunk`): the ``Countersink`` /
    ``Counterbore`` call's ``span`` and the part it sinks, ``owner`` (its structure)."""
    __slots__ = ("span", "owner")

    def __init__(self, span, owner):
        self.span, self.owner = span, owner


class Drawing(Compared):
    """The booleans' result of a model: its parts, lines, cuts and each structure's own shape."""
    __slots__ = ("parts", "lines", "hole_outlines", "open_curves", "exact", "strokes", "shapes",
                 "own", "cuts", "construction", "part_of", "thickness")

    def __init__(self, parts: list[Part] | None = None,
                 lines: list[tuple[str, np.ndarray]] | None = None,
                 hole_outlines: list[np.ndarray] | None = None,
                 open_curves: list[Geometry] | None = None, exact: Provenance | None = None,
                 strokes: list[tuple[str, tuple, Geometry | None]] | None = None,
                 shapes: dict | None = None, own: dict | None = None,
                 cuts: list[Cut] | None = None,
                 construction: list[tuple[str, tuple, Geometry | None]] | None = None,
                 part_of: dict | None = None, thickness: dict | None = None):
        self.parts = [] if parts is None else parts
        self.lines = [] if lines is None else lines  # (style, Nx2 polyline)
        self.hole_outlines = HoleOutlines() if hole_outlines is None else hole_outlines
        self.open_curves = [] if open_curves is None else open_curves
        # the exact curves behind every polygon handed to Manifold (:mod:`.exact`)
        self.exact = exact
        # engraving in exact form: ("line", p, q) | ("arc", c, r, a1, a2) | ("circle", c, r) |
        # ("poly", Nx2 closed polyline); with its style and source geometry
        self.strokes = [] if strokes is None else strokes
        self.shapes = {} if shapes is None else shapes  # Structure -> its final CrossSection
        self.own = {} if own is None else own  # Structure -> [(Geometry, CrossSection)]
        self.cuts = [] if cuts is None else cuts
        self.construction = [] if construction is None else construction
        self.part_of = {} if part_of is None else part_of  # Part name -> its Structure
        # Part name -> thickness in mm (`thickness 3 mm`: the structure's own, an ancestor's, or
        # the file's); parts without one are missing
        self.thickness = {} if thickness is None else thickness

    # faces that close on no area: [(structure, geometry or first curve of the loop, area
    # mm^2)], set by the renderer (an attribute, not a field: records of at most 12 fields
    # are made from templates, docs/dev/performance.md)
    empty_faces = ()
    # Part name -> kerf in mm (`kerf 0.15 mm`, found like the thickness); set by the renderer
    kerf = None
    # the through-cuts (:class:`Through`) of every part, and Part name -> (the part's shape
    # before its through-cuts, the same with every through-cut's band taken out: the webs the
    # wall check measures); the names of parts a through-cut split (their loops hold the cut
    # where it separates)
    through = ()
    # the curves of the sheet-level cuts (a `cut` in an assembly): (geometry, its cut
    # structure, [N x 2 polylines, mm])
    sheet_cuts = ()
    slit_shapes = {}
    # Structure -> its shape before its Fillet and Chamfer (holes cut): what W0405 tells the
    # rounding's own change from (a slot's cut at a rounded top is not the Fillet's)
    unfinished = {}
    split = frozenset()
    # Part name -> minimum wall in mm (`min_wall 0.3 mm`, found like the thickness; 0: the
    # wall checks off); parts without one are checked at the compile's default
    min_wall = None
    # [(geometry, message, hint[, code])]: an Offset or Shell that leaves nothing (E0406), a
    # Fillet or Chamfer at a spline's corner (E0407)
    shape_errors = ()
    # CubicSpline -> the Spline geometry it was drawn from (located refusals after the solve)
    spline_source = {}
    # Part name -> 4x4 matrix from the flat sheet (x, y in mm, z up through the thickness) to
    # the assembled product, when the program places parts (`Place`); else None
    placement = None
    # Part name -> its `Bend`s on the sheet, [(at mm, angle rad, inside radius mm)] (bends_of)
    bends = {}

    @property
    def circles(self) -> list[tuple[float, float, float]]:
        """Every circle of the solved model's outlines, absolute: (cx, cy, r) in mm."""
        if self.exact is None:
            return []
        return [c[1:] for c in self.exact.carriers if c[0] == "C"]

    def bounds(self):
        xs, ys = [], []
        for p in self.parts:
            if not p.shape.is_empty():
                b = p.shape.bounds()
                xs += [b[0], b[2]]
                ys += [b[1], b[3]]
        for _, pl in self.lines:
            if len(pl):
                xs += [pl[:, 0].min(), pl[:, 0].max()]
                ys += [pl[:, 1].min(), pl[:, 1].max()]
        if not xs:
            return (0.0, 0.0, 1.0, 1.0)
        return (min(xs), min(ys), max(xs), max(ys))
