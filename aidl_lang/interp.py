"""Interpret a checked AIDL program into a :class:`~aidl_lang.geometry.core.model.Model`.

Runs the statements of each structure (post-order children are created as their declarations
are met), evaluating expressions to values with units (:mod:`aidl_lang.geometry.core.values`),
creating geometry (:mod:`aidl_lang.geometry.shapes.primitives`) and compiling constraints to residual
equations (:mod:`aidl_lang.geometry.relations.constraints`).  Errors found while running (types, units,
indices, limits, the paper's two validity rules on the exact objects referenced) become
diagnostics; the statement is skipped and interpretation goes on, so one run reports several
problems.

This module is the entry point; the interpreter's parts are in :mod:`aidl_lang.interpreter`:
``statements`` (files, imports, bodies, loops, templates, constraints), ``calls`` (constructors,
coercion, built-in functions) and ``expressions`` (operators, units, members).

Limits (docs/language.md, "Limits"; :mod:`aidl_lang.base.limits`): loops and comprehensions at most
``MAX_ITER`` iterations, at most ``MAX_GEOMETRY`` geometry objects, template nesting at most
``MAX_TEMPLATE_DEPTH``.
"""
from __future__ import annotations

import time
from pathlib import Path

from .base.diagnostics import Diagnostic, DiagnosticSink, EvalError, Label, Span
from .geometry.core.expr import Lin, evaluate, lift
from .geometry.core.model import Model, Structure
from .geometry.relations.bbox import contains_bbox, expand
from .interpreter.calls import Calls
from .interpreter.common import BudgetExhausted, FileCtx, Scope
from .interpreter.expressions import Expressions
from .interpreter.placing import Placing
from .interpreter.statements import Statements
from .base.limits import (DEFAULT_BUDGET, MAX_GEOMETRY, MAX_ITER, MAX_TEMPLATE_DEPTH, WALL_GUARD, Budget,
                     Work, cpu_text, interp_work, now, started, wall_text)
from .base.memory import address_space, gc_paused, guard_limit
from .library.sources import STDLIB

__all__ = ["Interpreter", "EvalError", "STDLIB", "MAX_ITER", "MAX_GEOMETRY", "MAX_TEMPLATE_DEPTH"]



# the strings one compile builds: at most this many times the budget's ``size`` characters in
# all (64 million by default: at most a few hundred MB however they are kept)
STRING_CHARS = 64

class Interpreter(Statements, Calls, Placing, Expressions):
    """Runs a checked :class:`~aidl_lang.ast.Program` into a :class:`~aidl_lang.geometry.core.model.Model`.

    Usage: ``Interpreter(sink, overrides).run(program)``; errors go to ``sink`` as diagnostics.
    The methods live in the parts under :mod:`aidl_lang.interpreter`.
    """

    def __init__(self, sink: DiagnosticSink, overrides: dict[str, str] | None = None,
                 budget: Budget = DEFAULT_BUDGET, deadline: float | None = None,
                 work: Work | None = None):
        self.sink = sink
        self.budget = budget
        # the compile's backstop on CPU seconds (limits.now) and its wall guard: the steps,
        # objects and sizes below decide; these only stop what they do not count
        self.deadline = deadline if deadline is not None else now() + budget.backstop
        self.wall_end = time.monotonic() + WALL_GUARD * budget.seconds
        self.started = started()            # what the wall guard's message measures from
        # the compile's work meter: the steps and objects are added to it when the run ends
        self.work = work
        self.steps = 0
        self.objects = 0
        self.chars = 0                                # characters of every string built so far
        self.reported: set = set()
        self.ops = 0                                  # operators evaluated (time checks)
        self.frames: list[tuple[str, Span]] = []     # loops, comprehensions, template instances
        self.model = Model()
        self.on_top: list = []       # parts placed `on=` another at (x, y): on its top face
        self.memory_guard = guard_limit()   # bytes of address space: stop before a real OOM
        self.overrides = dict(overrides or {})
        # `--set NAME=TEXT` with a unit for a param whose default is a bare number:
        # NAME -> (TEXT, the value's dimension), see error()
        self.override_units: dict[str, tuple] = {}
        # id -> (value, the `//` node, its exact quotient): bare numbers made by floor
        # division, warned about (W0106) if used as a length
        self.floor_results: dict[int, tuple] = {}
        self.template_depth = 0
        self.n_geometry = 0
        self.loading: list[str] = []
        self.loaded: dict[str, FileCtx] = {}
        self.struct: Structure | None = None
        self.scope: Scope | None = None
        self.file: FileCtx | None = None
        self.root_dir: Path | None = None
        self.cur_span: Span | None = None
        self.body_stmts: list | None = None           # the structure body being run

    def run(self, program):
        """Interpret ``program``; an exhausted budget is one ``E0304`` (the model so far is
        returned, with the error in the sink).

        The cyclic garbage collector is paused while interpreting (the previous state is
        restored): a run makes hundreds of thousands of small objects (values, expressions,
        records) that reference counting frees, and the collector's full passes over a large
        heap were up to half the time (docs/dev/performance.md, "The interpreter").  What a run
        makes is bounded by its :class:`~aidl_lang.base.limits.Budget`."""
        if self.sink.main is None:       # diagnostics in other files: at the call (issue 86)
            self.sink.main = program.path
        with gc_paused():
            try:
                return Statements.run(self, program)
            except BudgetExhausted as ex:
                self.budget_error(ex)
                return self.model
            finally:
                if self.work is not None:
                    self.work.add(interp_work(self.steps, self.objects), "interpreting")

    # ------------------------------------------------------------------ the budget
    def step(self, span=None) -> None:
        """Count one evaluation step (loop iteration, comprehension element, call, template
        instance); checks the deadline every 128 steps."""
        self.steps += 1
        if self.steps > self.budget.steps:
            raise BudgetExhausted(f"more than {self.budget.steps:,} evaluation steps (loop "
                                  "iterations, comprehension elements, calls and template "
                                  "instances: a work unit each)", span or self.cur_span,
                                  self.frames)
        if not self.steps & 127:
            self.check_time(span)

    def check_time(self, span=None) -> None:
        """The budget's work units (the steps and objects so far, and what the meter holds
        from before), then the backstops: the CPU seconds, or the wall guard."""
        spent = interp_work(self.steps, self.objects) + (self.work.spent if self.work else 0.0)
        if spent > self.budget.work:
            raise BudgetExhausted(f"it needs more than {int(spent):,} work units, past its "
                                  f"budget of {self.budget.work:,}", span or self.cur_span,
                                  self.frames)
        if now() > self.deadline:
            raise BudgetExhausted(cpu_text(self.budget.backstop), span or self.cur_span,
                                  self.frames)
        if time.monotonic() > self.wall_end:
            raise BudgetExhausted(wall_text(self.budget.seconds, self.started),
                                  span or self.cur_span,
                                  self.frames)
        if self.memory_guard is not None:
            used = address_space()
            if used is not None and used > self.memory_guard:
                raise MemoryError(f"address space {used >> 20} MB, near its cap")

    def count_object(self, span=None) -> None:
        """Count one point, geometry object, structure or constraint against the budget;
        checks the deadline every 128 objects (one pattern call makes thousands of
        copies in a single step: fuzz seed 15501, 100,000 copies, 127 s past a 15 s budget)."""
        self.objects += 1
        if self.objects > self.budget.objects:
            raise BudgetExhausted(f"more than {self.budget.objects:,} points, geometry "
                                  "objects, structures and constraints", span or self.cur_span, self.frames)
        if not self.objects & 127:
            self.check_time(span)

    def check_size(self, n: int, span, what: str = "a string") -> None:
        """A string or list of ``n`` characters/items must fit the budget's ``size``; the
        strings one compile builds may hold :data:`STRING_CHARS` x ``size`` characters in all
        (each fits alone, but 8 000 of a million characters took 7.9 GB)."""
        unit = "items" if "list" in what else "characters"
        if n > self.budget.size:
            raise BudgetExhausted(f"{what} of {n:,} {unit}, more than the {self.budget.size:,} "
                                  "allowed", span, self.frames)
        if unit == "characters":
            self.chars += n
            if self.chars > STRING_CHARS * self.budget.size:
                raise BudgetExhausted(f"strings of more than {STRING_CHARS * self.budget.size:,} "
                                      "characters in all", span, self.frames)

    def budget_error(self, ex: BudgetExhausted) -> None:
        frames = [f for f in ex.frames if f[1] is not None]
        primary = frames[0][1] if frames else ex.span
        labels, seen = [], {frames[0][1]} if frames else set()
        for what, sp in frames[1:]:
            if sp in seen:
                continue
            seen.add(sp)
            n = sum(1 for f in frames if f[1] == sp)
            labels.append(Label(sp, f"inside {what}" + (f" ({n} levels)" if n > 1 else ""),
                                primary=False))
        labels = labels[:6]
        if ex.span is not None and all(ex.span != f[1] for f in frames):
            labels.append(Label(ex.span, "the budget ran out here", primary=False))
        where = f" in {frames[0][0]}" if frames else ""
        self.sink.add(Diagnostic(
            "E0304", f"the program ran out of its evaluation budget{where}: {ex.what}",
            primary, "error", labels=labels,
            hint="build less (smaller loops, fewer template instances); if the model really "
                 "needs more, raise the budget with `--budget 2` (or more)"))

    # ------------------------------------------------------------------ helpers
    @property
    def unit_scale(self) -> float:
        return self.file.unit_scale if self.file else 1.0

    def value_of(self, e) -> float:
        """The value of expression ``e`` at the current parameters (mm, radians)."""
        if type(e) is Lin:               # evaluate() of an affine expression, inline
            s, x = e.const, self.model.x
            for k, v in e.terms.items():
                s += v * x[k]
            return s
        if contains_bbox(e):             # a box's side (`hull.center`, `r.bb.center`): at x
            e = expand(e, self.model.x, set())
        return evaluate(lift(e), self.model.x)

    def error(self, e: EvalError) -> None:
        if self.override_units and e.code in ("E0108", "E0109") and e.span is not None:
            e = self._override_misuse(e)
            if e is None:
                return
        # the same error in every iteration of a loop: once (per call of the template it is in)
        key = (e.code, e.span, self.sink.calls[0][1] if self.sink.calls else None)
        if key in self.reported:
            return
        self.reported.add(key)
        self.sink.add(Diagnostic(e.code, e.message, e.span, "error", e.hint,
                                 labels=e.labels, suggestions=e.suggestions))

    def _override_misuse(self, e: EvalError) -> EvalError | None:
        """A unit mismatch at a use of a param given by ``--set NAME=TEXT`` with a unit while
        its default is a bare number (``param leg = 40``, ``--set leg=100 deg``, used as a
        length): the ``--set`` argument is the mistake, so the error names it (E0113), once
        per param (``None`` for the later uses)."""
        import re
        src = self.sink.sources.get(e.span.file, "")
        words = set(re.findall(r"[A-Za-z_]\w*", src[e.span.start:e.span.end]))
        used = next((n for n in self.override_units if n in words), None)
        if used is None:
            return e
        hit = self.override_units[used]
        text, _dim = hit
        if ("override", used) in self.reported:
            return None
        self.reported.add(("override", used))
        return EvalError("E0113", f"`--set {used}={text}`: {e.message} (the value of `{used}`, "
                         f"whose default in the file has no unit)", e.span,
                         hint=f"give `{used}` a value of the kind used here; a bare number is "
                              "read like one in the file (file units or degrees)")

    def moves_only(self, e) -> bool:
        """Whether ``e`` reads box sides whose unknowns cancel once the boxes are taken at the
        current values (a Text's `bb.width`: its right less its left, both its position plus
        a number): a size of a shape the solve only moves, never resizes, the same before and
        after solving, so no W0103 (run fq: a rail sized by `word.bb.width + 3 mm`, warned on
        every check, as the prompt recommends it)."""
        if not contains_bbox(e):
            return False
        from .geometry.relations.assertions import _indices
        x = self.model.xs()
        try:
            f = expand(e, self.model.x, set())
            read: set = set()
            _indices(f, read)
            if len(read) > 64:
                return False
            at = float(evaluate(f, x))
            for k in read:                  # each unknown moved 1 mm: the value stays
                old = x[k]                  # (x: a copy, moved and put back in place)
                x[k] = old + 1.0
                moved = float(evaluate(f, x))
                x[k] = old
                if abs(moved - at) > 1e-9:
                    return False
        except (ArithmeticError, KeyError, TypeError, ValueError, IndexError):
            return False
        return True

    def warn_nonconst(self, what: str) -> None:
        self.sink.warning("W0103", f"{what} depends on solved geometry; its starting value is "
                          "used and held", self.cur_span,
                          hint="give it a number or a param; relate shapes with constraints instead")

