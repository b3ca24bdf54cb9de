"""One live-preview session: a watched ``.aidl`` file compiled in a warm process.

No HTTP here (that is :mod:`.app`); a :class:`Session` turns the file and the customizer's values
into a *view*: a JSON-ready dict with the SVG of the last good picture, the diagnostics of the
last compile, the params (for the customizer) and the degrees-of-freedom summary.

Two ways in:

* :meth:`Session.load` re-reads the file (after a save): parse, check, interpret, solve, render.
  A broken edit keeps the last good picture and reports its errors beside it.
* :meth:`Session.set_params` applies customizer values, as ``--set NAME=VALUE`` texts.  The
  checked AST is reused (no re-parse); the program is interpreted again with the new values
  (params feed starting values, held dimensions and constants, so only the interpreter knows
  what a param moves), and when the new model has the same rows as the warm solver's
  (compared expression by expression; held values and starting positions may differ, constants
  baked into rows may not), the warm :class:`~aidl_lang.solver.Solver` is reused: every
  changed parameter is written with :meth:`~aidl_lang.solver.Solver.set_value` and Newton is
  re-run on the already-compiled tapes (paper, appendix "Solver Details"; the solver's
  *edit a held value, re-solve* path).  The start point is the new model's own, so the picture
  is exactly what ``aidl render FILE --set ...`` draws.  Otherwise the model is solved cold.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

from .. import ast as A
from ..base.diagnostics import Diagnostic, DiagnosticSink
from ..interp import Interpreter
from ..base.limits import Deadline
from ..output import build, to_svg
from ..parser import parse
from ..output.checks import check_drawing, check_topology, topology
from ..pipeline import after_solve, report_failure
from ..solver import Solver, run
from ..solver.core.holds import reuse
from ..library.sources import SourceRefused, read_program
from ..typecheck import check
from .params import Param, _nice, _param, default_span  # noqa: F401 - the customizer's params
from .wording import for_forms



@dataclass
class Result:
    """One compile: diagnostics, and when it succeeded the SVG and the solver."""

    sink: DiagnosticSink
    ok: bool = False
    svg: str | None = None
    model: object = None
    solver: Solver | None = None
    fctx: object = None
    warm: bool = False
    drawing: object = None
    output: object = None       # the exact Output the SVG was written from
    title: str = ""
    timings: dict = field(default_factory=dict)


class Session:
    """The state of ``aidl serve FILE``.  Not thread-safe: the server calls it from one worker
    at a time."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self.name = str(path)
        self.source = ""
        self.sources: dict[str, str] = {}
        self.program: A.Program | None = None
        self.values: dict[str, str] = {}          # customizer values, as --set texts
        self.params: list[Param] = []
        self.defaults: dict[str, object] = {}     # the program's own param values (display units)
        self.svg: str | None = None               # the last good picture
        self.svg_values: dict[str, str] = {}      # the values it was drawn with
        self.svg_source: str | None = None        # and the program text it was drawn from
        self.diagnostics: list[dict] = []
        self.ok = False
        self.dof: list[dict] = []
        self.solver: Solver | None = None         # warm: tapes compiled for the last model
        self._row_keys: list[str] | None = None
        self.version = 0                          # bumps on every load / set_params
        self.shown: tuple | None = None           # (version, Output) of the svg
        self._dof_pending: Solver | None = None
        self._checks_pending: tuple | None = None  # (version, drawing, sink) of set_params' picture
        self._base: object = None                 # the defaults' Drawing, then its topology
        self.last: dict = {}                      # timings and warm/cold of the last compile
        from ..base.limits import DEFAULT_BUDGET
        self.budget = DEFAULT_BUDGET              # each compile's evaluation budget

    # ------------------------------------------------------------------ public
    def load(self, source: str | None = None, assumed: dict | None = None) -> dict:
        """Re-read and recompile the file (or compile ``source``, the program's text given by
        the caller, ``aidl studio``'s code pane: the file is then only its name and where its
        imports and drawings are resolved from); keep customizer values whose param still
        exists and whose default did not change (:func:`keep_values`).  ``assumed``: ``{name:
        default}`` (display units, as the params' ``default``) the values were chosen against
        (the studio's page says it with each request); None: the defaults of this session's
        last load.  The params' ``default`` is always the program's own value, from a compile
        without customizer values, whatever values this session held before.  Never raises: an
        internal error (a bug in aidl) becomes an ``E0900`` diagnostic beside the last good
        picture, is logged, and the next save is compiled as usual."""
        t0 = time.perf_counter()
        try:
            return self._load(t0, source, assumed)
        except Exception as e:          # noqa: BLE001 - a bug must not stop the live reload
            self.program = None
            self.solver = self._row_keys = None
            self._dof_pending = self._checks_pending = None
            return self._publish(Result(self._failed(e, "compiling the file")), t0)

    def _load(self, t0: float, source: str | None = None, assumed: dict | None = None) -> dict:
        sink = DiagnosticSink()
        try:
            # as `aidl check` reads it: a regular file only (a FIFO swapped in is refused, not
            # waited on with the lock held), non-blocking, at most 1000000 bytes, UTF-8
            src = read_program(self.path) if source is None else source
        except SourceRefused as e:
            sink.add(e.diagnostic(self.name))
            self.program = None
            self.solver = self._row_keys = None
            return self._publish(Result(sink), t0)
        self.source = src
        program = parse(src, self.name, sink)
        if not sink.has_errors:
            check(program, sink)
        self.sources = dict(sink.sources)
        if sink.has_errors:
            self.program = None
            return self._publish(Result(sink), t0)
        self.program = program
        self.solver = self._row_keys = None             # a new program: nothing warm to reuse
        old_defaults = self.defaults if assumed is None else assumed
        base = self._compile({})
        self._base = base.drawing if base.ok else None    # W0510's baseline: the defaults
        # the program's own values are its defaults (never values this session held before)
        params = self._params(base.fctx, {}, defaults={}) if base.fctx is not None else []
        self.defaults = {p.name: p.default for p in params}
        # kept: a value whose param is still there with the same default (or is new: the
        # first load keeps the values a caller set before it)
        self.values = keep_values(self.values, self.defaults, old_defaults)
        res = base
        if self.values and base.ok:
            res = self._compile(self.values)
            if not res.ok:                              # the kept values no longer fit: drop them
                self.values, res = {}, base
            elif res.drawing is not None:
                self._topology_checks(res.drawing, res.sink)
        self.params = self._params(res.fctx, self.values) if res.fctx is not None else params
        self._dof_pending = res.solver if res.ok else None
        return self._publish(res, t0)

    def update_dof(self) -> dict | None:
        """Compute the degrees-of-freedom summary of the last load (an SVD per structure, so
        it runs after the picture is out); the view, or None when there is nothing new."""
        solver, self._dof_pending = self._dof_pending, None
        if solver is None:
            return None
        self._dof(solver)
        return self.view()

    def set_params(self, values: dict[str, str]) -> dict:
        """Apply customizer values (``{name: "172.5mm"}``, the ``--set`` syntax).  Unknown
        names are reported (E0113); a failed compile keeps the last good picture."""
        t0 = time.perf_counter()
        if self.program is None:
            return self.view()
        self.values = {str(k): str(v) for k, v in values.items()}
        try:
            res = self._compile(self.values, shape_checks=False)
        except Exception as e:          # noqa: BLE001 - keep the last picture, say so
            self.solver = self._row_keys = None
            self._checks_pending = None
            return self._publish(Result(self._failed(e, "applying the customizer values")), t0)
        if res.fctx is not None:
            self.params = self._params(res.fctx, self.values)
        view = self._publish(res, t0)
        self._checks_pending = ((self.version, res.drawing, res.sink) if res.drawing is not None
                                else None)
        return view

    def update_checks(self) -> dict | None:
        """The geometry checks (W0402, W0501-W0510: warnings) of the picture the last
        :meth:`set_params` published, run after that picture was sent, so a slider move shows
        its picture without waiting for them: the view with their diagnostics added (same
        version), or ``None`` when they found nothing or a newer compile came first."""
        pending, self._checks_pending = self._checks_pending, None
        if pending is None or pending[0] != self.version:
            return None
        sink = DiagnosticSink()
        sink.sources.update(self.sources)
        sink.follow(pending[2])         # what a template made: at its call in the program
        try:
            check_drawing(pending[1], sink)
            self._topology_checks(pending[1], sink)
        except Exception as e:          # noqa: BLE001 - warnings only: log, keep the picture
            sink = self._failed(e, "checking the shape")
        if not sink.items:
            return None
        self.diagnostics = self.diagnostics + [_diag_json(d, self.sources) for d in sink.items]
        return self.view()

    def _topology_checks(self, drawing, sink: DiagnosticSink) -> None:
        """W0510 for ``drawing`` (compiled with the customizer's values) against the defaults'
        drawing of the last load (its topology taken once, then kept)."""
        if self._base is None or not self.values:
            return
        if not isinstance(self._base, dict):
            self._base = topology(self._base)
        check_topology(self._base, drawing, self.values, sink)

    def drawing(self, values: dict[str, str]):
        """A fresh, cold compile with ``values`` for downloads: ``(drawing, title)`` (a
        :class:`~aidl_lang.output.Drawing`), or ``(None, diagnostics)`` when it fails."""
        if self.program is None:
            return None, self.diagnostics
        from ..pipeline import run_deep
        try:        # on the deep-stack thread, as `aidl check --set`: a deep value compiles
            res = run_deep(lambda: self._compile(values, keep_warm=False, drawing=True))
        except Exception as e:          # noqa: BLE001 - a 422 with the diagnostic, not a 500
            res = Result(self._failed(e, "compiling a download"))
        if not res.ok:
            return None, [_diag_json(d, self.sources) for d in res.sink.items]
        return res.drawing, res.title

    def param_names(self) -> set[str] | None:
        """The names of the program's top-level ``param`` declarations (what a customizer
        message may set), or None when no program is loaded."""
        if self.program is None:
            return None
        return {st.name for st in self.program.stmts if isinstance(st, A.ParamDecl)}

    def view(self) -> dict:
        """The page's state as JSON-ready data."""
        return {"file": self.name, "version": self.version, "ok": self.ok, "svg": self.svg,
                "values": self.svg_values, "diagnostics": self.diagnostics,
                "params": [p.to_json() for p in self.params], "dof": self.dof,
                "source": self.source, "timing": self.last}

    # ------------------------------------------------------------------ compile
    def _compile(self, values: dict[str, str], keep_warm: bool = True,
                 drawing: bool = False, shape_checks: bool = True) -> Result:
        t = {}
        t0 = time.perf_counter()
        sink = DiagnosticSink()
        sink.sources.update(self.sources)
        interp = Interpreter(sink, values, self.budget)
        model = interp.run(self.program)
        res = Result(sink, fctx=interp.file)
        t["interpret_ms"] = _ms(t0)
        if sink.has_errors:
            res.timings = t
            return res
        t1 = time.perf_counter()
        solver, warm = self._solver_for(model) if keep_warm else (Solver(model), False)
        solver.deadline = interp.deadline                # the compile's one time budget
        solved = run(solver)
        if solved.solver is not None and solved.solver is not solver:
            # solved again with a drawing's hold released (solver.run): that solver is the one
            solver = solved.solver
            if keep_warm:
                self.solver, self._row_keys = solver, None
        if solver.model is not model:                   # warm: the solver writes its own model
            model.x = list(solver.model.x)
        t["solve_ms"] = _ms(t1)
        if not solved.converged:
            report_failure(sink, solved)
            if warm:                                    # do not keep a solver that failed
                self.solver = self._row_keys = None
            res.timings = t
            return res
        res.solver, res.warm, res.model = solver, warm, model
        t2 = time.perf_counter()
        d = after_solve(sink, model, shape_checks=shape_checks,   # as `aidl check` does
                        deadline=Deadline(interp.deadline, interp.budget))
        t["render_ms"] = _ms(t2)
        if d is None:
            res.timings = t
            return res
        res.drawing, res.title = d, model.root.name
        if drawing:
            res.ok = not sink.has_errors
            return res
        t3 = time.perf_counter()
        res.output = build(d, model.root.name)      # once: the SVG's, and the studio's 3D
        res.svg = to_svg(res.output, title=model.root.name)
        t["svg_ms"] = _ms(t3)
        res.ok = not sink.has_errors
        res.timings = t
        return res

    def _solver_for(self, model) -> tuple[Solver, bool]:
        """The warm solver with the new model's values written in, when its rows are the new
        model's rows; else a new solver (which becomes the warm one)."""
        reused, self._row_keys = reuse(self.solver, model, self._row_keys)
        if reused:
            return self.solver, True
        s = Solver(model)
        self.solver, self._row_keys = s, None
        return s, False

    def _dof(self, solver: Solver | None) -> None:
        self.dof = []
        if solver is None:
            return
        from ..base.limits import DEFAULT_BUDGET, now
        from ..solver.diagnosis.freedom import degrees_of_freedom
        try:            # bounded as a compile is (issue 48): a structure past it is not counted
            end = now() + DEFAULT_BUDGET.backstop
            self.dof = [{"structure": d.structure.path, "unknowns": d.unknowns,
                         "dof": d.dof if d.rank >= 0 else None, "floating": d.floating[:12]}
                        for d in degrees_of_freedom(solver, deadline=end)]
        except Exception:          # the summary is an extra; never lose the picture over it
            self.dof = []

    def _publish(self, res: Result, t0: float) -> dict:
        self.version += 1
        self.diagnostics = [_diag_json(d, self.sources) for d in res.sink.items]
        self.ok = res.ok
        if res.ok:
            self.svg = res.svg
            self.svg_values = dict(self.values)
            self.svg_source = self.source
            # the picture's exact Output (aidl studio's 3D view is made from it)
            self.shown = (self.version, res.output)
        self.last = dict(res.timings, total_ms=_ms(t0), warm=res.warm)
        return self.view()

    def _failed(self, e: BaseException, stage: str) -> DiagnosticSink:
        """The sink of a compile that raised ``e``: out of memory (a ``MemoryError``
        anywhere: NumPy, Manifold, the checks) is the program's located ``E0304``; anything
        else is a bug, ``E0900`` (:func:`_internal`)."""
        from ..base.limits import is_out_of_memory
        from ..pipeline import out_of_memory_sink
        if is_out_of_memory(e):
            return out_of_memory_sink(self.name, self.source or None)
        if isinstance(e, RecursionError):
            # a program nested past what the checker walks (a 40,000-term sum): the program's
            # located E0302, as `aidl check` and every download say it (issue 113: "internal
            # error ... RecursionError" beside the DXF button's "nested too deeply")
            from ..pipeline import _deep_span
            sink = DiagnosticSink()
            src = self.source or ""
            sink.sources.setdefault(self.name, src)
            sink.error("E0302", "the program is nested too deeply to compile",
                       _deep_span(e, self.name, src),
                       hint="split long expressions into named constants")
            return sink
        return _internal(e, stage)

    # ------------------------------------------------------------------ params
    def _params(self, fctx, values: dict[str, str], defaults: dict | None = None) -> list[Param]:
        """The customizer's params of the compile whose interpreter file is ``fctx``, each
        with the program's own value as its ``default`` (``defaults``, else those of the last
        load: :attr:`defaults`), never a value of ``values``."""
        decls = {st.name: st for st in self.program.stmts if isinstance(st, A.ParamDecl)}
        ranges = getattr(fctx, "param_ranges", {})
        defaults = self.defaults if defaults is None else defaults
        out = []
        for name, st in decls.items():
            v = fctx.params.get(name)
            p = _param(name, v, ranges.get(name), st.span.line if st.span else 0,
                       defaults.get(name))
            if p is not None:
                out.append(p)
        return out


def same_default(a, b) -> bool:
    """Whether two params' defaults (display units: numbers, booleans, texts) are the same
    value: numbers to 1e-9 relative, a boolean only equal to a boolean."""
    if isinstance(a, bool) or isinstance(b, bool):
        return isinstance(a, bool) and isinstance(b, bool) and a == b
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))
    return a == b


def keep_values(values: dict[str, str], defaults: dict, assumed: dict | None) -> dict[str, str]:
    """The customizer ``values`` that still apply to a program whose params' own values are
    ``defaults``: a value whose param is still there, with the default it was chosen against
    (``assumed``: ``{name: default}``; a name it does not hold: any default).  A value for a
    param the program no longer has, or whose default the program changed, is dropped (the
    slider goes to the program's new value)."""
    assumed = assumed or {}
    return {k: v for k, v in values.items()
            if k in defaults and (k not in assumed or same_default(assumed[k], defaults[k]))}


def _internal(e: BaseException, stage: str) -> DiagnosticSink:
    """A sink holding one ``E0900`` for an exception raised while ``stage`` (a bug in aidl);
    the traceback goes to the server's log (stderr)."""
    import sys
    import traceback
    print(f"aidl serve: internal error while {stage}:\n{traceback.format_exc()}",
          file=sys.stderr, flush=True)
    sink = DiagnosticSink()
    sink.add(Diagnostic("E0900", f"internal error while {stage}: {type(e).__name__}: {e}",
                        None, hint="this is a bug in aidl, not in your program; please report "
                        "it with the file. The preview keeps watching: the next save is "
                        "compiled again"))
    return sink


def _diag_json(d: Diagnostic, sources: dict) -> dict:
    """``d`` as the page shows it, a param value named as the form's field, not as ``--set``
    (:func:`.wording.for_forms`)."""
    d.reword(for_forms)
    j = d.to_json(sources)
    return {k: j[k] for k in ("code", "severity", "message", "span", "hint", "rendered")}


def _ms(t0: float) -> float:
    return round((time.perf_counter() - t0) * 1000, 2)
