"""``aidl check --sweep``: a design checked across its params' ranges.

:func:`sweep` compiles the program at its written values, then with each numeric param at
the low end, the middle and the high end of its range (the others at their values), each
count at its values (all of a short range, else its ends) against each other param's ends,
then at a small Latin hypercube of combinations (seeded: the same points on every run).  A
param's range is its ``min=``/``max=``, else the span the studio's slider gives it
(:func:`aidl_lang.serve.params.default_span`); a plain number is a real unless it counts
(a whole ``step=``, used in ``range()``, or refused half a step past its value:
:mod:`aidl_lang.params.sweep_plan`).  A point is a *finding* when the design stops compiling
there (an error; a range that other values leave empty, E0124, included), a part changes
its topology (a solid falls into pieces, a hole leaves its solid or breaks through its
outline, two holes merge: what W0510 compares), or a warning appears that the written
values do not have.  Each finding is bisected between the written values (clean) and the
failing point to :data:`TOLERANCE` of the range (on a grid of 1-2-5 steps under half
that), and reported as a ``W0110`` located at the ``param`` line(s) with the largest clean
sub-range found and a fix that writes it into the program (docs/language.md, "Sweeping the
ranges").

One answer on any machine: the points are planned before the sweep starts (ends, middles,
the Latin hypercube, then each finding's bisection in order) and share one budget of work
(:data:`~aidl_lang.params.sweep_plan.WORK` units: each compile's interpreter steps, objects and
unknowns, :func:`~aidl_lang.params.sweep_plan.work`), the same on a quiet machine and a busy one;
what it leaves is said as not judged ("`pitch` below 4 mm: not judged, out of budget"),
never as bisected.  The compile's CPU seconds are only the outer guard, shared by every
point (none gets a budget of its own).

Cost: the program is parsed and checked once; each point is interpreted again with its
values, and when the model has the same rows as the last one the compiled solver is
reused (:func:`aidl_lang.solver.core.holds.reuse`: :meth:`~aidl_lang.solver.Solver.set_value`, as the
sliders of ``aidl serve`` do).
"""
from __future__ import annotations

import threading
from contextlib import contextmanager
from dataclasses import dataclass, field

from ..base.diagnostics import Diagnostic, DiagnosticSink, Label
from ..base.limits import DEFAULT_BUDGET, Budget, now
from .sweep_plan import WORK, display, value_text, work

# each ranged param's points, the Latin hypercube's size, and the bisection's stopping width
# (a fraction of the param's declared range)
LHS_POINTS = 8
TOLERANCE = 0.01
SEED = 0
# warnings that compare a compile with another one or say a check was cut short, and the
# note that a part outgrows the default sheet (a bed's size, W0534: a wall shelf at its
# declared 1,200 mm is no defect): not a property of the design at one value
NOT_COMPARED = {"W0510", "W0521", "W0534"}
# allocations between two passes of the cyclic collector's young generation during a sweep
# (:func:`_collector_spaced`)
GC_YOUNG = 50_000
# the top-level statements a point's ranges are found from (:meth:`_Sweep._clamped`)
DECLS = ("UnitsDecl", "Import", "ParamDecl", "Def", "ThicknessDecl")
# times a point's dependent params are moved into their ranges (the studio's MAX_CLAMPS)
CLAMPS = 3


@dataclass
class Finding:
    """One value (or combination) of the params where the design breaks.

    ``values``: ``{param: number}`` in display units (mm, deg, plain); ``code`` and
    ``message``: what happens there (the error or warning, or ``W0510`` for a part whose
    topology changes); ``clean``: ``{param: (lo, hi)}``, the largest clean sub-range found by
    bisection (display units); ``diagnostic``: the ``W0110`` located at the param line(s);
    ``problem``: the message of ``code`` alone; ``first``: ``(values, code, message)`` of the
    first failing point bisection found past the clean range when it fails otherwise than
    at ``values`` (None: the same way); ``declared``: every param moved has a declared range
    (else the sliders' default span was swept); ``cut``: the budget ran out before the
    bisection reached its tolerance (between ``clean`` and ``values``: not judged);
    ``bounds``: for a combination, ``{param: (clean, failing, side)}``: the param bisected
    alone, every other param at its value in ``values``, ``clean`` the value judged clean
    nearest the failing side (``below``/``above`` it the design fails), ``failing`` the
    value judged failing nearest it; a param left out has no bound judged on both sides
    (the budget, or a point the sweep judged contradicting it: issue 110)."""

    values: dict
    code: str
    message: str
    clean: dict
    diagnostic: Diagnostic
    problem: str = ""
    first: tuple | None = None
    declared: bool = True
    cut: bool = False
    bounds: dict = field(default_factory=dict)


@dataclass
class SweepReport:
    """What :func:`sweep` found.  ``ok``: the design compiles at its written values (else
    ``errors`` holds why and nothing was swept); ``swept``: the swept params' names;
    ``unranged``: those of them without a declared ``min=`` and ``max=`` (swept across the
    span the studio's sliders give them); ``fixed``: params whose ``min = max`` (one value:
    not swept, ``name = value``); ``points``: how many points were judged (bisection steps
    and count probes included); ``skipped``: planned points not judged once the budget was
    spent; ``warm``: points solved on the reused solver; ``seconds``: CPU seconds of the
    sweep (the written values' compile included); ``work``: the work units the points
    spent (:func:`~aidl_lang.params.sweep_plan.work`); ``judged``: ``{param: points}``, the points
    judged with that param off its written value (a param with none is not judged, never
    clean); ``bisections``: the bisection steps judged; ``tolerance``: the bisection's stopping
    width (a fraction of each range); ``ranges``: ``{param: (lo, hi)}`` swept (display
    units); ``findings``: :class:`Finding` list (empty: clean across the ranges);
    ``seen``: every point judged, ``{tuple(sorted((param, value), ...)): (code, ...)}`` (its
    problems' codes; empty: clean);
    ``lifted``: for a program without a numeric ``param``, ``{name: Literal}`` of the numbers
    swept as params (:mod:`aidl_lang.params.sweep_literals`; :func:`~aidl_lang.params.sweep_literals.written`
    writes a finding's values into the file)."""

    ok: bool = True
    swept: list = field(default_factory=list)
    unranged: list = field(default_factory=list)
    fixed: list = field(default_factory=list)
    points: int = 0
    skipped: int = 0
    warm: int = 0
    seconds: float = 0.0
    tolerance: float = TOLERANCE
    work: int = 0
    judged: dict = field(default_factory=dict)
    bisections: int = 0
    ranges: dict = field(default_factory=dict)
    units: dict = field(default_factory=dict)
    lifted: dict = field(default_factory=dict)
    findings: list = field(default_factory=list)
    errors: list = field(default_factory=list)
    seen: dict = field(default_factory=dict)    # (sorted (param, value) pairs) -> codes
    point_work: int = 0          # the least work a point was seen to need (the written
    short: int = 0               # values' compile first), and the work left when the next
    #                              point was not started for want of it (0: never)

    def clean_ranges(self) -> dict:
        """``{param: (lo, hi)}`` (display units): each swept param's range, narrowed to the
        clean sub-range of every finding that moved it alone (a combination is a finding of
        its own, :meth:`combinations`, not a narrowing of each of its params)."""
        out = {}
        for f in self.findings:
            if len(f.clean) != 1:
                continue
            for name, (lo, hi) in f.clean.items():
                a, b = out.get(name, (lo, hi))
                out[name] = (max(a, lo), min(b, hi))
        return out

    @property
    def diagnostics(self) -> list[Diagnostic]:
        """The findings' ``W0110`` diagnostics."""
        return [f.diagnostic for f in self.findings]

    def combinations(self) -> list[str]:
        """Each combination finding in words, each bound one the sweep judged on both sides
        (:attr:`Finding.bounds`: the param bisected alone, the others held at the finding's
        values): ``` `w` below 35.2 mm with `n` = 10; `n` above 5 with `w` = 20 mm: W0504```.
        A param with no such bound is said at its value (``no bound judged for `n```).
        Before (issue 110) the bound was where the line from the written values to the
        failing point crossed clean (``w below 32.2 mm with n above 8``), which a failing
        point off that line contradicted (w = 34 mm with n = 10)."""
        out = []
        for f in self.findings:
            if len(f.clean) < 2:
                continue
            names = list(f.clean)

            def shown(n, x):
                unit = self.units.get(n, "")
                return _text(x, unit, not unit and float(x).is_integer())
            parts = []
            for n, (clean, _, side) in f.bounds.items():
                held = " and ".join(f"`{m}` = {shown(m, f.values[m])}" for m in names if m != n)
                parts.append(f"`{n}` {side} {shown(n, clean)} with {held}")
            rest = [n for n in names if n not in f.bounds]
            if not parts:
                parts.append(" with ".join(f"`{n}` = {shown(n, f.values[n])}" for n in names)
                             + " (no bound judged on both sides)")
            elif rest:
                parts.append("no bound judged for " + ", ".join(f"`{n}`" for n in rest))
            out.append(f"{'; '.join(parts)}: {f.code}")
        return out

    def unjudged(self) -> list[str]:
        """The swept params with no point judged off their written values (the budget was
        spent before any): not judged, never clean."""
        return [n for n in self.swept if not self.judged.get(n)]

    def not_judged(self) -> list[str]:
        """``pitch below 4 mm: not judged, out of budget`` for each finding whose bisection
        the budget cut (one param moved), the values between its clean end and the failing
        value; the combinations' as ``with a=.., b=..``; and ``cols (swept 1-200): no value
        but the written one judged, out of budget`` for each param no point judged."""
        out = []
        for n in self.unjudged():
            lo, hi = self.ranges.get(n, (None, None))
            unit = self.units.get(n, "")
            span = (f" (swept {_span(lo, hi, unit, unit == '' and all(float(x).is_integer() for x in (lo, hi)))})"
                    if lo is not None else "")
            out.append(f"`{n}`{span}: no value but the written one judged, out of budget "
                       "(--budget K gives K times more)")
        for f in self.findings:
            if not f.cut:
                continue
            if len(f.clean) == 1:
                (n, (lo, hi)), = f.clean.items()
                v = f.values[n]
                unit = self.units.get(n, "")
                side, end = ("below", lo) if v < lo else ("above", hi)
                out.append(f"`{n}` {side} {_text(end, unit, unit == '' and float(end).is_integer())}: "
                           f"not judged, out of budget (fails at {_text(v, unit, unit == '' and float(v).is_integer())})")
            else:
                out.append("the combination " + ", ".join(f"{n}={x:g}" for n, x in f.values.items())
                           + ": between it and the written values not judged, out of budget")
        return out

    def text(self) -> str:
        """The summary line(s) ``aidl check --sweep`` prints after the diagnostics."""
        if not self.ok:
            return "sweep: not run: the program does not compile at its written values"
        if not self.swept:
            out = ("sweep: the program declares no numeric `param` to sweep (declare the values a "
                   "maker may change: `param NAME = VALUE, min = LO, max = HI`)")
        else:
            out = ""
            if self.lifted:
                out = ("sweep: no numeric `param`: the numbers that size the parts are swept as "
                       f"params ({len(self.lifted)} lifted in a copy, the file untouched)\n")
            n = len(self.findings)
            its = "its range" if len(self.swept) == 1 else "their ranges"
            out += (f"sweep: {', '.join(self.swept)} across {its}: {self.points} points, "
                   + (f"{n} finding{'s' if n != 1 else ''} (W0110)" if n else
                      "no finding in the points judged" if self.skipped or self.unjudged()
                      else "clean")
                   + (f"; bounds bisected to {100 * self.tolerance:.3g}% of each range"
                      if self.bisections else ""))
            if self.skipped:
                out += (f"; {self.skipped} planned point{'s' if self.skipped != 1 else ''} "
                        "not judged, out of budget (--budget K gives K times more)")
            if self.short:
                out += (f"\nsweep: one point needs about {self.point_work:,} work units (a "
                        f"compile of the design); {self.short:,} were left, so no more was "
                        "started (--budget K gives K times more)")
        clean = self.clean_ranges()
        for name in self.unranged:
            if name not in self.ranges:
                continue
            if name in self.unjudged():
                continue                # said by not_judged(): never "clean"
            lo, hi = self.ranges[name]
            u = self.units.get(name, "")
            a, b = clean.get(name, (lo, hi))
            whole = u == "" and all(float(x).is_integer() for x in (lo, hi, a, b))
            what = (self.lifted[name].where + ", no param" if name in self.lifted
                    else "no declared range")
            out += (f"\nsweep: `{name}` ({what}, swept {_span(lo, hi, u, whole)}): "
                    f"clean {_span(a, b, u, whole)}")
        for line in self.combinations():
            out += f"\nsweep: combination: {line}"
        left = [n for n in self.unranged if n not in self.ranges]
        if left:
            out += f"\nsweep: not swept (no declared range): {', '.join(left)}"
        for line in self.not_judged():
            out += f"\nsweep: {line}"
        if self.fixed:
            out += ("\nsweep: not swept (`min` = `max`, one value): " + ", ".join(self.fixed))
        return out

    def to_json(self) -> dict:
        return {"ok": self.ok, "swept": self.swept, "unranged": self.unranged,
                "fixed": self.fixed, "points": self.points, "skipped": self.skipped,
                "point_work": self.point_work, "short": self.short,
                "warm": self.warm, "tolerance": self.tolerance,
                "ranges": {k: list(v) for k, v in self.ranges.items()},
                "not_judged": self.not_judged(), "combinations": self.combinations(),
                "work": self.work, "judged": dict(self.judged), "bisections": self.bisections,
                "lifted": {n: {"where": x.where, "value": x.text,
                               "lines": sorted({sp.line for sp in x.spans})}
                           for n, x in self.lifted.items()},
                "findings": [{"values": f.values, "code": f.code, "message": f.message,
                              "clean": {k: list(v) for k, v in f.clean.items()},
                              "declared": f.declared, "cut": f.cut,
                              "bounds": {k: {"clean": c, "failing": x, "side": side}
                                         for k, (c, x, side) in f.bounds.items()}}
                             for f in self.findings]}


def _span(lo: float, hi: float, unit: str, whole: bool) -> str:
    """``14.6-35.4 mm``, ``1-10``: a range as the summary says it."""
    a, b = _text(lo, unit, whole), _text(hi, unit, whole)
    return f"{a.split(' ')[0]}{' to ' if lo < 0 or hi < 0 else '-'}{b}"


def _text(x: float, unit: str, integer: bool = False) -> str:
    return value_text(x, unit, integer)


def _display(q):
    return display(q)


def sweep(source: str, path: str = "<source>", budget: float | Budget | None = None,
          points: int = LHS_POINTS, seconds: float | None = None, seed: int = SEED,
          tolerance: float = TOLERANCE, work: float | None = None,
          unranged: bool = True, values: dict | None = None,
          spans: dict | None = None, only=None, pairs: bool | str = True) -> SweepReport:
    """Check ``source`` (named ``path``: diagnostics and imports) across its params'
    ranges (see the module's docstring).  ``budget``: each compile's budget, a factor or a
    :class:`~aidl_lang.base.limits.Budget` as :func:`aidl_lang.compile`, which also scales the
    sweep's work (:data:`~aidl_lang.params.sweep_plan.WORK` units; ``work`` overrides it): what
    the points share, counted the same on any machine; ``seconds``: the outer guard, the
    whole sweep's CPU seconds (default: the budget's); ``unranged``: False sweeps only the
    params with a declared ``min=`` and ``max=`` (the others as before issue 92, named in
    ``unranged`` and not swept); ``values``: ``--set`` texts every compile starts from (the
    studio's sliders where they are: each param is then swept with the others at these
    values); ``spans``: ``{param: (lo, hi)}`` (display units) swept for a param that
    declares no range instead of its default span (the sliders' own); ``only``: the names
    of the params to sweep (None: every numeric param); ``points``: the Latin hypercube's
    size (0: only the ends and middles); ``tolerance``: the bisection's stopping width, a
    fraction of each range; ``pairs``: each count at either end with every other param at
    either end (True), or only with those its range reads or whose ranges read it
    (``"related"``, :func:`~aidl_lang.params.sweep_plan.plan`: the suite's cheaper plan).
    Never raises for a mistake in the program (the report's
    ``errors``); :class:`ValueError` for ``points < 0`` or a tolerance outside (0, 0.5]."""
    from ..pipeline import run_deep
    if points < 0 or not 0 < tolerance <= 0.5:
        raise ValueError("sweep: points >= 0 and 0 < tolerance <= 0.5")
    b = budget if isinstance(budget, Budget) else (
        DEFAULT_BUDGET if budget is None else DEFAULT_BUDGET.scaled(float(budget)))
    w = WORK * b.steps / DEFAULT_BUDGET.steps if work is None else float(work)
    secs = b.backstop if seconds is None else float(seconds)
    with _collector_spaced():
        rep = run_deep(lambda: _Sweep(source, path, b, points, seed, tolerance, w, unranged,
                                      dict(values or {}), dict(spans or {}), only,
                                      pairs=pairs).run(secs))
    if rep.ok and not rep.swept and not rep.fixed and unranged and only is None:
        # no numeric param: the numbers that size the parts, lifted into params of a copy
        from .sweep_literals import lift
        lifted = lift(source, str(path))
        if lifted is not None:
            with _collector_spaced():
                again = run_deep(lambda: _Sweep(lifted.source, path, b, points, seed,
                                                tolerance, w, True, {}, {}, None,
                                                lifted.literals, pairs).run(secs))
            if again.ok and again.swept:
                again.lifted = {n: x for n, x in lifted.literals.items() if n in again.swept}
                again.seconds += rep.seconds
                return again
    return rep


@contextmanager
def _collector_spaced():
    """The cyclic collector's young generation collected every :data:`GC_YOUNG` allocations
    during a sweep (CPython's 700): each point's compile makes hundreds of thousands of
    short-lived objects, and the sweep keeps the parsed program, the base's topology and the
    last solver alive across the points, which every older pass walked again (planetary's
    plan: 303 young and 27 middle passes, 6.3 of 31.7 s CPU; spaced, 65 and 3, 7-8 % less
    CPU on planetary and tool_holder).  The thresholds are restored when the last of the
    sweeps running at once (the studio's threads) ends."""
    import gc
    with _GC_LOCK:
        if not _GC_SAVED:
            _GC_SAVED.append(gc.get_threshold())
            gc.set_threshold(GC_YOUNG, 20, 100)
        _GC_SAVED.append(None)
    try:
        yield
    finally:
        with _GC_LOCK:
            _GC_SAVED.pop()
            if len(_GC_SAVED) == 1:
                gc.set_threshold(*_GC_SAVED.pop())


_GC_LOCK = threading.Lock()
_GC_SAVED: list = []         # the thresholds before the first sweep, then one None a sweep


class _Sweep:
    def __init__(self, source, path, budget, points, seed, tolerance, work_units,
                 unranged=True, values=None, spans=None, only=None, lifted=None,
                 pairs=True):
        self.defaults, self.values, self.spans = unranged, values or {}, spans or {}
        self.pairs = pairs
        self.lifted = lifted or {}
        self.only = None if only is None else set(only)
        self.source, self.path, self.budget = source, str(path), budget
        self.n_lhs, self.seed, self.tol = points, seed, tolerance
        self.report = SweepReport()
        # the work the points may share, counted the same on any machine; the CPU seconds
        # are the outer guard only
        self.work_left = work_units
        self.cpu_out = False
        self.settled: dict = {}      # (the --set texts compiled, a count moved) -> problems

    # ---------------------------------------------------------------- set-up
    def run(self, seconds: float) -> SweepReport:
        from .. import ast as A
        from ..output.checks import topology
        from ..parser import parse
        from ..interpreter.constants import early_constants
        from ..typecheck import check
        t0 = now()
        self.end = None
        rep = self.report
        sink = DiagnosticSink()
        self.program = parse(self.source, self.path, sink)
        if not sink.has_errors:
            check(self.program, sink)
        self.sources = dict(sink.sources)
        # the declarations alone (:meth:`_clamped`): a point's values moved into the ranges
        # that follow other params before its compile
        early = early_constants(self.program.stmts)     # constants the params read
        self.decls = A.Program(self.program.span, self.program.path, self.program.source,
                               [s for s in self.program.stmts
                                if type(s).__name__ in DECLS or s in early])
        self.solver = self.keys = None
        base = self._compile({}) if not sink.has_errors else None
        if base is None or base.sink.has_errors or base.drawing is None:
            rep.ok = False
            rep.errors = [d for d in (base.sink if base else sink).items if d.is_error]
            rep.seconds = now() - t0
            return rep
        self.base_keys = {_key(d) for d in base.sink.items if not d.is_error}
        rep.point_work = base.cost          # the least a point is known to need, so far
        self.end = t0 + seconds
        self.base_topology = topology(base.drawing)
        self.problems: dict = {}
        self.hints: dict = {}
        self.params = []
        self._params(base.fctx)
        rep.unranged += [p.name for p in self.params if not p.declared]
        rep.swept = [p.name for p in self.params]
        rep.tolerance = self.tol
        rep.ranges = {p.name: (p.lo, p.hi) for p in self.params}
        rep.units = {p.name: p.unit for p in self.params}
        if self.params:
            self._sweep()
            self._fixes()
        rep.seconds = now() - t0
        return rep

    def _params(self, fctx) -> None:
        """The swept params (:func:`~aidl_lang.params.sweep_plan.make_param`): a plain whole number
        that may count is compiled once half a step past its value (:meth:`_counts`)."""
        from .. import ast as A
        from .sweep_plan import ambiguous, in_range_calls, make_param
        ranges = getattr(fctx, "param_ranges", {})
        counted = in_range_calls(self.program)
        for st in self.program.stmts:
            if not isinstance(st, A.ParamDecl):
                continue
            q, r = fctx.params.get(st.name), ranges.get(st.name)
            if display(q) is None or (self.only is not None and st.name not in self.only):
                continue
            counts = st.name in counted or bool(
                not display(q)[0] and (r or {}).get("step")
                and float((r or {}).get("step")).is_integer())
            declared = r is not None and r.get("min") is not None and r.get("max") is not None
            if not declared and not self.defaults:
                self.report.unranged.append(st.name)
                continue
            if ambiguous(st, q, r, counted):
                counts = self._counts(st.name, q.const(), r or {})
            p, why = make_param(st, q, r, counts)
            if p is not None and not p.declared and st.name in self.spans:
                lo, hi = self.spans[st.name]
                p.lo, p.hi = min(lo, p.value), max(hi, p.value)
            if p is not None and st.name in self.lifted:
                p.span = self.lifted[st.name].span      # the number in the file
            if p is not None:
                p.on_grid(self.tol)
                self.params.append(p)
            elif why == "fixed":
                unit, k = display(q)
                x = round(q.const() * k, 9)
                whole = not unit and float(x).is_integer()
                self.report.fixed.append(f"{st.name} = {value_text(x, unit, whole)}")

    def _counts(self, name: str, v: float, rng: dict) -> bool:
        """Whether the plain whole-number param ``name`` (value ``v``, declared range ``rng``)
        counts: the program refuses it half a step past its value (inside its range) with an
        error, where the written value compiles."""
        hi = rng.get("max")
        x = v - 0.5 if hi is not None and v + 0.5 > hi else v + 0.5
        got = self._judge({name: x}, {name: f"{x:.12g}"})
        return bool(got) and got[0][0].startswith("E")

    def _compile(self, ov: dict) -> "_Point":
        """The program with the ``--set`` texts ``ov``: interpreted again (parsed and checked
        once), solved on the last solver when the model's rows are its rows
        (:func:`~aidl_lang.solver.core.holds.reuse`), then the booleans and the shape checks; its
        deadline the sweep's (each point shares the one budget, none gets its own)."""
        from ..interp import Interpreter
        from ..base.limits import Deadline, Work, solve_work
        from ..pipeline import after_solve, report_failure
        from ..solver import Solver, run
        from ..solver.core.holds import reuse
        sink = DiagnosticSink()
        sink.sources.update(self.sources)
        own = now() + self.budget.backstop     # the written values' compile: its own budget
        # a point's compile may spend at most the sweep's work left (the written values'
        # compile, its whole budget): past it, E0304 means not judged, never a finding
        cap = (self.budget.work if self.end is None
               else min(self.budget.work, max(self.work_left, 0.0)))
        meter = Work(cap)
        interp = Interpreter(sink, {**self.values, **ov}, self.budget,
                             deadline=own if self.end is None else min(own, self.end),
                             work=meter)
        model = interp.run(self.program)
        out = _Point(sink, interp.file)
        out.capped = cap < self.budget.work
        out.cost = work(interp, model, sink)
        if sink.has_errors:
            return out
        out.warm, self.keys = reuse(self.solver, model, self.keys)
        if not out.warm:
            self.solver, self.keys = Solver(model), None
        solver = self.solver
        solver.deadline = interp.deadline                # the point's one time budget
        solved = run(solver)
        meter.add(solve_work(solved.iterations, len(model.x)), "solving")
        if solved.solver is not None and solved.solver is not solver:
            solver = self.solver = solved.solver         # solved again with a hold released
            self.keys = None
        if solver.model is not model:                    # warm: the solver writes its own model
            model.x = list(solver.model.x)
        if not solved.converged:
            report_failure(sink, solved)
            self.solver = self.keys = None
            out.cost = work(interp, model, sink, solved=solved)
            return out
        out.drawing = after_solve(sink, model, deadline=Deadline(interp.deadline, interp.budget,
                                                                 work=meter))
        out.cost = work(interp, model, sink, out.drawing, solved)
        return out

    # ---------------------------------------------------------------- the points
    def _sweep(self) -> None:
        from .sweep_plan import plan
        rep = self.report
        points = plan(self.params, self.n_lhs, self.seed, self.pairs)
        failing = []
        for k, vals in enumerate(points):
            got = self._judge(vals)
            if got is None:
                rep.skipped = len(points) - k
                break
            if got:
                failing.append((vals, got))
        written = {p.name: p.value for p in self.params}
        clean = {p.name: [p.lo, p.hi] for p in self.params}
        for vals, got in failing:
            vals, got = self._needed(vals, got, written)
            moved = [p for p in self.params if vals[p.name] != written[p.name]]
            inside = all(clean[p.name][0] <= vals[p.name] <= clean[p.name][1] for p in moved)
            if not inside:
                continue                    # past a bound a finding already narrowed
            t, start, cut = self._bisect(written, vals)
            for p in moved:
                # the value judged clean (t = 0: the written value itself, off the grid)
                x = p.at(written[p.name] + t * (vals[p.name] - written[p.name])) if t > 0 \
                    else written[p.name]
                lo, hi = clean[p.name]
                clean[p.name] = [lo, min(hi, x)] if vals[p.name] > written[p.name] \
                    else [max(lo, x), hi]
            self._finding(vals, got, {p.name: tuple(clean[p.name]) for p in moved}, moved,
                          start, cut)
            if len(moved) > 1:
                self.report.findings[-1].bounds = self._bounds(vals, moved, written)

    def _bounds(self, vals: dict, moved: list, written: dict) -> dict:
        """A combination's bound along each param ``moved`` alone, the others held at the
        failing ``vals`` (:attr:`Finding.bounds`): bisected from the param's written value
        (judged clean there first) to its failing one, and kept only when no point the sweep
        judged on that line contradicts it (failing on its clean side, or clean past it
        toward the failing value): issue 110's ``w below 41.5 with n above 7``, though
        w = 44 with n = 8 failed too."""
        out = {}
        for p in moved:
            a = {**vals, p.name: written[p.name]}
            if self._judge(a) != []:
                continue                # not judged, or it fails at its written value too
            # the sweep's own bisection: a subclass's (the studio's scan) reads the param
            # alone at the other params' written values, not at these
            t, start, cut = _Sweep._bisect(self, a, vals)
            if cut:
                continue
            x0, x1 = written[p.name], vals[p.name]
            clean = p.at(x0 + t * (x1 - x0)) if t > 0 else x0
            failing = start[0][p.name] if start is not None else x1
            up = x1 > x0
            ok = True
            for key, codes in self.report.seen.items():
                pt = dict(key)
                if p.name not in pt or any(pt.get(q.name, q.value) != vals[q.name]
                                           for q in self.params if q is not p):
                    continue            # off the line
                x = pt[p.name]
                beyond = x > clean if up else x < clean
                within = min(x0, clean) <= x <= max(x0, clean)
                toward = min(clean, x1) <= x <= max(clean, x1)
                if (within and codes) or (beyond and toward and not codes):
                    ok = False
                    break
            if ok:
                out[p.name] = (clean, failing, "above" if up else "below")
        return out

    def _needed(self, vals: dict, got: list, written: dict) -> tuple[dict, list]:
        """A failing combination ``vals`` (problems ``got``) with each param that plays no
        part in it put back at its written value: held there, the combination re-judged,
        and left there when the design still fails the same way (issue 105: a combination
        named `body_height` above 47.2 mm though the wall was as thin at 30 mm).  One
        param at a time, in order; a point the budget leaves unjudged keeps the param."""
        moved = [p for p in self.params if vals[p.name] != written[p.name]]
        if len(moved) < 2:
            return vals, got
        for p in moved:
            if sum(vals[q.name] != written[q.name] for q in self.params) < 2:
                break
            held = {**vals, p.name: written[p.name]}
            again = self._judge(held)
            if again and again[0][0] == got[0][0]:
                vals, got = held, again
        return vals, got

    def _bisect(self, a: dict, b: dict) -> tuple[float, tuple | None, bool]:
        """The largest t in [0, 1) judged clean on the segment from ``a`` (clean) to ``b``
        (failing), to the tolerance of the widest range moved; the first failing point
        judged past it with its problems (``(values, problems)``; None: ``b`` itself); and
        whether the budget ran out before the tolerance was reached (what lies between is
        not judged)."""
        lo, hi, start = 0.0, 1.0, None
        span = max(abs(b[p.name] - a[p.name]) / (p.hi - p.lo) for p in self.params)
        while (hi - lo) * span > self.tol:
            m = (lo + hi) / 2
            vals = {p.name: p.at(a[p.name] + m * (b[p.name] - a[p.name])) for p in self.params}
            if vals == b or vals == a:
                break
            got = self._judge(vals)
            if got is None:
                return lo, start, True
            self.report.bisections += 1
            if got:
                hi, start = m, (vals, got)
            else:
                lo = m
        return lo, start, False

    def _judge(self, vals: dict, ov: dict | None = None) -> list[tuple[str, str]] | None:
        """The problems of the design at ``vals``: ``[(code, message)]``, empty when clean;
        None when it is not judged: the work budget is spent (or, the outer guard, the CPU
        seconds).  A value that leaves a range following other params is moved into it first
        (as the studio's forms do); a range that other values empty is a problem (E0124)."""
        key = tuple(sorted(vals.items()))
        if key in self.problems:
            return self.problems[key]
        if self.work_left <= 0 or self.cpu_out or now() >= self.end:
            self.cpu_out = self.cpu_out or now() >= self.end
            return None
        self.report.points += 1
        if ov is None:
            by = {p.name: p for p in self.params}
            # only the params moved: one computed from them (`param pitch = af + wall`)
            # follows them as it does under `--set`
            ov = {n: by[n].text(x) for n, x in vals.items() if x != by[n].value}
        ov, cost = self._clamped(ov)
        counted = any(p.integer and vals.get(p.name, p.value) != p.value for p in self.params)
        # two planned points the ranges move onto the same values are one compile (the
        # planetary's suite plan: 34 points, 32 compiles); the move's work counted
        same = (tuple(sorted(ov.items())), counted)
        if same in self.settled:
            self.work_left -= cost
            self.report.work += cost
            self.problems[key] = self.settled[same]
            self.report.seen[key] = tuple(c for c, _ in self.settled[same])
            return self.settled[same]
        if self.work_left - cost < self.report.point_work:
            # a compile the work left cannot pay is not started (issue 110: a 20,000-hole
            # panel's sweep spent 11 s of CPU on points it began and abandoned)
            self.work_left -= cost
            self.report.work += cost
            self.report.points -= 1
            self.report.short = int(max(self.work_left, 0))
            return None
        res = self._compile(ov)
        cost += res.cost
        for _ in range(CLAMPS):         # what the declarations alone did not settle
            # a range (or step) that follows other params (docs/language.md, 2.3): the
            # dependent params moved into it and onto its steps, as the studio's forms do -
            # whatever the compile said: a value between the steps the form would not offer
            # fails the program's own asserts (a planetary's sun off its counts)
            fixed = _into_ranges(res.fctx)
            if not fixed:
                break
            ov.update(fixed)
            res = self._compile(ov)
            cost += res.cost
        self.work_left -= cost
        self.report.work += cost
        if not res.capped:
            self.report.point_work = min(self.report.point_work, res.cost)
        errs = [d for d in res.sink.items if d.is_error]
        if errs and errs[0].code == "E0304" and (now() >= self.end or res.capped):
            # the sweep's budget (its work left, or the backstop), not the design: not judged
            self.cpu_out = True
            self.report.points -= 1
            return None
        self.report.warm += bool(res.warm)
        for p in self.params:
            if vals.get(p.name, p.value) != p.value:
                self.report.judged[p.name] = self.report.judged.get(p.name, 0) + 1
        got = [(errs[0].code, errs[0].message)] if errs else self._changes(res, counted)
        self.problems[key] = self.settled[same] = got
        self.report.seen[key] = tuple(c for c, _ in got)
        return got

    def _clamped(self, ov: dict) -> tuple[dict, int]:
        """``ov`` with the params whose values leave a range that follows other params (or
        lie between its steps) moved into it (:func:`_into_ranges`), found by interpreting
        the program's declarations alone (imports, defs, params: no structure built, solved
        or checked) up to :data:`CLAMPS` times; and the work that took (its steps, objects
        and diagnostics).  Before, each such point was compiled whole, then again with the
        values moved (tool_holder: 88 of 183 compiles, 306,000 of 863,000 work units)."""
        from ..interp import Interpreter
        from .sweep_plan import PER_DIAGNOSTIC, PER_OBJECT
        cost = 0
        for _ in range(CLAMPS):
            sink = DiagnosticSink()
            interp = Interpreter(sink, {**self.values, **ov}, self.budget,
                                 deadline=self.end)
            interp.run(self.decls)
            cost += interp.steps + PER_OBJECT * interp.objects + PER_DIAGNOSTIC * len(sink.items)
            fixed = _into_ranges(interp.file)
            if not fixed:
                break
            ov = {**ov, **fixed}
        return ov, cost

    def _changes(self, res, counted: bool = False) -> list[tuple[str, str]]:
        """The new warnings of a compile (not at the written values) and its parts' changes
        of topology (``W0510``); ``counted``: a count moved, so a different number of
        openings is what it is for (a handle's grips copied in one hole: no new names)."""
        from ..output.checks.changes import topology, topology_changes
        got = [(d.code, d.message) for d in res.sink.items
               if d.code not in NOT_COMPARED and _key(d) not in self.base_keys]
        if res.drawing is not None:
            for part, t in topology(res.drawing).items():
                b = self.base_topology.get(part)
                if b is None:
                    continue
                what = [w for w in topology_changes(b, t)
                        if not (" opening" in w and "instead of" in w
                                and (counted or b.holes != t.holes))]
                if what:
                    got.append(("W0510", f"part `{part}` changes: " + "; ".join(what[:3])))
        return got

    def _fixes(self) -> None:
        """Each one-param finding's fix writes the param's range narrowed by every finding
        (both ends), in the file swept."""
        from .sweep_plan import range_fix
        clean = self.report.clean_ranges()
        by = {p.name: p for p in self.params}
        for f in self.report.findings:
            if len(f.clean) != 1:
                continue
            (n,) = f.clean
            p = by[n]
            lo, hi = clean[n]
            verb, how = self.hints[id(f)]
            if n in self.lifted:
                lit = self.lifted[n]
                f.diagnostic.hint = (f"make it a param with the largest clean range found: "
                                     f"`param {n} = {lit.text}, min = {p.text(lo)}, max = "
                                     f"{p.text(hi)}`, used for {lit.where}{how}, or fix the "
                                     "design at these values")
                continue
            f.diagnostic.hint = (f"{verb} the largest clean range found: `{n}`: "
                                 f"`min={p.text(lo)}, max={p.text(hi)}`{how}, or fix the "
                                 "design at these values")
            if p.span is not None and p.span.file == self.path:
                f.diagnostic.fix = range_fix(self.source, p, lo, hi)

    def _finding(self, vals, got, narrowed, moved, start=None, cut=False) -> None:
        by = {p.name: p for p in self.params}
        code, message = got[0]
        shown = {p.name: vals[p.name] for p in moved}

        def at(v):
            return ", ".join(f"{p.name}={p.text(v[p.name])}" for p in moved)
        message = f"{code}: {message}"
        if start is not None and start[1][0][0] != code:
            message += f"; from {at(start[0])} already {start[1][0][0]}: {start[1][0][1]}"
        declared = all(by[n].declared for n in narrowed)
        fix = ", ".join(f"`{n}`: `min={by[n].text(lo)}, max={by[n].text(hi)}`"
                        for n, (lo, hi) in narrowed.items())
        if cut:
            how = "; between it and the failing values: not judged, out of budget"
        else:
            how = ", ".join(f"{by[n].text(self.tol * (by[n].hi - by[n].lo))}"
                            for n in narrowed if not by[n].integer) or "exact"
            how = f" (bisected: {how})"
        first = moved[0] if moved else self.params[0]
        labels = [Label(p.span, f"`{p.name}` = {p.text(vals[p.name])} here", primary=False)
                  for p in moved[1:] if p.span is not None]
        where = "inside the declared range" if declared else "; ".join(
            f"`{p.name}` " + (f"is {self.lifted[p.name].where}, no param:" if p.name in
                              self.lifted else "no declared range,")
            + f" swept {p.range_text()}" for p in moved if not p.declared)
        verb = "narrow the range to" if declared else "declare"
        d = Diagnostic("W0110", f"with {at(vals)} ({where}), {message}",
                       first.span, "warning",
                       hint=f"{verb} the largest clean range found: {fix}{how}, "
                            f"or fix the design at these values",
                       labels=labels)
        first = None
        if start is not None and start[1][0][0] != code:
            first = ({p.name: start[0][p.name] for p in moved}, *start[1][0])
        f = Finding(shown, code, message, narrowed, d, got[0][1], first, declared, cut)
        self.hints[id(f)] = (verb, how)
        self.report.findings.append(f)


class _Point:
    __slots__ = ("sink", "fctx", "drawing", "warm", "cost", "capped")

    def __init__(self, sink, fctx):
        self.sink, self.fctx, self.drawing, self.warm, self.cost = sink, fctx, None, False, 0
        self.capped = False     # its compile's work was capped by the sweep's work left


def _into_ranges(fctx) -> dict[str, str]:
    """``--set`` texts for the params of a compile (its interpreter's file ``fctx``) whose
    value left a declared range that follows other params, or lies between its steps: the
    value moved into the range, onto its steps."""
    out = {}
    for name, r in (getattr(fctx, "param_ranges", None) or {}).items():
        v = fctx.params.get(name)
        shown = _display(v)
        lo, hi, step = r.get("min"), r.get("max"), r.get("step")
        if shown is None or lo is None or hi is None or lo > hi:
            continue
        x = v.const()
        w = min(max(x, lo), hi)
        if step and step > 0:
            w = lo + round((w - lo) / step) * step
            w = max(w - step if w > hi + 1e-9 else w, lo)
        if abs(w - x) > 1e-9 * max(1.0, abs(x)):
            out[name] = _text(round(w * shown[1], 9), shown[0])
    return out


def _key(d: Diagnostic) -> tuple:
    sp = d.span
    return (d.code, sp.file if sp else None, sp.line if sp else None)
