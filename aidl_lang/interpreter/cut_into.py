"""``CutInto(hole, part)`` (issue 61) and ``CutInto(drawing, part)`` (issue 111): a hole or a
drawing declared in an assembly given to a solid part of it (a template instance's lid, its
front), checked where the statement is written."""
from __future__ import annotations

from ..base.diagnostics import EvalError
from ..geometry.core.values import StructRef, type_name
from .common import _a


def cut_into(conv, node, spans):
    """``CutInto(hole, part)`` (issue 61): the hole ``hole``, declared in an assembly,
    cuts the solid ``part`` instead of being a part of its own.  Both are in the
    subtree of the structure the statement is written in (validity rule 2, checked by
    the caller); nothing moves in the structure tree, so every constraint keeps its
    frames: the booleans subtract the hole from the part (output/part/build/booleans.py).
    A drawing so given is engraved on the part: drawn with it, moved with it by a cutting
    layout, checked against its material (W0505; issue 111: "TEA" on a finger box's front)."""
    h, part = conv["hole"], conv["part"]
    if isinstance(h, (list, tuple)):    # a pattern's list (`vents = GridPattern(air, ...)`)
        for one in h:
            cut_into(dict(conv, hole=one), node, spans)
        return None
    hspan, pspan = spans.get("hole", node.span), spans.get("part", node.span)
    if not isinstance(h, StructRef) or h.struct.kind not in ("hole", "drawing", "cut"):
        raise EvalError("E0108", f"`CutInto` cuts with a hole or a cut structure (or engraves "
                        f"a drawing), got {_a(type_name(h))}", hspan,
                        hint="declare `hole NAME { ... }` (`cut NAME { ... }`, `drawing NAME "
                             "{ ... }`) beside the part's instance and write `CutInto(NAME, "
                             "box.lid)`")
    if not isinstance(part, StructRef) or part.struct.kind != "solid":
        raise EvalError("E0108", f"`CutInto` cuts into a solid, got {_a(type_name(part))}",
                        pspan, hint="name a solid part, e.g. `box.lid` of "
                                    "`box = finger_box(...)` (`aidl docs finger_box` "
                                    "lists its parts)")
    hs, ps = h.struct, part.struct
    what = hs.kind                      # hole, cut or drawing
    if hs.parent is None or hs.parent.kind != "assembly":
        where = hs.parent.path if hs.parent is not None else hs.path
        raise EvalError("E0108", f"`{hs.path}` already {'lies on' if what == 'drawing' else 'cuts'}"
                        f" `{where}`, the {hs.parent.kind if hs.parent else 'structure'} it is "
                        f"declared in: `CutInto` is for a {what} declared in an assembly",
                        hspan, hint=f"declare the {what} in the assembly that holds the "
                                    "part's instance, beside it")
    if ps.is_within(hs):
        raise EvalError("E0108", f"`{ps.path}` is inside the {what} `{hs.path}`", pspan)
    if hs.cuts_into is ps:
        return None                     # (a pattern's list naming its original, given already)
    if hs.cuts_into is not None:
        raise EvalError("E0108", f"`{hs.path}` already cuts `{hs.cuts_into.path}`", node.span,
                        hint=f"a {what} goes into one solid: declare another for the other")
    give(hs, ps)
    return None


def give(hs, ps) -> None:
    """``hs`` cuts (or is engraved on) ``ps``, and so does every copy a pattern made of it
    beside it (issue 111's hamster house: `GridPattern(air, 3, 5, 20)` then
    `CutInto(air, box.lid)` cut 1 of 15 holes; a pattern's copies follow their original, as
    its countersink does).  A pattern written after the call copies it too
    (:meth:`aidl_lang.geometry.derived.operations._Cloner.struct`)."""
    hs.cuts_into = ps
    ps.cut_by.append(hs)
    for copy in hs.__dict__.get("pattern_copies", ()):
        if copy.cuts_into is None and copy.parent is hs.parent:
            give(copy, ps)
