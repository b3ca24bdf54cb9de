"""W0405: a box side a constraint reads differs from the final outline's (issue 84).

The solve reads ``x0.bb.left`` (and every ``Align*``, ``Above``, ``Inside``... that reads
boxes) from the structure's geometry as drawn, before its ``Fillet`` or ``Chamfer`` (those act
on the finished outline, after the booleans: :func:`aidl_lang.geometry.derived.operations.finish`).
A fillet on a corner that is the box's extreme moves that side in (a 45-degree X's tips by
``r * (sqrt(2) - 1)``), so ``AlignLeft(x0, board)`` leaves the rounded X short of the board's
edge.  This check compares, for each structure with a Fillet or Chamfer whose box a
constraint reads, the side read with the same side of its final exact outline, and warns with
the difference and the constraint that closes it.  (An ``Offset``, ``Inset``, ``Shell``,
``Intersect`` is boxed by its drawn outline, exactly at the solution: issue 109;
:func:`check_drawn_boxes` warns where the solve moved its sources under a relation.)
"""
from __future__ import annotations

from ...base.diagnostics import Diagnostic, DiagnosticSink
from ...geometry.relations.bbox import (SIDES, BBTerm, collect, drawn_box_misses, exclusions,
                                        numeric_box, side_expr)
from ...geometry.core.expr import Nl, const, evaluate, rebuild
from ...geometry.core.model import Model, Structure
from ...geometry.shapes.tessellate import CHORD_TOL
from ..part.build.booleans import Drawing
from .common import _part_of

BOX_TOL = 1e-6        # mm: sides closer than this are the same


def final_box(d: Drawing, s: Structure, shape=None) -> tuple[float, float, float, float] | None:
    """(left, right, bottom, top) in mm of ``s``'s final exact outline in drawing ``d``
    (after its Fillet and Chamfer; of ``shape`` when given), or None when it has none."""
    shape = d.shapes.get(s) if shape is None else shape
    if shape is None or shape.is_empty():
        return None
    boxes = [seg.box() for loops in d.exact.loops_of([shape]) for lp in loops
             for seg in lp.segments]
    if not boxes:
        return None
    return (min(b[0] for b in boxes), max(b[2] for b in boxes),
            min(b[1] for b in boxes), max(b[3] for b in boxes))


# mm: a side a Fillet or Chamfer moves by less is the size asserted (a corner a little off
# square, rounded: run t's shelf, 0.023 mm); farther, the member is the final outline (issue
# 109's law), said even where a request meant the sharp corner (run av's fin, 2.771 mm)
ROUNDED_TOL = 0.05
SHARP_REACH = 3.0     # x the rounding: a side in by no more is held to the sharp corners (W0405 a note)


def reshaped(s: Structure) -> list[str]:
    """The operations after which ``s``'s box read by the solve may not be its final
    outline's: its ``Fillet``/``Chamfer`` of a size above 0, sorted names.  (An ``Inset``, a
    miter join, an ``Intersect`` are boxed from their drawn outlines: exact;
    :func:`check_drawn_boxes`.)"""
    return sorted({f[0] for f in getattr(s, "finish", None) or [] if f[1] > 0})


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
    parts = set((getattr(d, "part_of", None) or {}).values())
    placed = bool(getattr(d, "placement", None))
    for c in model.constraints:
        if not c.deferred or c.implicit or c.kind == "equation":
            continue                # an equation on box values is taken as written
        terms = [t for eq in c.deferred for t in collect(eq.expr, [])]
        read = {id(t.target) for t in terms} & finished.keys()
        if not read:
            continue
        if (c.kind in SPACING or placed) and len({_part_of(
                t.target if isinstance(t.target, Structure) else t.target.owner, parts)
                for t in terms} - {None}) > 1:
            continue                # separate parts spaced on the sheet (run ab's camp stool:
            # `RightOf(leg_b, leg_a, gap=10)`, 10.54 mm apart), or laid out on it where
            # `Place` assembles them (run br's file frame: `AlignLeft(rail, front)`, 0.475
            # mm: the final outline lies within the box read, so the parts never meet for
            # it, and Place starts from each part's frame)
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


def check_final_box_asserts(sink: DiagnosticSink, model: Model, d: Drawing,
                            calls=None) -> None:
    """W0405 for each ``assert`` that reads the box of a structure with ``Fillet`` or
    ``Chamfer`` (or of a shape that is the outline of a solid its own holes may cut:
    :func:`_holed`) and whose verdict on that box (the shapes as drawn before the rounding, what
    the assert is judged on: E0405) is not its verdict on the final outline: an assert that
    holds only because it reads the box before the rounding, or fails only for it (issue
    109: a member a model asserts on is the part it gets)."""
    if not model.assertions:
        return
    finished = {id(s): s for s in model.structures if reshaped(s) or _holed(s)}
    if not finished:
        return
    from ...geometry.relations.assertions import holds
    x = model.xs()
    moved: dict = {}
    solved: dict = {}
    named = {}                  # id(shape) -> its label: a finished structure's shape
    for a in model.assertions:
        terms = [t for grp in a.groups for _op, le, re_, _dim in grp for side in (le, re_)
                 if not isinstance(side, (int, float)) for t in collect(side, [])]
        for t in terms:         # a shape's box read where it is its structure's (issue 111's
            g = t.target        # tent stake: `body.bb.height == 180 mm` after `Fillet(2)`
            own = getattr(g, "owner", None)     # took 21.4 mm off its 9.8 deg point)
            if isinstance(g, Structure) or own is None or id(own) not in finished \
                    or id(g) in finished:
                continue
            if id(own) not in moved:
                moved[id(own)], solved[id(own)] = _moved(d, own, x)
            box = numeric_box(g, None, x)
            if _holed(own):     # against its material (its box holds its holes' too)
                mat = numeric_box(own, None, x, exclude={
                    c for c in own.children.values() if c.kind in ("hole", "cut")})
                fin = final_box(d, own)
                # (a side within the chords' sag of the drawn box is where it was drawn:
                # run gq's mouse template, an ellipse's top read 0.0000114 mm off, "its
                # top 0.000 mm in", W0405 on an assert that holds)
                moved[id(g)] = {} if box is None or mat is None or fin is None else {
                    sd: fin[i] - box[i] for i, sd in enumerate(SIDES)
                    if abs(box[i] - mat[i]) <= BOX_TOL and abs(fin[i] - box[i]) > CHORD_TOL}
            else:
                moved[id(g)] = {} if box is None else {
                    sd: v for sd, v in moved[id(own)].items()
                    if abs(box[SIDES.index(sd)] - solved[id(own)][sd]) <= BOX_TOL}
            finished[id(g)], named[id(g)] = own, g.label
        read = [k for k in dict.fromkeys(id(t.target) for t in terms) if k in finished]
        for k in read:
            if k not in moved:
                moved[k], solved[k] = _moved(d, finished[k], x)
        if not any(abs(v) > BOX_TOL for k in read for v in moved[k].values()):
            continue
        exclude = exclusions(terms)

        def value(e, final: bool) -> float:
            if isinstance(e, (int, float)):
                return float(e)
            if final:
                return float(evaluate(_at_final(e, x, exclude, moved), x))
            return float(evaluate(_at_final(e, x, exclude, {}), x))

        def verdict(final: bool) -> bool:
            return any(all(holds(op, value(le, final), value(re_, final))
                           for op, le, re_, _dim in grp) for grp in a.groups)

        before, after = verdict(False), verdict(True)
        if before == after:
            continue
        s = finished[read[0]]
        if not reshaped(s) and read[0] not in named:
            continue            # a structure's box holds its holes by the language's rule
        asked = {t.side for t in terms if id(t.target) == read[0]}
        if {"Fillet", "Chamfer"} & set(reshaped(s)) and all(
                abs(v) <= ROUNDED_TOL for sd, v in moved[read[0]].items() if sd in asked):
            continue            # in by less than a laser's kerf (run t's shelf: 0.023 mm)
        sides = ", ".join(f"its {sd} {abs(v):.3f} mm "
                          f"{'in' if (v > 0) == (sd in ('left', 'bottom')) else 'out'}"
                          for sd, v in moved[read[0]].items()
                          if abs(v) > BOX_TOL and sd in asked) or "its box moved"
        kinds = reshaped(s) + (["holes"] if _holed(s) and read[0] in named
                               and _holes_cut(d, s, asked, x) else [])
        ops = " and ".join(kinds)
        what = f"`{named[read[0]]}`, the outline of `{s.path}`," if read[0] in named \
            else f"`{s.path}`"
        rounded = [k for k in kinds if k in ("Fillet", "Chamfer")]
        size = max((f[1] for f in getattr(s, "finish", None) or []), default=0.0)
        # a size held to the sharp corners, each side in by no more than three times the
        # rounding's size (a corner of 29 degrees or more: r (1 / sin(a / 2) - 1) <= 3 r),
        # is how drawings give a rounded outline's size (run br: a trapezoid's 400 mm foot,
        # 0.475 mm in at each end under r 4; run ed: a 45-degree set square's legs, 2.8 mm
        # in under R2 tips): a note.  A needle point rounded back far (issue 111's tent
        # stake's 9.8 degrees: 21.4 mm under r 2, 10.7 r) is not.
        sharps = before and kinds == rounded and all(
            (v > 0) == (sd in ("left", "bottom")) and abs(v) <= SHARP_REACH * size + BOX_TOL
            for sd, v in moved[read[0]].items() if abs(v) > BOX_TOL and sd in asked)
        # a hole drawn out past the side it cuts (run ha: an arm's fork run 1 mm past the
        # round end it notches, the arm 219.4 mm long "as drawn on purpose"): the shape's
        # size as drawn is the one meant, a note
        through = before and kinds == ["holes"] and _run_out(
            s, {sd: abs(v) for sd, v in moved[read[0]].items() if abs(v) > BOX_TOL
                and sd in asked}, x)
        sink.add(Diagnostic(
            "W0405", f"`assert {a.text}` reads the box of {what} before its {ops}: it "
            f"{'holds' if before else 'fails'} there"
            + (" (to the sharp corners, as a drawing gives a rounded outline's size)"
               if sharps else " (the shape as drawn, a hole run out through that side "
               "cutting it back)" if through else "") + f" and would "
            f"{'fail' if before else 'hold'} on the final outline ({sides})",
            a.span, "note" if sharps or through else "warning",
            hint=("if the size to the sharp corners is meant, nothing is needed; "
                  if sharps else "if the shape's size as drawn is meant, nothing is needed; "
                  if through else "")
                 + f"an assert reads the shapes as drawn, before {ops} (adding the difference "
                 f"to the assert fails it there, E0405): to make the final outline the size "
                 f"asserted, "
                 + (f"draw that corner round (a `Hull` with a `Circle` of the radius at the "
                    f"tip) or round only corners away from it (`{rounded[0]}(at=[...], ...)`)"
                    if rounded else "assert the shape's own size (its `width`, `radius`, "
                    "`rx`...), which holes leave as drawn, when the holes are meant to cut that "
                    "side; or move the holes that cut that side")),
            calls=calls(a.owner) if calls is not None else None)


def _holed(s: Structure) -> bool:
    """Solid ``s`` has holes of its own (hole or cut children, none a template's) that may cut
    its outline: the box of a shape of it, read by an assert, is then the shape as drawn
    (issue 111, run s's toy sailboat: its foot cut back, `sail.body.bb` asserts held on the
    uncut polygon; that cut was a joint template's, which its docs now explain)."""
    holes = [c for c in s.children.values() if c.kind in ("hole", "cut")]
    # a joint template's cut is filled by its mate (a cross-halving slot at a rocket's nose,
    # a dovetail's sockets): the outline as drawn is the design there, not warned
    return s.kind == "solid" and bool(holes) and not any(c.template for c in holes)


def _run_out(s: Structure, sides: dict, x) -> bool:
    """Every side of ``sides`` (side -> how far the final outline's moved in, mm) of solid
    ``s``'s material box has a shape of one of its own holes drawn past it and reaching
    farther in than the side moved: a notch or a fork run out through the edge on purpose,
    material left beside it (not a cut that trims the whole side back)."""
    holes = {c for c in s.children.values() if c.kind in ("hole", "cut")}
    mat = numeric_box(s, None, x, exclude=holes)
    if mat is None or not sides:
        return False
    boxes = [b for h in holes for b in [numeric_box(h, None, x)] if b is not None]
    # (past the side, how far in from it)
    reach = {"left": lambda b: (b[0] < mat[0] - BOX_TOL, b[1] - mat[0]),
             "right": lambda b: (b[1] > mat[1] + BOX_TOL, mat[1] - b[0]),
             "bottom": lambda b: (b[2] < mat[2] - BOX_TOL, b[3] - mat[2]),
             "top": lambda b: (b[3] > mat[3] + BOX_TOL, mat[3] - b[2])}
    return all(any(p and deep > off + BOX_TOL for p, deep in map(reach[sd], boxes))
               for sd, off in sides.items())


def _holes_cut(d: Drawing, s: Structure, asked: set, x) -> bool:
    """Solid ``s``'s own holes move a side of ``asked`` of its outline: its outline before
    any rounding, holes cut (:attr:`Drawing.unfinished`), against its material's box.  A
    hanging hole well inside a set square is not why its legs' box moved (run ed: "before its
    Fillet and holes" for R2 tips alone, a warning where the rounding alone is a note)."""
    unf = d.unfinished.get(s)
    if unf is None:
        return True             # nothing rounded: the holes are what moved it
    before = final_box(d, s, unf)
    mat = numeric_box(s, None, x, exclude={c for c in s.children.values()
                                           if c.kind in ("hole", "cut")})
    if before is None or mat is None:
        return True
    return any(abs(before[i] - mat[i]) > BOX_TOL for i, sd in enumerate(SIDES) if sd in asked)


def check_drawn_boxes(sink: DiagnosticSink, model: Model, calls=None) -> None:
    """One W0405 per relation on a box read from a drawn outline (an ``Inset``, a miter
    join, an ``Intersect``: :func:`~aidl_lang.geometry.relations.bbox.boxed_by_drawing`)
    that the solution still misses after the solver solved again from it
    (:func:`aidl_lang.solver.solve`): the solve moved the shapes it is made from so that
    its outline changed under the relation (two shapes of an ``Intersect`` moved apart)."""
    for c, off in drawn_box_misses(model):
        if off <= BOX_TOL:
            continue
        sink.warning(
            "W0405", f"`{c.describe()}` is met by the box of the outline as the solve began, "
            f"not as drawn: the solve moved the shapes it is made from, and the drawn "
            f"outline misses it by {off:.3f} mm",
            c.span, calls=calls(c.owner) if calls is not None else None,
            hint="place the shapes a derived shape (Inset, Intersect, a miter Offset) is made "
                 "from with their own relations, or relate its box once they are placed")


def _moved(d: Drawing, s: Structure, x) -> tuple[dict, dict]:
    """(``side -> final - solved``, ``side -> solved``) in mm of structure ``s``'s box, in
    the model's frame (empty: no outline)."""
    solved, final = numeric_box(s, None, x), final_box(d, s)
    if solved is None or final is None:
        return {}, {}
    # the rounding's own change: against the outline before it, where its holes cut it too
    # (run u's cactus: a cross-halving slot at its rounded top, "its top 0.080 mm in", was
    # said of the Fillets at its elbows)
    unf = d.unfinished.get(s)
    before = final_box(d, s, unf) if unf is not None and reshaped(s) else None
    if before is not None:
        return ({side: final[i] - before[i] for i, side in enumerate(SIDES)},
                dict(zip(SIDES, solved)))
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


# relations that space two boxes apart: between two separate parts they only lay the parts
# out on the drawing, where a fillet's half millimetre changes nothing that is cut

SPACING = frozenset({"LeftOf", "RightOf", "Above", "Below", "Gap"})


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
             if rounded else "")
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
