"""``distance(a, b)`` of shapes in an ``assert`` (issue 111's runs dd, dh, dr: a gap between two
shapes, a point's distance to a line, written by hand or not at all): the least distance
between two geometries' outlines (points; lines as segments; closed shapes by their exact
outlines; open curves as drawn), measured at the solution as ``aidl check``'s asserts are
judged, exact to 1e-9 mm (:func:`aidl_lang.output.part.measure.gaps.gap`).  Outlines that
cross are 0 apart.  A measured value, not an expression the solver can move: only an
``assert`` reads it (E0108 elsewhere: ``Distance(a, b, d)`` is the relation that places)."""
from __future__ import annotations

import math

from ..base.diagnostics import EvalError
from ..geometry.core.expr import Expr, evaluate
from ..geometry.core.model import Structure
from ..geometry.core.values import LEN, GeomRef, Q, StructRef


class Measured(Expr):
    """The least distance (mm) between the outlines of ``a`` and ``b`` (each a
    :class:`~aidl_lang.geometry.core.model.Geometry`, or a point given as two expressions)
    in ``model``, at the parameter values :func:`~aidl_lang.geometry.core.expr.evaluate`
    is given (:meth:`value`)."""

    __slots__ = ("a", "b", "model")

    def __init__(self, a, b, model):
        self.a, self.b, self.model = a, b, model

    def __repr__(self):
        return f"distance({_label(self.a)}, {_label(self.b)})"

    def value(self, x) -> float:
        from ..output.part.build.booleans import Renderer
        from ..output.part.measure import gaps as G
        r = Renderer(self.model, x=x[:len(self.model.free)])
        try:
            ea, eb = (_entity(side, r, x, G) for side in (self.a, self.b))
        except MeasureError:
            return math.nan     # (an empty Text: the assert then says it does not hold)
        return float(G.gap(ea, eb)[0])


def _entity(side, renderer, x, G) -> list:
    """The exact pieces of one side of :class:`Measured` at ``x``."""
    if isinstance(side, tuple):                 # a point: its two coordinates' expressions
        p = (float(evaluate(side[0], x)), float(evaluate(side[1], x)))
        return [("L", p, p)]
    if isinstance(side, list):                  # a structure, a list: each shape it draws
        got = []
        for g in side:
            try:
                got += _entity(g, renderer, x, G)
            except MeasureError:
                continue                        # (a shape of nothing: the others are measured)
        if not got:
            raise MeasureError("nothing drawn to measure")
        return got
    try:
        return G.entity(side, renderer)["pieces"]
    except KeyError:            # a Text's strokes (or a mark of no curve): its lines as drawn
        from ..output.part.build.result import Drawing
        scratch = Drawing()
        renderer.draw_lines(side, scratch)
        pieces = [("L", tuple(map(float, a)), tuple(map(float, b)))
                  for _, pl in scratch.lines for a, b in zip(pl[:-1], pl[1:])]
        if not pieces:
            raise MeasureError(f"`{side.label}` ({side.kind}) has no line to measure")
        return pieces


def _made_construction(obj) -> bool:
    """Whether shape or structure ``obj`` has shapes and every one is construction (a copy
    in place, a pattern with ``start_angle=``, turned it so), not left empty by an error."""
    if isinstance(obj, Structure):
        shapes = [g for s in obj.subtree() for g in s.geometry]
        return bool(shapes) and all(g.construction for g in shapes)
    return bool(getattr(obj, "construction", False))


class MeasureError(Exception):
    """A side of :class:`Measured` has nothing to measure (an empty Text)."""


def _label(side) -> str:
    return "a point" if isinstance(side, tuple) else \
        f"`{side[0].owner.path}`" if isinstance(side, list) else f"`{side.label}`"


def measured_distance(interp, args, span) -> Q:
    """``distance(a, b)`` with a shape among ``a``, ``b`` (a point the other may be): a
    :class:`Measured` length inside an ``assert``'s condition, else E0108."""
    if not getattr(interp, "in_assert", False):
        raise EvalError("E0108", "`distance` of a shape is measured after solving: it is read "
                        "only by an `assert`", span,
                        hint="write it in the assert itself (`assert distance(label, hole) >= "
                             "2 mm`); to place two shapes apart, `Distance(a, b, 5 mm)`")
    sides, owners = [], set()
    for a in args[:2]:
        if of_shapes([a]):
            drawn = _drawn(a, owners)           # a shape, a hole, a drawing, a part, a list
            if not drawn:
                what = (f" (`{a.geom.label}`, a Text of no letters)" if isinstance(a, GeomRef)
                        and a.geom.kind == "Text" else "")
                hint = "name a shape, a structure or a list of them that draws a line"
                obj = a.struct if isinstance(a, StructRef) else \
                    a.geom if isinstance(a, GeomRef) else None
                copies = obj.__dict__.get("pattern_copies") if obj is not None else None
                if copies and _made_construction(obj):
                    # run gh: `distance(plate.petal, ...)` of a CircularPattern's original
                    # that `start_angle=` made construction: "an error above left its shapes
                    # out" was said of the next such assert
                    c0 = copies[0]
                    listed = (c0.path if isinstance(c0, Structure) else
                              f"{c0.owner.path}.{c0.name}").split("[")[0]
                    shown = obj.path if isinstance(obj, Structure) else obj.label
                    here = getattr(getattr(interp, "struct", None), "path", None)
                    if here and listed.startswith(here + "."):
                        listed = listed[len(here) + 1:]     # as the assert writes it
                    if here and shown.startswith(here + "."):
                        shown = shown[len(here) + 1:]
                    what = (f" (`{shown}` is a pattern's original, not drawn: its "
                            f"pattern drew copies in its place)")
                    hint = (f"measure the pattern's copies, `{listed}` (the list; one of "
                            f"them: `{listed}[0]`)")
                elif not what and interp.sink.has_errors:
                    # run ew: a list of notches left empty by an E0109 in their centres; the
                    # hint sent the model to swap the arguments
                    what = " (it is empty: an error above left its shapes out)"
                    hint = "mend the error above first; this one follows from it"
                raise EvalError("E0108", f"`distance` was given nothing drawn to measure{what}",
                                span, hint=hint)
            sides.append(drawn)
        else:
            p = interp._to_point(a, span)
            sides.append((p.x, p.y))
            owners |= set(p.owners)
    return Q(Measured(sides[0], sides[1], interp.model), LEN, frozenset(owners))


def of_shapes(args) -> bool:
    """Whether a ``distance(a, b)`` call is given a shape, a structure or a list of them
    (measured: :func:`measured_distance`) rather than two points."""
    return any(isinstance(a, StructRef) or isinstance(a, GeomRef) and a.geom.kind != "Point"
               or isinstance(a, (list, tuple)) and a and not _is_point(a) for a in args[:2])


def _is_point(v) -> bool:
    """``(x, y)`` written as two numbers or lengths: a point, not a list of shapes."""
    return isinstance(v, (list, tuple)) and len(v) == 2 and all(isinstance(c, Q) for c in v)


def _drawn(v, owners: set) -> list:
    """The geometries drawn by ``v`` (a shape, a structure's subtree, a list of them: run
    dy's `distance(label, holes)` of a pattern's copies), their owners added to ``owners``."""
    if isinstance(v, GeomRef):
        owners.add(v.geom.owner)
        return [v.geom] if v.geom.kind != "Point" and _draws(v.geom) else []
    if isinstance(v, StructRef):
        owners.add(v.struct)
        return [g for s in v.struct.subtree() for g in s.geometry
                if not g.construction and _draws(g)]
    if isinstance(v, (list, tuple)):
        return [g for item in v for g in _drawn(item, owners)]
    return []


def _draws(g) -> bool:
    """Whether geometry ``g`` draws something to measure (a Text of no letters does not)."""
    return g.kind != "Text" or bool(str(g.data.get("text", "")).strip())
