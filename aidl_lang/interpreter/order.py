"""The order a structure body runs in: its definitions first, in order, then its constraint
statements (docs/language.md, "Order"), but for a change in place (``Scale``, ``Translate``
or ``Move``, ``Flip`` of a name) that a definition below it reads: that change runs just
before the definition (:func:`changes_read_below`)."""
from __future__ import annotations

from .. import ast as A
from ..registry import canonical

IN_PLACE = frozenset(("Scale", "Translate", "Flip"))


def _changed_name(st) -> str | None:
    """The name a statement ``Scale(NAME, ...)`` (``Translate``, ``Move``, ``Flip``) changes in
    place, else None."""
    e = st.expr if type(st) is A.ExprStmt else None
    if type(e) is not A.Call or type(e.func) is not A.Name or canonical(e.func.id) not in IN_PLACE:
        return None
    return e.args[0].id if e.args and type(e.args[0]) is A.Name else None


def changes_read_below(stmts: list) -> dict[int, list]:
    """Index of a definition (an assignment) in ``stmts`` -> the changes in place written above
    it, not yet pulled forward, of a name its value reads: run before it, in their order (run
    bs: `Translate(first_paw, (110, -95))` then `trail = LinearPattern(first_paw, 3, ...)`,
    the pattern copied the paw where it was written, the constraints' pass moving it after)."""
    out: dict[int, list] = {}
    waiting: list = []          # (name, statement) of the changes above, in order
    for i, st in enumerate(stmts):
        name = _changed_name(st)
        if name is not None:
            waiting.append((name, st))
        elif type(st) is A.Assign and waiting:
            reads = {n.id for n in A.walk(st.value) if type(n) is A.Name}
            pulled = [w for w in waiting if w[0] in reads]
            if pulled:
                out[i] = [s for _, s in pulled]
                waiting = [w for w in waiting if w not in pulled]
    return out
