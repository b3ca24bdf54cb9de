"""The one registry of AIDL's vocabulary: primitives, constraints, structural relations, functions.

Each :class:`Entry` gives its argument lists (one per constructor variant) with types, units and
defaults, a one-line doc, and a category.  The checker, the interpreter, ``aidl explain`` and the
docs all read this table.  Adding a synonym is one line in :data:`SYNONYMS`.

Argument types: ``point``, ``length``, ``angle``, ``number``, ``bool``, ``string``, ``points``
(list of points), ``line``, ``circular`` (Circle or Arc), ``centered`` (a shape with a
``center`` member, or a point), ``curve`` (Line, Circle or Arc),
``geometry``, ``boxed`` (anything with a bounding box: geometry or structure), ``any``.
"""
from __future__ import annotations

import math

from .base.records import Frozen, Record

REQUIRED = object()


class Arg(Frozen):
    """One argument of a registry entry's variant: name, AIDL type, default (REQUIRED if none), doc."""
    __slots__ = ("name", "type", "default", "doc", "kw_only")

    def __init__(self, name: str, type: str, default: object = REQUIRED, doc: str = "",
                 kw_only: bool = False):
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "type", type)
        object.__setattr__(self, "default", default)
        object.__setattr__(self, "doc", doc)
        # may only be given by keyword (e.g. ``construction=``)
        object.__setattr__(self, "kw_only", kw_only)

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    @property
    def shown_required(self) -> bool:
        """Written without a default in signatures: needed unless another is given (run hi)."""
        return self.required or self.doc.startswith("required unless")

    @property
    def default_text(self) -> str:
        """The default as AIDL source: ``true``, ``"x"``, ``none``, ``360 deg``, ``0``."""
        d = self.default
        if isinstance(d, bool):
            return "true" if d else "false"
        if d is None:
            return "none"
        if isinstance(d, str):
            return f'"{d}"'
        if isinstance(d, float) and self.type == "angle" and d:
            return f"{math.degrees(d):g} deg"
        return f"{d:g}" if isinstance(d, float) else str(d)


class Entry(Record):
    """A builtin (primitive, constraint, structural or function): its call variants, doc and members."""
    __slots__ = ("name", "category", "variants", "doc", "members", "varargs")

    def __init__(self, name: str, category: str, variants: list[tuple[Arg, ...]], doc: str,
                 members: dict[str, str] | None = None, varargs: bool = False):
        self.name = name
        self.category = category  # primitive | constraint | structural | function
        self.variants = variants
        self.doc = doc
        self.members = {} if members is None else members  # member -> type (primitives)
        # more positional arguments than the variant has join its last positional one, as a list:
        # ``Rigid(a, b, c, d)`` binds b = [b, c, d]
        self.varargs = varargs

    def signature(self, variant: tuple[Arg, ...] | None = None) -> str:
        vs = [variant] if variant is not None else self.variants
        outs = []
        for v in vs:
            parts = []
            for i, a in enumerate(v):
                if a.kw_only and (i == 0 or not v[i - 1].kw_only):
                    parts.append("*")
                if a.shown_required:
                    parts.append(f"{a.name}: {a.type}")
                else:
                    parts.append(f"{a.name}: {a.type} = {a.default_text}")
            if self.varargs:
                parts.insert(sum(not a.kw_only for a in v), "...")
            outs.append(f"{self.name}({', '.join(parts)})")
        return "\n".join(outs)


CONSTRUCTION = Arg("construction", "bool", False, "helper geometry: solved, not drawn",
                   kw_only=True)

OVERRUN = Arg("overrun", "bool", False, "the part of a cut that runs past the part's edge so "
              "it opens cleanly: drawn, left out of its structures' boxes", kw_only=True)

FLEXIBLE = Arg("flexible", "bool", False, "points given by literal coordinates are starting "
               "guesses only (the shape may bend), not a rigid shape", kw_only=True)

MIRROR = Arg("mirror", "any", None, "\"y\" (x -> -x), \"x\" (y -> -y) or a Line: the points "
             "are one half, followed by their mirror images in reverse order, exactly as "
             "`mirror(points, about)` (a point on the axis at either end is not repeated)",
             kw_only=True)

POINT_MEMBERS = {"x": "coordinate", "y": "coordinate"}
LINE_MEMBERS = {"start": "point", "end": "point", "midpoint": "point", "length": "length",
                "dx": "length", "dy": "length", "angle": "angle", "bb": "bbox"}
CIRCLE_MEMBERS = {"center": "point", "radius": "length", "diameter": "length", "bb": "bbox",
                  "top": "point", "bottom": "point", "left": "point", "right": "point"}
ARC_MEMBERS = {"center": "point", "start": "point", "end": "point", "through": "point",
               "radius": "length",
               "diameter": "length", "midpoint": "point", "bb": "bbox"}
RECT_MEMBERS = {"top_left": "point", "top_right": "point", "bottom_left": "point",
                "bottom_right": "point", "center": "point", "top": "line", "bottom": "line",
                "left": "line", "right": "line", "width": "length", "height": "length",
                "bb": "bbox"}
POLY_MEMBERS = {"points": "points", "edges": "lines", "center": "point", "centroid": "point",
                "bb": "bbox"}
REGPOLY_MEMBERS = POLY_MEMBERS | {"radius": "length", "diameter": "length", "side": "length",
                                  "across_flats": "length", "apothem": "length"}  # run ck
TRI_MEMBERS = {"a": "point", "b": "point", "c": "point", "points": "points",
               "ab": "line", "bc": "line", "ca": "line", "edges": "lines", "center": "point",
               "centroid": "point", "incenter": "point", "inradius": "length", "bb": "bbox",
               "base": "length", "height": "length"}
TRAP_MEMBERS = {k: v for k, v in RECT_MEMBERS.items() if k != "width"} | {
    "points": "points", "edges": "lines", "bottom_width": "length", "top_width": "length"}
ELLIPSE_MEMBERS = {"center": "point", "rx": "length", "ry": "length", "bb": "bbox"}
SLOT_MEMBERS = {"start": "point", "end": "point", "center": "point", "radius": "length",
                "width": "length", "length": "length", "spine": "line", "bb": "bbox"}
TEXT_MEMBERS = {"position": "point", "center": "point", "size": "length", "bb": "bbox",
                "text": "string"}
STAR_MEMBERS = POLY_MEMBERS | {"outer_radius": "length", "inner_radius": "length",
                               "tip_radius": "length"}
ARCSLOT_MEMBERS = {"center": "point", "start": "point", "end": "point", "midpoint": "point",
                   "radius": "length", "width": "length", "inner_radius": "length",
                   "outer_radius": "length", "bb": "bbox"}
SECTOR_MEMBERS = ARCSLOT_MEMBERS
DERIVED_MEMBERS = {"bb": "bbox"}
HULL_MEMBERS = {"bb": "bbox", "center": "point"}     # center: its box's (issue 105)
GROWN_MEMBERS = HULL_MEMBERS    # an Offset's or Shell's center: its shape's, else its box's
SPLINE_MEMBERS = {"points": "points", "start": "point", "end": "point", "bb": "bbox"}
BBOX_MEMBERS = {"left": "coordinate", "right": "coordinate", "top": "coordinate",
                "bottom": "coordinate", "width": "length", "height": "length",
                "center": "point", "center_x": "coordinate", "center_y": "coordinate",
                "top_left": "point", "top_right": "point", "bottom_left": "point",
                "bottom_right": "point"}
STRUCTURE_MEMBERS = {"bb": "bbox"}
DRAWING_MEMBERS = {"outlines": "shapes", "circles": "circles", "paths": "curves",
                   "origin": "point", "bb": "bbox"}


def _p(*variants, doc, members=None):
    return ("primitive", [tuple(v) + (CONSTRUCTION, OVERRUN) for v in variants], doc,
            members or {})


def _c(*variants, doc, cat="constraint", varargs=False):
    return (cat, [tuple(v) for v in variants], doc, {}, varargs)


def _op(doc: str, *more):
    """An operation on a ``target`` (geometry or a structure) and the arguments ``more``."""
    return _c([A("target", "boxed"), *more], cat="operation", doc=doc)


def _boxes(doc: str, *more):
    """A structural constraint between two boxed things ``a`` and ``b`` (and the arguments
    ``more`` after them)."""
    return _c([A("a", "boxed"), A("b", "boxed"), *more], cat="structural", doc=doc)


A = Arg
# the relations whose a or b may be a point, read as its coordinate (run z7's stocking tag:
# `AlignCenterX(cuff, sock.points[0])`, the natural way to put a box's centre over a point)
POINT_ALIGNS = frozenset({"AlignCenterX", "AlignCenterY", "AlignLeft", "AlignRight", "AlignTop",
                          "AlignBottom"})
_GAP = A("gap", "length", 0.0)      # the optional gap of Above, Below, LeftOf, RightOf
# GridPattern's staggered rows (issue 111: a perforated panel's or a bee hotel's honeycomb)
_STAGGER = A("stagger", "bool", False, "every odd row (r = 1, 3, ...) moved by half the column "
             "spacing: a honeycomb or brick pattern, cols copies in every row", kw_only=True)
# Scaled and Scale (issue 95): the same arguments, and the words models give them
_SCALE_ARGS = [A("target", "boxed"), A("factor", "number"), A("center", "point", None)]
_SCALE_WORDS = {"scale": "factor", "by": "factor", "k": "factor", "ratio": "factor",
                "about": "center", "origin": "center", "around": "center"}
_BY_WORDS = {"offset": "by", "delta": "by", "vector": "by", "step": "by"}
_DEFS = {
    # ------------------------------------------------------------ primitives
    "Point": _p([A("x", "length"), A("y", "length")], [A("at", "point")],
                doc="A point; its position is a starting guess.", members=POINT_MEMBERS),
    "Line": _p([A("start", "point"), A("end", "point")],
               [A("start", "point"), A("length", "length"), A("angle", "angle")],
               doc="A line segment between two points (starting guesses), or from start "
                   "by length and angle (held).",
               members=LINE_MEMBERS),
    "Circle": _p([A("center", "point"), A("radius", "length")],
                 [A("center", "point"), A("diameter", "length")],
                 doc="A circle; the radius (or diameter) is held.", members=CIRCLE_MEMBERS),
    "Arc": _p([A("center", "point"), A("start", "point"), A("end", "point")],
              [A("center", "point"), A("radius", "length"), A("start_angle", "angle"),
               A("end_angle", "angle")],
              [A("start", "point"), A("through", "point"), A("end", "point")],
              doc="A counter-clockwise arc from start to end about center; by points (guesses), "
                  "by radius and angles (held), or through three points (keywords start=, "
                  "through=, end=).", members=ARC_MEMBERS),
    "Rectangle": _p([A("center", "point"), A("width", "length"), A("height", "length"),
                     A("rotation", "angle", 0.0)],
                    [A("bottom_left", "point"), A("width", "length"), A("height", "length"),
                     A("rotation", "angle", 0.0)],
                    [A("corner", "point"), A("opposite", "point"), A("rotation", "angle", 0.0)],
                    [A("start", "point"), A("end", "point"), A("width", "length")],
                    doc="A rectangle (sizes and rotation held, position a guess). By two "
                        "corners only the rotation is held. By start, end: a bar along the "
                        "segment (members start, end; its height is its length).",
                    members=RECT_MEMBERS),
    "RoundedRectangle": _p([A("center", "point"), A("width", "length"), A("height", "length"),
                            A("corner_radius", "length", None), A("rotation", "angle", 0.0),
                            A("corner_radii", "any", None)],
                           [A("bottom_left", "point"), A("width", "length"), A("height", "length"),
                            A("corner_radius", "length", None), A("rotation", "angle", 0.0),
                            A("corner_radii", "any", None)],
                           [A("corner", "point"), A("opposite", "point"),
                            A("corner_radius", "length", None), A("rotation", "angle", 0.0),
                            A("corner_radii", "any", None)],
                           doc="A rectangle with rounded corners; corner_radii=[top_left, "
                               "top_right, bottom_right, bottom_left] (0: sharp).",
                           members=RECT_MEMBERS),
    "Triangle": _p([A("a", "point"), A("b", "point"), A("c", "point"), FLEXIBLE],
                   [A("center", "point"), A("base", "length"), A("height", "length"),
                    A("rotation", "angle", 0.0)],
                   doc="A triangle through three points (as Polygon), or an isosceles "
                       "one by base and height (held; a, b on the base, c the apex, center the "
                       "bounding-box center); members base (|ab|) and height (c from ab).", members=TRI_MEMBERS),
    "Trapezoid": _p([A("center", "point"), A("bottom_width", "length"), A("top_width", "length"),
                     A("height", "length"), A("rotation", "angle", 0.0)],
                    doc="An isosceles trapezoid; widths, height and rotation are held, the "
                        "center is a starting guess.", members=TRAP_MEMBERS),
    "Ellipse": _p([A("center", "point"), A("rx", "length"), A("ry", "length"),
                   A("rotation", "angle", 0.0),
                   A("start_angle", "angle", None, "with end_angle: the open arc of the "
                     "ellipse counter-clockwise between these parameter angles",
                     kw_only=True),
                   A("end_angle", "angle", None, "see start_angle", kw_only=True)],
                  doc="An ellipse with semi-axes rx (along the rotation) and ry; semi-axes and "
                      "rotation are held, the center is a starting guess. Exact in every "
                      "output (an Offset, Shell or kerf of it: within 1e-4 mm).",
                  members=ELLIPSE_MEMBERS),
    "Polygon": _p([A("points", "points"), FLEXIBLE, MIRROR],
                  doc="A closed polygon; literal coordinates make it rigid (it moves, keeps "
                      "its shape) unless flexible=true; other points are starting guesses; "
                      "mirror=\"y\": the points are the left or right half. No radius=: "
                      "Fillet(p, r) rounds its corners.",
                  members=POLY_MEMBERS),
    "Drawing2D": _p([A("file", "string"), A("layer", "any", None), A("color", "any", None),
                     A("id", "any", None), A("units", "string", None), A("at", "point", None),
                     A("rotation", "angle", 0.0),
                     A("close_tolerance", "length", None, "chains whose ends meet within "
                       "this are closed (default 0.05 mm)", kw_only=True),
                     A("cut", "any", None, "layers or colours cut (outlines, holes)",
                       kw_only=True),
                     A("engrave", "any", None, "layers or colours engraved", kw_only=True),
                     A("ignore", "any", None, "layers or colours left out", kw_only=True),
                     A("roles", "string", None, "\"laser\": black and blue cut, green "
                       "engraved, red left out (Boxes.py)", kw_only=True)],
                    doc="A .dxf/.svg file beside the program as exact curves, where the "
                        "file puts it (at= moves it); inner loops are holes; cut=, engrave=, "
                        "ignore= (layers or colours), roles=\"laser\", close_tolerance=.",
                    members=DRAWING_MEMBERS),
    "Polyline": _p([A("points", "points"), A("closed", "bool", False), FLEXIBLE, MIRROR],
                   doc="Open chain of lines (mirror=\"y\": written by one half); rounded "
                       "corners: closed=true and Fillet.",
                   members=SPLINE_MEMBERS),
    "Spline": _p([A("points", "points"), A("closed", "bool", False),
                  A("corners", "any", None, "indices of points where the curve turns "
                    "sharply (tangent-discontinuous)", kw_only=True), FLEXIBLE, MIRROR],
                 doc="A smooth curve through the points; closed=true: an outline; "
                     "corners=[i]: sharp; mirror=\"y\": the points are one half. Its box is "
                     "the curve's, which may bulge past its points: assert on `points[i]`.",
                 members=SPLINE_MEMBERS),
    "Bezier": _p([A("points", "points"), A("closed", "bool", False), FLEXIBLE],
                 doc="Cubic Bézier chain: p0, c1, c2, p1, ... (3k+1 points).",
                 members=SPLINE_MEMBERS),
    "RegularPolygon": _p([A("center", "point"), A("radius", "length"), A("sides", "number"),
                          A("rotation", "angle", 0.0)],
                         [A("center", "point"), A("across_flats", "length"), A("sides", "number"),
                          A("rotation", "angle", 0.0)],
                         [A("center", "point"), A("side", "length"), A("sides", "number"),
                          A("rotation", "angle", 0.0)],
                         doc="A rigid regular polygon; radius (center to vertex), across_flats "
                             "(between opposite sides) or side (one edge's length), sides and "
                             "rotation are held; first vertex at +x.", members=REGPOLY_MEMBERS),
    "Slot": _p([A("start", "point"), A("end", "point"), A("radius", "length")],
               [A("start", "point"), A("end", "point"), A("width", "length")],
               [A("center", "point"), A("length", "length"), A("width", "length"),
                A("rotation", "angle", 0.0)],
               [A("start", "point"), A("length", "length"), A("angle", "angle"),
                A("width", "length")],
               doc="A stadium around the segment start-end (its end arcs' centers); radius = "
                   "width/2 is held; by center or start, length and rotation "
                   "or angle are held too.",
               members=SLOT_MEMBERS),
    "ArcSlot": _p([A("center", "point"), A("radius", "length"), A("start_angle", "angle"),
                   A("end_angle", "angle"), A("width", "length")],
                  doc="A slot `width` wide along the counter-clockwise arc of `radius` about "
                      "center from start_angle to end_angle (all held): the angles are its "
                      "end caps' centers (start, end), the round ends reach width / 2 past them.",
                  members=ARCSLOT_MEMBERS),
    "Sector": _p([A("center", "point"), A("radius", "length"), A("start_angle", "angle"),
                  A("end_angle", "angle"),
                  A("inner_radius", "length", 0.0, "> 0: an annulus segment (a ring's piece) "
                    "instead of a pie slice", kw_only=True)],
                 doc="Pie slice; inner_radius=: annulus.",
                 members=SECTOR_MEMBERS),
    "Star": _p([A("center", "point"), A("points", "number"), A("outer_radius", "length"),
                A("inner_radius", "length"), A("rotation", "angle", 0.0),
                A("tip_radius", "length", 0.0, "> 0: each tip rounded by an arc of this radius "
                  "tangent to its two sides (the notches stay sharp)", kw_only=True)],
               doc="A rigid star: `points` tips at outer_radius, notches at inner_radius, "
                   "first tip up (+y); tip_radius=: rounded tips (outer_radius stays the "
                   "sharp star's; `.bb` is the rounded one's size).",
               members=STAR_MEMBERS),
    "Offset": _p([A("shape", "any"), A("distance", "length"), A("join", "string", "round")],
                 doc="The shape (a list: their union) grown by distance (negative: shrunk), "
                     "join \"round\" or \"miter\"; the shape is not drawn.",
                 members=GROWN_MEMBERS),
    "Inset": _p([A("shape", "any"), A("distance", "length"), A("join", "string", "round")],
                doc="Offset(shape, -distance).", members=GROWN_MEMBERS),
    "Shell": _p([A("shape", "geometry"), A("thickness", "length"), A("join", "string", "round")],
                doc="A wall `thickness` wide outside the shape (negative: inside); the shape "
                    "is not drawn.", members=GROWN_MEMBERS),
    "Stroke": _p([A("path", "any"), A("width", "length"),
                  A("cap", "string", "round", "\"round\" (the path's Minkowski sum with a "
                    "disc) or \"flat\" (ends cut square)", kw_only=True)],
                 doc="Band along an open path; round ends, or cap=\"flat\" for square ones.",
                 members=DERIVED_MEMBERS),
    "Hull": _p([A("shapes", "any")],
               [A("shape1", "geometry"), A("shape2", "geometry")]
               + [A(f"shape{i}", "geometry", None) for i in range(3, 7)],
               doc="The convex hull of shapes (a list, or up to six; a Point: a sharp "
                   "corner; a Line or an Arc: its points), not drawn.",
               members=HULL_MEMBERS),
    "Intersect": _p([A("shapes", "any")],
                    [A("shape1", "any"), A("shape2", "any")]
                    + [A(f"shape{i}", "any", None) for i in range(3, 7)],
                    doc="The area common to closed shapes; open Lines, Arcs, Polylines "
                        "among them are clipped to it. Not drawn.",
                    members=DERIVED_MEMBERS),
    "Text": _p([A("text", "string"), A("position", "point", None, "required unless along= is given"),
                A("size", "length", 5.0),
                A("anchor", "string", "middle"), A("valign", "string", "baseline"),
                A("rotation", "angle", 0.0),
                A("along", "any", None, "a Circle or Arc: the text follows it clockwise, "
                  "each letter upright, instead of a position", kw_only=True),
                A("angle", "angle", None, "with along=: where on the circle the position "
                  "point goes (default: the arc's middle, a circle's top)", kw_only=True),
                A("flip", "bool", False, "with along=: read counter-clockwise, letters' up "
                  "toward the center (text under a circle, readable)", kw_only=True),
                A("stencil", "bool", False, "the letters as openings cut out (in a hole or a "
                  "solid), their islands held by bridges", kw_only=True),
                A("weight", "length", None, "with stencil=: the letters' stroke width "
                  "(default size / 6)", kw_only=True),
                A("bridge", "length", None, "with stencil=: the bridges' width (default "
                  "size / 10)", kw_only=True),
                A("max_width", "length", None, "the text's width along its baseline at most "
                  "this: a longer text is drawn at the size that fits (note W0113)",
                  kw_only=True),
                A("font", "string", None, "the letters as the closed outlines of a font: "
                  "\"sans\", \"serif\", \"Family:Bold\" or a .ttf/.otf/.ttc file beside "
                  "the program; material in a solid, openings in a hole, engraved outlines "
                  "in a drawing", kw_only=True),
                A("fill", "bool", False, "with font= in a drawing: the letters' area "
                  "engraved (a fill layer: SVG fill, DXF HATCH, LightBurn Scan, G-code "
                  "line fill), not only their outlines", kw_only=True)],
               doc="Text: single strokes in a drawing, or with font= the letters' closed "
                   "outlines (in a solid, hole or drawing); size: cap height (a capital "
                   "~ size wide, a small letter ~ 0.7 x size; little room: max_width=); "
                   "anchor: start, middle, end; valign: baseline, middle, top, bottom; rotation about "
                   "position; along=circle, angle=; stencil=true (in a hole): cut out; "
                   "max_width=: shrinks to fit; fill=true (font=, in a drawing): the "
                   "letters' area engraved.", members=TEXT_MEMBERS),
    # ------------------------------------------------------------ geometric constraints
    "Coincident": _c([A("a", "geometry"), A("b", "geometry")],
                     doc="Two points are the same point (a point and a line, circle, arc or "
                         "ellipse: on it)."),
    "Horizontal": _c([A("a", "geometry"), A("b", "point", None)],
                     doc="A line, or the two points a and b, are horizontal."),
    "Vertical": _c([A("a", "geometry"), A("b", "point", None)],
                   doc="A line, or the two points a and b, are vertical."),
    "Fixed": _c([A("a", "any")],
                doc="Hold a point, geometry or structure (a list: each) where it starts."),
    "Distance": _c([A("a", "geometry"), A("b", "geometry"), A("distance", "length")],
                   doc="Distance between two points, from a point to a line, or between two "
                       "parallel lines (they are made parallel)."),
    "HorizontalDistance": _c([A("a", "point"), A("b", "point"), A("distance", "length")],
                             doc="b.x - a.x == distance."),
    "VerticalDistance": _c([A("a", "point"), A("b", "point"), A("distance", "length")],
                           doc="b.y - a.y == distance."),
    "At": _c([A("a", "point"), A("b", "point"), A("dx", "length", 0.0), A("dy", "length", 0.0)],
             doc="a == b + (dx, dy)."),
    "Length": _c([A("line", "line"), A("length", "length")], doc="A line's length."),
    "Radius": _c([A("circle", "circular"), A("radius", "length")],
                 doc="A circle's or arc's radius."),
    "Diameter": _c([A("circle", "circular"), A("diameter", "length")],
                   doc="A circle's or arc's diameter."),
    "Equal": _c([A("a", "any"), A("b", "any")],
                doc="Equal lengths (lines), radii (circles/arcs), sizes (rectangles) or values."),
    "Parallel": _c([A("a", "line"), A("b", "line")], doc="Two lines are parallel."),
    "Perpendicular": _c([A("a", "line"), A("b", "line")], doc="Two lines are perpendicular."),
    "Tangent": _c([A("a", "curve"), A("b", "curve")],
                  doc="A line and a circle/arc, or two circles/arcs, touch tangentially."),
    "Symmetric": _c([A("a", "geometry"), A("b", "geometry"), A("about", "line")],
                    doc="a and b are mirror images about a line."),
    "Midpoint": _c([A("point", "point"), A("line", "line")],
                   doc="The point is the line's midpoint."),
    "OnLine": _c([A("point", "point"), A("line", "line")],
                 doc="The point lies on the (infinite) line."),
    "OnCircle": _c([A("point", "point"), A("circle", "circular")],
                   doc="The point lies on the circle or the arc's circle."),
    "Collinear": _c([A("a", "geometry"), A("b", "geometry"), A("c", "point", None)],
                    doc="Two lines lie on one infinite line, or three points lie on one line."),
    "Concentric": _c([A("a", "centered"), A("b", "centered")],
                     doc="Shapes with a center (or points) share it."),
    "Angle": _c([A("a", "line"), A("b", "line"), A("angle", "angle")],
                doc="The angle from line a to line b; the sense (cw/ccw) nearest the starting "
                    "geometry is used."),
    # ------------------------------------------------------------ structural
    "Above": _boxes("a sits on top of b: a.bb.bottom == b.bb.top + gap.", _GAP),
    "Below": _boxes("a sits under b: a.bb.top == b.bb.bottom - gap.", _GAP),
    "LeftOf": _boxes("a touches b from the left: a.bb.right == b.bb.left - gap.", _GAP),
    "RightOf": _boxes("a touches b from the right: a.bb.left == b.bb.right + gap.", _GAP),
    "Gap": _boxes("Empty space between a's and b's bounding boxes along axis \"x\" or \"y\", "
                  "whichever side each is on.", A("gap", "length"), A("axis", "string", "x")),
    "Inside": _boxes("a's bounding box lies within b's, at least margin in.",
                     A("margin", "length", 0.0)),
    "CenterInside": _boxes("a is centered in b: their bounding-box centers coincide (a Star or "
                            "RegularPolygon: its own center)."),
    "Taller": _boxes("a.bb.height >= b.bb.height."),
    "Wider": _boxes("a.bb.width >= b.bb.width."),
    "AlignCenterX": _boxes("Same horizontal center: a.bb.center_x == b.bb.center_x "
                           "(a point: its x; a Star or RegularPolygon: its center's)."),
    "AlignCenterY": _boxes("Same vertical center: a.bb.center_y == b.bb.center_y "
                           "(a point: its y; a Star or RegularPolygon: its center's)."),
    "AlignLeft": _boxes("a.bb.left == b.bb.left (a point: its x)."),
    "AlignRight": _boxes("a.bb.right == b.bb.right (a point: its x)."),
    "AlignTop": _boxes("a.bb.top == b.bb.top (a point: its y)."),
    "AlignBottom": _boxes("a.bb.bottom == b.bb.bottom (a point: its y)."),
    # ------------------------------------------------------------ placement (3D)
    "Place": _c([A("part", "boxed"), A("position", "any", None), A("rotation", "any", None),
                 A("face", "any", None), A("up", "any", None), A("on", "any", None)],
                cat="placement",
                doc="Place a part (or an assembly) in 3D for the assembled view: its local "
                    "point p (x, y in its frame, z up through its thickness) goes to "
                    "R p + position; position (x, y, z) lengths; R by rotation (rx, ry, rz) "
                    "angles turned about x, then y, then z, or by face= (where its top face, "
                    "the side its engraving and countersinks are on, looks: \"front\" is -y, "
                    "\"back\" +y, \"left\", \"right\", \"up\" +z, \"down\", \"+x\" ... or "
                    "three numbers) and up= (where its drawing's +y goes; default \"up\", or "
                    "\"back\" for a face up or down); all known before solving. on= another part "
                    "(or its structure, or an assembly): position and turn are in its frame "
                    "(x, y as drawn in it, z up from its bottom face; a position of two "
                    "numbers stands on its top face), so the part follows it wherever it is "
                    "placed."),
    "Bend": _c([A("part", "boxed"), A("at", "length"), A("angle", "angle"),
                A("radius", "length", 0.0)],
               cat="placement",
               doc="Bend a part (a living hinge's band, a folded panel) in the assembled view "
                   "only: along the line x = at of its frame (parallel to y, the middle of the "
                   "bend), by angle (positive: its top face, z = thickness, inside the bend) "
                   "round an inside radius; the bend is angle * (radius + thickness / 2) wide "
                   "on the sheet, the part left of it stays where Place puts it, the rest "
                   "turns; all known before solving. The sheet stays flat."),
    # ------------------------------------------------------------ operations
    "Mirrored": _op("A copy of geometry or a structure mirrored about a line; it follows the "
                    "original. Of a list (`Mirrored(legs, axis)`): the list of each item's "
                    "mirror image, in order. `Mirror(a, b, about)` is the Symmetric "
                    "constraint.",
                    A("about", "line")),
    "Scaled": _c(_SCALE_ARGS, cat="operation",
                 doc="A copy scaled by factor about center (the origin unless given)."),
    "Scale": _c(_SCALE_ARGS, cat="operation",
                doc="Resize a whole structure or shape in place about its own centre (its "
                    "box's, unless center=), never by rewriting its numbers: `Scale(plaque, "
                    "0.7)` is 30 % smaller; the constraints that placed it place the scaled one "
                    "(the original: construction `plaque_original`)."),
    "Translated": _op("A copy moved by the vector by.",
                      A("by", "point")),
    "Translate": _op("Move a structure or shape in place by the vector by.",
                     A("by", "point")),
    "Flip": _op("Mirror a structure or shape in place about a line.",
                A("about", "line")),
    "LinearPattern": _op("count instances in all, each moved by step (a vector) from the last; "
                         "gives the list [original, copy1, ...].",
                         A("count", "number"), A("step", "point")),
    "CircularPattern": _c([A("target", "boxed"), A("count", "number"), A("center", "point"),
                           A("angle", "angle", 2 * math.pi), A("start_angle", "angle", 0.0)],
                          [A("target", "boxed"), A("count", "number"), A("center", "point"),
                           A("step", "angle"), A("start_angle", "angle", 0.0)], cat="operation",
                          doc="count instances turned counter-clockwise about center: angle is "
                              "the span from first to last (360 deg: evenly all round), step the "
                              "angle between neighbours; gives [original, copy1, ...]; "
                              "start_angle turns all further from where the original is drawn "
                              "(original: construction), so a first copy at 45 deg is the "
                              "original on +x with start_angle=45, or the original at 45 with "
                              "none."),
    "GridPattern": _c([A("target", "boxed"), A("rows", "number"), A("cols", "number"),
                       A("spacing", "any"), _STAGGER],
                      [A("target", "boxed"), A("rows", "number"), A("cols", "number"),
                       A("col_spacing", "length"), A("row_spacing", "length"), _STAGGER],
                      cat="operation",
                      doc="copy (r, c) moved by (c*dx, r*dy); spacing (dx, dy) or a length; "
                          "gives one flat list, row by row: copy (r, c) is `g[r * cols + c]`; "
                          "stagger=true: every odd row also moved by dx/2 (a honeycomb or "
                          "brick pattern)."),
    "CornerPattern": _c([A("target", "boxed"), A("rect", "boxed"), A("inset", "any", 0.0,
                                                                     "a length, or (dx, dy)")],
                        [A("target", "boxed"), A("at", "points")], cat="operation",
                        doc="target centered on each corner of a Rectangle or "
                            "RoundedRectangle rect (inset inward: length or (dx, dy)), or on "
                            "each point of at: the original at the bottom-left corner (at[0]), "
                            "copies at the others; what is Fixed stays put (a Fixed original "
                            "pulls the plate)."),
    "CutInto": _c([A("hole", "any"), A("part", "boxed")], cat="operation",
                  doc="A hole or cut (or drawing) declared in an assembly cuts (engraves) a solid "
                      "of it, e.g. a template instance's part (`CutInto(lid_hole, box.lid)`: "
                      "a hole in finger_box's lid; a pattern's copies follow); written "
                      "where both are, placed as usual."),
    "Rigid": _c([A("a", "any"), A("b", "any", None, "and every further argument, as a list")],
                cat="operation", varargs=True,
                doc="any number of shapes, structures (drawings too) or lists of them keep "
                    "their placement to each other; a structure moves, never bends."),
    "AllowOverlap": _c([A("a", "any"), A("b", "any", doc="and every further argument, as "
                         "a list")], [A("a", "any", doc="a list: its items")],
                       cat="operation", varargs=True,
                       doc="these may overlap: refilled hole (W0501), holes (W0508, "
                           "W0512), assembly parts (W0511), windows (W0515), engraving and "
                           "`self` or a hole it crosses (W0505)."),
    "Countersink": _c([A("hole", "any"), A("diameter", "length"),
                       A("angle", "angle", math.pi / 2)], cat="operation",
                      doc="Flat-head screw seat: a cone (top diameter, included angle) "
                          "atop round holes (a hole, its Circle or a list)."),
    "Counterbore": _c([A("hole", "any"), A("diameter", "length"), A("depth", "length")],
                      cat="operation",
                      doc="Socket-head screw seat: a flat recess atop round holes."),
    "Fillet": _c([A("radius", "length")], [A("at", "any"), A("radius", "length")],
                 [A("a", "any"), A("b", "any"), A("radius", "length")],
                 cat="operation",
                 doc="Round every corner of this solid's (or hole's) final outline, holes "
                     "included, or only the corners at: a point, [edge1, edge2] (where they "
                     "meet or cross), [shape1, shape2] or [edge, shape] (where their outlines "
                     "cross: a tab on a disc; not a Hull's or an Arc's, whose corner is given by "
                     "its point), a shape's corners (`Fillet(plate, 4)`), or a list of "
                     "these. In a sharp tip of angle a the arc lies r / sin(a / 2) - r from the "
                     "point (keep a long tip: a Hull with a Circle)."),
    "Chamfer": _c([A("distance", "length")], [A("at", "any"), A("distance", "length")],
                  [A("a", "any"), A("b", "any"), A("distance", "length")],
                  cat="operation",
                  doc="Cut every convex corner of this solid's final outline (or those at, "
                      "as Fillet) with two legs of distance."),
}

# name -> canonical name.  One line per synonym.
SYNONYMS: dict[str, str] = {
    "Orthogonal": "Perpendicular",
    "Coincide": "Coincident",
    "Join": "Coincident",
    "Fix": "Fixed",
    "Lock": "Fixed",
    "Anchor": "Fixed",
    "Same": "Equal",
    "EqualLength": "Equal",
    "EqualRadius": "Equal",
    "Centered": "CenterInside",
    "OnTopOf": "Above",
    "Over": "Above",
    "Under": "Below",
    "Underneath": "Below",
    "ToTheLeftOf": "LeftOf",
    "ToTheRightOf": "RightOf",
    "Within": "Inside",
    "Contains": "Inside",            # argument order swapped: see SWAPPED
    "AtMidpoint": "Midpoint",
    "Mirror": "Symmetric",
    "Move": "Translate",
    "Moved": "Translated",
    "Shift": "Translate",
    "Resize": "Scale",
    "Resized": "Scaled",
    "MirrorSymmetric": "Symmetric",
    "DistanceX": "HorizontalDistance",
    "DistanceY": "VerticalDistance",
    "HorizontallyCentered": "AlignCenterX",
    "VerticallyCentered": "AlignCenterY",
    "PointOnLine": "OnLine",
    "OnArc": "OnCircle",
    "Outset": "Offset",
    "Grow": "Offset",
    "Expand": "Offset",
    "Shrink": "Inset",
    "ConvexHull": "Hull",
    "ImportDXF": "Drawing2D",
    "ImportSVG": "Drawing2D",
    "ImportDrawing": "Drawing2D",
    "DXF": "Drawing2D",
    "SVG": "Drawing2D",
    "convex_hull": "Hull",
    "Intersection": "Intersect",
    "Clip": "Intersect",
    "Common": "Intersect",
    "RectangularPattern": "GridPattern",
    "ArrayPattern": "GridPattern",
    "AtOffset": "At",
    "IntendedOverlap": "AllowOverlap",
    "RigidGroup": "Rigid",
    "MoveTogether": "Rigid",
    "OverlapOK": "AllowOverlap",
    "PlaceAt": "At",
    "AtCorners": "CornerPattern",
    "CounterSink": "Countersink",
    "Csink": "Countersink",
    "CounterBore": "Counterbore",
    "Cbore": "Counterbore",
    "BSpline": "Spline",
    "PolyLine": "Polyline",
    "LineString": "Polyline",
    "Path": "Polyline",
    "OpenPolygon": "Polyline",
    "Chain": "Polyline",
    "ZigZag": "Polyline",
    "Sweep": "Stroke",
    "Band": "Stroke",
    "Thicken": "Stroke",
    "ThickLine": "Stroke",
    "Wire": "Stroke",
    "Trace": "Stroke",
    "Wedge": "Sector",
    "Pie": "Sector",
    "PieSlice": "Sector",
    "CircularSector": "Sector",
    "AnnularSector": "Sector",
    "AnnulusSegment": "Sector",
    "RingSegment": "Sector",
    "Interpolate": "Spline",
    "InterpolatedCurve": "Spline",
    "SmoothCurve": "Spline",
    "Curve": "Spline",
    "FitSpline": "Spline",
    "CubicSpline": "Spline",
    "BezierCurve": "Bezier",
    "CubicBezier": "Bezier",
    "BezierPath": "Bezier",
    "BezierChain": "Bezier",
    "BezierSpline": "Bezier",
}

# Offset's and Inset's argument synonyms (Shell's too, with thickness for distance)
_OFFSET = {"target": "shape", "geometry": "shape", "of": "shape", "amount": "distance",
           "by": "distance", "offset": "distance", "delta": "distance", "r": "distance",
           "radius": "distance", "style": "join", "join_type": "join", "corners": "join"}

# argument synonyms: entry name -> {name a model writes -> canonical argument name}.  One line
# per synonym; the checker renames silently, and only where the canonical argument belongs to
# the chosen form and is not given as well.  "*" applies to every entry (each alias lists its
# candidates; the first one the form has is used).
ARG_SYNONYMS: dict[str, dict[str, str | tuple[str, ...]]] = {
    "*": {"r": "radius", "rad": "radius", "d": ("diameter", "distance"), "dia": "diameter",
          "w": "width", "h": "height", "pos": ("position", "center"), "rot": "rotation",
          "n": ("count", "sides", "points"), "num": ("count", "sides", "points")},
    "Text": {"center": "position", "at": "position", "height": "size", "string": "text",
             "font_size": "size", "on": "along", "path": "along", "arc": "along",
             "circle": "along", "curve": "along", "at_angle": "angle", "start_angle": "angle",
             "around": "along", "inward": "flip", "inside": "flip", "reverse": "flip",
             "halign": "anchor", "align": "anchor", "h_align": "anchor"},
    "Place": {"normal": "face", "facing": "face", "faces": "face", "top": "face",
              "up_vector": "up", "upward": "up", "onto": "on", "relative_to": "on",
              "parent": "on", "attach_to": "on", "at": "position"},
    "Symmetric": {"axis": "about", "line": "about", "mirror": "about"},
    "Mirrored": {"axis": "about", "line": "about", "mirror": "about"},
    "Flip": {"axis": "about", "line": "about", "mirror": "about"},
    "Scaled": _SCALE_WORDS, "Scale": _SCALE_WORDS, "Translated": _BY_WORDS, "Translate": _BY_WORDS,
    "Circle": {"position": "center", "at": "center"},
    "Rectangle": {"position": "center", "at": "center", "size_x": "width", "size_y": "height",
                  "angle": "rotation", "p1": "start", "p2": "end", "thickness": "width"},
    "RegularPolygon": {"n_sides": "sides", "num_sides": "sides", "af": "across_flats",
                       "flat_to_flat": "across_flats", "side_length": "side",
                       "edge_length": "side", "edge": "side", "length": "side"},
    "Slot": {"p1": "start", "p2": "end", "a": "start", "b": "end", "angle": "rotation",
             "direction": "angle", "heading": "angle"},
    "Line": {"p1": "start", "p2": "end", "from": "start", "to": "end", "direction": "angle",
             "heading": "angle", "origin": "start"},
    "At": {"point": "a", "p": "a", "to": "b", "of": "b", "reference": "b", "base": "b",
           "x": "dx", "y": "dy", "offset_x": "dx", "offset_y": "dy"},
    "ArcSlot": {"position": "center", "at": "center", "start": "start_angle",
                "end": "end_angle", "from_angle": "start_angle", "to_angle": "end_angle",
                "angle1": "start_angle", "angle2": "end_angle", "path_radius": "radius"},
    "Sector": {"position": "center", "at": "center", "start": "start_angle",
               "end": "end_angle", "from_angle": "start_angle", "to_angle": "end_angle",
               "angle1": "start_angle", "angle2": "end_angle", "outer_radius": "radius",
               "r_outer": "radius", "outer": "radius", "r_inner": "inner_radius",
               "inner": "inner_radius", "hole_radius": "inner_radius"},
    "Star": {"position": "center", "at": "center", "n_points": "points", "tips": "points",
             "count": "points", "num_points": "points", "r_outer": "outer_radius",
             "r_inner": "inner_radius", "radius": "outer_radius",
             "outer": "outer_radius", "inner": "inner_radius", "tip_fillet": "tip_radius",
             "fillet": "tip_radius", "corner_radius": "tip_radius", "round": "tip_radius",
             "rounding": "tip_radius", "tip_round": "tip_radius", "tip_r": "tip_radius"},
    "Offset": _OFFSET,
    "Inset": _OFFSET,
    "Shell": {**_OFFSET, "amount": "thickness", "by": "thickness", "offset": "thickness",
              "delta": "thickness", "r": "thickness", "radius": "thickness", "wall": "thickness",
              "t": "thickness", "width": "thickness", "distance": "thickness",
              "wall_thickness": "thickness"},
    "Spline": {"through": "points", "pts": "points", "vertices": "points",
               "fit_points": "points", "through_points": "points", "periodic": "closed",
               "cyclic": "closed", "is_closed": "closed", "loop": "closed",
               "sharp": "corners", "sharp_points": "corners", "cusps": "corners",
               "kinks": "corners", "corner_points": "corners", "sharp_corners": "corners"},
    "Countersink": {"holes": "hole", "of": "hole", "d": "diameter", "head": "diameter",
                    "head_diameter": "diameter", "included_angle": "angle"},
    "Counterbore": {"holes": "hole", "of": "hole", "d": "diameter", "head": "diameter",
                    "head_diameter": "diameter", "deep": "depth"},
    "Polyline": {"through": "points", "pts": "points", "vertices": "points",
                 "is_closed": "closed", "loop": "closed", "close": "closed"},
    "Bezier": {"control_points": "points", "controls": "points", "ctrl": "points",
               "pts": "points", "poles": "points", "is_closed": "closed", "loop": "closed",
               "close": "closed", "cyclic": "closed", "periodic": "closed"},
    "Stroke": {"along": "path", "curve": "path", "spine": "path", "shape": "path",
               "of": "path", "paths": "path", "thickness": "width", "stroke_width": "width",
               "line_width": "width", "caps": "cap", "end": "cap", "ends": "cap",
               "cap_style": "cap", "end_cap": "cap"},
    "Intersect": {"items": "shapes", "objects": "shapes", "geometries": "shapes",
                  "children": "shapes", "of": "shapes"},
    "Hull": {"items": "shapes", "objects": "shapes", "geometries": "shapes",
             "children": "shapes", "of": "shapes"},
    "RoundedRectangle": {"radii": "corner_radii", "corner_radius_list": "corner_radii",
                         "radius": "corner_radius", "r": "corner_radius",
                         "fillet": "corner_radius", "fillet_radius": "corner_radius",
                         "rounding": "corner_radius", "round": "corner_radius",
                         "rounded": "corner_radius", "corner_r": "corner_radius",
                         "corner_rounding": "corner_radius", "corner_fillet": "corner_radius",
                         "round_radius": "corner_radius", "rounding_radius": "corner_radius",
                         "position": "center", "at": "center"},
    "CircularPattern": {"number": "count", "copies": "count", "around": "center",
                        "origin": "center", "span": "angle", "total_angle": "angle",
                        "spacing": "step", "pitch": "step", "angle_step": "step",
                        "start": "start_angle", "offset_angle": "start_angle",
                        "phase": "start_angle", "first_angle": "start_angle"},
    "LinearPattern": {"number": "count", "copies": "count", "spacing": "step",
                      "offset": "step", "delta": "step", "pitch": "step"},
    "GridPattern": {"nrows": "rows", "n_rows": "rows", "ny": "rows", "columns": "cols",
                    "ncols": "cols", "n_cols": "cols", "nx": "cols", "n_columns": "cols",
                    "step": "spacing", "pitch": "spacing", "gap": "spacing",
                    "column_spacing": "col_spacing", "x_spacing": "col_spacing",
                    "dx": "col_spacing", "y_spacing": "row_spacing", "dy": "row_spacing"},
    "CornerPattern": {"rectangle": "rect", "shape": "rect", "of": "rect", "on": "rect",
                      "margin": "inset", "offset": "inset", "edge_distance": "inset",
                      "corners": "at", "points": "at", "positions": "at", "locations": "at"},
    "Fillet": {"r": "radius", "corner": "at", "corners": "at", "where": "at"},
    "Chamfer": {"size": "distance", "d": "distance", "length": "distance", "corner": "at",
                "corners": "at", "where": "at"},
}

# synonyms whose arguments mean the canonical entry's arguments in another order:
# synonym -> {argument name as written -> canonical argument name}.  ``Contains(a, b)`` is
# ``Inside(b, a)``: positional and keyword arguments are both renamed.
SWAPPED: dict[str, dict[str, str]] = {
    "Contains": {"a": "b", "b": "a"},
}

# one-line docs of synonyms that do not simply mean the canonical entry
SYNONYM_DOCS: dict[str, str] = {
    "Contains": "a's bounding box contains b's: Contains(a, b) is Inside(b, a).",
}

# functions usable in expressions: name -> (min args, max args, doc)
FUNCTIONS: dict[str, tuple[int, int, str]] = {
    "sin": (1, 1, "sine of an angle (a bare number is radians)"),
    "cos": (1, 1, "cosine of an angle (a bare number is radians)"),
    "tan": (1, 1, "tangent of an angle (a bare number is radians)"),
    "asin": (1, 1, "arc sine, an angle"), "acos": (1, 1, "arc cosine, an angle"),
    "atan": (1, 1, "arc tangent, an angle"), "atan2": (2, 2, "atan2(y, x), an angle"),
    "sqrt": (1, 1, "square root"), "abs": (1, 1, "absolute value"),
    "exp": (1, 1, "e to a plain number"), "log": (1, 1, "natural logarithm of a positive number"),
    "min": (1, 64, "smallest value (or of one list)"), "max": (1, 64, "largest value"),
    "norm": (1, 1, "length of a vector/point (x, y)"), "square": (1, 1, "x * x"),
    "len": (1, 1, "number of items of a list or string"),
    "sum": (1, 1, "sum of a list of numbers, lengths or angles (0 for an empty list)"),
    "range": (1, 3, "range(stop), range(start, stop), range(start, stop, step)"),
    "round": (1, 2, "round to a number of decimals"), "floor": (1, 1, "round down"),
    "ceil": (1, 1, "round up"), "str": (1, 1, "text of a value"),
    "radians": (1, 1, "a bare number of degrees as an angle (an angle: itself)"), "degrees": (1, 1, "an angle as a bare number of degrees"),
    "distance": (2, 2, "distance between two points (a length expression); in an assert, "
                       "of shapes or structures too: their outlines' least distance"),
    "polar": (3, 3, "polar(center, radius, angle): the point `radius` from `center` at `angle` "
                    "counter-clockwise from +x (exact, follows the center when it moves; no "
                    "mirror image solves it, unlike Distance + an angle; a center of its own "
                    "structure's, not a parent's: E0201)"),
    "mirror": (1, 2, "mirror(points, about=\"y\"): the points, then their mirror images in "
                     "reverse order (a symmetric outline written once); about: \"y\" (the "
                     "y axis: x -> -x), \"x\" (y -> -y) or a Line (as it starts); a point on "
                     "the axis at either end is not repeated"),
}

CONSTANTS = {"pi": "number", "true": "bool", "false": "bool", "True": "bool", "False": "bool",
             "PI": "number", "tau": "number"}

KEYWORDS = ["units", "import", "as", "param", "def", "for", "in", "if", "else", "elif", "assert",
            "and", "or", "not", "self", "true", "false"]
STRUCTURE_KINDS = ["solid", "hole", "cut", "drawing", "assembly"]

UNITS_LENGTH = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "inch": 25.4, "inches": 25.4,
                "ft": 304.8}
UNITS_ANGLE = {"deg": 3.141592653589793 / 180.0, "rad": 1.0}

# closed shapes a drawing engraves filled with `fill=true` (issue 111, runs at and av: a
# warning triangle's 8 mm border drawn as 241 hand-clipped lines, dominoes' pips as rings)
FILL = Arg("fill", "bool", False, "in a drawing: the closed shape's area engraved filled (on "
           "the fill layer), not its outline", kw_only=True)
FILLABLE = ("Circle", "Rectangle", "RoundedRectangle", "Triangle", "Trapezoid", "Ellipse",
            "Polygon", "Polyline", "Spline", "Bezier", "RegularPolygon", "Slot", "ArcSlot",
            "Sector", "Star", "Offset", "Inset", "Shell", "Stroke", "Hull", "Intersect")
for _n in FILLABLE:
    _spec = _DEFS[_n]
    _DEFS[_n] = (_spec[0], [tuple(v) + (FILL,) for v in _spec[1]]) + tuple(_spec[2:])

ENTRIES: dict[str, Entry] = {n: Entry(n, *spec) for n, spec in _DEFS.items()}


def lookup(name: str) -> Entry | None:
    """The entry for a canonical name or synonym, else None."""
    return ENTRIES.get(SYNONYMS.get(name, name))


def canonical(name: str) -> str:
    return SYNONYMS.get(name, name)


def canonical_args(name: str, args: dict) -> dict:
    """Bound arguments of a call of ``name`` renamed to the canonical entry's arguments.

    Only synonyms listed in :data:`SWAPPED` rename anything (``Contains(a=X, b=Y)`` gives
    ``{"a": Y, "b": X}`` for ``Inside``); for every other name ``args`` is returned as is.
    """
    ren = SWAPPED.get(name)
    if not ren:
        return args
    return {ren.get(k, k): v for k, v in args.items()}


def all_callable_names() -> list[str]:
    return list(ENTRIES) + list(SYNONYMS) + list(FUNCTIONS)


def arg_synonyms(entry_name: str) -> dict[str, tuple[str, ...]]:
    """Argument synonyms of an entry: alias -> candidate canonical names (entry's own first)."""
    out: dict[str, tuple[str, ...]] = {}
    for table in (ARG_SYNONYMS.get(entry_name, {}), ARG_SYNONYMS["*"]):
        for alias, canon in table.items():
            out.setdefault(alias, canon if isinstance(canon, tuple) else (canon,))
    return out


# a count spelled as an LLM would guess it: `num_teeth`, `n_teeth`, `number_of_teeth`,
# `teeth_count` for a template parameter `teeth`
_COUNT_PREFIXES = ("num_", "n_", "number_of_")
_COUNT_SUFFIXES = ("_count",)


def template_param(keyword: str, params: list[str]) -> str | None:
    """The parameter of a template (``def f(teeth=20, radius=5 mm)``) that the keyword
    ``keyword`` of a call names: itself, else a synonym an LLM would guess — the generic
    argument synonyms of every entry (``r`` -> ``radius``, ``d`` -> ``diameter``, ``w`` ->
    ``width``...) or a count spelled ``num_X``, ``n_X``, ``number_of_X``, ``X_count`` — when
    it is a parameter; ``None`` when nothing fits.  A library written in AIDL gets the same
    synonyms as the built-in shapes without declaring any."""
    if keyword in params:
        return keyword
    canon = ARG_SYNONYMS["*"].get(keyword, ())
    cands = list(canon if isinstance(canon, tuple) else (canon,))
    cands += [keyword[len(p):] for p in _COUNT_PREFIXES if keyword.startswith(p)]
    cands += [keyword[:-len(s)] for s in _COUNT_SUFFIXES if keyword.endswith(s)]
    return next((c for c in cands if c in params), None)


def rename_args(entry: Entry, variant: tuple[Arg, ...], npos: int,
                kwnames: list[str]) -> dict[str, str]:
    """Keyword names as written -> the variant's canonical names (aliases resolved).

    An alias is renamed only when its canonical argument belongs to ``variant`` and is not
    given otherwise (positionally or by its own name); other names map to themselves.
    """
    names = [a.name for a in variant]
    taken = set(names[:npos]) | {k for k in kwnames if k in names}
    syn = arg_synonyms(entry.name)
    out = {}
    for k in kwnames:
        if k not in names:
            for canon in syn.get(k, ()):
                if canon in names and canon not in taken:
                    out[k] = canon
                    taken.add(canon)
                    break
        out.setdefault(k, k)
    return out


def near_args(name: str, names: list[str]) -> list[str]:
    """Accepted argument names near ``name`` in spelling, for did-you-mean: none shorter than
    3 letters unless ``name`` is that short too (`font` is not `on`, though difflib says
    0.67)."""
    from .base.diagnostics import did_you_mean
    return [c for c in did_you_mean(name, names) if len(c) >= 3 or len(name) <= 3]


def accepted_args(entry: Entry) -> list[str]:
    """Every argument name an entry accepts: canonical ones, then synonyms that fit a form."""
    canon = list(dict.fromkeys(a.name for v in entry.variants for a in v))
    syn = [k for k, cs in arg_synonyms(entry.name).items() if any(c in canon for c in cs)]
    return canon + syn


def choose_variant(entry: Entry, npos: int, kwnames: list[str]):
    """Pick the constructor variant matching ``npos`` positional and ``kwnames`` keyword args
    (argument synonyms allowed; see :func:`bind_variant` for the renaming).

    Returns (variant, None) or (None, reason).
    """
    v, _ren, reason = bind_variant(entry, npos, kwnames)
    return v, reason


_BOUND: dict = {}


def bind_variant(entry: Entry, npos: int, kwnames: list[str]):
    """Like :func:`choose_variant`, also giving the keyword renaming of :func:`rename_args`.

    Returns (variant, {written: canonical}, None) or (None, {}, reason).  The answer depends
    only on the (fixed) entry, ``npos`` and the keyword names, so it is remembered: the checker
    and the interpreter ask it for every call (thousands in a 500-structure model).  The
    returned renaming is shared: read it, do not change it.
    """
    key = (entry.name, npos, tuple(kwnames))
    got = _BOUND.get(key)
    if got is None or got[0] is not entry:
        got = (entry, _bind_variant(entry, npos, kwnames))
        _BOUND[key] = got
    return got[1]


def _bind_variant(entry: Entry, npos: int, kwnames: list[str]):
    misfits = []        # (variant, extra keywords as written, missing, given twice)
    for v in entry.variants:
        names = [a.name for a in v]
        ren = rename_args(entry, v, npos, kwnames)
        kwnames_c = [ren[k] for k in kwnames]
        if npos > sum(not a.kw_only for a in v) and not entry.varargs:
            continue
        bound = set(names[:npos])
        extra = [k for k in kwnames if ren[k] not in names]
        dup = next((k for k in kwnames_c if k in bound or kwnames_c.count(k) > 1), None)
        given = bound | set(kwnames_c)
        missing = [a.name for a in v if a.required and a.name not in given]
        if not extra and dup is None and not missing:
            return v, ren, None
        misfits.append((v, extra, missing, dup))
    return None, {}, _misfit_reason(entry, npos, kwnames, misfits)


def _misfit_reason(entry: Entry, npos: int, kwnames: list[str], misfits: list) -> str:
    """Why a call with ``npos`` positional and ``kwnames`` keyword arguments binds none of
    ``entry``'s forms, from each reachable form's ``(variant, extra, missing, dup)``: too many
    positional arguments for every form; a keyword no form has; an argument given twice; the
    required argument that would complete a form taking every argument given; else the
    arguments that do not fit with the others (issue 83: `Arc(radius=, start=, end=)` said
    "no argument `radius`").  Those are the ones outside a form the call completes when there
    is one (the arguments of a complete form are never the culprits), else outside the form
    they fit best; the hint of the caller lists the forms."""
    if not misfits:
        most = max(sum(not a.kw_only for a in v) for v in entry.variants)
        return f"takes at most {most} arguments, got {npos}"
    unknown = [k for k in kwnames if all(k in extra for _v, extra, _m, _d in misfits)]
    if unknown:
        return f"has no argument `{unknown[0]}`"
    takes_all = [m for m in misfits if not m[1]]
    if takes_all:
        dup = next((d for _v, _e, _m, d in takes_all if d is not None), None)
        if dup is not None:
            return f"argument `{dup}` given twice"
        _v, _e, missing, _d = min(takes_all, key=lambda m: len(m[2]))
        return f"missing argument `{missing[0]}`"
    _v, extra, _m, _d = min(misfits, key=lambda m: (bool(m[2]), len(m[1]), len(m[2])))
    fitting = [f"`{k}`" for k in kwnames if k not in extra]
    if npos:
        fitting.append(f"{npos} positional argument{'s' if npos > 1 else ''}")
    return (f"has no form taking {_and([f'`{k}`' for k in extra])}"
            + (f" with {_and(fitting)}" if fitting else " together"))


def _and(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]
