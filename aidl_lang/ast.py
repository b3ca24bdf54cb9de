"""Typed AST of an AIDL file. Every node carries the :class:`Span` of its source text.

Built by :mod:`aidl_lang.parser` from the Lark tree of ``grammar/aidl.lark``.

The nodes are plain slotted classes, not dataclasses: ``dataclass`` writes and compiles an
``__init__`` and a ``__repr__`` per class at import time, 45 M instructions for these 35
classes, 5% of a cold ``aidl check`` (docs/dev/performance.md, "The cold check"). Nodes are
compared by identity, as they were with ``eq=False``.
"""
from __future__ import annotations

import functools

from .base.diagnostics import Span

STRUCTURE_KINDS = ("solid", "hole", "cut", "drawing", "assembly")


class Node:
    """Base of every node: ``span`` is the node's source text (file, line, column, end)."""
    __slots__ = ("span",)

    def __init__(self, span: Span):
        self.span = span

    def __repr__(self) -> str:
        """``Num(span=Span(...), value=40.0, unit='mm')``: the fields in order, as a dataclass's."""
        names = ("span",) + _fields(type(self))
        return f"{type(self).__name__}({', '.join(f'{n}={getattr(self, n)!r}' for n in names)})"


# ---------------------------------------------------------------- expressions
class Num(Node):
    """A number with its unit as written: ``40 mm`` (value 40.0, unit ``"mm"``), ``3`` (unit None)."""
    __slots__ = ("value", "unit")

    def __init__(self, span: Span, value: float, unit: str | None):
        self.span = span
        self.value = value
        self.unit = unit  # as written: "mm", "deg", ... or None for a bare number


class Str(Node):
    """A string literal ``"..."`` (escapes resolved)."""
    __slots__ = ("value",)

    def __init__(self, span: Span, value: str):
        self.span = span
        self.value = value


class FStr(Node):
    """An f-string ``f"w={w}"``: literal ``str`` parts and expression nodes, in order."""
    __slots__ = ("parts",)

    def __init__(self, span: Span, parts: list):
        self.span = span
        self.parts = parts  # str | Node


class Name(Node):
    """A name in an expression: ``w``, ``Circle``."""
    __slots__ = ("id",)

    def __init__(self, span: Span, id: str):
        self.span = span
        self.id = id


class Keyword(Node):
    """A keyword argument ``name=value`` of a call."""
    __slots__ = ("name", "value")

    def __init__(self, span: Span, name: str, value: Node):
        self.span = span
        self.name = name
        self.value = value


class Call(Node):
    """A call ``func(args..., name=value...)``."""
    __slots__ = ("func", "args", "kwargs")

    def __init__(self, span: Span, func: Node, args: list[Node], kwargs: list[Keyword]):
        self.span = span
        self.func = func
        self.args = args
        self.kwargs = kwargs


class Member(Node):
    """A member access ``obj.name`` (``name_span`` is the name's own span)."""
    __slots__ = ("obj", "name", "name_span")

    def __init__(self, span: Span, obj: Node, name: str, name_span: Span):
        self.span = span
        self.obj = obj
        self.name = name
        self.name_span = name_span


class Index(Node):
    """A subscript ``obj[index]``."""
    __slots__ = ("obj", "index")

    def __init__(self, span: Span, obj: Node, index: Node):
        self.span = span
        self.obj = obj
        self.index = index


class BinOp(Node):
    """An arithmetic operation ``left op right``."""
    __slots__ = ("op", "left", "right")

    def __init__(self, span: Span, op: str, left: Node, right: Node):
        self.span = span
        self.op = op  # + - * / // % **
        self.left = left
        self.right = right


class Compare(Node):
    """A comparison chain ``a < b <= c``: ``len(ops) == len(operands) - 1``."""
    __slots__ = ("ops", "operands")

    def __init__(self, span: Span, ops: list[str], operands: list[Node]):
        self.span = span
        self.ops = ops  # == != <= >= < >
        self.operands = operands


class BoolOp(Node):
    """``left and right`` / ``left or right``."""
    __slots__ = ("op", "left", "right")

    def __init__(self, span: Span, op: str, left: Node, right: Node):
        self.span = span
        self.op = op  # and | or
        self.left = left
        self.right = right


class Not(Node):
    """``not operand``."""
    __slots__ = ("operand",)

    def __init__(self, span: Span, operand: Node):
        self.span = span
        self.operand = operand


class Neg(Node):
    """``-operand``."""
    __slots__ = ("operand",)

    def __init__(self, span: Span, operand: Node):
        self.span = span
        self.operand = operand


class Ternary(Node):
    """``then if cond else orelse``."""
    __slots__ = ("cond", "then", "orelse")

    def __init__(self, span: Span, cond: Node, then: Node, orelse: Node):
        self.span = span
        self.cond = cond
        self.then = then
        self.orelse = orelse


class TupleLit(Node):
    """A tuple ``(a, b)``."""
    __slots__ = ("items",)

    def __init__(self, span: Span, items: list[Node]):
        self.span = span
        self.items = items


class ListLit(Node):
    """A list ``[a, b]``."""
    __slots__ = ("items",)

    def __init__(self, span: Span, items: list[Node]):
        self.span = span
        self.items = items


class ListComp(Node):
    """A list comprehension ``[elt for var in iter if cond]``.  ``flat``: ``elt`` is the
    comprehension of a further ``for`` whose items are joined into this one's, as Python's
    ``[f(a, b) for a in xs for b in ys]`` (the parser makes one ListComp per ``for``, the
    outer ones flat)."""
    __slots__ = ("elt", "var", "var_span", "iter", "cond", "flat")

    def __init__(self, span: Span, elt: Node, var: str, var_span: Span, iter: Node,
                 cond: Node | None, flat: bool = False):
        self.span = span
        self.elt = elt
        self.var = var
        self.var_span = var_span
        self.iter = iter
        self.cond = cond
        self.flat = flat


# ---------------------------------------------------------------- statements
class Block(Node):
    """An indented block of statements."""
    __slots__ = ("stmts",)

    def __init__(self, span: Span, stmts: list[Node]):
        self.span = span
        self.stmts = stmts


class UnitsDecl(Node):
    """``units mm``: the file's default length unit."""
    __slots__ = ("unit", "unit_span")

    def __init__(self, span: Span, unit: str, unit_span: Span):
        self.span = span
        self.unit = unit
        self.unit_span = unit_span


class ThicknessDecl(Node):
    """``thickness 3 mm``: the extrusion thickness of the file's parts (at the top level) or of
    one structure and its children (inside it); see docs/outputs.md."""
    __slots__ = ("value",)

    def __init__(self, span: Span, value: Node):
        self.span = span
        self.value = value


class KerfDecl(ThicknessDecl):
    """``kerf 0.15 mm``: the width the laser burns away, for the file's parts (top level) or
    one structure and its children; cuts are offset by half of it (docs/outputs.md, "Kerf").
    Handled wherever a :class:`ThicknessDecl` is."""
    __slots__ = ()


class MinWallDecl(ThicknessDecl):
    """``min_wall 0.3 mm``: the thinnest wall (and narrowest slit) the final-part checks accept
    (W0507, W0519, W0520) for the file's parts (top level) or one structure and its children;
    ``min_wall 0`` turns those checks off (a part not cut by a laser or router).  The command
    line's ``--min-wall`` overrides it.  Handled wherever a :class:`ThicknessDecl` is."""
    __slots__ = ()


class Import(Node):
    """``import "path.aidl" as alias``."""
    __slots__ = ("path", "path_span", "alias")

    def __init__(self, span: Span, path: str, path_span: Span, alias: str | None):
        self.span = span
        self.path = path
        self.path_span = path_span
        self.alias = alias


class ParamDecl(Node):
    """``param name = value`` (with its optional ``min=``/``max=``/``step=`` options)."""
    __slots__ = ("name", "name_span", "value", "options")

    def __init__(self, span: Span, name: str, name_span: Span, value: Node,
                 options: list["ParamOption"] | None = None):
        self.span = span
        self.name = name
        self.name_span = name_span
        self.value = value
        # the optional range ``param w = 40 mm, min=10 mm, max=80 mm, step=1 mm``, in order
        self.options = [] if options is None else options


class ParamOption(Node):
    """One ``min=``/``max=``/``step=`` option of a ``param``."""
    __slots__ = ("name", "name_span", "value")

    def __init__(self, span: Span, name: str, name_span: Span, value: Node):
        self.span = span
        self.name = name  # min | max | step (checked by the interpreter)
        self.name_span = name_span
        self.value = value


class TemplateParam(Node):
    """One parameter of a ``def`` template, with its default expression if any."""
    __slots__ = ("name", "default")

    def __init__(self, span: Span, name: str, default: Node | None):
        self.span = span
        self.name = name
        self.default = default


class Func(Node):
    """``def name(params) = expr``: a function, whose call is ``expr``'s value with the
    parameters bound (numbers, points, lists; no geometry of its own)."""
    __slots__ = ("name", "name_span", "params", "value", "within")

    def __init__(self, span: Span, name: str, name_span: Span, params: list["TemplateParam"],
                 value: Node, within: str | None = None):
        self.span = span
        self.name = name
        self.name_span = name_span
        self.params = params
        self.value = value
        self.within = within    # written inside this top-level structure (hoisted above it)


class Def(Node):
    """``def KIND name(params):`` a structure template of kind ``kind``."""
    __slots__ = ("name", "name_span", "kind", "kind_span", "params", "body", "within")

    def __init__(self, span: Span, name: str, name_span: Span, kind: str, kind_span: Span,
                 params: list[TemplateParam], body: Block, within: str | None = None):
        self.span = span
        self.name = name
        self.name_span = name_span
        self.kind = kind
        self.kind_span = kind_span
        self.params = params
        self.body = body
        self.within = within    # written inside this top-level structure (hoisted above it)


class StructDecl(Node):
    """``KIND name:`` a structure (solid, hole, cut, drawing, assembly) and its body."""
    __slots__ = ("kind", "kind_span", "name", "name_span", "body")

    def __init__(self, span: Span, kind: str, kind_span: Span, name: str, name_span: Span,
                 body: Block):
        self.span = span
        self.kind = kind
        self.kind_span = kind_span
        self.name = name
        self.name_span = name_span
        self.body = body


class Assign(Node):
    """``name = value``."""
    __slots__ = ("name", "name_span", "value")

    def __init__(self, span: Span, name: str, name_span: Span, value: Node):
        self.span = span
        self.name = name
        self.name_span = name_span
        self.value = value


class KindAssign(Assign):
    """``KIND NAME = template(...)``: a template instance of structure kind ``kind``."""
    __slots__ = ("kind", "kind_span")

    def __init__(self, span: Span, name: str, name_span: Span, value: Node, kind: str,
                 kind_span: Span):
        super().__init__(span, name, name_span, value)
        self.kind = kind
        self.kind_span = kind_span


class For(Node):
    """``for var in iter:`` body."""
    __slots__ = ("var", "var_span", "iter", "body")

    def __init__(self, span: Span, var: str, var_span: Span, iter: Node, body: Block):
        self.span = span
        self.var = var
        self.var_span = var_span
        self.iter = iter
        self.body = body


class If(Node):
    """``if cond:`` body, with the ``else`` (or ``elif``, nested) block if any."""
    __slots__ = ("cond", "body", "orelse")

    def __init__(self, span: Span, cond: Node, body: Block, orelse: Block | None):
        self.span = span
        self.cond = cond
        self.body = body
        self.orelse = orelse


class ExprStmt(Node):
    """An expression used as a statement (a constraint call, a primitive)."""
    __slots__ = ("expr",)

    def __init__(self, span: Span, expr: Node):
        self.span = span
        self.expr = expr


class Assert(Node):
    """``assert cond, "message"``: ``cond`` (comparisons joined by ``and``) must hold at the
    solved values; checked after solving, never a constraint (docs/language.md)."""
    __slots__ = ("expr", "message")

    def __init__(self, span: Span, expr: Node, message: str | None = None):
        self.span = span
        self.expr = expr
        self.message = message


class Program(Node):
    """A parsed file: its path, source text and top-level statements."""
    __slots__ = ("path", "source", "stmts")

    def __init__(self, span: Span, path: str, source: str, stmts: list[Node] | None = None):
        self.span = span
        self.path = path
        self.source = source
        self.stmts = [] if stmts is None else stmts


@functools.cache
def _fields(cls: type) -> tuple[str, ...]:
    """The fields of node class ``cls`` in order, its bases' first (``KindAssign``: ``name``,
    ``name_span``, ``value`` of ``Assign``, then ``kind``, ``kind_span``), without ``span``."""
    return tuple(n for c in reversed(cls.__mro__[:-1]) for n in c.__slots__ if n != "span")


def walk(node):
    """Yield ``node`` and all nodes below it (pre-order), through every field, inherited ones
    included (a ``KindAssign``'s template call is its ``Assign`` part)."""
    stack = [node]
    while stack:
        n = stack.pop()
        if not isinstance(n, Node):
            continue
        yield n
        for name in _fields(type(n)):
            v = getattr(n, name, None)
            if isinstance(v, Node):
                stack.append(v)
            elif isinstance(v, list):
                for x in reversed(v):
                    if isinstance(x, Node):
                        stack.append(x)
                    elif isinstance(x, tuple):      # an f-string's (expression, format)
                        stack.extend(y for y in reversed(x) if isinstance(y, Node))
