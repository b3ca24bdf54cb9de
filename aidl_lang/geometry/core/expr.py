"""Residual expressions over the model's parameter vector, with analytic gradients.

An expression is either affine, :class:`Lin` (``sum(coef_i * x_i) + c``: most CAD constraints,
kept as sparse rows), or a nonlinear :class:`Nl` tree.  Values are in mm and radians.
:func:`evaluate` computes one value in Python (the interpreter's starting values, branch
choices); the solver compiles expressions into a vectorised tape with a reverse-mode Jacobian
(:mod:`aidl_lang.solver.core.tape`), where ``min``/``max`` become frozen branch selections (paper,
appendix "Solver Details", *Iterated Newton solve for branching expressions*).
"""
from __future__ import annotations

import math
from typing import Union

Number = Union[int, float]


class Expr:
    __slots__ = ()

    # arithmetic -------------------------------------------------------------
    def __add__(self, o):
        return add(self, o)

    def __radd__(self, o):
        return add(o, self)

    def __sub__(self, o):
        return sub(self, o)

    def __rsub__(self, o):
        return add(o, mul(-1.0, self))

    def __mul__(self, o):
        return mul(self, o)

    def __rmul__(self, o):
        return mul(o, self)

    def __truediv__(self, o):
        return div(self, o)

    def __rtruediv__(self, o):
        return div(o, self)

    def __neg__(self):
        return mul(-1.0, self)


class Lin(Expr):
    """Affine expression ``sum(terms[i] * x[i]) + const``."""

    __slots__ = ("terms", "const")

    def __init__(self, terms: dict[int, float] | None = None, const: float = 0.0):
        self.terms = terms or {}
        self.const = float(const)

    def is_const(self) -> bool:
        return not self.terms

    def __repr__(self):
        return f"Lin({self.terms}, {self.const})"


class Nl(Expr):
    """Nonlinear node: ``op`` in mul, div, pow, sin, cos, tan, asin, acos, atan, atan2, sqrt,
    abs, min, max, exp, log."""

    __slots__ = ("op", "args")

    def __init__(self, op: str, args: tuple):
        self.op = op
        self.args = args

    def __repr__(self):
        return f"{self.op}{self.args}"


def var(i: int) -> Lin:
    return Lin({i: 1.0})


def const(c: float) -> Lin:
    return Lin({}, c)


def lift(x) -> Expr:
    if isinstance(x, Expr):
        return x
    return Lin({}, float(x))


def as_const(x) -> float | None:
    """The constant value of ``x`` if it has no unknowns, else None."""
    if type(x) is Lin:
        return None if x.terms else x.const
    if isinstance(x, (int, float)):
        return float(x)
    if isinstance(x, Lin) and not x.terms:
        return x.const
    return None


def _lin(terms: dict, c: float) -> Lin:
    """A :class:`Lin` from a fresh terms dict and a float constant, without ``__init__``
    (the interpreter builds tens of thousands)."""
    e = _new(Lin)
    e.terms = terms
    e.const = c
    return e


_new = object.__new__


def add(a, b) -> Expr:
    ta = type(a)                 # type tests first: isinstance only for non-expressions
    if ta is not Lin and ta is not Nl and not isinstance(a, Expr):
        a = _lin({}, float(a))
        ta = Lin
    tb = type(b)
    if tb is not Lin and tb is not Nl and not isinstance(b, Expr):
        b = _lin({}, float(b))
        tb = Lin
    if ta is Lin and tb is Lin:
        bt = b.terms
        if not bt:
            return _lin(dict(a.terms), a.const + b.const)
        t = dict(a.terms)
        get = t.get
        for k, v in bt.items():
            t[k] = get(k, 0.0) + v
        return _lin(t, a.const + b.const)
    e = _new(Nl)                 # Nl("add", (a, b)) without __init__
    e.op = "add"
    e.args = (a, b)
    return e


def combine(pairs, c: float = 0.0) -> Expr:
    """``sum(k * e for k, e in pairs) + c`` (``k`` floats, ``e`` expressions or numbers): one
    :class:`Lin` built in one pass when every ``e`` is affine (a copy's point is the affine
    image of the original's, several thousand in a patterned gear), else the sum of products."""
    terms: dict = {}
    get = terms.get
    s = c
    for k, e in pairs:
        t = type(e)
        if t is Lin:
            for i, v in e.terms.items():
                terms[i] = get(i, 0.0) + k * v
            s += k * e.const
        elif t is Nl or isinstance(e, Expr):      # a nonlinear term: the sum of products
            out = lift(c)
            for k2, e2 in pairs:
                out = add(out, mul(k2, e2))
            return out
        else:                                     # a number
            s += k * float(e)
    return _lin(terms, s)


def sub(a: Expr, b) -> Expr:
    """``a - b``: the same expression, with the same floating-point operations, as
    ``add(a, mul(-1.0, b))``, without the negated copy of ``b`` when both are affine."""
    if type(a) is Lin and type(b) is Lin:
        bt = b.terms
        t = dict(a.terms)
        if bt:
            get = t.get
            for k, v in bt.items():
                t[k] = get(k, 0.0) + v * -1.0
        e = _new(Lin)
        e.terms = t
        e.const = a.const + b.const * -1.0
        return e
    return add(a, mul(-1.0, b))


def mul(a, b) -> Expr:
    ta, tb = type(a), type(b)
    if ta is float:              # a float and an expression: the product directly
        if tb is Lin:
            t = {}
            for k, v in b.terms.items():
                t[k] = v * a
            return _lin(t, b.const * a)
        if tb is Nl or (tb is not float and isinstance(b, Expr)):
            if a == 0.0:
                return _lin({}, 0.0)
            e = _new(Nl)
            e.op = "mul"
            e.args = (_lin({}, a), b)
            return e
    elif tb is float:
        if ta is Lin:
            terms = a.terms
            if not terms:
                return _lin({}, b * a.const)
            t = {}
            for k, v in terms.items():
                t[k] = v * b
            return _lin(t, a.const * b)
        if ta is Nl or isinstance(a, Expr):
            if b == 0.0:
                return _lin({}, 0.0)
            e = _new(Nl)
            e.op = "mul"
            e.args = (a, _lin({}, b))
            return e
    if ta is not Lin and ta is not Nl and not isinstance(a, Expr):
        a = _lin({}, float(a))
        ta = Lin
    if tb is not Lin and tb is not Nl and not isinstance(b, Expr):
        b = _lin({}, float(b))
        tb = Lin
    ca = a.const if ta is Lin and not a.terms else None
    cb = b.const if tb is Lin and not b.terms else None
    if ca is not None and tb is Lin:
        t = {}
        for k, v in b.terms.items():
            t[k] = v * ca
        return _lin(t, b.const * ca)
    if cb is not None and ta is Lin:
        t = {}
        for k, v in a.terms.items():
            t[k] = v * cb
        return _lin(t, a.const * cb)
    if ca == 0.0 or cb == 0.0:
        return _lin({}, 0.0)
    e = _new(Nl)                 # Nl("mul", (a, b)) without __init__
    e.op = "mul"
    e.args = (a, b)
    return e


def div(a, b) -> Expr:
    a, b = lift(a), lift(b)
    cb = as_const(b)
    if cb is not None:
        if cb == 0.0:
            raise ZeroDivisionError("division by zero")
        return mul(a, 1.0 / cb)
    return Nl("div", (a, b))


_UNARY = {"sin": math.sin, "cos": math.cos, "tan": math.tan, "asin": math.asin,
          "acos": math.acos, "atan": math.atan, "sqrt": math.sqrt, "abs": abs,
          "exp": math.exp, "log": math.log}


def func(op: str, *args) -> Expr:
    """Apply a named function; constant arguments fold to a constant (may raise ValueError)."""
    for a in args:               # an argument with unknowns: nothing folds (no lifting needed
        t = type(a)              # when every argument already is an expression)
        if t is Nl or (t is Lin and a.terms):
            for b in args:
                t = type(b)
                if t is not Lin and t is not Nl and not isinstance(b, Expr):
                    break
            else:
                e = _new(Nl)     # Nl(op, args)
                e.op = op
                e.args = args
                return e
            break
    args = tuple(map(lift, args))
    consts = list(map(as_const, args))
    if None not in consts:
        if op in _UNARY:
            return const(_UNARY[op](consts[0]))
        if op == "atan2":
            return const(math.atan2(consts[0], consts[1]))
        if op == "min":
            return const(min(consts))
        if op == "max":
            return const(max(consts))
        if op == "pow":
            return const(consts[0] ** consts[1])
    return Nl(op, args)


def sqr(a) -> Expr:
    return mul(a, a)


def hypot(dx, dy) -> Expr:
    return func("sqrt", add(sqr(dx), sqr(dy)))


# ------------------------------------------------------------------ evaluation
def evaluate(e, x) -> float:
    if isinstance(e, (int, float)):
        return float(e)
    if isinstance(e, Lin):
        s = e.const
        for k, v in e.terms.items():
            s += v * x[k]
        return s
    if not isinstance(e, Nl):       # a box's side (bbox.BBTerm): measured at x
        return e.value(x)
    op, args = e.op, e.args
    if op == "add":
        return evaluate(args[0], x) + evaluate(args[1], x)
    if op == "mul":
        return evaluate(args[0], x) * evaluate(args[1], x)
    if op == "div":
        d = evaluate(args[1], x)
        return evaluate(args[0], x) / (d if d != 0 else 1e-300)
    if op == "pow":
        return evaluate(args[0], x) ** evaluate(args[1], x)
    if op == "min":
        return min(evaluate(a, x) for a in args)
    if op == "max":
        return max(evaluate(a, x) for a in args)
    if op == "atan2":
        return math.atan2(evaluate(args[0], x), evaluate(args[1], x))
    v = evaluate(args[0], x)
    if op in ("asin", "acos"):
        v = max(-1.0, min(1.0, v))
    if op == "sqrt":
        v = max(0.0, v)
    return _UNARY[op](v)


def rebuild(op: str, args: tuple) -> Expr:
    """The node ``op(*args)`` rebuilt after its arguments were replaced, folding constants
    again where the arithmetic helpers can (used when expanding deferred terms)."""
    if op == "add":
        return add(*args)
    if op == "mul":
        return mul(*args)
    if op == "div":
        return div(*args)
    return Nl(op, args)
