"""The one entry of the geometry constructors, :func:`build`: geometry ``kind`` created from its
checked arguments by the ``_build_KIND`` of :mod:`.primitives` (the basic shapes),
:mod:`.point_shapes` (shapes given by points) or :mod:`.composites` (shapes made from shapes).
"""
from __future__ import annotations

from ..core.expr import _new
from ..core.model import Geometry
from . import composites, point_shapes, primitives


def build(ctx, kind: str, args: dict, span) -> Geometry:
    """Create geometry ``kind`` in ``ctx.struct`` from bound arguments ``args``."""
    g = _new(Geometry)                 # Geometry(kind, ctx.struct, span, ...) without the class call
    g.kind = kind
    g.owner = ctx.struct
    g.span = span
    g.name = ""
    g.points = {}
    g.scalars = {}
    g.data = {}
    g.parts = {}
    g.construction = bool(args.get("construction", False))
    g.closed = False
    g.listed = True
    g.pattern_original = None
    fn = _BUILD[kind]
    fn(ctx, g, args)
    if args.get("fill") and kind != "Text":     # (a Text's fill is its font's: text_outlines)
        if not g.closed:
            raise primitives.PrimitiveError(
                f"fill=true needs a closed shape: this {kind} is open, a line with no area",
                hint="close it (`closed=true`; an Ellipse with no start_angle), or draw the "
                     "area as a closed shape")
        g.data["fill"] = True          # a drawing engraves its area (style "fill")
    if args.get("overrun"):
        # drawn, left out of its structures' boxes (relations/bbox.py): a cut's run past the
        # part's edge (issue 111)
        g.data["overrun"] = True
    ctx.struct.geometry.append(g)
    return g


_BUILD = {k[7:]: f for m in (primitives, point_shapes, composites)
          for k, f in vars(m).items() if k.startswith("_build_")}
