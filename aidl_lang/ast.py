"""Typed AST of an AIDL file. Every node carries the :class:`Span` of its source text.

Built by :mod:`aidl_lang.parser` from the Lark tree of ``grammar/aidl.lark``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .diagnostics import Span

STRUCTURE_KINDS = ("solid", "hole", "drawing", "assembly")


@dataclass(eq=False, slots=True)
class Node:
    span: Span


# ---------------------------------------------------------------- expressions
@dataclass(eq=False, slots=True)
class Num(Node):
    value: float
    unit: str | None          # as written: "mm", "deg", ... or None for a bare number


@dataclass(eq=False, slots=True)
class Str(Node):
    value: str


@dataclass(eq=False, slots=True)
class FStr(Node):
    parts: list               # str | Node


@dataclass(eq=False, slots=True)
class Name(Node):
    id: str


@dataclass(eq=False, slots=True)
class Keyword(Node):
    name: str
    value: Node


@dataclass(eq=False, slots=True)
class Call(Node):
    func: Node
    args: list[Node]
    kwargs: list[Keyword]


@dataclass(eq=False, slots=True)
class Member(Node):
    obj: Node
    name: str
    name_span: Span


@dataclass(eq=False, slots=True)
class Index(Node):
    obj: Node
    index: Node


@dataclass(eq=False, slots=True)
class BinOp(Node):
    op: str                   # + - * / // % **
    left: Node
    right: Node


@dataclass(eq=False, slots=True)
class Compare(Node):
    ops: list[str]            # == != <= >= < >
    operands: list[Node]


@dataclass(eq=False, slots=True)
class BoolOp(Node):
    op: str                   # and | or
    left: Node
    right: Node


@dataclass(eq=False, slots=True)
class Not(Node):
    operand: Node


@dataclass(eq=False, slots=True)
class Neg(Node):
    operand: Node


@dataclass(eq=False, slots=True)
class Ternary(Node):
    cond: Node
    then: Node
    orelse: Node


@dataclass(eq=False, slots=True)
class TupleLit(Node):
    items: list[Node]


@dataclass(eq=False, slots=True)
class ListLit(Node):
    items: list[Node]


@dataclass(eq=False, slots=True)
class ListComp(Node):
    elt: Node
    var: str
    var_span: Span
    iter: Node
    cond: Node | None


# ---------------------------------------------------------------- statements
@dataclass(eq=False, slots=True)
class Block(Node):
    stmts: list[Node]


@dataclass(eq=False, slots=True)
class UnitsDecl(Node):
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
    path: str
    path_span: Span
    alias: str | None


@dataclass(eq=False, slots=True)
class ParamDecl(Node):
    name: str
    name_span: Span
    value: Node
    # the optional range ``param w = 40 mm, min=10 mm, max=80 mm, step=1 mm``, in order
    options: list["ParamOption"] = field(default_factory=list)


@dataclass(eq=False, slots=True)
class ParamOption(Node):
    name: str                      # min | max | step (checked by the interpreter)
    name_span: Span
    value: Node


@dataclass(eq=False, slots=True)
class TemplateParam(Node):
    name: str
    default: Node | None


@dataclass(eq=False, slots=True)
class Def(Node):
    name: str
    name_span: Span
    kind: str
    kind_span: Span
    params: list[TemplateParam]
    body: Block


@dataclass(eq=False, slots=True)
class StructDecl(Node):
    kind: str
    kind_span: Span
    name: str
    name_span: Span
    body: Block


@dataclass(eq=False, slots=True)
class Assign(Node):
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
    var: str
    var_span: Span
    iter: Node
    body: Block


@dataclass(eq=False, slots=True)
class If(Node):
    cond: Node
    body: Block
    orelse: Block | None


@dataclass(eq=False, slots=True)
class ExprStmt(Node):
    expr: Node


@dataclass(eq=False, slots=True)
class Assert(Node):
    """``assert cond, "message"``: ``cond`` (comparisons joined by ``and``) must hold at the
    solved values; checked after solving, never a constraint (docs/language.md)."""
    expr: Node
    message: str | None = None


@dataclass(eq=False, slots=True)
class Program(Node):
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
