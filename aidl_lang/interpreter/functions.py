"""Functions, ``def name(params) = expr`` (docs/language.md 2.7, "Functions"): a call is
the expression's value with the parameters bound, evaluated in the scope the function was
defined in (issue 111: models reach for a named formula, `def angle_of(v) = 225 deg - v *
27 deg`)."""
from __future__ import annotations

from .. import ast as A
from ..base.diagnostics import EvalError, Label, did_you_mean
from ..base.limits import MAX_CALL_DEPTH
from ..geometry.core.values import Function
from .common import Scope, show


def call_function(ip, f: Function, node: A.Call):
    """The value of function ``f`` (``def name(params) = expr``) called by ``node``: its
    expression evaluated in the scope it was defined in, the parameters bound to the
    arguments (by position or name) or their defaults; E0104/E0105/E0106 for the
    arguments as a template's, E0302 past :data:`MAX_CALL_DEPTH` nested calls."""
    d = f.node
    params = [p.name for p in d.params]
    sig = f"`{d.name}({', '.join(params)})`"
    if len(node.args) > len(params):
        raise EvalError("E0104", f"`{d.name}` takes {len(params)} arguments, got "
                        f"{len(node.args)}", node.span, hint=sig)
    vals = {p: ip.eval(a) for p, a in zip(params, node.args)}
    for kw in node.kwargs:
        if kw.name not in params:
            sugg = did_you_mean(kw.name, params)
            raise EvalError("E0105", f"`{d.name}` has no parameter `{kw.name}`", kw.span,
                            hint=(f"did you mean `{sugg[0]}`? " if sugg else "") + sig,
                            suggestions=sugg)
        if kw.name in vals:
            raise EvalError("E0105", f"`{d.name}`: `{kw.name}` is given twice", kw.span,
                            hint=f"give `{kw.name}` once")
        vals[kw.name] = ip.eval(kw.value)
    if len(ip.frames) >= MAX_CALL_DEPTH:
        raise EvalError("E0302", f"function calls nested more than {MAX_CALL_DEPTH} deep",
                        node.span, hint=f"`{d.name}` probably calls itself without end")
    ip.step(node.span)
    scope = Scope(f.scope, ip.struct, f.scope.file)
    saved = ip.scope
    ip.frames.append((f"the function `{d.name}(...)`", node.span))
    try:
        ip.scope = scope
        for p in d.params:
            if p.name in vals:
                scope.vars[p.name] = vals[p.name]
            elif p.default is not None:
                scope.vars[p.name] = ip.eval(p.default)
            else:
                raise EvalError("E0106", f"`{d.name}` needs the argument `{p.name}`",
                                node.span, hint=sig)
        try:
            return ip.eval(d.value)
        except EvalError as err:
            # run gg: "a length can only be raised to a whole power" at the `def`'s line, and
            # not which of its calls passed the length: the call is a label, with what it gave
            if err.span is not None and d.span is not None and err.span.file == d.span.file \
                    and d.span.start <= err.span.start <= d.span.end \
                    and not any(lb.span == node.span for lb in err.labels):
                gave = ", ".join(f"{p.name} = {_shown(scope.vars[p.name])}"
                                 for p in d.params if p.name in scope.vars)[:160]
                err.labels = list(err.labels) + [Label(
                    node.span, f"`{d.name}` called here" + (f" with {gave}" if gave else ""),
                    primary=False)]
            raise
    finally:
        ip.scope = saved
        ip.frames.pop()


def _shown(v) -> str:
    """A value as a call's label says it: a length in mm, an angle in degrees (what tells a
    length passed from a plain number)."""
    from ..geometry.core.values import ANG, LEN, Q
    if isinstance(v, Q) and v.const() is not None and v.dim in (LEN, ANG):
        return f"{show(v)} {'mm' if v.dim == LEN else 'deg'}"
    return show(v)
