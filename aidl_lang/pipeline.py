"""The pipeline in one call: parse -> check -> interpret -> solve -> booleans and the geometry
checks on the final shape (:mod:`aidl_lang.output.checks`); the writers run in cli/render.

Each stage appends diagnostics to one :class:`DiagnosticSink`; a stage runs only when the
previous ones produced no errors.
"""
from __future__ import annotations

import math
import threading
import time
import warnings

import numpy as np

from .base.records import Compared
from .base.diagnostics import Diagnostic, DiagnosticSink, Label, as_lf, in_stdlib, shown_path
from .solver.diagnosis.notes import library_instance, literal_note, member_words, rigid_note, sizes_note
from .interp import Interpreter
from .base.memory import gc_paused
from .base.limits import (DEFAULT_BUDGET, MAX_EXTENT, MEMORY_HINT, Budget, Deadline, OutOfBudget,
                     OutOfMemory, Work, is_out_of_memory, memory_fix, memory_text, now,
                     solve_work)
from .geometry.core.expr import Lin, Nl
from .geometry.core.model import Model
from .parser import parse
from .output.part.build.booleans import Drawing, render_model
from .output.checks import (check_drawing, check_loose_drawings, check_stray_holes,
                             check_topology, topology)
from .output.checks.boxes import check_drawn_boxes, check_final_box_asserts, check_final_boxes
from .solver import SolveResult, solve

# the shape findings said as notes, not warnings: a design may mean them (W0410: a Fillet of
# the whole outline that rounds a narrow hole's ends; W0412: a Spline swinging off a straight
# run of its points, a wave a pond's outline may mean)
NOTE_CODES = frozenset({"W0410", "W0412"})
from .typecheck import check


class Compiled(Compared):
    """What :func:`compile_source` made: the diagnostics, and each stage's result it reached."""
    __slots__ = ("sink", "model", "solve", "drawing", "solve_seconds", "params", "deadline",
                 "work")

    def __init__(self, sink: DiagnosticSink, model: Model | None = None,
                 solve: SolveResult | None = None, drawing: Drawing | None = None,
                 solve_seconds: float = 0.0, params: dict | None = None,
                 deadline: Deadline | None = None, work: Work | None = None):
        self.sink = sink
        self.model = model
        self.solve = solve
        self.drawing = drawing  # the booleans' result, when the solve converged
        self.solve_seconds = solve_seconds  # wall time of the solve alone (``aidl batch`` rows)
        self.params = params  # the main file's params: name -> value (Q, bool, str)
        self.deadline = deadline  # the compile's end (limits.Deadline), for the writers after it
        # the compile's work meter (limits.Work): the units each stage spent, the same on any
        # machine (`--json`'s `work`); the writers after it spend from the same meter
        self.work = work if work is not None else (deadline.work if deadline is not None
                                                   else None)

    @property
    def ok(self) -> bool:
        return not self.sink.has_errors


def compile_source(source: str, path: str, overrides: dict[str, str] | None = None,
                   do_solve: bool = True, min_wall: float | None = None,
                   budget: Budget = DEFAULT_BUDGET) -> Compiled:
    """Run the pipeline on ``source``; never raises for bad input (errors are diagnostics).

    ``budget`` bounds interpretation and solving together (:class:`aidl_lang.base.limits.Budget`;
    running out is ``E0304``)."""
    sink = DiagnosticSink()
    if source.startswith("\ufeff"):       # a UTF-8 byte order mark is not part of the program
        source = source[1:]
    source = as_lf(source)               # a lone CR is a line break (diagnostics.LINE_BREAK)
    try:
        res = run_deep(lambda: _compile(sink, source, path, overrides, do_solve, min_wall,
                                        budget))
        if overrides and res.drawing is not None and res.ok:
            # W0510: the baseline is the program with its own defaults (its warnings are not
            # reported), compiled once per source and kept (defaults_topology)
            try:
                base = defaults_topology(source, path, min_wall, budget)
                if base is not None:
                    check_topology(base, res.drawing, overrides, sink, res.deadline)
            except OutOfBudget as ex:
                report_out_of_budget(sink, ex)
        return res
    except RecursionError as ex:
        sink.sources.setdefault(path, source)
        sink.error("E0302", "the program is nested too deeply to compile", _deep_span(ex, path, source),
                   hint="split long expressions into named constants")
        return Compiled(sink)
    except MemoryError:
        pass                         # handled below, once the exception (and its frames) is gone
    except SystemError as ex:
        if not is_out_of_memory(ex):
            raise
        # an allocation failed inside C code (numpy, Manifold, the interpreter's own C
        # helpers) that lost the MemoryError on its way out: the same out of memory
    # Out of memory: what the failed compile built is garbage now, much of it in reference
    # cycles (structures and their parents), which only the cycle collector frees — and it
    # would not run before the next allocations fail.  Free it, then report.
    return Compiled(out_of_memory_sink(path, source))


def out_of_memory_sink(path: str, source: str | None, stage: str | None = None,
                       where=None) -> DiagnosticSink:
    """A sink holding the one located ``E0304`` of a compile that ran out of memory (a
    ``MemoryError`` anywhere: NumPy, Manifold, the checks, a writer), for every front end's
    last resort: at ``where`` (a structure, with ``path`` and ``span``) when known, else at the
    program's first structure.  Frees what the failed compile left in reference cycles
    first (:func:`gc.collect`), so the process goes on; call it once the exception is gone."""
    import gc
    gc.collect()
    sink = DiagnosticSink()
    if source is not None:
        sink.sources[path] = source
    at = f" in {stage}" if stage else " while compiling"
    of = f" of `{where.path}`" if getattr(where, "path", None) else ""
    span = getattr(where, "span", None)
    if span is None and source is not None:
        span = _structure_span(path, source)
    sink.error("E0304", f"the program ran out of memory{at}{of}: {memory_text()}", span,
               hint=MEMORY_HINT + memory_fix())
    return sink


def output_error_sink(path: str, source: str | None, error) -> DiagnosticSink:
    """A sink holding the one located ``E0304`` of an exact-outline recovery or a writer that
    refused its input (:class:`~aidl_lang.output.part.part.OutputError`: bounded work ran out,
    thousands of curves drawn on top of each other), for a front end that reads the output
    after the compile (``aidl parts``, ``--describe``, the MCP tools): at the structure the
    error names when it has one, else at the program's first structure."""
    sink = DiagnosticSink()
    if source is not None:
        sink.sources[path] = source
    budget = getattr(error, "budget", None)
    if budget is not None:
        report_out_of_budget(sink, budget)
        return sink
    span = _structure_span(path, source) if source is not None else None
    sink.error("E0304", f"the final part's outlines could not be made within bounded work: "
               f"{error}", span,
               hint="draw fewer curves on top of each other (a loop that stacks thousands of "
                    "shapes in one place), or check without --describe")
    return sink


DEFAULTS_KEPT = 8     # sources whose defaults' topology a process keeps (serve, LSP, MCP)
_defaults: dict = {}  # (path, source, min_wall, budget) -> (imported files' texts, topology)


def defaults_topology(source: str, path: str, min_wall: float | None = None,
                      budget: Budget = DEFAULT_BUDGET) -> dict | None:
    """The :func:`~aidl_lang.output.checks.topology` of ``source`` compiled with its own
    defaults (what W0510 compares a ``--set`` compile with), or None when that compile
    fails.  Kept for the last :data:`DEFAULTS_KEPT` sources, so a slider move in ``aidl
    serve``, the editor's preview or an MCP session compiles once; a kept one is used while
    the files it imported still read the same."""
    key = (path, source, min_wall, budget)
    kept = _defaults.pop(key, None)
    if kept is not None and all(_reads(p) == text for p, text in kept[0].items()):
        _defaults[key] = kept                          # the most recent last
        return kept[1]
    base = run_deep(lambda: _compile(DiagnosticSink(), source, path, None, True,
                                     min_wall, budget, shape_checks=False))
    topo = topology(base.drawing, base.deadline) if base.drawing is not None and base.ok \
        else None
    imported = {p: t for p, t in base.sink.sources.items() if p != path}
    while len(_defaults) >= DEFAULTS_KEPT:
        del _defaults[next(iter(_defaults))]           # the least recently used
    _defaults[key] = (imported, topo)
    return topo


def _reads(path: str) -> str | None:
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except (OSError, UnicodeDecodeError):
        return None


# Deep but legal programs (a 500-term `**` chain, 600 nested conditional expressions) recurse
# through the parser's tree builder, the checker and the interpreter.  They run on a thread
# with a large stack and a raised recursion limit; beyond that, E0302 at the expression.
DEEP_STACK = 256 * 1024 * 1024
DEEP_RECURSION = 60_000


def _touch_thread_locals():
    """Allocate this thread's C++ exception state now, while memory is free.  glibc gives a
    thread its block of a loaded library's thread-local storage on first use; the C++
    runtime's first use comes with the first exception thrown on the thread, which under an
    address-space cap (``--memory``) is Manifold's ``std::bad_alloc`` deep in the booleans:
    the block cannot be allocated then, and glibc ends the process ("cannot allocate memory
    for thread-local data: ABORT", exit 127) instead of the ``MemoryError`` that becomes
    E0304.  ``__cxa_get_globals`` is that first use, made here."""
    import ctypes
    try:        # loaded already (Manifold's runtime): dlopen only finds it again
        ctypes.CDLL("libstdc++.so.6").__cxa_get_globals()
    except (OSError, AttributeError):      # no libstdc++ (another platform): nothing to touch
        pass


def run_deep(fn):
    """Call ``fn()`` on a thread with a :data:`DEEP_STACK` stack and a recursion limit of
    :data:`DEEP_RECURSION`; returns its result or re-raises its exception."""
    import sys
    import threading
    if getattr(_deep_state, "inside", False):
        return fn()
    box: dict = {}

    def target():
        _deep_state.inside = True
        try:
            _touch_thread_locals()
            box["value"] = fn()
        except BaseException as ex:          # re-raised in the caller's thread
            box["error"] = ex

    with _deep_lock:
        old_stack = threading.stack_size()
        old_limit = sys.getrecursionlimit()
        sys.setrecursionlimit(max(old_limit, DEEP_RECURSION))
        try:
            try:
                threading.stack_size(DEEP_STACK)
                t = threading.Thread(target=target, name="aidl-compile", daemon=True)
                t.start()
            except (RuntimeError, MemoryError):
                t = None               # no room for the big stack (an address-space limit)
            finally:
                threading.stack_size(old_stack)
            if t is None:
                sys.setrecursionlimit(old_limit)
                return fn()            # deep programs then end in a located E0302
            t.join()
        finally:
            sys.setrecursionlimit(old_limit)
    if "error" in box:
        raise box["error"]
    if "value" not in box:        # the thread died before its own handler ran: no memory
        raise MemoryError("the compile thread ended without a result")
    return box["value"]


def _structure_span(path: str, source: str):
    """The first top-level structure's header line (``solid plate {``), else line 1: where a
    whole-program error (out of memory) is shown."""
    import re
    from .base.diagnostics import Span
    m = re.search(r"^(solid|hole|drawing|assembly)[ \t]+\w+", source, re.M)
    start, end = (m.start(), m.end()) if m else (0, len(source.split("\n", 1)[0]))
    line = source.count("\n", 0, start) + 1
    col = start - (source.rfind("\n", 0, start) + 1) + 1
    return Span(path, line, col, line, col + end - start, start, end)


def _deep_span(ex, path: str, source: str):
    """The line with the most operators (the deepest expression, as far as one can tell)."""
    import re
    from .base.diagnostics import Span
    best, best_score, start = None, -1, 0
    for no, line in enumerate(source.split("\n"), 1):
        score = len(re.findall(r"\*\*|\bif\b|\bnot\b|\band\b|\bor\b|[-+*/(\[]", line))
        if score > best_score and line.strip():
            lead = len(line) - len(line.lstrip())
            body = line.rstrip()
            best = Span(path, no, lead + 1, no, len(body) + 1, start + lead, start + len(body))
            best_score = score
        start += len(line) + 1
    return best


_deep_lock = threading.Lock()
_deep_state = threading.local()


def _compile(sink, source, path, overrides, do_solve, min_wall=None,
             budget: Budget = DEFAULT_BUDGET, shape_checks: bool = True) -> Compiled:
    end = Deadline.starting(budget)     # the work meter and the backstops, for every stage
    work = end.work
    program = parse(source, path, sink)
    if sink.has_errors:
        return Compiled(sink, work=work)
    check(program, sink)
    if sink.has_errors:
        return Compiled(sink, work=work)
    interp = Interpreter(sink, overrides, budget, end.at, work=work)
    model = interp.run(program)
    params = getattr(interp.file, "params", None)
    if not sink.has_errors and _empty_drawing(program, model):
        sink.warning("W0104", "the program builds no geometry: the drawing will be empty",
                     program.span if program.stmts else None,
                     hint="add a structure with shapes, e.g. `solid plate { body = "
                          "Rectangle(center=(0, 0), width=40, height=20) }`")
    if not do_solve or sink.has_errors and not _only_requirements(sink):
        return Compiled(sink, model, params=params, work=work)
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        # overflow in a residual is reported as a failed solve, not as a numpy warning
        warnings.simplefilter("ignore", RuntimeWarning)
        t0 = time.perf_counter()
        model.x_written = list(model.x)         # where each value is written (E0405 says)
        result = solve(model, deadline=end.at)
        took = time.perf_counter() - t0
    work.add(solve_work(result.iterations, len(model.x)), "solving")
    if not result.converged:
        report_failure(sink, result, path)
        check_assertions(sink, model, held_only=True)
        return Compiled(sink, model, result, solve_seconds=took, params=params, work=work)
    return Compiled(sink, model, result, after_solve(sink, model, min_wall, shape_checks, end),
                    solve_seconds=took, params=params, deadline=end)


def _only_requirements(sink: DiagnosticSink) -> bool:
    """Whether every error so far is a false ``assert`` on known values (E0405): the program
    was built whole, so it is solved and its other asserts are checked too (all the failed
    requirements are reported, not the first one)."""
    return all(d.code == "E0405" for d in sink.items if d.is_error)


def after_solve(sink: DiagnosticSink, model: Model, min_wall: float | None = None,
                shape_checks: bool = True, deadline: Deadline | None = None) -> Drawing | None:
    """The stages after a converged solve, shared by :func:`compile_source` and the live
    preview: the extent check (E0305), branch flips (W0403), the booleans (an Offset or
    Shell that leaves nothing: E0406) and the geometry checks on the final shape (W0402, W0501-W0509).  Returns the booleans' :class:`Drawing`,
    or ``None`` when the extent check failed (nothing absurd reaches a writer).
    ``shape_checks=False`` leaves the geometry checks (warnings only) to the caller: the live
    preview runs them (:func:`aidl_lang.output.checks.check_drawing`) after the picture is on
    the page."""
    if not check_extent(sink, model):
        return None
    check_assertions(sink, model)
    check_branches(sink, model)
    stage = "the booleans"
    try:
        try:
            # the collector paused: a perforated sheet's faces, cuts and check records are
            # tens of thousands of small objects with no cycles among them, and each full pass
            # walked every one of the model's (20,000 holes: 1.5 s of 9 s CPU)
            with gc_paused():
                with warnings.catch_warnings(), np.errstate(all="ignore"):
                    warnings.simplefilter("ignore", RuntimeWarning)  # degenerate sizes: quiet
                    drawing = render_model(model, deadline)
                for g, message, hint, *code in drawing.shape_errors:
                    code = code[0] if code else "E0406"     # (a W code: a warning, W0406)
                    severity = ("note" if code in NOTE_CODES else
                                "warning" if code[0] == "W" else "error")
                    # (a geometry, a call, or a structure: E0407 on a spline the structure's
                    # own outline made, a Stroke's band along a Spline, names the structure)
                    sink.add(Diagnostic(code, message, g.span, severity, hint=hint),
                             calls=instance_calls(getattr(g, "owner", g)))
                check_final_boxes(sink, model, drawing, instance_calls)
                check_drawn_boxes(sink, model, instance_calls)
                check_final_box_asserts(sink, model, drawing, instance_calls)
                check_stray_holes(sink, drawing, deadline)
                check_loose_drawings(sink, drawing, deadline)
                if shape_checks:
                    stage = "the shape checks"
                    check_drawing(drawing, sink, min_wall, deadline)
            return drawing
        except (MemoryError, SystemError) as ex:
            if not is_out_of_memory(ex):
                raise
        # out of memory: raised again once the failed stage's frames (its arrays) are gone
        import gc
        drawing = None
        gc.collect()
        raise OutOfMemory(stage, _first_structure(model))
    except OutOfBudget as ex:
        if ex.where is None:            # a step of no one structure: at the program's first
            ex.where = _first_structure(model)
        report_out_of_budget(sink, ex)
        return None


def _first_structure(model: Model):
    """The model's first structure with a place in the source (where a whole-model error is
    shown), or None."""
    for s in getattr(model, "structures", ()):
        if getattr(s, "span", None) is not None:
            return s
    return None


def report_out_of_budget(sink: DiagnosticSink, ex: OutOfBudget) -> None:
    """One ``E0304`` for a budget that ran out after the solve, at the structure being worked
    on (the booleans, the shape checks, a writer)."""
    s = ex.where
    at = f" of `{s.path}`" if s is not None else ""
    what = "memory" if isinstance(ex, OutOfMemory) else "its evaluation budget"
    sink.add(Diagnostic(
        "E0304", f"the program ran out of {what} in {ex.stage}{at}: {ex.what}",
        getattr(s, "span", None), "error",
        hint=ex.hint or "build less (fewer or smaller shapes: every circle and arc becomes "
                        "chords of 0.005 mm), or raise the budget with `--budget 2` (or more)"))


def report_stacked(sink: DiagnosticSink, drawing, ex) -> None:
    """One ``E0501`` for a machine file refused because two parts lie over each other
    (:class:`~aidl_lang.output.writers.StackedParts` ``ex``), at the first part's
    structure (``drawing.part_of``), or unlocated without a drawing."""
    part_of = getattr(drawing, "part_of", None) or {}
    s = part_of.get(ex.parts[0])
    sink.add(Diagnostic("E0501", ex.message, getattr(s, "span", None), "error", hint=ex.hint))


def report_nothing(sink: DiagnosticSink, model: Model, ex) -> None:
    """One ``E0502`` for a sheet layout of a design with no solid part
    (:class:`~aidl_lang.output.fabrication.layout.NothingToLayOut` ``ex``), at the design's
    first structure: the design named as written, "this design" for the implicit `model`."""
    root = model.root
    implicit = root.name == "model" and getattr(root.span, "start", 1) == 0
    first = next(iter(root.children.values()), root) if implicit else root
    one = first if not implicit or len(root.children) == 1 else None
    name = f"{one.kind} `{one.name}`" if one is not None else "this design"
    sink.add(Diagnostic("E0502", (
        f"nothing to lay out on a sheet: {name} has no solid part to cut, {ex.holds} "
        "(a drawing is lines, not a part)"), getattr(first, "span", None), "error",
        hint="render it without `--layout` (the drawing as it is), or put the drawing inside "
             "the `solid` plate it is engraved on"))


def _empty_drawing(program, model: Model) -> bool:
    """W0104's condition: nothing at all in the file, or structures that build no geometry.
    A file of only templates, params and constants is a library: no warning."""
    from . import ast as A
    if any(True for _ in model.all_geometry()):
        return False
    if not program.stmts:
        return True
    return any(not isinstance(s, (A.Import, A.ParamDecl, A.Def, A.Func, A.UnitsDecl, A.Assign))
               for s in program.stmts)


def check_extent(sink: DiagnosticSink, model: Model) -> bool:
    """After solving: every unknown finite and within the model extent
    (:data:`~aidl_lang.base.limits.MAX_EXTENT`), else one E0305 at the structure that holds the
    first offending unknown (no NaN or absurd coordinate reaches a writer)."""
    import math
    x = np.asarray(model.x, dtype=float)
    bad = np.flatnonzero(~(np.isfinite(x) & (np.abs(x) <= MAX_EXTENT)))   # NaN: not finite
    if not len(bad):
        return True
    i = int(bad[0])
    v = model.x[i]
    owner = model.param_owner[i]
    what = "not finite" if not math.isfinite(v) else f"{v:.4g} mm"
    sink.error("E0305", f"after solving, `{model.param_label[i]}` is {what}, beyond the "
               f"model extent of {MAX_EXTENT:.0e} mm",
               owner.span if owner is not None else None,
               hint="the constraints push the geometry very far away: check the values "
                    "and units of the dimensions")
    return False


# the failed asserts (the first this many) whose message names the constraints that moved
# what they read (:func:`~.geometry.relations.assertions.describe`)
MOVED_SAID = 20


def check_assertions(sink: DiagnosticSink, model: Model, held_only: bool = False) -> None:
    """E0405 for each ``assert`` that does not hold at the solution, every one of them (after
    a failed solve, ``held_only``: those that read no solved value)."""
    if not model.assertions:
        return
    from .geometry.relations.assertions import describe, failed, judged_at
    from .interpreter.asserts import ASSERT_HINT
    x = None if held_only else judged_at(model)
    for n, (a, bad) in enumerate(failed(model, held_only)):
        # which constraint moved what it reads: a search of every constraint, for the first
        # MOVED_SAID failures (a loop's thousand asserts stay linear)
        sink.add(Diagnostic("E0405", describe(a, bad, len(a.groups), x, model.param_owner,
                                              None if held_only else model.xs(),
                                              model if n < MOVED_SAID else None),
                            a.span, "error",
                            hint=ASSERT_HINT),
                 calls=instance_calls(a.owner))


def instance_calls(s) -> list:
    """The template calls (outermost first: ``("`name`", call span)``) that made structure
    ``s`` or the instance it is in: where a diagnostic on its geometry, constraints or
    asserts in a template's file is reported (:func:`aidl_lang.base.diagnostics.at_call_site`;
    one on a structure itself, whose span is in its parent's text: ``s.parent``'s)."""
    out = []
    while s is not None:
        if s.template:
            out.append((f"`{s.template}`", s.span))
        s = s.parent
    return out[::-1]


def check_branches(sink: DiagnosticSink, model: Model) -> None:
    """W0403 for a convention-dependent constraint that ended on another branch than the one
    chosen at the start (paper, appendix "Solver Details", *Deferred expressions*)."""
    from .geometry.core.expr import evaluate
    x = model.xs()
    for c in model.constraints:
        for eq in c.equations:
            if eq.branch is not None and evaluate(eq.branch, x) < -1e-9:
                sink.warning("W0403", f"`{c.describe()}` ended on another branch than it started "
                             "on: a line now points the opposite way", c.span,
                             hint="give starting positions closer to the intended shape, so "
                                  "the nearest branch is the one you mean",
                             calls=instance_calls(c.owner))
                break


def report_redundancies(sink: DiagnosticSink, result: SolveResult,
                        seconds: float | None = None, max_rows: int | None = None,
                        deadline: float | None = None, why: set | None = None) -> int:
    """W0401 for each user constraint that others already imply (``aidl check``; what it
    measures: :func:`aidl_lang.solver.diagnosis.redundancy.redundancies`).  ``seconds`` bounds the search, in
    seconds of the reference machine (its factorisations' flops at
    :data:`~aidl_lang.solver.core.rank.SVD_FLOPS_PER_SECOND`: the blocks searched by then are
    reported, the same on every machine) and ``max_rows`` the blocks of rows sharing
    unknowns that it ranks; ``deadline`` (:func:`~aidl_lang.base.limits.now`: the run's end in CPU seconds) bounds it
    too.  Returns the number of user constraints not looked at (out of time, or in a block
    too large)."""
    from .solver.core.rank import MAX_DENSE, SVD_FLOPS_PER_SECOND
    from .solver.diagnosis.redundancy import search
    skipped: list = []
    # `seconds` of the reference machine, as the flops of the search's factorisations: the
    # same blocks searched on every machine; the deadline (CPU) is only the backstop
    found = search(result.solver, deadline=deadline, max_rows=max_rows or MAX_DENSE,
                   skipped=skipped, why=why,
                   flops=None if seconds is None else seconds * SVD_FLOPS_PER_SECOND)
    reds = found.found
    makes = _makers(result.solver.model)
    grouped = _report_groups(sink, reds, found, makes)
    made = _instances(result.solver.model)
    red_at: dict = {}
    for red in reds:
        red_at[_at(red.constraint)] = red_at.get(_at(red.constraint), 0) + 1
    echoes = _echoes(reds, found)
    for red in reds:
        c = red.constraint
        if id(c) in grouped or _in_template(c) or id(c) in echoes:
            continue            # reported with its group; or a template's own (issue 61)
        n = made.get(_at(c), 1)
        if n > red_at.get(_at(c), 0):
            _report_instance(sink, red, n, red_at[_at(c)])
            continue
        by = ", ".join(_source_of(b, c.owner) for b in red.by[:4])
        more = f" and {len(red.by) - 4} more" if len(red.by) > 4 else ""
        labels = [Label(b.span, "overlaps with this" if red.partly else "implied by this",
                        primary=False)
                  for b in red.by[:4] if b.span is not None]
        if red.partly:
            msg = (f"`{c.describe()}` is partly redundant: part of what it says already "
                   f"follows from {by}{more} (the rest still pins the model)")
        elif by:
            msg = (f"`{c.describe()}` is redundant: it follows from {by}{more}, so removing "
                   "it would free nothing")
        else:
            msg = (f"`{c.describe()}` is redundant: it only restates values already held (a "
                   "constructor's dimensions or `Fixed`), so removing it would free nothing")
        hint = ("harmless now, but if one of these values changes the model becomes "
                "over-constrained; drop one of them only if it repeats the same intent")
        if _made(c, makes):
            hint += (f", not `{c.describe()}`: it also makes geometry (its copies), which "
                     "dropping it would delete")
        sink.add(Diagnostic("W0401", msg, c.span, "warning", hint=hint, labels=labels),
                 calls=instance_calls(c.owner))
    return len(skipped)


def _echoes(reds: list, found) -> set:
    """The ids of the partly redundant constraints whose overlap is another finding's whole
    redundancy seen from the other side: ``At(holes[1].c.center, body.center)`` beside a
    redundant ``AlignCenterY(brush, body)`` (105c: two W0401s for one redundancy, each
    naming the other, and a model could not tell which to drop).  ``P`` is such an echo of
    a wholly redundant ``R`` that names it when, ``R`` dropped, nothing of ``P`` is implied
    any more: dropping both frees all that ``P`` pins beyond its shapes
    (``found.rank_lost([P, R]) >= P.beyond``); ``R``'s own warning says it all."""
    whole = {id(r.constraint): r for r in reds if not r.partly and r.by}
    out: set = set()
    for p in reds:
        if not p.partly:
            continue
        for b in p.by:
            r = whole.get(id(b))
            if r is not None and any(x is p.constraint for x in r.by):
                lost = found.rank_lost([p.constraint, r.constraint])
                if lost is not None and lost >= p.beyond:
                    out.add(id(p.constraint))
                    break
    return out


def _at(c):
    """Where constraint ``c`` is written (``(file, offset)``; None when it has no span)."""
    return None if c.span is None else (c.span.file, c.span.start)


def _instances(model) -> dict:
    """``(file, offset)`` -> how many written constraints that line makes (a loop's body, a
    list argument: several; one written line, one)."""
    out: dict = {}
    for c in model.constraints:
        if not c.implicit and c.kind != "internal" and c.span is not None:
            out[_at(c)] = out.get(_at(c), 0) + 1
    return out


def _report_instance(sink: DiagnosticSink, red, made: int, redundant: int) -> None:
    """W0401 for some of the constraints one written line makes (a loop's body run ``made``
    times, ``redundant`` of them implied by others): the line itself is not redundant,
    removing it would free what its other instances hold, so the warning says so and its
    hint never offers to drop it (the fresh models' run data/model_runs/issue105c, request
    16: `AlignCenterY(pockets.p[i], body)` in a loop of 5 beside `CenterInside(pockets,
    body)`; dropping the line left the pockets on a diagonal)."""
    c = red.constraint
    by = ", ".join(_source_of(b, c.owner) for b in red.by[:4])
    which = "one" if redundant == 1 else str(redundant)
    also = f" (with {by})" if by else ""
    msg = (f"{which} of the {made} constraints `{c.describe()}` makes "
           f"{'is' if redundant == 1 else 'are'} {'partly ' if red.partly else ''}redundant"
           f"{also}; the line is not: removing it would free what the other "
           f"{made - redundant} hold")
    hint = ("harmless: keep the line; where two statements say the same, narrow the other one"
            + (f" ({by})" if by else "") + " to what the line does not say"
            + (" (`AlignCenterX(...)` says the x of a `CenterInside(...)` alone, "
               "`AlignCenterY(...)` its y)" if "CenterInside(" in by else ""))
    labels = [Label(b.span, "overlaps with this", primary=False)
              for b in red.by[:4] if b.span is not None]
    sink.add(Diagnostic("W0401", msg, c.span, "warning", hint=hint, labels=labels),
             calls=instance_calls(c.owner))


def _source_of(b, owner) -> str:
    """A constraint ``b`` as W0401's "it follows from" says it: a written one as written (in
    backquotes); a shape's own relations ("RoundedRectangle shape", issue 105) as the shape
    a reader finds in the code, ``the shape of `picks[1].tri```, its path from ``owner`` (the
    redundant constraint's structure); a copy rule as made (``the pattern `picks`'s copy
    rule``)."""
    if b.kind != "internal":
        return f"`{b.describe()}`"
    text = b.describe()
    if text.startswith("the "):
        return text
    g = next((g for g in getattr(b.owner, "geometry", ()) if g.span == b.span and g.name), None)
    if g is None:
        return f"`{text}`"
    path = g.label
    if owner is not None and path.startswith(owner.path + "."):
        path = path[len(owner.path) + 1:]
    what = text[:-len(" shape")] if text.endswith(" shape") else text
    return (f"the shape of `{path}`" if text.endswith(" shape") else
            f"the {what[0].lower() + what[1:]} of `{path}`")


def _makers(model) -> set:
    """Where the statements that make geometry are (``(file, offset)``): a pattern's or a
    mirror's copies are tied to their original by implicit rows at the statement's span, so
    a written constraint sharing its span with such rows (CornerPattern's placement of its
    original) is a statement whose removal changes what is drawn (issue 84: W0401 offered to
    drop a CornerPattern, and three of its four holes went with it)."""
    return {(c.span.file, c.span.start) for c in model.constraints
            if c.implicit and c.kind == "internal" and c.span is not None}


def _made(c, makes: set) -> bool:
    """True when the statement of constraint ``c`` also makes geometry (:func:`_makers`)."""
    return c.span is not None and (c.span.file, c.span.start) in makes


MAX_SLIDING_UNKNOWNS = 20000    # larger models are not searched for sliding features


def report_sliding(sink: DiagnosticSink, result: SolveResult):
    """W0404 for each feature (a structure inside a part) that can move relative to its part
    along an axis some constraint reads (`Below(labels, bits, gap=4)` between two features
    nothing ties to the part in y), so a changed value moves it there and only its starting
    guess holds it (:func:`aidl_lang.solver.diagnosis.sliding.sliding`); a feature placed
    by its coordinates alone along its free axes (`AlignTop(groove, body)` and a written x,
    issue 111) is listed on the ok line, not warned.
    Freedom of a whole part (where it sits) is harmless and not reported.  Returns the
    :class:`~aidl_lang.solver.diagnosis.sliding.Sliding` found (None for a model too large)."""
    from .solver.diagnosis.sliding import sliding, where_now
    solver = result.solver
    if int(solver.free.sum()) > MAX_SLIDING_UNKNOWNS:
        return None
    sl = sliding(solver)
    warned = [(t, sl.read[id(t)]) for t, _ in sl.features
              if id(t) in sl.constrained and id(t) not in sl.bounded
              and not (t.span is not None and in_stdlib(t.span.file))]
    # placed by its coordinates alone, as AIDL allows, or free only within the room an
    # inequality leaves: not warned; nor a structure inside a standard-library template
    # (the template's own affair, not its user's, issue 61)
    for t, axes in warned:
        part = t.parent
        while part is not None and part.parent is not None and part.parent.kind != "assembly":
            part = part.parent
        name = t.name
        ex = (f"`AlignCenterX({name}, ...)`" if axes == "x" else
              f"`AlignCenterY({name}, ...)`" if axes == "y" else
              f"`{name}.bb.center == (..., ...)`")
        now = where_now(t, part, axes, solver.model)
        now = f"where it is now, {now}, or another relation (e.g. {ex})" if now else f"e.g. {ex}"
        sink.warning("W0404", f"{t.kind} `{t.path}` can slide along {axes} relative to "
                     f"`{part.path if part is not None else t.path}`: only its starting "
                     "position places it there", t.span, calls=instance_calls(t.parent),
                     hint=f"tie it to a shape of its part with a constraint in the parent "
                          f"({now}); `Fixed({name})` holds it only where the part is "
                          "fixed too; where the whole part sits may stay free, that is "
                          "harmless" + (
                              "; tie one feature, then check again: features tied to each "
                              "other (`VerticalDistance(a, b, ...)`) follow it, and a second "
                              "`.bb.center ==` would repeat them (W0401)"
                              if len(warned) > 1 else ""))
    return sl


def _report_groups(sink: DiagnosticSink, reds: list, found, makes: set) -> set:
    """One W0401 per group of constraints that each follow from the others (two `Fixed` of
    points of one held shape, `Coincident(a, b)` beside `a == b`): the group is reported
    once, and the hint says which to drop and which to keep.  The drop set is chosen so that
    nothing is lost (issue 84): a standard-library template's own constraints and statements
    that make geometry (a pattern's placement, :func:`_makers`) are kept, and the others are
    tried from the last written back, each dropped only when the kept ones still hold every
    unknown the group held (``found.rank_lost``, :class:`~aidl_lang.solver.diagnosis.redundancy.Search`;
    each member is implied by the others, not any two by any one).  With nothing safe to drop
    the redundancy is named without a drop list.  Returns the ids of the constraints so
    reported."""
    full = {id(r.constraint): r for r in reds if not r.partly and r.by}
    parent = {k: k for k in full}

    def find(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k
    for k, r in full.items():
        for b in r.by:
            if id(b) in full:
                parent[find(k)] = find(id(b))
    groups: dict = {}
    for k in full:
        groups.setdefault(find(k), []).append(full[k].constraint)
    done: set = set()

    def pos(c):
        return (c.span.line, c.span.col) if c.span is not None else (0, 0)
    for members in groups.values():
        if len(members) < 2:
            continue
        done.update(id(c) for c in members)
        # a standard-library template's own constraints are kept and never blamed: its user
        # cannot edit them (issue 61: `CenterInside(h, body)` beside the joint's `Fixed(self)`)
        members.sort(key=lambda c: (not _in_template(c), pos(c)))
        if all(_in_template(c) for c in members):
            continue                        # all the template's: its own affair
        drop: list = []
        for c in reversed(members):
            if _in_template(c) or _made(c, makes):
                continue
            if found.rank_lost(drop + [c]) == 0:
                drop.append(c)
        drop.sort(key=pos)
        keep = [c for c in members if c not in drop]
        at_owner = members[-1].owner
        names = ", ".join(f"`{c.describe()}`" for c in members[:-1]) + \
            f" and `{members[-1].describe()}`"
        others = [b for k in keep for b in full[id(k)].by if id(b) not in done]
        others = [b for i, b in enumerate(others) if b not in others[:i]]
        also = (" (with " + ", ".join(_source_of(b, at_owner) for b in others[:3]) + ")"
                if others else "")
        lines = ", ".join(f"`{c.describe()}` ({_line_of(c)})" for c in drop)
        held = [c for c in members if _in_template(c)]
        made = [c for c in keep if _made(c, makes)]
        at = drop[0] if drop else next(c for c in reversed(members) if not _in_template(c))
        labels = [Label(c.span, "the template holds it here" if _in_template(c) else
                        "keep this one" if c in keep else "says the same",
                        primary=False) for c in members if c is not at and c.span]
        kept = ", ".join(f"`{c.describe()}` ({_line_of(c)})" for c in keep)
        if not drop:
            msg_end = "none can go without losing what it makes"
            hint = (f"keep them all: {kept} make geometry; harmless now, but if one of these "
                    "values changes the model becomes over-constrained, so change them "
                    "together")
        elif held:
            msg_end = f"{len(drop)} of the {len(members)} can go"
            hint = (f"drop {lines}: the template holds it already ("
                    + ", ".join(f"`{c.describe()}`, {_line_of(c)}" for c in held[:2])
                    + "); place a template that holds itself by its arguments (`cx=`, `cy=`, "
                      "`rotation=`)")
        else:
            msg_end = f"{len(drop)} of the {len(members)} can go"
            why = (" (" + ", ".join(f"`{c.describe()}`" for c in made)
                   + " also make" + ("s" if len(made) == 1 else "") + " geometry: dropping it "
                   "would delete its copies)") if made else ""
            hint = (f"keep {kept} and drop {lines}" if len(keep) <= 3 else
                    f"drop {lines} and keep the other {len(keep)}") + \
                f": the model stays exactly as constrained{why}"
        sink.add(Diagnostic(
            "W0401", f"{names} say the same thing: each follows from the "
                     f"{'other' if len(members) == 2 else 'others'}{also}, so {msg_end}",
            at.span, "warning", hint=hint, labels=labels), calls=instance_calls(at.owner))
    return done


def _in_template(c) -> bool:
    """True for a constraint written in a standard-library template (its user cannot edit it)."""
    return c.span is not None and in_stdlib(c.span.file)


def _line_of(c) -> str:
    """``line 12`` (the program's), ``std/joints.aidl line 136`` (a template's), ``no line``."""
    if c.span is None:
        return "no line"
    return f"{shown_path(c.span.file)} line {c.span.line}" if in_stdlib(c.span.file) else \
        f"line {c.span.line}"


def _against_held(sink: DiagnosticSink, model: Model, c) -> bool:
    """E0401 for a constraint whose every parameter is a dimension its constructor holds
    (``Radius(c, 8)`` on ``Circle(..., radius=5)``): no solve can move it, so the message
    names the held values and the label points at the constructors.  False (nothing
    reported) when the constraint involves an unknown or a value held by no constructor."""
    from .registry import UNITS_LENGTH
    index: set[int] = set()                 # the parameters of its equations
    todo = [e.expr for e in c.equations]
    while todo:
        e = todo.pop()
        if isinstance(e, Lin):
            index.update(e.terms)
        elif isinstance(e, Nl):
            todo += [a for a in e.args if isinstance(a, (Lin, Nl))]
    if not index or any(model.free[i] for i in index):
        return False
    held = {}
    for st in model.structures:
        for g in st.geometry:
            for name, sc in g.scalars.items():
                if sc.index in index and g.span is not None:
                    held[sc.index] = (g, name, sc)
    if set(held) != index:
        return False
    unit = model.file_units.get(c.span.file, "mm") if c.span is not None else "mm"

    def value(sc) -> str:
        v = model.x[sc.index]
        if sc.dim == "length":
            return f"{v / UNITS_LENGTH[unit]:.6g} {unit}"
        if sc.dim == "angle":
            return f"{math.degrees(v):.6g} deg"
        return f"{v:.6g}"
    said = ", ".join(f"`{g.owner.path}.{g.name or g.kind}.{name}` = {value(sc)}"
                     for g, name, sc in held.values())
    labels = [Label(g.span, f"`{name}` is held at {value(sc)} by this constructor",
                    primary=False) for g, name, sc in held.values()]
    sink.add(Diagnostic(
        "E0401",
        f"`{c.describe()}` cannot hold: it involves only sizes held by "
        f"{'their constructors' if len(held) > 1 else 'a constructor'} ({said}), which no "
        "solve changes",
        c.span, "error",
        hint="a size given to a constructor is held, not solved: give the constructor the "
             f"size you want and drop `{c.describe()}`, or change it to agree",
        labels=labels), calls=instance_calls(c.owner))
    return True


def report_failure(sink: DiagnosticSink, result: SolveResult, path: str | None = None) -> None:
    """E0401 for each conflict set found (else for the unsatisfied constraints); E0402 when
    the iteration budget ran out.  The error sits on the last-written user constraint of a
    set, one of the program ``path``'s own when it has any (not a line of an imported
    template the user did not write)."""
    if result.out_of_time:
        sink.add(Diagnostic(
            "E0304", "the program ran out of its evaluation budget while solving: more than "
            "its CPU time", None, "error",
            hint="simplify the model, or raise the budget with `--budget 2` (or more)"))
    elif result.budget_exceeded:
        sink.add(Diagnostic(
            "E0402", f"the solver gave up after {result.iterations} Newton steps (its budget)",
            None, "error",
            hint="the constraints are probably far from satisfiable from the starting "
                 "positions: give starting positions closer to the intended shape, or check "
                 "the constraints named by other errors"))
    shown = 0
    for k in result.conflicts[:3]:
        items = k.items
        # primary: the last-written user constraint of the set
        user = [(c, r) for c, r in items if not c.implicit and c.span is not None] or items
        own = [(c, r) for c, r in user if c.span is not None and c.span.file == path]
        first, r0 = (own or user)[-1]
        # one line a statement: a template's loop makes its copies with one span and text
        # (run k's note holder listed two tabs' `Fixed(tab.center)` twice)
        seen: dict = {}
        for c, r in items:
            inside = library_instance(c)
            # a standard-library template's own constraints and held shapes: one entry, the
            # instance as its template draws it (run dn: `Fixed(tab.center)` and `Rectangle
            # shape` of std/joints.aidl listed, and a hint to edit a `width=` no call of the
            # program has)
            key = (inside.span, f"`{inside.path}` as its template `{inside.template}` draws "
                   "it (its sizes)") if inside is not None else (c.span, member_words(c))
            n, rr, cc = seen.get(key, (0, 0.0, c))
            seen[key] = (n + 1 if inside is None else 1, max(rr, r), cc)
        labels = [Label(span, f"conflicts with this: {where}"
                        + (f" ({n} of them)" if n > 1 else "")
                        + (f", residual {r:.3g}" if r > 1e-6 else ""), primary=False)
                  for (span, where), (n, r, c) in seen.items()
                  if c is not first and span is not None and span != first.span]
        worst = max(r for _, r in items)
        names = "; ".join(where + (f" ({n} of them)" if n > 1 else "")
                          for (_, where), (n, _, _) in seen.items())
        sink.add(Diagnostic(
            "E0401",
            f"these {len(items)} constraints conflict in `{first.owner.path}`: they cannot "
            f"all hold (largest residual {worst:.3g})",
            first.span, "error",
            hint=(f"the conflicting set is: {names}. Change one of them so that they agree "
                  "(a different value, or a constraint that says what you mean); keep the "
                  "others" + rigid_note(first.owner) + literal_note(items)
                  + sizes_note([(c, r) for c, r in items if library_instance(c) is None])),
            labels=labels), calls=instance_calls(first.owner))
        shown += 1
    if shown:
        return
    items = result.unsatisfied
    if not items:
        if not result.budget_exceeded:
            # never "ok" with a solve that did not converge
            sink.add(Diagnostic("E0401", "the solver did not converge, but no single constraint "
                                "is off by more than the tolerance", None, "error",
                                hint="the model is probably badly scaled (sizes far apart); "
                                     "check the dimensions"))
        return
    explicit = [(c, r) for c, r in items if not c.implicit] or items
    if sum([_against_held(sink, result.solver.model, c) for c, _ in explicit[:3]]):
        return
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
              "for the same thing, and that the starting positions are near the intended "
              "shape"),
        labels=labels), calls=instance_calls(first.owner))
