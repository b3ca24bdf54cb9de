"""Names shared by the interpreter's parts: scopes, per-file context, the poison marker for
names whose definition failed, and small helpers (see :mod:`aidl_lang.interp`)."""
from __future__ import annotations

import math
import re

from .. import ast as A
from ..base.diagnostics import DiagnosticSink, EvalError, Span
from ..geometry.core.expr import Lin
from ..geometry.core.model import Structure
from ..registry import (FUNCTIONS, lookup)

DEG = math.pi / 180.0
# E0109's hint for an angle^2 (`acos(16 / 20) * 1 rad`: issue 111's runs i and m)
ANGLE_TWICE = ("`atan2`, `asin`, `acos` and `atan` give an angle already: drop the `* 1 rad` "
               "(or `deg`) after it")
# a fraction written before a unit, `3/8 in`: the unit belongs to the 8 (E0109's hint)
FRACTION = re.compile(r"\b(\d+(?:\.\d+)?)\s*/\s*(\d+(?:\.\d+)?)\s*(in|inch|mm|cm|m|ft|deg)\b")


def fraction_hint(text: str | None) -> str | None:
    """E0109's hint for a fraction written before a unit in ``text`` (`3/8 in` is 3 / (8 in),
    a length^-1: issue 111, run ck), else None."""
    frac = FRACTION.search(re.sub(r'"[^"]*"', '""', text or ""))     # not in a message
    if frac is None:
        return None
    n, m, unit = frac.groups()
    return (f"`{frac.group(0)}` reads `{n} / ({m} {unit})`: a unit belongs to the number "
            f"before it; write `{float(n) / float(m):g} {unit}` or `{n} {unit} / {m}`")


class _Silent(Exception):
    """Raised when a statement uses a name whose definition already failed (reported once)."""


POISON = object()

# what a statement may raise and still be reported and skipped (Statements._stmt_failed)
_STMT_ERRORS = (_Silent, EvalError, ValueError, ZeroDivisionError, OverflowError, RecursionError)


class BudgetExhausted(Exception):
    """Raised when the compile's evaluation budget (:class:`aidl_lang.base.limits.Budget`) runs
    out; it unwinds the whole interpretation (no statement catches it) and
    :meth:`aidl_lang.interp.Interpreter.run` turns it into one ``E0304``."""

    def __init__(self, what: str, span, frames):
        super().__init__(what)
        self.what = what
        self.span = span
        self.frames = list(frames)


class Scope:
    """Names bound in a body, loop iteration, comprehension, template instance or file;
    ``chain`` is the ``vars`` dicts from this scope out to the file's, for lookups."""

    def __init__(self, parent: "Scope | None", struct: Structure | None, file: "FileCtx"):
        self.vars: dict = {}
        self.parent = parent
        self.struct = struct
        self.file = file
        self.chain: tuple = (self.vars,) + parent.chain if parent is not None else (self.vars,)

    def lookup(self, name: str):
        s = self
        while s is not None:
            if name in s.vars:
                return s.vars[name], s
            s = s.parent
        return None, None

    def names(self):
        out = set()
        s = self
        while s is not None:
            out |= set(s.vars)
            s = s.parent
        return out


class FileCtx:
    def __init__(self, path: str, unit_scale: float = 1.0):
        self.path = path
        self.unit_scale = unit_scale
        self.scope = Scope(None, None, self)



def file_functions(stmts) -> frozenset:
    """The names of the one-line functions (``def f(x) = ...``) among ``stmts``."""
    return frozenset(s.name for s in stmts if isinstance(s, A.Func))


def _is_plain_const(st, funcs: frozenset = frozenset()) -> bool:
    """A top-level `NAME = expr` that creates no geometry (a file constant); ``funcs``: the
    file's one-line functions (:func:`file_functions`), whose calls give values (run br's
    `X1 = sx(N - 1) + 22 mm` was taken for a template's instance, and no template saw it)."""
    if not isinstance(st, A.Assign):
        return False
    for n in A.walk(st.value):
        if isinstance(n, A.Call) and isinstance(n.func, A.Name):
            e = lookup(n.func.id)
            if e is not None and e.category in ("primitive", "operation"):
                return False
            if n.func.id not in FUNCTIONS and e is None and n.func.id not in funcs:
                return False   # a template call
    return True


def _is_geometry_stmt(st) -> bool:
    """A top-level statement that creates geometry directly (not a constraint)."""
    v = st.value if isinstance(st, A.Assign) else st.expr if isinstance(st, A.ExprStmt) else None
    if isinstance(v, A.Call) and isinstance(v.func, A.Name):
        e = lookup(v.func.id)
        return e is not None and e.category == "primitive"
    return isinstance(st, (A.For, A.If))


def _common_ancestor(a: Structure, b: Structure):
    anc = set()
    s = a
    while s is not None:
        anc.add(s)
        s = s.parent
    s = b
    while s is not None:
        if s in anc:
            return s
        s = s.parent
    return None


def _src(sink: DiagnosticSink, span: Span | None) -> str:
    """The source text at ``span``, blanks collapsed, at most 120 characters (what
    ``Constraint.text`` of a written constraint reads, cut when first asked), a cut one
    ending in "..." (run aa's sundial read `... - 51` for `- 51.5 deg`)."""
    if span is None:
        return ""
    src = sink.sources.get(span.file, "")
    text = " ".join(src[span.start:span.end].split())
    return text if len(text) <= 120 else text[:117] + "..."


def _a(word: str) -> str:
    return ("an " if word[:1] in "aeiou" else "a ") + word


def _fmt_num(c: float) -> str:
    if abs(c - round(c)) < 1e-9:
        return str(int(round(c)))
    return f"{c:.6g}"


def show(v, unit_scale: float = 1.0, depth: int = 0) -> str:
    """The text ``str(v)`` and an f-string give for a value: numbers in the file's unit,
    points as ``(x, y)``, geometry and structures by kind and path; never an internal repr
    or a file path."""
    from ..geometry.core.expr import as_const
    from ..geometry.core.values import (ANG, LEN, PV, BBoxRef, Builtin, GeomRef, Namespace, Q,
                                   StructRef, Template, type_name)
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return v
    if isinstance(v, Q):
        c = v.const()
        if c is None:
            return f"{_a(type_name(v))} known after solving"
        if v.dim == LEN:
            c /= unit_scale
        elif v.dim == ANG:
            c /= DEG
        return _fmt_num(c)
    if depth > 3:
        return "..."
    if isinstance(v, (list, tuple)):
        items = [show(x, unit_scale, depth + 1) for x in v[:20]]
        if len(v) > 20:
            items.append(f"... ({len(v)} items)")
        o, c_ = ("[", "]") if isinstance(v, list) else ("(", ")")
        return o + ", ".join(items) + c_
    if isinstance(v, PV):
        x, y = as_const(v.x), as_const(v.y)
        if x is not None and y is not None:
            return f"({_fmt_num(x / unit_scale)}, {_fmt_num(y / unit_scale)})"
        if v.obj is not None:
            return f"point `{v.obj.label}` in `{v.obj.owner.path}`"
        return "a point known after solving"
    if isinstance(v, GeomRef):
        g = v.geom
        return f"{g.kind} `{g.owner.path}.{g.name}`" if g.name else f"{g.kind} in `{g.owner.path}`"
    if isinstance(v, StructRef):
        return f"{v.struct.kind} `{v.struct.path}`"
    if isinstance(v, Template):
        return f"template `{v.node.name}`"
    if isinstance(v, Namespace):
        return f"import `{v.name}`"
    if isinstance(v, Builtin):
        return f"built-in `{v.name}`"
    if isinstance(v, BBoxRef):
        return "a bounding box"
    if v is None:
        return "none"
    return type_name(v)


def _const(x) -> bool:
    return isinstance(x, (int, float)) or (type(x) is Lin and not x.terms)


def _value(x) -> float:
    return float(x) if isinstance(x, (int, float)) else float(x.const)


def _definition_lines(stmts, out=None) -> dict[str, int]:
    """Name -> line of its first definition in a body (also inside its loops and ifs)."""
    out = {} if out is None else out
    for st in stmts:
        if isinstance(st, (A.Assign, A.StructDecl)):
            out.setdefault(st.name, st.span.line)
        elif isinstance(st, A.For):
            _definition_lines(st.body.stmts, out)
        elif isinstance(st, A.If):
            _definition_lines(st.body.stmts, out)
            if st.orelse is not None:
                _definition_lines(st.orelse.stmts, out)
    return out


def said_shrunk(sink, g, span) -> None:
    """The note W0113 of a ``Text(..., max_width=)`` (geometry ``g``) drawn smaller than its
    ``size`` to fit, at ``span``: the size asked, the width it had, the size drawn."""
    import math
    from ..base.diagnostics import Diagnostic
    asked, wide = g.data["shrunk"]
    m, fit = g.data["max_width"], g.data["size"]
    t = g.data["text"]
    shown = t if len(t) <= 40 else t[:37] + "..."
    sink.add(Diagnostic(
        "W0113", f"the text \"{shown}\" at size {asked:.4g} mm is {wide:.4g} mm wide along its "
        "baseline, as max_width measures it (its `.bb` is the letters' own box, which may be "
        f"a little narrower), more than its max_width {m:.4g} mm: drawn at size {fit:.4g} mm, "
        f"{m:.4g} mm wide", span,           # (run ac's name: 61.53 wide, its .bb 59.76)
        "note", hint="nothing to change when fitting the width is meant: the size follows "
                     "max_width (and the text) whenever they change; for a set size instead, "
                     f"`size={math.floor(fit * 100) / 100:g}` without max_width"))


def _defer_boxes(c) -> None:
    """A constructor's point or size read from a bounding box: :func:`.bbox.defer_boxes`."""
    from ..geometry.relations.bbox import defer_boxes
    defer_boxes(c)


def loop_bound_names(block) -> list[str]:
    """The names a loop body binds, in the order written (``name = ...``, a named structure,
    inside an ``if`` or an inner loop too): after the loop each is the list of its values, an
    empty list when no pass bound it (issue 111's run dd: `tens` set under an `if` that no
    pass of the loop met; `len(rod.marks.tens) == 0` was E0102)."""
    out: list[str] = []
    todo = list(block.stmts)
    while todo:
        s = todo.pop(0)
        if isinstance(s, A.Assign) or (isinstance(s, A.StructDecl) and s.name):
            out.append(s.name)
        elif isinstance(s, A.If):
            todo += s.body.stmts + (s.orelse.stmts if s.orelse is not None else [])
        elif isinstance(s, A.For):
            todo += s.body.stmts
    return list(dict.fromkeys(out))
