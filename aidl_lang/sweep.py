"""``aidl check --sweep``: a design checked across its params' declared ranges.

:func:`sweep` compiles the program at its written values, then with each ranged param at
the low end, the middle and the high end of its ``min=``/``max=`` (the others at their
values), then at a small Latin hypercube of combinations (seeded: the same points on every
run).  A point is a *finding* when the design stops compiling there (an error), a part
changes its topology (a solid falls into pieces, a hole leaves its solid or breaks through
its outline, two holes merge: what W0510 compares), or a warning appears that the written
values do not have.  Each finding is bisected between the written values (clean) and the
failing point to :data:`TOLERANCE` of the range, and reported as a ``W0110`` located at the
``param`` line(s) with the largest clean sub-range found (docs/language.md, "Sweeping the
ranges").

Cost: the program is parsed and checked once; each point is interpreted again with its
values, and when the model has the same rows as the last one the compiled solver is
reused (:func:`aidl_lang.solver.holds.reuse`: :meth:`~aidl_lang.solver.Solver.set_value`, as the
sliders of ``aidl serve`` do).  The whole sweep is bounded by the compile's CPU
budget (:func:`aidl_lang.limits.now`); the points past it are counted in ``skipped``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .diagnostics import Diagnostic, DiagnosticSink, Label
from .limits import DEFAULT_BUDGET, Budget, now

# each ranged param's points, the Latin hypercube's size, and the bisection's stopping width
# (a fraction of the param's declared range)
LHS_POINTS = 8
TOLERANCE = 0.01
SEED = 0
# warnings that compare a compile with another one or say a check was cut short: not a
# property of the design at one value
NOT_COMPARED = {"W0510", "W0521"}
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
    at ``values`` (None: the same way)."""

    values: dict
    code: str
    message: str
    clean: dict
    diagnostic: Diagnostic
    problem: str = ""
    first: tuple | None = None


@dataclass
class SweepReport:
    """What :func:`sweep` found.  ``ok``: the design compiles at its written values (else
    ``errors`` holds why and nothing was swept); ``swept``: the ranged params' names;
    ``unranged``: numeric params without both ``min=`` and ``max=`` (not swept); ``points``:
    how many points were checked (bisection steps included), ``skipped``: planned points not
    checked once the budget was spent; ``warm``: points solved on the reused solver;
    ``seconds``: CPU seconds of the sweep (the written values' compile included);
    ``findings``: :class:`Finding` list (empty: clean across the ranges)."""

    ok: bool = True
    swept: list = field(default_factory=list)
    unranged: list = field(default_factory=list)
    points: int = 0
    skipped: int = 0
    warm: int = 0
    seconds: float = 0.0
    findings: list = field(default_factory=list)
    errors: list = field(default_factory=list)

    def clean_ranges(self) -> dict:
        """``{param: (lo, hi)}`` (display units): each swept param's declared range, narrowed
        to the clean sub-range of every finding that moved it."""
        out = {}
        for f in self.findings:
            for name, (lo, hi) in f.clean.items():
                a, b = out.get(name, (lo, hi))
                out[name] = (max(a, lo), min(b, hi))
        return out

    @property
    def diagnostics(self) -> list[Diagnostic]:
        """The findings' ``W0110`` diagnostics."""
        return [f.diagnostic for f in self.findings]

    def text(self) -> str:
        """The summary line(s) ``aidl check --sweep`` prints after the diagnostics."""
        if not self.ok:
            return "sweep: not run: the program does not compile at its written values"
        if not self.swept:
            out = "sweep: no param declares a range (`min=` and `max=`): nothing swept"
        else:
            n = len(self.findings)
            its = "its range" if len(self.swept) == 1 else "their ranges"
            out = (f"sweep: {', '.join(self.swept)} across {its}: {self.points} points, "
                   + (f"{n} finding{'s' if n != 1 else ''} (W0110)" if n else "clean"))
            if self.skipped:
                out += (f"; {self.skipped} point{'s' if self.skipped != 1 else ''} skipped "
                        "(out of the budget's CPU time; --budget K gives K times more)")
        if self.unranged:
            out += (f"\nsweep: not swept (no declared range): {', '.join(self.unranged)}")
        return out

    def to_json(self) -> dict:
        return {"ok": self.ok, "swept": self.swept, "unranged": self.unranged,
                "points": self.points, "skipped": self.skipped, "warm": self.warm,
                "findings": [{"values": f.values, "code": f.code, "message": f.message,
                              "clean": {k: list(v) for k, v in f.clean.items()}}
                             for f in self.findings]}


class _Param:
    """A ranged param in display units (mm, deg, plain): its written value, ``min``/``max``
    and ``step`` (0: none)."""
    __slots__ = ("name", "unit", "k", "value", "lo", "hi", "step", "integer", "span")

    def __init__(self, name, unit, k, value, rng, span):
        self.name, self.unit, self.k, self.span = name, unit, k, span
        self.value = round(value * k, 9)
        self.lo, self.hi = round(rng["min"] * k, 9), round(rng["max"] * k, 9)
        self.step = round(rng["step"] * k, 9) if rng.get("step") else 0.0
        self.integer = not unit and all(float(v).is_integer() for v in
                                        (self.value, self.lo, self.hi, self.step or 1))

    def at(self, x: float) -> float:
        """``x`` in the range, on the slider's steps (``step=``) when the param has them: the
        values a form offers (and no second compile to move a point onto them)."""
        x = min(max(x, self.lo), self.hi)
        if self.step > 0 and self.hi - self.lo > self.step:
            x = self.lo + round((x - self.lo) / self.step) * self.step
            if x > self.hi + 1e-9:
                x -= self.step
        return float(round(x)) if self.integer else round(x, 9)

    def text(self, x: float) -> str:
        return _text(x, self.unit, self.integer)


def _text(x: float, unit: str, integer: bool = False) -> str:
    """A value as ``--set`` reads it: ``12.5 mm``, ``30 deg``, ``6``."""
    return str(int(x)) if integer else f"{x:.12g} {unit}".strip()


def _display(q) -> tuple[str, float] | None:
    """``(unit, factor)`` of a param's value (display unit = factor x the model's unit:
    mm, deg from radians, plain numbers); None for one that is not a known number."""
    import math
    from .geometry.values import ANG, LEN, NUM, Q
    if isinstance(q, bool) or not isinstance(q, Q) or q.const() is None:
        return None
    return {LEN: ("mm", 1.0), ANG: ("deg", 180 / math.pi), NUM: ("", 1.0)}.get(q.dim)


def sweep(source: str, path: str = "<source>", budget: float | Budget | None = None,
          points: int = LHS_POINTS, seconds: float | None = None, seed: int = SEED,
          tolerance: float = TOLERANCE) -> SweepReport:
    """Check ``source`` (named ``path``: diagnostics and imports) across its params'
    declared ranges (see the module's docstring).  ``budget``: each compile's budget, a
    factor or a :class:`~aidl_lang.limits.Budget` as :func:`aidl_lang.compile`; ``seconds``:
    the whole sweep's CPU seconds (default: the budget's); ``points``: the Latin hypercube's
    size (0: only the ends and middles); ``tolerance``: the bisection's stopping width, a
    fraction of each range.  Never raises for a mistake in the program (the report's
    ``errors``); :class:`ValueError` for ``points < 0`` or a tolerance outside (0, 0.5]."""
    from .pipeline import run_deep
    if points < 0 or not 0 < tolerance <= 0.5:
        raise ValueError("sweep: points >= 0 and 0 < tolerance <= 0.5")
    b = budget if isinstance(budget, Budget) else (
        DEFAULT_BUDGET if budget is None else DEFAULT_BUDGET.scaled(float(budget)))
    return run_deep(lambda: _Sweep(source, path, b, points, seed, tolerance).run(
        b.seconds if seconds is None else float(seconds)))


class _Sweep:
    def __init__(self, source, path, budget, points, seed, tolerance):
        self.source, self.path, self.budget = source, str(path), budget
        self.n_lhs, self.seed, self.tol = points, seed, tolerance
        self.report = SweepReport()

    # ---------------------------------------------------------------- set-up
    def run(self, seconds: float) -> SweepReport:
        from . import ast as A
        from .output.checks import topology
        from .parser import parse
        from .typecheck import check
        t0 = now()
        rep = self.report
        sink = DiagnosticSink()
        self.program = parse(self.source, self.path, sink)
        if not sink.has_errors:
            check(self.program, sink)
        self.sources = dict(sink.sources)
        self.solver = self.keys = None
        base = self._compile({}) if not sink.has_errors else None
        if base is None or base.sink.has_errors or base.drawing is None:
            rep.ok = False
            rep.errors = [d for d in (base.sink if base else sink).items if d.is_error]
            rep.seconds = now() - t0
            return rep
        self.base_keys = {_key(d) for d in base.sink.items if not d.is_error}
        self.base_topology = topology(base.drawing)
        fctx = base.fctx
        ranges = getattr(fctx, "param_ranges", {})
        self.params = []
        for st in self.program.stmts:
            if not isinstance(st, A.ParamDecl):
                continue
            v = fctx.params.get(st.name)
            shown = _display(v)
            if shown is None:
                continue
            r = ranges.get(st.name) or {}
            if r.get("min") is None or r.get("max") is None or r["max"] <= r["min"]:
                rep.unranged.append(st.name)
            else:
                self.params.append(_Param(st.name, shown[0], shown[1], v.const(), r, st.span))
        rep.swept = [p.name for p in self.params]
        self.end = t0 + seconds
        self.problems: dict = {}
        if self.params:
            self._sweep()
        rep.seconds = now() - t0
        return rep

    def _compile(self, ov: dict) -> "_Point":
        """The program with the ``--set`` texts ``ov``: interpreted again (parsed and checked
        once), solved on the last solver when the model's rows are its rows
        (:func:`~aidl_lang.solver.holds.reuse`), then the booleans and the shape checks."""
        from .interp import Interpreter
        from .limits import Deadline
        from .pipeline import after_solve, report_failure
        from .solver import Solver, run
        from .solver.holds import reuse
        sink = DiagnosticSink()
        sink.sources.update(self.sources)
        interp = Interpreter(sink, ov, self.budget)
        model = interp.run(self.program)
        out = _Point(sink, interp.file)
        if sink.has_errors:
            return out
        out.warm, self.keys = reuse(self.solver, model, self.keys)
        if not out.warm:
            self.solver, self.keys = Solver(model), None
        solver = self.solver
        solver.deadline = interp.deadline                # the point's one time budget
        solved = run(solver)
        if solved.solver is not None and solved.solver is not solver:
            solver = self.solver = solved.solver         # solved again with a hold released
            self.keys = None
        if solver.model is not model:                    # warm: the solver writes its own model
            model.x = list(solver.model.x)
        if not solved.converged:
            report_failure(sink, solved)
            self.solver = self.keys = None
            return out
        out.drawing = after_solve(sink, model, deadline=Deadline(interp.deadline, interp.budget))
        return out

    def _plan(self) -> list[dict]:
        written = {p.name: p.value for p in self.params}
        plan, seen = [], {tuple(sorted(written.items()))}

        def add(vals):
            k = tuple(sorted(vals.items()))
            if k not in seen:
                seen.add(k)
                plan.append(vals)
        for p in self.params:
            for x in (p.lo, (p.lo + p.hi) / 2, p.hi):
                add(dict(written, **{p.name: p.at(x)}))
        if self.n_lhs and len(self.params) > 1:
            from scipy.stats import qmc
            u = qmc.LatinHypercube(d=len(self.params), seed=self.seed).random(self.n_lhs)
            for row in u:
                add({p.name: p.at(p.lo + r * (p.hi - p.lo)) for p, r in zip(self.params, row)})
        return plan

    # ---------------------------------------------------------------- the points
    def _sweep(self) -> None:
        rep = self.report
        plan = self._plan()
        failing = []
        for k, vals in enumerate(plan):
            if now() >= self.end:
                rep.skipped = len(plan) - k
                break
            got = self._judge(vals)
            if got:
                failing.append((vals, got))
        written = {p.name: p.value for p in self.params}
        clean = {p.name: [p.lo, p.hi] for p in self.params}
        for vals, got in failing:
            moved = [p for p in self.params if vals[p.name] != written[p.name]]
            inside = all(clean[p.name][0] <= vals[p.name] <= clean[p.name][1] for p in moved)
            if not inside:
                continue                    # past a bound a finding already narrowed
            t, start = self._bisect(written, vals)
            for p in moved:
                x = p.at(written[p.name] + t * (vals[p.name] - written[p.name]))
                lo, hi = clean[p.name]
                clean[p.name] = [lo, min(hi, x)] if vals[p.name] > written[p.name] \
                    else [max(lo, x), hi]
            self._finding(vals, got, {p.name: tuple(clean[p.name]) for p in moved}, moved,
                          start)

    def _bisect(self, a: dict, b: dict) -> tuple[float, tuple | None]:
        """The largest t in [0, 1) found clean on the segment from ``a`` (clean) to ``b``
        (failing), to the tolerance of the widest range moved, and the first failing point
        found past it with its problems (``(values, problems)``; None: ``b`` itself)."""
        lo, hi, start = 0.0, 1.0, None
        span = max(abs(b[p.name] - a[p.name]) / (p.hi - p.lo) for p in self.params)
        while (hi - lo) * span > self.tol and now() < self.end:
            m = (lo + hi) / 2
            vals = {p.name: p.at(a[p.name] + m * (b[p.name] - a[p.name])) for p in self.params}
            if vals == b or vals == a:
                break
            got = self._judge(vals)
            if got:
                hi, start = m, (vals, got)
            else:
                lo = m
        return lo, start

    def _judge(self, vals: dict) -> list[tuple[str, str]]:
        """The problems of the design at ``vals``: ``[(code, message)]``, empty when clean
        (or when the values leave a range that follows other params: not a design's fault)."""
        key = tuple(sorted(vals.items()))
        if key in self.problems:
            return self.problems[key]
        from .output.checks.changes import topology, topology_changes
        self.report.points += 1
        by = {p.name: p for p in self.params}
        ov = {n: by[n].text(x) for n, x in vals.items()}
        res = self._compile(ov)
        for _ in range(CLAMPS):
            # a range (or step) that follows other params (docs/language.md, 2.3): the
            # dependent params moved into it and onto its steps, as the studio's forms do -
            # whatever the compile said: a value between the steps the form would not offer
            # fails the program's own asserts (a planetary's sun off its counts)
            fixed = _into_ranges(res.fctx)
            if not fixed:
                break
            ov.update(fixed)
            res = self._compile(ov)
        errs = [d for d in res.sink.items if d.is_error]
        if any(d.code == "E0124" for d in errs):
            self.problems[key] = []         # no value of the dependent params fits
            return []
        self.report.warm += bool(res.warm)
        if errs:
            got = [(errs[0].code, errs[0].message)]
        else:
            got = [(d.code, d.message) for d in res.sink.items
                   if d.code not in NOT_COMPARED and _key(d) not in self.base_keys]
            if res.drawing is not None:
                now_t = topology(res.drawing)
                for part, t in now_t.items():
                    b = self.base_topology.get(part)
                    if b is None:
                        continue
                    what = [w for w in topology_changes(b, t)
                            if not (" opening" in w and "instead of" in w and b.holes != t.holes)]
                    if what:
                        got.append(("W0510", f"part `{part}` changes: " + "; ".join(what[:3])))
        self.problems[key] = got
        return got

    def _finding(self, vals, got, narrowed, moved, start=None) -> None:
        by = {p.name: p for p in self.params}
        code, message = got[0]
        shown = {p.name: vals[p.name] for p in moved}

        def at(v):
            return ", ".join(f"{p.name}={p.text(v[p.name])}" for p in moved)
        message = f"{code}: {message}"
        if start is not None and start[1][0][0] != code:
            message += f"; from {at(start[0])} already {start[1][0][0]}: {start[1][0][1]}"
        fix = ", ".join(f"`{n}`: `min={by[n].text(lo)}, max={by[n].text(hi)}`"
                        for n, (lo, hi) in narrowed.items())
        tol = ", ".join(f"{by[n].text(self.tol * (by[n].hi - by[n].lo))}" for n in narrowed
                        if not by[n].integer) or "exact"
        first = moved[0] if moved else self.params[0]
        labels = [Label(p.span, f"`{p.name}` = {p.text(vals[p.name])} here", primary=False)
                  for p in moved[1:] if p.span is not None]
        d = Diagnostic("W0110", f"with {at(vals)} (inside the declared range), {message}",
                       first.span, "warning",
                       hint=f"narrow the range to the largest clean one found: {fix} "
                            f"(bisected: {tol}), or fix the design at these values",
                       labels=labels)
        first = None
        if start is not None and start[1][0][0] != code:
            first = ({p.name: start[0][p.name] for p in moved}, *start[1][0])
        self.report.findings.append(Finding(shown, code, message, narrowed, d, got[0][1],
                                            first))


class _Point:
    __slots__ = ("sink", "fctx", "drawing", "warm")

    def __init__(self, sink, fctx):
        self.sink, self.fctx, self.drawing, self.warm = sink, fctx, None, False


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
