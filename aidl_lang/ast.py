"""Typed AST of an AIDL file. Every node carries the :class:`Span` of its source text.

Built by :mod:`aidl_lang.parser` from the Lark tree of ``grammar/aidl.lark``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .diagnostics import Span

STRUCTURE_KINDS = ("solid", "hole", "drawing", "assembly")


@dataclass(eq=False, slots=True)
class Node:
    """Base of every node: ``span`` is the node's source text (file, line, column, end)."""
    span: Span


# ---------------------------------------------------------------- expressions
@dataclass(eq=False, slots=True)
class Num(Node):
    """A number with its unit as written: ``40 mm`` (value 40.0, unit ``"mm"``), ``3`` (unit None)."""
    value: float
    unit: str | None          # as written: "mm", "deg", ... or None for a bare number


@dataclass(eq=False, slots=True)
class Str(Node):
    """A string literal ``"..."`` (escapes resolved)."""
    value: str


@dataclass(eq=False, slots=True)
class FStr(Node):
    """An f-string ``f"w={w}"``: literal ``str`` parts and expression nodes, in order."""
    parts: list               # str | Node


@dataclass(eq=False, slots=True)
class Name(Node):
    """A name in an expression: ``w``, ``Circle``."""
    id: str


@dataclass(eq=False, slots=True)
class Keyword(Node):
    """A keyword argument ``name=value`` of a call."""
    name: str
    value: Node


@dataclass(eq=False, slots=True)
class Call(Node):
    """A call ``func(args..., name=value...)``."""
    func: Node
    args: list[Node]
    kwargs: list[Keyword]


@dataclass(eq=False, slots=True)
class Member(Node):
    """A member access ``obj.name`` (``name_span`` is the name's own span)."""
    obj: Node
    name: str
    name_span: Span


@dataclass(eq=False, slots=True)
class Index(Node):
    """A subscript ``obj[index]``."""
    obj: Node
    index: Node


@dataclass(eq=False, slots=True)
class BinOp(Node):
    """An arithmetic operation ``left op right``."""
    op: str                   # + - * / // % **
    left: Node
    right: Node


@dataclass(eq=False, slots=True)
class Compare(Node):
    """A comparison chain ``a < b <= c``: ``len(ops) == len(operands) - 1``."""
    ops: list[str]            # == != <= >= < >
    operands: list[Node]


@dataclass(eq=False, slots=True)
class BoolOp(Node):
    """``left and right`` / ``left or right``."""
    op: str                   # and | or
    left: Node
    right: Node


@dataclass(eq=False, slots=True)
class Not(Node):
    """``not operand``."""
    operand: Node


@dataclass(eq=False, slots=True)
class Neg(Node):
    """``-operand``."""
    operand: Node


@dataclass(eq=False, slots=True)
class Ternary(Node):
    """``then if cond else orelse``."""
    cond: Node
    then: Node
    orelse: Node


@dataclass(eq=False, slots=True)
class TupleLit(Node):
    """A tuple ``(a, b)``."""
    items: list[Node]


@dataclass(eq=False, slots=True)
class ListLit(Node):
    """A list ``[a, b]``."""
    items: list[Node]


@dataclass(eq=False, slots=True)
class ListComp(Node):
    """A list comprehension ``[elt for var in iter if cond]``."""
    elt: Node
    var: str
    var_span: Span
    iter: Node
    cond: Node | None


# ---------------------------------------------------------------- statements
@dataclass(eq=False, slots=True)
class Block(Node):
    """An indented block of statements."""
    stmts: list[Node]


@dataclass(eq=False, slots=True)
class UnitsDecl(Node):
    """``units mm``: the file's default length unit."""
    unit: str
    unit_span: Span


@dataclass(eq=False, slots=True)
class ThicknessDecl(Node):
    """``thickness 3 mm``: the extrusion thickness of the file's parts (at the top level) or of
    one structure and its children (inside it); see docs/outputs.md."""
    value: Node


@dataclass(eq=False, slots=True)
class KerfDecl(ThicknessDecl):
    """``kerf 0.15 mm``: the width the laser burns away, for the file's parts (top level) or
    one structure and its children; cuts are offset by half of it (docs/outputs.md, "Kerf").
    Handled wherever a :class:`ThicknessDecl` is."""


@dataclass(eq=False, slots=True)
class Import(Node):
    """``import "path.aidl" as alias``."""
    path: str
    path_span: Span
    alias: str | None


@dataclass(eq=False, slots=True)
class ParamDecl(Node):
    """``param name = value`` (with its optional ``min=``/``max=``/``step=`` options)."""
    name: str
    name_span: Span
    value: Node
    # the optional range ``param w = 40 mm, min=10 mm, max=80 mm, step=1 mm``, in order
    options: list["ParamOption"] = field(default_factory=list)


@dataclass(eq=False, slots=True)
class ParamOption(Node):
    """One ``min=``/``max=``/``step=`` option of a ``param``."""
    name: str                      # min | max | step (checked by the interpreter)
    name_span: Span
    value: Node


@dataclass(eq=False, slots=True)
class TemplateParam(Node):
    """One parameter of a ``def`` template, with its default expression if any."""
    name: str
    default: Node | None


@dataclass(eq=False, slots=True)
class Def(Node):
    """``def KIND name(params):`` a structure template of kind ``kind``."""
    name: str
    name_span: Span
    kind: str
    kind_span: Span
    params: list[TemplateParam]
    body: Block


@dataclass(eq=False, slots=True)
class StructDecl(Node):
    """``KIND name:`` a structure (solid, hole, drawing, assembly) and its body."""
    kind: str
    kind_span: Span
    name: str
    name_span: Span
    body: Block


@dataclass(eq=False, slots=True)
class Assign(Node):
    """``name = value``."""
    name: str
    name_span: Span
    value: Node


@dataclass(eq=False, slots=True)
class KindAssign(Assign):
    """``KIND NAME = template(...)``: a template instance of structure kind ``kind``."""
    kind: str
    kind_span: Span


@dataclass(eq=False, slots=True)
class For(Node):
    """``for var in iter:`` body."""
    var: str
    var_span: Span
    iter: Node
    body: Block


@dataclass(eq=False, slots=True)
class If(Node):
    """``if cond:`` body, with the ``else`` (or ``elif``, nested) block if any."""
    cond: Node
    body: Block
    orelse: Block | None


@dataclass(eq=False, slots=True)
class ExprStmt(Node):
    """An expression used as a statement (a constraint call, a primitive)."""
    expr: Node


@dataclass(eq=False, slots=True)
class Assert(Node):
    """``assert cond, "message"``: ``cond`` (comparisons joined by ``and``) must hold at the
    solved values; checked after solving, never a constraint (docs/language.md)."""
    expr: Node
    message: str | None = None


@dataclass(eq=False, slots=True)
class Program(Node):
    """A parsed file: its path, source text and top-level statements."""
    path: str
    source: str
    stmts: list[Node] = field(default_factory=list)


def walk(node):
    """Yield ``node`` and all nodes below it (pre-order)."""
    stack = [node]
    while stack:
        n = stack.pop()
        if not isinstance(n, Node):
            continue
        yield n
        for name in n.__slots__ if hasattr(n, "__slots__") else ():
            if name == "span":
                continue
            v = getattr(n, name, None)
            if isinstance(v, Node):
                stack.append(v)
            elif isinstance(v, list):
                stack.extend(x for x in reversed(v) if isinstance(x, Node))
