"""``assert`` statements checked at the solved values (docs/language.md, "assert").

The interpreter keeps each ``assert`` whose sides depend on the solve as an
:class:`~.model.Assertion`; :func:`failed` evaluates them at the solution (box terms expanded
there) and :func:`describe` says what was found.  A condition holds within :data:`TOL`
(mm or radians), the solver's own accuracy being far finer.
"""
from __future__ import annotations

import math
import numpy as np

from .bbox import collect, contains_bbox, exclusions, expand
from ..core.expr import Lin, evaluate
from ..core.model import Assertion, Model

TOL = 1e-6


def holds(op: str, left: float, right: float, bound: str = "") -> bool:
    """``left op right`` within :data:`TOL` (``<``, ``>`` and ``!=`` need a gap of more than
    TOL).  ``bound``: which side is a number as written ("left", "right" or ""); a strict
    bound below TOL (``abs(dx) < 1e-9``: the author's own epsilon, false at ``dx = 1.3e-15``
    in run aa's sundial) is read as the tolerance: judged as ``<=`` (``>=``)."""
    if not (math.isfinite(left) and math.isfinite(right)):
        return False
    d = left - right
    if (op == "<" or op == ">") and bound and 0 < abs(right if bound == "right" else left) <= TOL:
        op += "="
    return {"==": abs(d) <= TOL, "!=": abs(d) > TOL, "<=": d <= TOL, ">=": d >= -TOL,
            "<": d < -TOL, ">": d > TOL}[op]


def _number(side) -> bool:
    """A side that is a number as written (no unknown in it)."""
    return isinstance(side, (int, float)) or (type(side) is Lin and not side.terms)


def _show(v: float, dim, a: Assertion) -> str:
    if dim == "text":                   # a string (or a truth value) compared as it is
        return f'"{v}"' if isinstance(v, str) else ("true" if v else "false")
    if dim == (1, 0):
        return f"{v / a.scale:.6g} {a.unit}"
    if dim == (0, 1):
        return f"{math.degrees(v):.6g} deg"
    return f"{v:.6g}"


def _structures_read(a: Assertion, owners) -> list:
    """The structures whose geometry or box the assertion reads (boxes' targets, and through
    ``owners``, the model's ``param_owner``, those of the parameters its reads use)."""
    out: list = []
    for t in _box_terms(a):
        tg = t.target
        out.append(tg if hasattr(tg, "children") else getattr(tg, "owner", None))
    todo = [e for _, e, dim in a.reads if dim not in ("said", "slot")] + [
        side for grp in a.groups for _, le, re_, _ in grp for side in (le, re_)
        if not isinstance(side, (int, float))]
    while todo and owners is not None:
        e = todo.pop()
        if isinstance(e, Lin):
            out += [owners[k] for k in e.terms if k < len(owners)]
        elif hasattr(e, "args"):
            todo += [v for v in e.args if not isinstance(v, (int, float))]
    return [s for s in dict.fromkeys(o for o in out if o is not None)]


def _indices(e, into: set) -> None:
    """The parameter indices expression ``e`` (box terms expanded) reads, added to ``into``."""
    todo = [e]
    while todo:
        e = todo.pop()
        if isinstance(e, Lin):
            into.update(e.terms)
        elif hasattr(e, "args") and hasattr(e, "op"):
            todo += [v for v in e.args if not isinstance(v, (int, float))]


# a value the solve moved less than this (mm, or radians) from where it is written is not said
MOVED = 0.01


def _geometry_of(model) -> dict:
    """Parameter index -> ``(geometry, its name there)``: ``position.y``, ``radius``."""
    out: dict = {}
    for g in model.all_geometry():
        for name, p in g.points.items():
            out.setdefault(p.ix, (g, f"{name}.x"))
            out.setdefault(p.iy, (g, f"{name}.y"))
        for name, s in g.scalars.items():
            out.setdefault(s.index, (g, name))
    return out


def _as_written(model, g, i: int) -> bool:
    """Whether parameter ``i`` starts where the program writes it: not a pattern's or a
    mirror's copy (whose start is the original's, moved), nor a part's frame."""
    s = model.param_owner[i]
    if g is None or getattr(g, "pattern_original", None) is not None:
        return False
    return s is None or all(getattr(a, "copy_origin", None) is None and a.pattern_original
                            is None for a in [s, *s.ancestors()])


def _moved_within(a: Assertion, x, model) -> str:
    """A value the assertion reads that the solve moved within its part (a point, a size; not
    a part's frame, :func:`_moved_part`), from where it is written to where it lies, and the
    written constraints that read its shape's moved values without moving the part whole
    (those that do, laying it out, are named only when no other is) (issue 111, run eh: a
    word 4.25 mm off its rail, moved by `backer.plate.bb.height == letters.bb.height + 2 * 10
    mm`, unnamed): "; the solve moved `letters.word.position.y` from 0 mm as written to
    4.25374 mm, by `...` (line 32)"; ``""`` when none was."""
    start = getattr(model, "x_written", None)
    if x is None or start is None:
        return ""
    read: set = set()
    for grp in a.groups:
        for _, le, re_, _ in grp:
            for side in (le, re_):
                if not isinstance(side, (int, float)):
                    try:
                        _indices(expand(side, x, set()), read)
                    except (ArithmeticError, KeyError, TypeError, ValueError, IndexError):
                        continue
    geometry = _geometry_of(model)

    def moved(k) -> bool:
        return k < len(start) and model.free[k] and abs(float(x[k]) - start[k]) > MOVED

    found = [k for k in read if moved(k) and _as_written(model, geometry.get(k, (None,))[0], k)]
    if not found:
        return ""
    i = max(found, key=lambda k: (abs(float(x[k]) - start[k]), -k))
    g, name = geometry[i]
    shape = {k for k, (h, _) in geometry.items() if h is g and moved(k)}     # with its size
    owner = model.param_owner[i]
    chain = [k for s in ([owner, *owner.ancestors()] if owner is not None else [])
             for k in (s.fx, s.fy) if k >= 0]
    shifted = np.array(x, dtype=float)
    shifted[chain] += 1.0                       # the part moved whole, 1 mm each way
    by, layout = [], []
    for c in model.constraints:
        if c.implicit or c.span is None or c.hold:
            continue
        idx: set = set()
        whole = False
        for eq in list(c.equations) + list(c.deferred or ()):
            try:
                e = expand(eq.expr, x, set())
                _indices(e, idx)
                whole = whole or abs(evaluate(e, shifted) - evaluate(e, x)) > 1e-9
            except (ArithmeticError, KeyError, TypeError, ValueError, IndexError):
                continue
        if idx & shape:
            (layout if whole else by).append(c)
    by = by or layout
    label = _relative(f"{g.label}.{name}", a.owner)
    show = (lambda v: f"{math.degrees(v):.6g} deg") if g.scalars.get(name) is not None and \
        g.scalars[name].dim == "angle" else (lambda v: f"{v / a.scale:.6g} {a.unit}")
    how = " and".join(f" `{c.describe()}` (line {c.span.line})" for c in by[:2])
    more = f" and {len(by) - 2} more" if len(by) > 2 else ""
    return (f"; the solve moved `{label}` from {show(start[i])} as written to "
            f"{show(float(x[i]))}" + (f", by{how}{more}" if by else "")
            + ": the assert reads it where the constraints put it")


def _reads_place(a: Assertion, x, fx: int, fy: int) -> bool:
    """Whether a comparison of ``a`` changes when the frame (``fx``, ``fy``) is put back
    where it is written: the assert reads where the part lies, not only its sizes.  Judged
    on each comparison's two sides together (their difference): two members of one part
    move together, and a layout's move of it changes no verdict (run eh's sign: a rail's
    bottom against its word's baseline, both in the placed `letters`, was said to be read
    "where it is written" though the frame cancels)."""
    y = np.array(x, dtype=float)
    y[fx] = y[fy] = 0.0

    def value(side, at):
        return float(side) if isinstance(side, (int, float)) else evaluate(side, at)
    for grp in a.groups:
        for _, le, re_, _ in grp:
            try:
                if abs((value(le, x) - value(re_, x)) - (value(le, y) - value(re_, y))) > 1e-6:
                    return True
            except (ArithmeticError, KeyError, TypeError, ValueError, IndexError):
                continue
    return False


def _moved_part(a: Assertion, x, owners) -> str:
    """Where a part the assertion reads was moved from where it is written, and by which
    relation (runs as, au, aw, ay: asserts on coordinates a layout's `Below`/`RightOf` had
    moved, "-13 mm == 137 mm is false" with no word of why): ``""`` when none was."""
    if x is None:
        return ""
    for s in _structures_read(a, owners):
        chain = [s] + list(s.ancestors()) if hasattr(s, "ancestors") else [s]
        for p in reversed(chain):              # the outermost moved first
            fx, fy = getattr(p, "fx", None), getattr(p, "fy", None)
            if p.parent is None or fx is None or getattr(p, "copy_origin", None) is not None:
                continue
            try:
                dx, dy = float(x[fx]), float(x[fy])      # (its frame: where it went)
            except (IndexError, TypeError):
                continue
            if math.hypot(dx, dy) <= 0.01 or not _reads_place(a, x, fx, fy):
                continue
            by = [c for c in p.parent.constraints if not c.implicit and c.args
                  and any(p is t or (hasattr(t, "is_within") and t.is_within(p))
                          for t in c.args[0])]
            how = " and".join(f" by `{c.describe()}`" + (f" (line {c.span.line})" if c.span
                                                          is not None else "") for c in by[:2])
            return (f"; `{p.path}` lies ({dx:+.6g}, {dy:+.6g}) mm from where it is written, "
                    f"moved{how}: the assert reads it where it lies now (compare members of "
                    f"one part, which move together)")
    return ""


def _placed_note(a: Assertion, sheet, owners) -> str:
    """That a part the assertion reads is placed with ``Place`` and so read where it is
    written, not where the sheet's layout moved it (``sheet``: the solution): ``""`` when
    none was moved."""
    if sheet is None:
        return ""
    for s in _structures_read(a, owners):
        for p in [s] + list(s.ancestors()) if hasattr(s, "ancestors") else [s]:
            if getattr(p, "placement", None) is None or p.fx < 0:
                continue
            dx, dy = float(sheet[p.fx]), float(sheet[p.fy])
            if math.hypot(dx, dy) <= 0.01 or not _reads_place(a, sheet, p.fx, p.fy):
                continue                # (a size, or within one part: the frame cancels)
            by = [c for c in p.parent.constraints if not c.implicit and c.args
                  and any(p is t or (hasattr(t, "is_within") and t.is_within(p))
                          for t in c.args[0])] if p.parent is not None else []
            how = " and".join(f" `{c.describe()}`" for c in by[:2])
            return (f"; `{p.path}` is placed with `Place`, so the assert reads it where it is "
                    f"written (the sheet's layout moves it ({dx:+.6g}, {dy:+.6g}) mm"
                    + (f", by{how}" if how else "") + ")")
    return ""


def describe(a: Assertion, found: list, alternatives: int = 1, x=None, owners=None,
             sheet=None, model: Model | None = None) -> str:
    """The E0405 message: the condition, the user's reason and the values found
    (``found``: ``(op, left, right, dim)`` of the sides that fail; ``alternatives``: how
    many alternatives of an `or` failed, each by the sides found), then the value of each
    name and member the condition reads (``a.reads``, at ``x`` when given: where it is
    judged, :func:`judged_at`), where it is not the side itself: `(ring.bb.width = 124 mm,
    wall = 3 mm)`; a part it reads that a relation moved from where it is written, and the
    relation (``owners``: the model's ``param_owner``); a value it reads that the solve moved
    within its part, and the constraints that moved it (``model``: its ``x_written``); a
    placed part read where it is written though the layout moved it (``sheet``: the
    solution)."""
    why = f" ({a.message})" if a.message else ""
    parts = []
    for op, l, r, dim in found[:3]:
        parts.append(f"{_show(l, dim, a)} {op} {_show(r, dim, a)} is false" + _within_tol(op, l, r, dim))
    lead = "no alternative holds: " if alternatives > 1 else ""
    said = [f"{text} = {shown}" for text, shown in _reads(a, x)
            if not a.text.strip() == text]
    where = f" (where {', '.join(said)})" if said else ""
    # an assert in a template names the instance it failed in (run gz: four word tiles of
    # one `def`, "which of the 4 tiles failed" unsaid)
    inst = next((u for u in ([a.owner, *a.owner.ancestors()] if a.owner is not None else [])
                 if getattr(u, "template", None)), None)
    at = f" in `{inst.path}`" if inst is not None else ""
    return (f"assertion failed{at}: `{a.text}`{why}: {lead}" + "; ".join(parts) + where
            + _drawn_boxes(a, x) + _text_boxes(a, x) + _star_boxes(a, x) + _spline_boxes(a, x)
            + _slot_lengths(a, x)
            + _moved_part(a, x, owners) + _moved_within(a, x, model)
            + _placed_note(a, sheet, owners))


def _box_terms(a: Assertion) -> list:
    """The box sides (:class:`.bbox.BBTerm`) the sides of ``a``'s alternatives read."""
    terms: list = []
    for group in a.groups:
        for _, le, re_, _ in group:
            for side in (le, re_):
                if not isinstance(side, (int, float)):
                    collect(side, terms)
    return terms


def _relative(label: str, owner) -> str:
    """``label`` as written from inside ``owner`` (``star.s`` of ``lid.star.s`` in ``lid``)."""
    path = getattr(owner, "path", None)
    return label[len(path) + 1:] if path and label.startswith(path + ".") else label


def _written_name(label: str, a: Assertion) -> str:
    """``label`` (a full path, ``lid.star.s``) as the assertion writes it: its shortest tail
    that the text names (``star.s``), else as written from inside ``a.owner``."""
    import re
    parts = label.split(".")
    for k in range(len(parts) - 1, -1, -1):
        tail = ".".join(parts[k:])
        if re.search(r"(?<![\w.])" + re.escape(tail) + r"(?![\w])", a.text):
            return tail
    return _relative(label, a.owner)


def _slot_lengths(a: Assertion, x) -> str:
    """What a Slot's ``length``, which the assertion reads, measures (issue 111, run ci: a
    hook's shank asserted 34.5 mm centre to centre read 39.5 mm): "; `first.shank` is a Slot:
    its `length` is end to end, its round ends included; centre to centre
    (`first.shank.spine.length`) it is 34.5 mm"."""
    out = []
    for text, e, dim in a.reads:
        if dim != "slot":
            continue
        try:
            v = float(e) if isinstance(e, (int, float)) else (
                float(e.const) if isinstance(e, Lin) and not e.terms else
                _eval(e, x, set()) if x is not None else None)
        except (ArithmeticError, KeyError, TypeError, ValueError):
            continue
        if v is not None and math.isfinite(v):
            out.append(f"; `{text}` is a Slot: its `length` is end to end, its round ends "
                       f"included; centre to centre (`{text}.spine.length`) it is "
                       f"{_show(v, (1, 0), a)}")
    return "".join(out)


def _one_shape(target):
    """``target`` itself, a shape; of a structure, its one drawn closed shape (None when it
    has several or none)."""
    from ..core.model import Structure
    if not isinstance(target, Structure):
        return target
    shapes = [h for st in target.subtree() for h in st.geometry
              if h.closed and not h.construction]
    return shapes[0] if len(shapes) == 1 else None


def _star_boxes(a: Assertion, x) -> str:
    """What a Star's box, which the assertion reads, is beside the circle through its tips
    (issue 111, run y: `assert star.bb.width > 40 mm` for a star "40 mm across the tips"
    failed at 39.47 mm, a five-pointed star's box being narrower, 2 R sin 72 deg): "; `lid.star.bb`
    is the star's box, 39.47 x 37.64 mm; the circle through its tips is 40 mm across
    (`2 * star.outer_radius`)", or "" where the box is as wide and tall as that circle."""
    if x is None:
        return ""
    from ..core.model import Structure
    from .bbox import numeric_box
    seen, out = set(), []
    for t in _box_terms(a):
        g = _one_shape(t.target)               # (a hole of one star: `star.bb`)
        if getattr(g, "kind", None) != "Star" or id(g) in seen:
            continue
        seen.add(id(g))
        try:
            box = numeric_box(t.target, t.frame, x)
        except (ArithmeticError, KeyError, TypeError, ValueError):
            continue
        d = 2 * g.data["dims"]["outer_radius"]
        if box is None:
            continue
        w, h = box[1] - box[0], box[3] - box[2]
        if abs(w - d) <= TOL and abs(h - d) <= TOL:
            continue
        tips = " (its tips before `tip_radius` rounds them)" if g.data["dims"].get("tip_radius") \
            else ""
        name = t.target.path if isinstance(t.target, Structure) else g.label
        out.append(f"`{name}.bb` is the star's box, {w / a.scale:.6g} x {h / a.scale:.6g} "
                   f"{a.unit}; the circle through its tips{tips} is {d / a.scale:.6g} {a.unit} "
                   f"across (`2 * {_relative(g.label, a.owner)}.outer_radius`)")
    return "".join(f"; {o}" for o in out)


def _spline_boxes(a: Assertion, x) -> str:
    """Where a Spline's box, which the assertion reads, bulges past its points (issue 111,
    runs gr and gs: `head.profile.bb.right - head.neck.bb.left == 200 mm` failed at 200.075
    mm, the closed curve swelling past its nose point): "; `head.profile.bb` is the curve's
    box, 0.0752 mm past its rightmost point `head.profile.points[5]` (a spline swells
    between its points): where a point is meant, assert on it; a limit on the cut part (a
    rule, the bed) reads the box rightly, and the points must come in" (run hb: a paddle's
    legal width, which the points would have passed), or "" where the sides read are its
    points'.  A structure read whose one closed shape is a Spline is said the same way."""
    if x is None:
        return ""
    from ..core.model import Structure
    from .bbox import numeric_box
    from .members import _pv, points_of
    read: dict = {}                            # id(target) -> (a term, the sides read)
    for t in _box_terms(a):
        read.setdefault(id(t.target), (t, set()))[1].add(t.side)
    out = []
    for t, sides_read in read.values():
        g = _one_shape(t.target)
        if getattr(g, "kind", None) != "Spline":
            continue
        try:
            box = numeric_box(t.target, t.frame, x)
            pts = [_pv(p, t.frame) for p in points_of(g)]
            px = [evaluate(p.x, x) for p in pts]
            py = [evaluate(p.y, x) for p in pts]
        except (ArithmeticError, KeyError, TypeError, ValueError, AttributeError):
            continue
        if box is None or not px:
            continue
        most = {"right": max(range(len(px)), key=px.__getitem__),
                "left": min(range(len(px)), key=px.__getitem__),
                "top": max(range(len(py)), key=py.__getitem__),
                "bottom": min(range(len(py)), key=py.__getitem__)}
        past = [(box[1] - px[most["right"]], "right"), (px[most["left"]] - box[0], "left"),
                (box[3] - py[most["top"]], "top"), (py[most["bottom"]] - box[2], "bottom")]
        past = [(d, side) for d, side in past if d > TOL and side in sides_read]
        if not past:
            continue
        name = _written_name(t.target.path if isinstance(t.target, Structure) else g.label, a)
        pts_name = (name + g.label[len(t.target.path):] if isinstance(t.target, Structure)
                    and g.label.startswith(t.target.path + ".") else _written_name(g.label, a))
        sides = ", ".join(f"{d / a.scale:.6g} {a.unit} past its {side}most point "
                          f"`{pts_name}.points[{most[side]}]`" for d, side in past)
        out.append(f"`{name}.bb` is the curve's box, {sides} (a spline swells between its "
                   f"points): where a point is meant, assert on it; a limit on the cut part "
                   f"(a rule, the bed) reads the box rightly, and the points must come in")
    return "".join(f"; {o}" for o in out)


def _text_boxes(a: Assertion, x) -> str:
    """Where a Text's `.center`, which the assertion reads, lies off its `position` (issue
    111, run j: `assert label.t.center.y == ...` failed by 0.042 mm, the letters' box being
    lower than the middle valign="middle" puts at the position): "; `d.t.center` is its
    letters' box centre, 1.36 mm below its `position` (descenders, round letters'
    overshoot): a text is placed, and best asserted, by its `position`", or "".  The texts
    are those of the assertion's structure whose position a `.center` it reads is made of."""
    if x is None or a.owner is None or ".center" not in a.text:
        return ""
    sides = [e for text, e, _ in a.reads if ".center" in text]
    sides += [e for group in a.groups for _, le, re_, _ in group for e in (le, re_)]
    used: set = set()
    for e in sides:
        todo = [e]
        while todo:
            n = todo.pop()
            if isinstance(n, Lin):
                used |= set(n.terms)
            else:
                todo += [u for u in getattr(n, "args", ()) if not isinstance(u, (int, float))]
    if not used:
        return ""
    out = []
    for st in a.owner.subtree():
        for g in st.geometry:
            p = g.points.get("position") if g.kind == "Text" else None
            if p is None or g.data.get("along") is not None or g.data.get("stencil") \
                    or g.data.get("rotation", 0.0) or not ({p.ix, p.iy} & used):
                continue
            x0, x1, y0, y1 = g.data.get("extent", (0.0, 0.0, 0.0, 0.0))
            for axis, off, mid in (("y", (y0 + y1) / 2, g.data.get("valign") == "middle"),
                                   ("x", (x0 + x1) / 2,
                                    g.data.get("anchor", "middle") == "middle")):
                if not mid or abs(off) <= TOL or (p.iy if axis == "y" else p.ix) not in used:
                    continue
                way = ("above" if off > 0 else "below") if axis == "y" else \
                    ("right of" if off > 0 else "left of")
                out.append(f"`{g.label}.center` is its letters' box centre, "
                           f"{abs(off) / a.scale:.3g} {a.unit} {way} its `position` "
                           "(descenders, round letters' overshoot): a text is placed, and "
                           "best asserted, by its `position`")
    return "".join(f"; {o}" for o in out)


def _drawn_boxes(a: Assertion, x) -> str:
    """What a structure's box the assertion reads owes to its drawings and holes, when they
    widen it (issue 111: `assert marker.bb.width == 25 mm` failed at 30.1 mm, the engraved
    word being wider than the stake; run z7's board stand: `side.bb.height == 115 mm` at
    125.75, slots for the boards running out through the arched top): "; `marker.bb` holds
    its drawing `marker.label`: its material alone spans 25 x 120 mm (`marker.body.bb`)",
    or ""."""
    if x is None:
        return ""
    from ..core.model import Structure
    from .bbox import numeric_box
    seen, out = set(), []
    for t in _box_terms(a):
        s = t.target
        if not isinstance(s, Structure) or id(s) in seen:
            continue
        seen.add(id(s))
        extra = [d for d in s.subtree() if d is not s and d.kind in ("drawing", "hole", "cut")
                 and not any(u.kind in ("drawing", "hole", "cut") for u in d.ancestors()
                             if u.is_within(s) and u is not s)]
        if not extra or s.kind in ("hole", "cut", "drawing"):
            continue
        try:
            full = numeric_box(s, t.frame, x)
            bare = numeric_box(s, t.frame, x, exclude=set(extra))
        except (ArithmeticError, KeyError, TypeError, ValueError):
            continue
        if full is None or bare is None or max(abs(u - v) for u, v in zip(full, bare)) <= TOL:
            continue
        wide = []                          # those that reach past the material's box
        for d in extra:
            try:
                b = numeric_box(d, t.frame, x)
            except (ArithmeticError, KeyError, TypeError, ValueError):
                b = None
            if b is not None and (b[0] < bare[0] - TOL or b[1] > bare[1] + TOL
                                  or b[2] < bare[2] - TOL or b[3] > bare[3] + TOL):
                wide.append(d)
        wide = wide or extra
        shapes = [g for g in s.geometry if g.name and g.closed and not g.construction]
        # (its one shape, when no child solid adds material: run hi's silhouette named its
        # harness for the moon's 280 x 280 mm)
        alone = not any(c.kind == "solid" for c in s.children.values())
        named = f" (`{s.path}.{shapes[0].name}.bb`)" if len(shapes) == 1 and alone else ""
        who = ", ".join(f"{'drawing' if d.kind == 'drawing' else d.kind} `{d.path}`"
                        for d in wide[:3])
        holes = any(d.kind != "drawing" for d in wide)
        out.append(f"`{s.path}.bb` holds its {who}"
                   + (" (a hole's box counts where it runs past the material)" if holes
                      else "")
                   + f": its material alone spans {(bare[1] - bare[0]) / a.scale:.6g} x "
                   f"{(bare[3] - bare[2]) / a.scale:.6g} {a.unit}{named}")
    return "".join(f"; {o}" for o in out)


def _reads(a: Assertion, x) -> list[tuple[str, str]]:
    """``(text, value as said)`` of each name and member the assertion reads, evaluated at
    ``x`` (a value that cannot be worked out there is left out)."""
    out = []
    for text, e, dim in a.reads:
        if dim == "said":                   # said when read (a list of lists' shape)
            out.append((text, e))
            continue
        if dim == "slot":                   # :func:`_slot_lengths` says it
            continue
        try:
            if isinstance(e, (int, float)) or (isinstance(e, Lin) and not e.terms):
                v = float(e) if isinstance(e, (int, float)) else float(e.const)
            elif x is None:
                continue
            else:
                terms: list = []
                collect(e, terms)
                v = _eval(e, x, exclusions(terms) if terms else set())
        except (ArithmeticError, KeyError, TypeError, ValueError):
            continue
        if math.isfinite(v):
            out.append((text, _show(v, dim, a)))
    return out


def _within_tol(op: str, left: float, right: float, dim) -> str:
    """What a strict comparison that holds as plain numbers but not within :data:`TOL`
    needs (issue 105: `assert a > 0` at `a = 1e-7` said only "1e-07 > 0 is false"): the
    gap, and the tolerance, in mm, radians or plain units; "" for any other failure."""
    if dim == "text":
        return ""
    d = left - right
    unit = {(1, 0): " mm", (0, 1): " rad"}.get(dim, "")
    if op == "==" and math.isfinite(d) and abs(d) > TOL and f"{left:.6g}" == f"{right:.6g}":
        # said alike to 6 digits (run t: "-75 mm == -75 mm is false", 3.5e-5 mm apart)
        return (f" (the sides differ by {abs(d):.3g}{unit}, more than the {TOL:g}{unit} every "
                "comparison is judged within: say how close is enough, `abs(a - b) < 0.01 mm`)")
    if not (math.isfinite(d) and ((op == ">" and 0 < d <= TOL) or (op == "<" and -TOL <= d < 0))):
        return ""
    return (f" (the sides are only {abs(d):.3g}{unit} apart: `{op}` needs a gap of more than "
            f"{TOL:g}{unit}, the tolerance every comparison is judged within)")


def _eval(e, x, exclude: set) -> float:
    if isinstance(e, (int, float)):
        return float(e)
    if contains_bbox(e):
        e = expand(e, x, exclude)
    return float(evaluate(e, x))


def _unknowns(e, free, out: list) -> None:
    """Whether expression ``e`` reads a free parameter or a box (appended to ``out``)."""
    if out or isinstance(e, (int, float)):
        return
    if isinstance(e, Lin):
        if any(free[i] for i in e.terms):
            out.append(e)
        return
    args = getattr(e, "args", None)
    if args is None:                # a box term
        out.append(e)
        return
    for a in args:
        _unknowns(a, free, out)


def failed(model: Model, held_only: bool = False) -> list[tuple[Assertion, list]]:
    """Each assertion that does not hold at :func:`judged_at` (the solution, the parts placed
    with ``Place`` where they are written), with its failing sides' values.  ``held_only``:
    only the assertions whose sides read no solved value (params, constants, held
    dimensions): what can be judged when the solve failed."""
    out = []
    if not model.assertions:
        return out
    x = judged_at(model)
    free = model.free
    for a in model.assertions:
        if held_only:
            reads: list = []
            for group in a.groups:
                for _, le, re_, _ in group:
                    _unknowns(le, free, reads)
                    _unknowns(re_, free, reads)
            if reads:
                continue
        bad = _wrong(a, x)
        if bad:
            out.append((a, bad))
    return out


def judged_at(model: Model):
    """The values asserts are judged at: the solution, but in an assembly that places its
    parts with ``Place``, those parts where they are written (:func:`written`): the sheet's
    layout moves them apart for cutting, and the product is made from where they are written
    (runs bp, bs, bv: `strip[1].r.bb.left - strip[0].r.bb.right == 32 mm`, a game's channel as
    drawn, failed by the 6 mm the strips were laid apart on the sheet; run bz: judged either
    way, an assert the layout had made true, `bail.inner.bb.left > 4 mm`, could not fail)."""
    x = model.xs()
    home = written(model, x)
    return x if home is False else home


def _wrong(a: Assertion, x) -> list:
    """The failing sides ``(op, left, right, dim)`` of ``a`` at ``x`` (every alternative's),
    or [] when one of its alternatives holds."""
    bad: list = []
    for group in a.groups:
        wrong = []
        for op, le, re_, dim in group:
            terms: list = []
            for side in (le, re_):
                if not isinstance(side, (int, float)):
                    collect(side, terms)
            exclude = exclusions(terms) if terms else set()   # as in a constraint (bbox.py)
            lv, rv = _eval(le, x, exclude), _eval(re_, x, exclude)
            if not holds(op, lv, rv, "right" if _number(re_) else "left" if _number(le)
                         else ""):
                wrong.append((op, lv, rv, dim))
        if not wrong:
            return []                   # this alternative holds: so does the assertion
        bad += wrong
    return bad


def written(model: Model, x):
    """``x`` with the frame of every structure that has a ``Place`` set back to where it is
    written (its frame's offset 0), or ``False`` when none has one or none was moved: the
    coordinates of the assembled product as the program draws its parts."""
    placed = [s for s in model.structures if getattr(s, "placement", None) is not None
              and s.parent is not None and s.fx >= 0 and s.copy_origin is None]
    if not any(x[s.fx] != 0.0 or x[s.fy] != 0.0 for s in placed):
        return False
    home = x.copy()
    for s in placed:
        home[s.fx] = home[s.fy] = 0.0
    # what `CutInto` cuts into a placed part goes back with it (run bq: a door cut into an
    # end wall, placed on it by relations, was read where the sheet had the wall)
    for h in model.structures:
        p = h.cuts_into
        while p is not None and getattr(p, "placement", None) is None:
            p = p.parent
        if p is None or h.fx < 0 or h.parent is not p.parent or p not in placed:
            continue
        home[h.fx] -= x[p.fx]
        home[h.fy] -= x[p.fy]
    return home
