"""The syntax the studio's relations read in a program ``aidl import --infer`` wrote
(:mod:`.drawn`, :mod:`.plates`): its rangeless ``param``\\ s, a call's keyword
arguments, the ``Circle`` calls beneath a node, a node's source text.  Not part of the
stable API."""
from __future__ import annotations

from ... import ast as A

WALL = 1.0          # mm of material kept between a hole and an edge or another hole


def _params(prog) -> dict:
    """The top-level ``param``\\ s with a plain literal value and no range, by name."""
    return {s.name: s for s in prog.stmts if isinstance(s, A.ParamDecl) and not s.options
            and isinstance(s.value, A.Num) and s.value.unit in (None, "mm")}


def _kw(call, name):
    return next((k.value for k in call.kwargs if k.name == name), None)


def _circles(node):
    """Every ``Circle(...)`` call beneath ``node``."""
    return [n for n in A.walk(node) if isinstance(n, A.Call) and isinstance(n.func, A.Name)
            and n.func.id == "Circle"]


def _name(node, params) -> str | None:
    return node.id if isinstance(node, A.Name) and node.id in params else None


def _text(source: str, node) -> str:
    return source[node.span.start:node.span.end]


def _fmt(x: float) -> str:
    return f"{x:.6g}"
