"""Names shared by the interpreter's parts: scopes, per-file context, the poison marker for
names whose definition failed, and small helpers (see :mod:`aidl_lang.interp`)."""
from __future__ import annotations

import math

from .. import ast as A
from ..diagnostics import DiagnosticSink, Span
from ..geometry.model import Structure
from ..registry import (FUNCTIONS, lookup)

DEG = math.pi / 180.0


class _Silent(Exception):
    """Raised when a statement uses a name whose definition already failed (reported once)."""


POISON = object()


class BudgetExhausted(Exception):
    """Raised when the compile's evaluation budget (:class:`aidl_lang.limits.Budget`) runs
    out; it unwinds the whole interpretation (no statement catches it) and
    :meth:`aidl_lang.interp.Interpreter.run` turns it into one ``E0304``."""

    def __init__(self, what: str, span, frames):
        super().__init__(what)
        self.what = what
        self.span = span
        self.frames = list(frames)


class Scope:
    def __init__(self, parent: "Scope | None", struct: Structure | None, file: "FileCtx"):
        self.vars: dict = {}
        self.parent = parent
        self.struct = struct
        self.file = file

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



def _is_plain_const(st) -> bool:
    """A top-level `NAME = expr` that creates no geometry (a file constant)."""
    if not isinstance(st, A.Assign):
        return False
    for n in A.walk(st.value):
        if isinstance(n, A.Call) and isinstance(n.func, A.Name):
            e = lookup(n.func.id)
            if e is not None and e.category in ("primitive", "operation"):
                return False
            if n.func.id not in FUNCTIONS and e is None:
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
    if span is None:
        return ""
    src = sink.sources.get(span.file, "")
    return " ".join(src[span.start:span.end].split())[:120]


def _a(word: str) -> str:
    return ("an " if word[:1] in "aeiou" else "a ") + word


def _fmt_num(c: float) -> str:
    if abs(c - round(c)) < 1e-9:
        return str(int(round(c)))
    return f"{c:.6g}"
