"""The hints of a call whose argument is of the wrong kind (E0108): a shape with a center
where a point or curve is taken (name its member), a list where a box is taken (the equation
that centres the group)."""
from __future__ import annotations

from .. import ast as A
from ..geometry.core.values import GeomRef
from ..registry import lookup


def _center_hint(values, otherwise: str) -> str:
    """The hint of a point or curve constraint given a shape with a center that it does not
    take (an ArcSlot, a Star, ...): name the member to use, `s.center`; else ``otherwise``."""
    for v in values:
        if isinstance(v, GeomRef) and v.geom.kind not in ("Circle", "Arc", "Line", "Point"):
            entry = lookup(v.geom.kind)
            if entry is not None and "center" in entry.members:
                nm = v.geom.name or "shape"
                an = "an" if v.geom.kind[0] in "AEIOU" else "a"
                return (f"`{nm}` is {an} {v.geom.kind}: name its point, `{nm}.center`, or another "
                        f"point of it; {otherwise}")
    return otherwise


_AXIS = {"AlignCenterX": "center_x", "AlignCenterY": "center_y"}


def _list_hint(cname: str, key: str, node, sink) -> str | None:
    """The hint of a relation between boxes given a list as ``key`` (`AlignCenterX(body,
    [hook_l, hook_r])`, 105d: centring a pair is natural to write, and a list has no box):
    for a centre alignment, the equation on the items' centres, written from the call's own
    text; else how to give the group a box."""
    from .common import _src
    arg = next((a for a in node.args if isinstance(a, A.ListLit)), None)
    items = [_src(sink, e.span) for e in arg.items] if arg is not None else []
    others = [_src(sink, a.span) for a in node.args if not isinstance(a, A.ListLit)]
    axis = _AXIS.get(cname)
    if axis and items and all(items) and len(others) == 1 and others[0] and len(items) <= 6:
        mean = " + ".join(f"{t}.bb.{axis}" for t in items)
        return (f"a list has no box of its own: for the middle of the {len(items)} on "
                f"`{others[0]}`'s centre line write `({mean}) / {len(items)} == "
                f"{others[0]}.bb.{axis}` (the middle of their centres), or draw them in one "
                "structure and align that")
    return (f"a list has no box of its own: relate each of them, or draw them in one "
            f"structure and relate that (`{cname}` takes a structure or a shape as `{key}`)")


def list_arg_hint(interp, cname: str, key: str, node, spans: dict, bound: dict) -> str | None:
    """The hint of a list given as argument ``key`` where a relation takes one box (E0108):
    a loop's copies named whole in another loop (:func:`_copy_hint`), else
    :func:`_list_hint`."""
    return _copy_hint(interp.scope, spans[key], bound[key], interp.sink) or _list_hint(
        cname, key, node, interp.sink)


def _copy_hint(scope, span, value: list, sink) -> str | None:
    """The hint of a name of a loop's list of copies given as one thing inside another loop
    (run bp, twice: `strip = ...` in one loop, then `RightOf(strip, ...)` in a second loop
    over the same count: "relate each of them"): this loop's copy, `strip[k]`; else None."""
    from .common import _src
    name = _src(sink, span) if span is not None else ""
    if not name.isidentifier():
        return None
    s = scope
    while s is not None and getattr(s, "loop_var", None) is None:
        s = s.parent
    if s is None:
        return None
    var, k = s.loop_var, s.loop_index
    item = s.vars.get(var)
    n = item if isinstance(item, (int, float)) else getattr(item, "const", lambda: None)()
    if n is None or isinstance(n, bool) or n != int(n) or not 0 <= k < len(value):
        return None                     # a loop over things, not counting: no index to give
    off = int(n) - k
    index = var if off == 0 else f"{var} - {off}" if off > 0 else f"{var} + {-off}"
    return (f"`{name}` is a list of {len(value)} (a name set in a loop is the current copy "
            f"only inside its loop, the list after it): in this loop, one of them is "
            f"`{name}[{index}]`")


def shadowed(interp, v, span) -> str | None:
    """The hint of an argument that names a structure where a value was meant, because a
    structure of that name hides a constant of an outer scope (run ag's donut wall: `foot_l
    = 60 mm` at the top, `solid foot_l { ... Rectangle(..., width=foot_l) }`: "must be a
    length, got solid structure"): the two definitions and the fix; else None."""
    from ..geometry.core.values import StructRef
    from .common import _src
    name = _src(interp.sink, span)
    if type(v) is not StructRef or not name.isidentifier():
        return None
    line = v.struct.span.line if v.struct.span is not None else "?"
    if getattr(v.struct, "hides", None) == name:
        # the structure took the name of a value of its own scope (a template's parameter:
        # run gf's `hole aperture` in `def lens_plate(aperture=1.0 mm)`)
        return (f"`{name}` here is the {v.struct.kind} `{v.struct.path}` (line {line}), which "
                f"took the name of the value `{name}` above it (a parameter or a constant) "
                f"from its line on: give the structure or the value another name")
    _, at = interp.scope.lookup(name)
    outer = at.parent if at is not None else None
    hidden, _ = outer.lookup(name) if outer is not None else (None, None)
    if hidden is None or isinstance(hidden, StructRef):
        return None
    return (f"`{name}` here is the {v.struct.kind} `{v.struct.path}` (line {line}), which hides "
            f"the outer `{name}`: give the structure or the value another name")


def _drawn_member(v) -> bool:
    """A member a program reads of a template instance: a shape, a structure, or a list of
    them (a loop's copies), not a number its body worked with."""
    from ..geometry.core.values import StructRef
    if isinstance(v, list):
        return bool(v) and all(_drawn_member(x) for x in v)
    return isinstance(v, (GeomRef, StructRef))


def branch_making(d: A.Def, name: str, sink) -> str | None:
    """The hint for a member ``name`` a template instance lacks that template ``d`` makes in
    a branch of an ``if`` its call did not take (run bt, bu: `tab_and_slot(part="tab")`'s
    `slot`, made only for part "slot"); None when its body never sets ``name``."""
    from .common import _src

    def find(stmts, conds):
        for st in stmts:
            if isinstance(st, (A.Assign, A.StructDecl)) and st.name == name and conds:
                return conds
            if isinstance(st, A.For):
                got = find(st.body.stmts, conds)
            elif isinstance(st, A.If):
                cond = _src(sink, st.cond.span) or "..."
                got = find(st.body.stmts, conds + [f"`{cond}` holds"]) or (
                    find(st.orelse.stmts, conds + [f"`{cond}` is false"])
                    if st.orelse is not None else None)
            else:
                got = None
            if got:
                return got
        return None
    where = find(d.body.stmts, [])
    if not where:
        return None
    return (f"`{d.name}` makes `{name}` only where {' and '.join(where)}, which this call "
            f"does not give (its docs: `aidl docs {d.name}`)")


def foreign_read(interp, node, span, other) -> str | None:
    """The text of the first name or member chain inside ``span`` of call ``node`` whose value
    is geometry of structure ``other`` (``disc.center`` of ``Line(polar(disc.center, 46,
    a), ...)``), for E0201's message; None when none is found (issue 111, run ck: E0201 named
    the Line's argument `start` and not what the argument read)."""
    from ..base.diagnostics import EvalError
    from ..geometry.core.values import owners_of
    from .asserts import _chain, _children
    from .common import _src
    if span is None:
        return None
    todo = [node]
    while todo:
        n = todo.pop(0)
        sp = getattr(n, "span", None)
        if sp is None or sp.end <= span.start or sp.start >= span.end:
            continue
        if isinstance(n, (A.Name, A.Member)) and _chain(n) and span.start <= sp.start \
                and sp.end <= span.end:
            try:
                v = interp.eval(n)
            except EvalError:
                v = None
            if v is not None and other in owners_of(v):
                return _src(interp.sink, sp) or None
            if isinstance(n, A.Name):
                continue
        todo += _children(n)
    return None
