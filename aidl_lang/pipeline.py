"""The pipeline in one call: parse -> check -> interpret -> solve (-> render, in cli/render).

Each stage appends diagnostics to one :class:`DiagnosticSink`; a stage runs only when the
previous ones produced no errors.
"""
from __future__ import annotations

from dataclasses import dataclass

from .diagnostics import Diagnostic, DiagnosticSink, Label
from .interp import Interpreter
from .model import Model
from .parser import parse
from .solver import SolveResult, solve
from .typecheck import check


@dataclass
class Compiled:
    sink: DiagnosticSink
    model: Model | None = None
    solve: SolveResult | None = None

    @property
    def ok(self) -> bool:
        return not self.sink.has_errors


def compile_source(source: str, path: str, overrides: dict[str, str] | None = None,
                   do_solve: bool = True) -> Compiled:
    """Run the pipeline on ``source``; never raises for bad input (errors are diagnostics)."""
    sink = DiagnosticSink()
    try:
        return _compile(sink, source, path, overrides, do_solve)
    except RecursionError:
        sink.sources.setdefault(path, source)
        sink.error("E0302", "the program is nested too deeply to compile", None,
                   hint="split long expressions into named constants")
        return Compiled(sink)


def _compile(sink, source, path, overrides, do_solve) -> Compiled:
    program = parse(source, path, sink)
    if sink.has_errors:
        return Compiled(sink)
    check(program, sink)
    if sink.has_errors:
        return Compiled(sink)
    interp = Interpreter(sink, overrides)
    model = interp.run(program)
    if sink.has_errors or not do_solve:
        return Compiled(sink, model)
    result = solve(model)
    if not result.converged:
        report_failure(sink, result)
    return Compiled(sink, model, result)


def report_failure(sink: DiagnosticSink, result: SolveResult) -> None:
    items = result.unsatisfied
    explicit = [(c, r) for c, r in items if not c.implicit] or items
    first, r0 = explicit[0]
    labels = []
    for c, r in explicit[1:8]:
        if c.span is not None:
            labels.append(Label(c.span, f"also unsatisfied (residual {r:.3g}) in `{c.owner.path}`",
                                primary=False))
    names = ", ".join(f"`{c.describe()}`" for c, _ in explicit[:4])
    sink.add(Diagnostic(
        "E0401",
        f"the constraints cannot all be satisfied: {len(explicit)} still off after solving "
        f"(largest residual {r0:.3g} in `{first.owner.path}`)",
        first.span, "error",
        hint=("these constraints conflict with each other or with the dimensions held by "
              f"constructors: {names}. Check that no two of them demand different values "
              "for the same thing; remove or relax the one that does not express your intent"),
        labels=labels))
