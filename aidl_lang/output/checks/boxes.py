"""W0405: a box side a constraint reads differs from the final outline's (issue 84).

The solve reads ``x0.bb.left`` (and every ``Align*``, ``Above``, ``Inside``... that reads
boxes) from the structure's geometry as drawn, before its ``Fillet`` or ``Chamfer`` (those act
on the finished outline, after the booleans: :func:`aidl_lang.geometry.derived.operations.finish`).
A fillet on a corner that is the box's extreme moves that side in (a 45-degree X's tips by
``r * (sqrt(2) - 1)``), so ``AlignLeft(x0, board)`` leaves the rounded X short of the board's
edge.  An ``Offset`` or ``Shell`` is boxed from its source's box grown by the distance: exact
for an outward round join, not for a miter join (a star's tips reach further) nor an inset (an
``Inset`` or negative distance: smaller).  This check compares, for each structure with a
Fillet or Chamfer or such an offset whose box a constraint reads, the side read with the same
side of its final exact outline, and warns with the difference and the constraint that closes it.
"""
from __future__ import annotations

from ...base.diagnostics import DiagnosticSink
from ...geometry.relations.bbox import SIDES, BBTerm, collect, exclusions, numeric_box, side_expr
from ...geometry.core.expr import Nl, const, evaluate, rebuild
from ...geometry.core.model import Model, Structure
from ..part.build.booleans import Drawing

BOX_TOL = 1e-6        # mm: sides closer than this are the same


def final_box(d: Drawing, s: Structure) -> tuple[float, float, float, float] | None:
    """(left, right, bottom, top) in mm of ``s``'s final exact outline in drawing ``d``
    (after its Fillet and Chamfer), or None when it has none."""
    shape = d.shapes.get(s)
    if shape is None or shape.is_empty():
        return None
    boxes = [seg.box() for loops in d.exact.loops_of([shape]) for lp in loops
             for seg in lp.segments]
    if not boxes:
        return None
    return (min(b[0] for b in boxes), max(b[2] for b in boxes),
            min(b[1] for b in boxes), max(b[3] for b in boxes))


def reshaped(s: Structure) -> list[str]:
    """The operations after which ``s``'s box read by the solve may not be its final
    outline's: its ``Fillet``/``Chamfer`` and the ``Offset``/``Shell``/``Inset`` among its own
    and its children's shapes that are not exact on the box (a miter join, an inset), sorted
    names."""
    ops = {f[0] for f in getattr(s, "finish", None) or [] if f[1] > 0}
    todo = [s]
    while todo:
        t = todo.pop()
        for g in t.geometry:
            if g.kind in ("Offset", "Shell") and not g.construction:
                d = g.data.get("distance", g.data.get("thickness", 0.0))
                if g.data.get("join") == "miter" or d < 0:
                    ops.add("Inset" if g.kind == "Offset" and d < 0 else g.kind)
        todo += [c for c in t.children.values() if c.kind == "solid"]
    return sorted(ops)


def check_final_boxes(sink: DiagnosticSink, model: Model, d: Drawing, calls=None) -> None:
    """One W0405 per relation of the registry (``AlignLeft``, ``Above``, ``Inside``, ...)
    that reads the box of a structure with ``Fillet``/``Chamfer`` and that its final outlines
    no longer meet: each such equation is evaluated again with the sides read from the final
    exact outline (``AlignCenterY`` of a shape rounded alike at top and bottom still holds,
    an ``Above`` whose gap grew still holds) and warned when off by more than
    :data:`BOX_TOL`, naming the sides that moved.  An equation on box values
    (``x0.bb.left + 0.621 mm == board.bb.left``, the fix the hint writes) is taken as
    written.  ``calls``: ``instance_calls`` of the pipeline (a template's statement is
    reported at its call)."""
    finished = {id(s): s for s in model.structures if reshaped(s)}
    if not finished:
        return
    x = model.xs()
    moved: dict = {}                # id(structure) -> final minus solved, per side
    solved: dict = {}               # id(structure) -> its solved box, per side
    for c in model.constraints:
        if not c.deferred or c.implicit or c.kind == "equation":
            continue                # an equation on box values is taken as written
        terms = [t for eq in c.deferred for t in collect(eq.expr, [])]
        read = {id(t.target) for t in terms} & finished.keys()
        if not read:
            continue
        for k in read:
            if k not in moved:
                moved[k], solved[k] = _moved(d, finished[k], x)
        exclude = exclusions(terms)
        off = False
        for eq in c.deferred:
            v = float(evaluate(_at_final(eq.expr, x, exclude, moved), x))
            off = off or (v < -BOX_TOL if eq.ineq else abs(v) > BOX_TOL)
        if off:
            _warn(sink, c, terms, finished, moved, solved, calls)


def _moved(d: Drawing, s: Structure, x) -> tuple[dict, dict]:
    """(``side -> final - solved``, ``side -> solved``) in mm of structure ``s``'s box, in
    the model's frame (empty: no outline)."""
    solved, final = numeric_box(s, None, x), final_box(d, s)
    if solved is None or final is None:
        return {}, {}
    return ({side: final[i] - solved[i] for i, side in enumerate(SIDES)},
            dict(zip(SIDES, solved)))


def _at_final(e, x, exclude: set, moved: dict):
    """``e`` with each box side replaced by its value on the final outline."""
    if isinstance(e, BBTerm):
        v = float(evaluate(side_expr(e.target, e.side, e.frame, x, exclude), x))
        return const(v + moved.get(id(e.target), {}).get(e.side, 0.0))
    if isinstance(e, Nl):
        return rebuild(e.op, tuple(_at_final(a, x, exclude, moved) for a in e.args))
    return e


def _warn(sink, c, terms, finished, moved, solved, calls) -> None:
    seen = []
    for t in terms:
        s = finished.get(id(t.target))
        diff = moved.get(id(t.target), {}).get(t.side, 0.0) if s is not None else 0.0
        if abs(diff) > BOX_TOL and (s, t.side) not in seen:
            seen.append((s, t.side))
    if not seen:
        return
    s, side = seen[0]
    diff = moved[id(s)][side]
    kinds = reshaped(s)
    ops = " and ".join(kinds)
    rounded = [k for k in kinds if k in ("Fillet", "Chamfer")]
    other = (f"or round only corners away from that side (`{rounded[0]}(at=[...], ...)`)"
             if rounded else "or use `join=\"round\"` (an outward round offset's box is exact)"
             if any(k in ("Offset", "Shell") for k in kinds) else "")
    inward = diff > 0 if side in ("left", "bottom") else diff < 0
    at = solved[id(s)][side]
    more = "".join(f"; its {sd} {abs(moved[id(t)][sd]):.3f} mm" for t, sd in seen[1:])
    sink.warning(
        "W0405", f"`{c.describe()}` reads the box of `{s.path}` before its {ops}: its {side} "
        f"is at {at:.3f} mm, the final outline's at {at + diff:.3f} mm ({abs(diff):.3f} mm "
        f"{'in' if inward else 'out'}{more})",
        c.span, calls=calls(c.owner) if calls is not None else None,
        hint=f"a box is read from the shapes as drawn, before {ops}: to put the final outline "
             f"there, write that side as an equation with the difference "
             f"(`{s.name}.bb.{side} {'+' if diff > 0 else '-'} {_mm(abs(diff))} mm == ...`, an "
             f"equation is taken as written){', ' + other if other else ''}")


def _mm(v: float) -> str:
    """``v`` in mm to 1e-6 mm (the hint's equation puts the outline on the side to within
    :data:`BOX_TOL`), trailing zeros dropped: 0.62132."""
    return f"{v:.6f}".rstrip("0").rstrip(".")
