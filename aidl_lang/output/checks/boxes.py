"""W0405: a box side a constraint reads differs from the final outline's (issue 84).

The solve reads ``x0.bb.left`` (and every ``Align*``, ``Above``, ``Inside``... that reads
boxes) from the structure's geometry as drawn, before its ``Fillet`` or ``Chamfer`` (those act
on the finished outline, after the booleans: :func:`aidl_lang.geometry.operations.finish`).
A fillet on a corner that is the box's extreme moves that side in (a 45-degree X's tips by
``r * (sqrt(2) - 1)``), so ``AlignLeft(x0, board)`` leaves the rounded X short of the board's
edge.  This check compares, for each structure with a Fillet or Chamfer whose box a
constraint reads, the side read with the same side of its final exact outline, and warns with
the difference and the constraint that closes it.
"""
from __future__ import annotations

from ...diagnostics import DiagnosticSink
from ...geometry.bbox import BBTerm, collect, numeric_box
from ...geometry.model import Model, Structure
from ..part.booleans import Drawing

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


def check_final_boxes(sink: DiagnosticSink, model: Model, d: Drawing, calls=None) -> None:
    """One W0405 per (constraint, structure, side) where a relation of the registry
    (``AlignLeft``, ``Above``, ``Inside``, ...) reads a side of the box of a structure with
    ``Fillet``/``Chamfer`` that its final outline does not reach (by more than
    :data:`BOX_TOL`).  An equation on box values (``x0.bb.left + 0.621 mm ==
    board.bb.left``, the fix the hint writes) is taken as written.  ``calls``: ``instance_calls`` of the pipeline (a template's
    statement is reported at its call)."""
    finished = [s for s in model.structures if getattr(s, "finish", None)]
    if not finished:
        return
    ids = {id(s) for s in finished}
    x = model.xs()
    boxes: dict = {}
    for c in model.constraints:
        if not c.deferred or c.implicit or c.kind == "equation":
            continue                # an equation on box values is taken as written
        seen = set()
        for eq in c.deferred:
            for t in collect(eq.expr, []):
                s = t.target
                if not isinstance(t, BBTerm) or id(s) not in ids or (id(s), t.side) in seen:
                    continue
                seen.add((id(s), t.side))
                if id(s) not in boxes:
                    boxes[id(s)] = (numeric_box(s, None, x), final_box(d, s))
                solved, final = boxes[id(s)]
                if solved is None or final is None:
                    continue
                k = ("left", "right", "bottom", "top").index(t.side)
                diff = final[k] - solved[k]
                if abs(diff) <= BOX_TOL:
                    continue
                ops = " and ".join(sorted({f[0] for f in s.finish}))
                inward = diff > 0 if k in (0, 2) else diff < 0
                sign = "+" if diff > 0 else "-"
                sink.warning(
                    "W0405", f"`{c.describe()}` reads the box of `{s.path}` before its {ops}: "
                    f"its {t.side} is at {solved[k]:.3f} mm, the final outline's at "
                    f"{final[k]:.3f} mm ({abs(diff):.3f} mm {'in' if inward else 'out'})",
                    c.span, calls=calls(c.owner) if calls is not None else None,
                    hint=f"a box is read from the shapes as drawn, before {ops}: to put the "
                         f"final outline there, write that side as an equation with the "
                         f"difference (`{s.name}.bb.{t.side} {sign} {abs(diff):.3f} mm == "
                         f"...`, an equation is taken as written), or round only corners "
                         f"away from that side (`{ops.split()[0]}(at=[...], ...)`)")
