"""What ``AllowOverlap`` accepts among engraved marks (:func:`text_allowed`): two texts or
marks it names, or the drawings around them, laid out close on purpose (W0513 then says
nothing of them, and the statement counts as used for W0523)."""
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
