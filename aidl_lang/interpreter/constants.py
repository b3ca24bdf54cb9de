"""The top-level constants that the params read (issue 111): which are worked out in the
file's order with the params (:func:`early_constants`), and the error that says why one is
not (:func:`late_constant`).  docs/language.md 2.3."""
from __future__ import annotations

from collections import Counter

from .. import ast as A
from ..base.diagnostics import EvalError
from .common import _is_plain_const, file_functions


def early_constants(stmts: list) -> set:
    """The top-level constants (``NAME = expr`` making no geometry, assigned once) that a
    param's default, ``min`` or ``max`` reads, directly or through other such constants, and
    that read only params and constants above them: these are worked out in the file's order
    with the params (docs/language.md 2.3: `hooks = 5` then `param w = hooks * pitch`, issue
    111), the other constants after every param, as before."""
    count = Counter(st.name for st in stmts if isinstance(st, (A.Assign, A.ParamDecl, A.Def,
                                                                 A.Func)))
    tops = set(count)
    reads = {}
    above: set = set()
    funcs = file_functions(stmts)
    for st in stmts:
        if isinstance(st, A.ParamDecl):
            above.add(st.name)
        elif isinstance(st, A.Func) and count[st.name] == 1:
            # a one-line function is defined where it stands; what it reads must be ready
            # when a constant above a param calls it (run br: `X1 = sx(N - 1) + 22 mm`)
            names = {n.id for n in A.walk(st.value) if type(n) is A.Name} & tops \
                - {p.name for p in st.params}
            if names <= above:
                reads[st] = names
                above.add(st.name)
        elif isinstance(st, A.Assign) and count[st.name] == 1 and _is_plain_const(st, funcs):
            names = {n.id for n in A.walk(st.value) if type(n) is A.Name} & tops
            if names <= above:
                reads[st] = names
                above.add(st.name)
    wanted = set()
    for st in stmts:
        if isinstance(st, A.ParamDecl):
            for node in [st.value] + [o.value for o in st.options]:
                wanted |= {n.id for n in A.walk(node) if type(n) is A.Name}
    early = set()
    for st in reversed(stmts):              # a constant that a wanted one reads is wanted
        if st in reads and st.name in wanted:
            if isinstance(st, A.Assign):    # (a function is defined in its place anyway)
                early.add(st)
            wanted |= reads[st]
    return early


def late_constant(e: EvalError, program: A.Program) -> EvalError | None:
    """A param's E0101 for a top-level constant that is worked out after the params
    (:func:`early_constants` did not take it): the error saying why, with the line that
    keeps it back, or None when ``e`` is another error."""
    if e.code != "E0101" or e.span is None or not program.source:
        return None
    name = program.source[e.span.start:e.span.end]
    defs = [st for st in program.stmts if isinstance(st, A.Assign) and st.name == name]
    if not defs or defs[0].span is None:
        return None
    const = defs[0]
    where = {st.name: st.span.line for st in program.stmts
             if isinstance(st, (A.ParamDecl, A.Assign)) and st.span is not None}
    if len(defs) > 1:
        why = f"it is assigned {len(defs)} times"
        fix = "assign it once"
    elif not _is_plain_const(const, file_functions(program.stmts)):
        why = "it makes geometry"
        fix = "compute the param from numbers instead"
    else:
        late = sorted({n.id for n in A.walk(const.value) if type(n) is A.Name
                       and where.get(n.id, 0) > const.span.line}, key=lambda n: where[n])
        if not late:
            late = [n.id for n in A.walk(const.value) if type(n) is A.Name
                    and n.id in where and n.id != name][:1]
        if not late:
            return None
        why = f"it reads `{late[0]}`, defined below it (line {where[late[0]]})"
        fix = f"move line {where[late[0]]} above line {const.span.line}"
    return EvalError("E0101", f"`{name}` (line {const.span.line}) is worked out after the "
                              f"params: {why}", e.span,
                     hint=f"a param may read the params and the constants above it whose own "
                          f"names are above them too; {fix}")
