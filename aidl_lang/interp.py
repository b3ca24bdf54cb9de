"""Interpret a checked AIDL program into a :class:`~aidl_lang.geometry.model.Model`.

Runs the statements of each structure (post-order children are created as their declarations
are met), evaluating expressions to values with units (:mod:`aidl_lang.geometry.values`),
creating geometry (:mod:`aidl_lang.geometry.primitives`) and compiling constraints to residual
equations (:mod:`aidl_lang.geometry.constraints`).  Errors found while running (types, units,
indices, limits, the paper's two validity rules on the exact objects referenced) become
diagnostics; the statement is skipped and interpretation goes on, so one run reports several
problems.

This module is the entry point; the interpreter's parts are in :mod:`aidl_lang.interpreter`:
``statements`` (files, imports, bodies, loops, templates, constraints), ``calls`` (constructors,
coercion, built-in functions) and ``expressions`` (operators, units, members).

Limits (docs/language.md, "Limits"; :mod:`aidl_lang.limits`): loops and comprehensions at most
``MAX_ITER`` iterations, at most ``MAX_GEOMETRY`` geometry objects, template nesting at most
``MAX_TEMPLATE_DEPTH``.
"""
from __future__ import annotations

from pathlib import Path

from .diagnostics import Diagnostic, DiagnosticSink, EvalError, Span
from .geometry.expr import evaluate, lift
from .geometry.model import Model, Structure
from .interpreter.calls import Calls
from .interpreter.common import FileCtx, Scope
from .interpreter.expressions import Expressions
from .interpreter.statements import Statements
from .limits import MAX_GEOMETRY, MAX_ITER, MAX_TEMPLATE_DEPTH
from .sources import STDLIB

__all__ = ["Interpreter", "EvalError", "STDLIB", "MAX_ITER", "MAX_GEOMETRY", "MAX_TEMPLATE_DEPTH"]


class Interpreter(Statements, Calls, Expressions):
    """Runs a checked :class:`~aidl_lang.ast.Program` into a :class:`~aidl_lang.geometry.model.Model`.

    Usage: ``Interpreter(sink, overrides).run(program)``; errors go to ``sink`` as diagnostics.
    The methods live in the parts under :mod:`aidl_lang.interpreter`.
    """

    def __init__(self, sink: DiagnosticSink, overrides: dict[str, str] | None = None):
        self.sink = sink
        self.model = Model()
        self.overrides = dict(overrides or {})
        self.template_depth = 0
        self.n_geometry = 0
        self.loading: list[str] = []
        self.loaded: dict[str, FileCtx] = {}
        self.struct: Structure | None = None
        self.scope: Scope | None = None
        self.file: FileCtx | None = None
        self.root_dir: Path | None = None
        self.cur_span: Span | None = None

    # ------------------------------------------------------------------ helpers
    @property
    def unit_scale(self) -> float:
        return self.file.unit_scale if self.file else 1.0

    def value_of(self, e) -> float:
        return evaluate(lift(e), self.model.x)

    def error(self, e: EvalError) -> None:
        self.sink.add(Diagnostic(e.code, e.message, e.span, "error", e.hint,
                                 labels=e.labels, suggestions=e.suggestions))

    def warn_nonconst(self, what: str) -> None:
        self.sink.warning("W0103", f"{what} depends on solved geometry; its starting value is "
                          "used and held", self.cur_span,
                          hint="give it a number or a param; relate shapes with constraints instead")

