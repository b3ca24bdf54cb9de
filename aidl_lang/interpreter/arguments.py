"""A template's arguments checked at its call, before its body runs (issue 95).

Two checks, each one located error at the argument in the caller, naming it and what it
may be, so that a wrong call never floods the caller with the template's insides:

* **kinds** (:func:`check_kinds`): an argument of another kind than its parameter's default
  (a string for ``teeth=20``, a number for ``vent="slots"``, a list for a length); in the
  standard library, whose lengths and angles all carry a unit, a length or an angle given
  to a parameter whose default is a bare number (a count, a ratio). The unit kinds of
  ``thickness=3 mm`` or ``angle=30 deg`` are checked (and bare numbers adapted) by
  ``Statements._adapt_args``; both say the template's reasons for that parameter.
* **asserts over the arguments** (:func:`precheck_asserts`): the template's top-level
  ``assert`` statements that read only its parameters, the file's names and top-level
  values computed from them (``n = len(teeth)``) are evaluated first; the first that fails
  is E0405 at the argument(s) it reads, the assert's line a note, and the body is not run.
"""
from __future__ import annotations

from .. import ast as A
from ..base.diagnostics import EvalError, Label, shown_path
from ..geometry.core.values import ANG, LEN, NUM, Q, dim_name, type_name
from ..registry import FUNCTIONS, UNITS_LENGTH
from .common import _STMT_ERRORS, POISON, Scope, _a, _const, _definition_lines, _src

# what a default's text says its parameter holds
_KIND_OF_DEFAULT = {A.Num: "number", A.Neg: "number", A.Str: "string", A.FStr: "string",
                    A.ListLit: "list", A.ListComp: "list", A.TupleLit: "point"}


def default_kind(p: A.TemplateParam) -> str | None:
    """The kind a parameter's default is written as (``number``, ``string``, ``list``,
    ``point``, ``boolean``), or None when its text does not say (an expression)."""
    d = p.default
    if d is None:
        return None
    if type(d) is A.Name and d.id in ("true", "false", "True", "False"):
        return "boolean"
    if type(d) is A.Neg and type(d.operand) is not A.Num:
        return None
    return _KIND_OF_DEFAULT.get(type(d))


def value_kind(v) -> str:
    """The kind of a value as :func:`default_kind` says it: any number, length or angle is a
    number; a point or a pair a point; else its type name (boolean, string, list, ...)."""
    if isinstance(v, Q):
        return "number"
    return "point" if isinstance(v, tuple) else type_name(v)


def _shown(v, unit_scale: float) -> str:
    from .common import show
    if isinstance(v, str):
        return f'the string "{v}"'
    if isinstance(v, bool):
        return f"`{'true' if v else 'false'}`"
    if isinstance(v, Q) and v.const() is not None:
        unit = {LEN: " mm" if unit_scale == 1.0 else "", ANG: " deg"}.get(v.dim, "")
        return f"{_a(dim_name(v.dim))} (`{show(v, unit_scale)}{unit}`)"
    if isinstance(v, list):
        return f"a list (`{show(v, unit_scale)}`)"
    return _a(value_kind(v))


def reasons(d: A.Def, param: str) -> list[str]:
    """The messages of ``d``'s top-level asserts that read ``param``, also through values
    computed from it (``n = len(teeth)``): those that read no other parameter when there are
    some, else all."""
    _assigns, asserts = _plan(d, set(_definition_lines(d.body.stmts)))
    out = [st.message for st, deps in asserts if st.message and param in deps]
    alone = [st.message for st, deps in asserts if st.message and deps == {param}]
    return alone or out


def _word(p: A.TemplateParam, want: str) -> str:
    """What ``p``'s default says it is: a length or an angle for a number with its unit."""
    d = p.default
    if type(d) is A.Neg:
        d = d.operand
    if want == "number" and type(d) is A.Num and d.unit is not None:
        return "length" if d.unit in UNITS_LENGTH else "angle"
    return want


def kind_error(ip, d: A.Def, p: A.TemplateParam, v, span, want: str) -> EvalError:
    """E0108 (another kind of value) or E0109 (another unit kind): ``p`` of template ``d``
    is ``want`` like its default, got ``v``; the hint gives the template's reasons."""
    dflt = _src(ip.sink, p.default.span)
    code = "E0109" if isinstance(v, Q) and want in ("number", "length", "angle") else "E0108"
    what = "a plain number (a count or a ratio)" if want == "number" and code == "E0109" \
        else _a(_word(p, want))
    why = reasons(d, p.name)
    hint = (f"{'; '.join(why)}; " if why else "") + f"e.g. `{p.name}={dflt}`"
    return EvalError(code, f"`{p.name}` of `{d.name}` is {what} like its default `{dflt}`, "
                     f"got {_shown(v, ip.unit_scale)}", span, hint=hint)


def check_kinds(ip, t, d: A.Def, vals: dict, spans: dict) -> None:
    """Raise the first argument in ``vals`` (param -> (value, node)) whose kind is not its
    default's (``spans``: param -> the argument's value's text)."""
    strict = _in_stdlib(t)
    for p in d.params:
        got = vals.get(p.name)
        want = default_kind(p)
        if got is None or want is None:
            continue
        v = got[0]
        if v is POISON:
            continue
        have = value_kind(v)
        if have != want:
            if want == "point" and have == "list" and len(v) == 2:
                continue
            raise kind_error(ip, d, p, v, spans[p.name], want)
        if want == "list":
            _check_items(ip, d, p, v, spans[p.name])
        if (strict and want == "number" and type(p.default) is A.Num and p.default.unit is None
                and v.dim != NUM and v.const() is not None):
            raise kind_error(ip, d, p, v, spans[p.name], "number")


def _check_items(ip, d: A.Def, p: A.TemplateParam, v: list, span) -> None:
    """A list given for a list default whose items are all of one kind (`teeth=[12, 36]`):
    each item of that kind, else E0108 naming the parameter and the item."""
    kinds = {default_kind(A.TemplateParam(x.span, "", x)) for x in p.default.items} \
        if type(p.default) is A.ListLit else set()
    if len(kinds) != 1 or None in kinds:
        return
    want = kinds.pop()
    for i, x in enumerate(v):
        if x is not POISON and value_kind(x) != want:
            dflt = _src(ip.sink, p.default.span)
            why = reasons(d, p.name)
            raise EvalError("E0108", f"`{p.name}` of `{d.name}` is a list of {want}s like its "
                            f"default `{dflt}`, got {_shown(x, ip.unit_scale)} as item {i}",
                            span, hint=(f"{'; '.join(why)}; " if why else "")
                            + f"e.g. `{p.name}={dflt}`")


def _in_stdlib(t) -> bool:
    f = t.scope.file
    return f is not None and shown_path(f.path).startswith("std/")


# ------------------------------------------------------------------ asserts over the arguments
def _pure(e) -> bool:
    """Whether expression ``e`` computes a value only (no geometry, template or member)."""
    for n in A.walk(e):
        t = type(n)
        if t is A.Member:
            return False
        if t is A.Call and not (type(n.func) is A.Name and n.func.id in FUNCTIONS):
            return False
    return True


def _free(e) -> set:
    """The names ``e`` reads (a comprehension's own variable left out)."""
    bound = {n.var for n in A.walk(e) if type(n) is A.ListComp}
    return {n.id for n in A.walk(e) if type(n) is A.Name} - bound


def _plan(d: A.Def, defined: set):
    """The top-level assignments computed from the arguments alone (in order) and the asserts
    over them, each with the parameters it depends on: ``(assigns, asserts)``."""
    params = {p.name: {p.name} for p in d.params}
    deps = dict(params)
    assigns, asserts = [], []
    for st in d.body.stmts:
        if type(st) is A.Assign and _pure(st.value):
            names = _free(st.value)
            if all(n in deps or n not in defined for n in names):
                deps[st.name] = set().union(*(deps.get(n, ()) for n in names))
                assigns.append(st)
    for st in d.body.stmts:
        if type(st) is A.Assert and _pure(st.expr):
            names = _free(st.expr)
            if all(n in deps or n not in defined for n in names):
                asserts.append((st, set().union(*(deps.get(n, ()) for n in names))))
    return assigns, asserts


def precheck_asserts(ip, d: A.Def, tscope: Scope, given: dict, spans: dict) -> None:
    """Evaluate ``d``'s asserts over its arguments in a scratch scope below ``tscope``
    (the parameters bound); raise E0405 at the arguments of ``given`` (param -> value) that
    the first failing one reads.  An assert that cannot be decided now, or reads only
    defaults, is left to the body."""
    plans = ip.__dict__.setdefault("_arg_plans", {})     # per template, once a compile
    got = plans.get(id(d))
    if got is None or got[0] is not d:
        got = plans[id(d)] = (d, *_plan(d, set(_definition_lines(d.body.stmts))))
    _d, assigns, asserts = got
    if not any(deps & given.keys() for _st, deps in asserts):
        return
    saved = ip.scope
    scratch = Scope(tscope, tscope.struct, tscope.file)
    ip.scope = scratch
    try:
        for st in assigns:
            try:
                scratch.vars[st.name] = ip.eval(st.value)
            except _STMT_ERRORS:
                scratch.vars[st.name] = POISON
        for st, deps in asserts:
            named = [p.name for p in d.params if p.name in deps and p.name in given]
            if not named:
                continue
            err = _failed(ip, st, d, named, spans)
            if err is not None:
                raise err
    finally:
        ip.scope = saved


def _failed(ip, st: A.Assert, d: A.Def, named: list, spans: dict) -> EvalError | None:
    """The error at the call when assert ``st`` fails on the arguments ``named``, else None."""
    from ..geometry.relations.assertions import describe
    from .asserts import judge_known
    try:
        groups = ip._assert_groups(st.expr)
    except EvalError as ex:          # a kind the condition cannot compare: that argument's
        return _at_args(ip, ex.code, f"{ex.message}", st, d, named, spans)
    except _STMT_ERRORS:
        return None
    if not all(_const(l) and _const(r) for g in groups for _, l, r, _ in g):
        return None                  # it reads more than the arguments: judged in the body
    verdict, _, known = judge_known(groups)
    if verdict is not False:
        return None
    return _at_args(ip, "E0405", describe(ip._assertion(st, None), known, len(groups)), st, d,
                    named, spans)


def _at_args(ip, code: str, text: str, st: A.Assert, d: A.Def, named: list,
             spans: dict) -> EvalError:
    which = ", ".join(f"`{n}`" for n in named)
    word = "argument" if len(named) == 1 else "arguments"
    sp = st.span
    note = Label(sp, f"inside `{d.name}`, at {shown_path(sp.file)}:{sp.line}:{sp.col}",
                 primary=False)
    cond = _src(ip.sink, st.expr.span)
    why = f" ({st.message})" if st.message else ""
    values = "a value" if len(named) == 1 else "values"
    hint = (f"give {which} {values} for which `{cond}` holds{why}; the template is not built "
            f"until it does")
    first = spans[named[0]]
    span = first.cover(spans[named[-1]]) if len(named) > 1 and \
        spans[named[-1]].file == first.file else first
    return EvalError(code, f"{word} {which} of `{d.name}`: {text}", span, hint=hint,
                     labels=[note])
