"""E0124 for a param whose ``min`` comes out larger than its ``max`` (docs/codes.md, E0124).

Bounds written as numbers (``min = 80 mm, max = 20 mm``) are a slip: the hint says to swap
them, and only when the swapped range holds the param's value (the design then compiles as
written).  Bounds written as expressions of numbers alone (``min = max(10 mm, 25 mm)``) get
no swap either: the hint asks for the bound that is wrong to be changed.  Bounds that follow other params (``min = max(a, 10 mm), max = min(c, 70 mm)``)
are no slip: swapping them would change what the author meant (``b`` at least ``a`` and at
most ``c``), so nothing is proposed; the message says what each bound reads and came to, and
the hint says in words which values of which param empty the range, found along each such
param's own declared range with the others at their values (:func:`emptying`).
"""
from __future__ import annotations

from .. import ast as A
from ..base.diagnostics import EvalError

# values of a param tried along its declared range, then each change of side bisected
SAMPLES = 48
BISECTIONS = 40


def empty_range(interp, st, opt: dict, lo: float, hi: float, val, fmt) -> EvalError:
    """The E0124 of ``param`` ``st`` whose bounds ``opt`` (its options by name) came to
    ``lo > hi`` (internal units) for the value ``val``; ``fmt(x, dim)`` writes a value."""
    dim = val.dim
    reads = _reads(interp, opt)
    said = ", ".join(f"{k} = {fmt(x, dim)}" + (f" (`{w}`)" if w and w != fmt(x, dim) else "")
                     for k, x, w in (("min", lo, _text(interp, opt["min"])),
                                     ("max", hi, _text(interp, opt["max"]))))
    if not reads and not all(_literal(opt[k].value) for k in ("min", "max")):
        # bounds written as expressions of numbers (`min = max(10 mm, 25 mm)`): swapping the
        # expressions would change what they compute (issue 105), so none is proposed
        return EvalError("E0124", f"param `{st.name}`: min is larger than max ({said})",
                         opt["min"].span,
                         hint="change the bound that is wrong so that min comes out at most "
                              "max (swapping the expressions would change what they mean)")
    if not reads:
        v = val.const()
        hint = ("swap them" if hi - 1e-9 <= v <= lo + 1e-9 else
                f"write min below max, both around the value {fmt(v, dim)} (swapped, "
                f"{fmt(hi, dim)} .. {fmt(lo, dim)} would not hold it)")
        return EvalError("E0124", f"param `{st.name}`: min is larger than max ({said})",
                         opt["min"].span, hint=hint)
    at = ", ".join(f"`{n}` = {fmt(q.const(), q.dim)}" for n, q in reads.items())
    words = [w for w in (emptying(interp, n, reads, opt, fmt) for n in reads) if w]
    hint = (f"the range follows {', '.join(f'`{n}`' for n in reads)}: "
            + ("; ".join(words) if words else f"at {at} it is empty")
            + " (swapping min and max would change what they mean); "
            + ("move that param back, or declare its range" if len(reads) == 1 else
               "move those params back, or declare their ranges")
            + " so this range cannot empty")
    return EvalError("E0124", f"param `{st.name}`: its range is empty at {at}: {said}",
                     opt["min"].span, hint=hint)


def _literal(node) -> bool:
    """A bound written as a number (``20 mm``, ``-5``), the only kind "swap them" fits."""
    if isinstance(node, A.Neg):
        node = node.operand
    return isinstance(node, A.Num)


def _text(interp, o) -> str:
    """The bound as written (``max(a, 10 mm)``)."""
    from .common import _src
    return _src(interp.sink, o.value.span)


def _reads(interp, opt: dict) -> dict:
    """``{name: value}`` of the params of this file the bounds read (in order)."""
    params = getattr(interp.file, "params", None) or {}
    out = {}
    for key in ("min", "max"):
        for n in A.walk(opt[key].value):
            if isinstance(n, A.Name) and params.get(n.id) is not None and n.id not in out:
                out[n.id] = params[n.id]
    return out


def _gap(interp, name: str, q, opt: dict) -> float | None:
    """min - max with ``name`` at ``q`` (None: a bound is not a number there)."""
    vars_ = interp.file.scope.vars
    old = vars_.get(name)
    vars_[name] = q
    try:
        a, b = interp.eval(opt["min"].value), interp.eval(opt["max"].value)
        a, b = a.const(), b.const()
        return None if a is None or b is None else a - b
    except Exception:  # noqa: BLE001 - a value where a bound fails: not judged
        return None
    finally:
        vars_[name] = old


def emptying(interp, name: str, reads: dict, opt: dict, fmt) -> str:
    """``a above 60 mm`` (or below, or between two values): where along ``name``'s declared
    range (the others at their values) min comes out larger than max; "" when ``name`` has
    no declared range or no value in it empties the range."""
    from ..geometry.core.values import Q
    rng = (getattr(interp.file, "param_ranges", None) or {}).get(name) or {}
    q0 = reads[name]
    a, b = rng.get("min"), rng.get("max")
    if a is None or b is None or b <= a:
        return ""
    xs = [a + (b - a) * k / (SAMPLES - 1) for k in range(SAMPLES)]

    def bad(x):
        g = _gap(interp, name, Q.num(x, q0.dim), opt)
        return g is not None and g > 1e-9
    flags = [bad(x) for x in xs]
    if not any(flags):
        return ""
    edges = []
    for i in range(1, SAMPLES):
        if flags[i] != flags[i - 1]:
            lo_, hi_ = xs[i - 1], xs[i]
            for _ in range(BISECTIONS):
                m = (lo_ + hi_) / 2
                if bad(m) == flags[i - 1]:
                    lo_ = m
                else:
                    hi_ = m
            # on a grid of a millionth of the range: 0 mm, not 9.98509e-10 mm
            g = (b - a) * 1e-6
            edges.append((round(lo_ / g) * g, round(hi_ / g) * g, flags[i]))
    others = ", ".join(f"`{n}` = {fmt(q.const(), q.dim)}" for n, q in reads.items() if n != name)
    with_ = f" with {others}" if others else ""

    if not edges:
        return f"`{name}` empties it anywhere in its range{with_}"
    if len(edges) == 1:
        lo_, hi_, turns_bad = edges[0]
        if turns_bad:
            return f"`{name}` above {fmt(lo_, q0.dim)} empties it{with_}"
        return f"`{name}` below {fmt(hi_, q0.dim)} empties it{with_}"
    parts = []
    start = a if flags[0] else None
    for lo_, hi_, turns_bad in edges:
        if turns_bad:
            start = hi_
        else:
            parts.append((start, lo_))
            start = None
    if start is not None:
        parts.append((start, b))
    return f"`{name}` " + " or ".join(
        f"from {fmt(x, q0.dim)} to {fmt(y, q0.dim)}" for x, y in parts) + f" empties it{with_}"
