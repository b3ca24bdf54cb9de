"""What ``AllowOverlap`` accepts among engraved marks: two texts or marks it names, or the
drawings around them, laid out close on purpose (:func:`text_allowed`: W0513 then says nothing
of them), and an engraving named with its part, run off the material on purpose
(:func:`meant_off`: W0505); either statement counts as used for W0523."""
from __future__ import annotations

from ....geometry.core.model import Structure


def text_allowed(a, b) -> bool:
    """``AllowOverlap`` named both marks (shapes of drawings), or drawings around them, as
    laid out close on purpose (W0513 not said; the statement is then used, W0523)."""
    def covered(t, named) -> bool:
        return any(o is t or isinstance(o, Structure) and (t.owner is o or t.owner.is_within(o))
                   for o in named)
    node = a.owner
    while node is not None:
        named = getattr(node, "text_ok", ())
        if named and covered(a, named) and covered(b, named):
            node.text_used = True
            return True
        node = node.parent
    return False


def meant_off(g, part) -> bool:
    """``AllowOverlap(g, self)`` (or naming a drawing around ``g``, and ``part``, a structure
    around it or a shape of it) was written: ``g`` runs off ``part``'s material on purpose
    (issue 111: a checkerboard's grid lines carried over its dovetail band).  The statement
    is marked as used (``engrave_used``, read by W0523)."""
    node = g.owner
    while node is not None:
        for named, material in getattr(node, "engrave_ok", ()):
            if named is not g and named is not node:
                continue
            if any(part is m or part.is_within(m) or m.kind == "hole" and m.is_within(part)
                   if isinstance(m, Structure) else m.owner is part
                   or m.owner.kind == "hole" and m.owner.is_within(part) for m in material):
                node.engrave_used = getattr(node, "engrave_used", set()) | {id(named)}
                return True
        if node is part:
            break
        node = node.parent
    return False
