"""Each slider alone, scanned across its range (the studio's hatching, issue 92): where does
moving one param, the others at their values, break the design?

:func:`aidl_lang.params.sweep.sweep` judges a param at its ends and middle and bisects from the
written value to what fails: a single clean interval.  A slider's range can break in a band
between clean values (a rounded tab's width 31-40 mm with its length 20 mm: a ledge, W0520,
clean again once the length follows the width) or at scattered values (a bracket's odd bolt
counts: W0508), which that misses.  :func:`scan` judges each param at :data:`SCAN` + 1
values of its range (a count at each value when it has at most that many), coarse to fine
and the params in turn (ends, middle, quarters, ...: a budget cut leaves every slider
evenly covered), then bisects every change between neighbouring values judged (clean and
broken) to the sweep's tolerance.  The answer: each param's :class:`Run` list, its range cut
where the design changes between clean and broken, and where the budget left a change not
bisected to the tolerance: a run not judged, neither hatched nor clean.  Shares the sweep's machinery (one parse, the solver
reused, the work budget counted the same on any machine, dependent ranges moved into place
as the studio's forms move them: :class:`aidl_lang.params.sweep._Sweep`).

:func:`scan_and_sweep` is the studio's one request: the scan, then the sweep's combinations,
one object sharing the judged points, the work budget and the deadline (issue 92: the two
ran one after the other, each with a full budget).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..base.limits import DEFAULT_BUDGET, Budget
from .sweep import LHS_POINTS, SEED, TOLERANCE, SweepReport, _Sweep
from .sweep_plan import WORK

# intervals of a slider's range judged (SCAN + 1 values): a band of a thirty-second of
# the range is never missed
SCAN = 32
# the part of a studio request's work the scan may spend before the sweep's combinations
# (which then have the rest and whatever the scan left)
SCAN_SHARE = 0.75


@dataclass
class Run:
    """Consecutive judged values of one param in one state: ``lo``/``hi`` the first and the
    last value judged (display units), ``broken`` (None: not judged, the values strictly
    between ``lo`` and ``hi``, the judged ones on either side), and for a broken run
    ``code`` and ``problem`` (what the compile says at its value nearest the param's own) and
    ``far``: ``(value, code, problem)`` at its value farthest from it."""

    lo: float
    hi: float
    broken: bool | None
    code: str = ""
    problem: str = ""
    far: tuple | None = None


@dataclass
class ScanReport:
    """What :func:`scan` found: ``ok`` (the program compiles at its values; else ``errors``),
    ``swept`` (the params scanned), ``runs`` (``{param: [Run]}``, in order along the range),
    ``ranges`` and ``units`` (display units), ``points`` judged, ``skipped`` (planned points
    past the budget), ``work`` (the budget's units spent), ``cut`` (params whose bisection
    the budget stopped)."""

    ok: bool = True
    swept: list = field(default_factory=list)
    runs: dict = field(default_factory=dict)
    ranges: dict = field(default_factory=dict)
    units: dict = field(default_factory=dict)
    values: dict = field(default_factory=dict)
    points: int = 0
    skipped: int = 0
    work: int = 0
    cut: list = field(default_factory=list)
    errors: list = field(default_factory=list)

    def broken(self, name: str) -> list[tuple[float | None, float | None, Run]]:
        """The hatches of param ``name``: ``(after, before, run)`` for each broken run, the
        values strictly between ``after`` and ``before`` (the clean values judged on either
        side; None: from the range's end) broken.  Next to a part not judged a hatch ends at
        its own value judged there: what the budget cut is never hatched."""
        runs = self.runs.get(name, [])
        out = []
        for i, r in enumerate(runs):
            if not r.broken:
                continue
            prev = runs[i - 1] if i else None
            nxt = runs[i + 1] if i + 1 < len(runs) else None
            after = None if prev is None else prev.hi if prev.broken is False else r.lo
            before = None if nxt is None else nxt.lo if nxt.broken is False else r.hi
            out.append((after, before, r))
        return out

    def unjudged(self, name: str) -> list[tuple[float, float]]:
        """The parts of param ``name``'s range the budget left not judged: ``(after,
        before)``, the values strictly between them."""
        return [(r.lo, r.hi) for r in self.runs.get(name, []) if r.broken is None]


def _budget(budget) -> Budget:
    return budget if isinstance(budget, Budget) else (
        DEFAULT_BUDGET if budget is None else DEFAULT_BUDGET.scaled(float(budget)))


def scan(source: str, path: str = "<source>", budget: float | Budget | None = None,
         values: dict | None = None, spans: dict | None = None, only=None,
         n: int = SCAN, tolerance: float = TOLERANCE, work: float | None = None,
         seconds: float | None = None) -> ScanReport:
    """Each numeric param of ``source`` alone across its range, the others at ``values``
    (``--set`` texts; the sliders' values), as the module's docstring says; ``spans``,
    ``only``, ``budget``, ``work``, ``seconds`` and ``tolerance`` as
    :func:`aidl_lang.params.sweep.sweep`'s.  Never raises for a mistake in the program."""
    from ..pipeline import run_deep
    b = _budget(budget)
    w = WORK * b.steps / DEFAULT_BUDGET.steps if work is None else float(work)
    s = _Scan(source, path, b, 0, 0, tolerance, w, True, dict(values or {}),
              dict(spans or {}), only)
    s.n = max(2, int(n))
    rep = run_deep(lambda: s.run(b.backstop if seconds is None else float(seconds)))
    return _scan_report(s, rep)


def scan_and_sweep(source: str, path: str = "<source>", budget: float | Budget | None = None,
                   values: dict | None = None, spans: dict | None = None,
                   work: float | None = None, seconds: float | None = None,
                   share: float = SCAN_SHARE) -> tuple[ScanReport, SweepReport]:
    """The studio's sweep request within one budget: :func:`scan` (spending at most ``share``
    of the work), then :func:`~aidl_lang.params.sweep.sweep`'s plan for the combinations with
    the rest, one object: a point either judges is judged once, one work budget (``work``,
    else the budget's) and one CPU backstop (``seconds``, else the budget's backstop) for both.  The scan's
    runs take every point that moved one param alone, the sweep's too; the sweep's
    one-param findings take their bounds from the scan's where it bisected them.  What the
    budget cut is not judged (:meth:`ScanReport.unjudged`; the sweep's ``skipped`` and
    :meth:`~aidl_lang.params.sweep.SweepReport.not_judged`).  The two reports share
    ``points`` and ``work`` (the request's)."""
    from ..pipeline import run_deep
    b = _budget(budget)
    w = WORK * b.steps / DEFAULT_BUDGET.steps if work is None else float(work)
    s = _Both(source, path, b, LHS_POINTS, SEED, TOLERANCE, w, True, dict(values or {}),
              dict(spans or {}), None)
    s.share = min(max(float(share), 0.0), 1.0)
    rep = run_deep(lambda: s.run(b.backstop if seconds is None else float(seconds)))
    return _scan_report(s, rep), rep


def _scan_report(s, rep) -> ScanReport:
    out = ScanReport(ok=rep.ok, swept=list(rep.swept), ranges=dict(rep.ranges),
                     units=dict(rep.units), points=rep.points, work=rep.work,
                     errors=list(rep.errors))
    out.runs, out.skipped, out.cut = getattr(s, "runs", {}), getattr(s, "left", 0), \
        getattr(s, "cut_params", [])
    out.values = {p.name: p.value for p in getattr(s, "params", [])}
    return out


class _Scan(_Sweep):
    n = SCAN
    current: list = []

    def _fixes(self) -> None:
        pass

    def _params(self, fctx) -> None:
        """The swept params; with the sliders moved (``values``), what breaks the design is
        what its written values do not say (as ``--set`` says it: W0510 "not so with the
        defaults"), not what the sliders' own point does not: a slider dragged into a band
        left the others judged against a broken design (each clean value of theirs hatched as
        a change from it)."""
        super()._params(fctx)
        if not self.values or not self.params:
            return
        from ..output.checks import topology
        from .sweep import _key
        moved, self.values = self.values, {}
        ref = self._compile({})
        self.values = moved
        self.solver = self.keys = None
        if ref.drawing is not None and not ref.sink.has_errors:
            self.base_keys = {_key(d) for d in ref.sink.items if not d.is_error}
            self.base_topology = topology(ref.drawing)

    def _grid(self, p) -> list[float]:
        """The values of ``p`` scanned, in order of judging (coarse to fine)."""
        if p.integer and p.hi - p.lo <= self.n:
            vals = [p.lo + k for k in range(int(round(p.hi - p.lo)) + 1)]
        else:
            vals = [p.lo + k * (p.hi - p.lo) / self.n for k in range(self.n + 1)]
        m = len(vals) - 1
        order, level = [0, m], [(0, m)]
        while level:
            nxt = []
            for a, b in level:
                if b - a > 1:
                    c = (a + b) // 2
                    order.append(c)
                    nxt += [(a, c), (c, b)]
            level = nxt
        out, seen = [], {p.value}
        for k in order:
            x = p.at(vals[k])
            if x not in seen:
                seen.add(x)
                out.append(x)
        return out

    def _sweep(self) -> None:
        self._scan()
        self._finish()

    def _scan(self) -> None:
        """Each param's grid judged, coarse to fine and the params in turn, then each change
        bisected (:meth:`_bisect_changes`)."""
        written = {p.name: p.value for p in self.params}
        self.probes = set(self.problems)    # a count's probe (:meth:`_counts`): no point
        self.grids = {p.name: self._grid(p) for p in self.params}
        plan, depth = [], max(len(g) for g in self.grids.values())
        # coarse to fine, the params in turn: the ends of each, then each middle, ...
        for i in range(depth):
            for p in self.params:
                if i < len(self.grids[p.name]):
                    plan.append((p, self.grids[p.name][i]))
        self.left = 0
        self.unreached = {}
        # the sliders' own point, judged against the written values (clean when it is them)
        self.current = (self._judge(written) or []) if self.values else []
        for k, (p, x) in enumerate(plan):
            if self._judge(dict(written, **{p.name: x})) is None:
                self.left = len(plan) - k
                for q, y in plan[k:]:       # the grid values the budget never reached
                    self.unreached.setdefault(q.name, []).append(y)
                break
        alone = self._alone()
        self.cut_params = [p.name for p in self.params
                           if not self._bisect_changes(p, written, alone[p.name])]

    def _alone(self) -> dict:
        """``{param: {value: problems}}``: every point judged so far that moved one param
        alone (the others at their values), the written values clean."""
        written = {p.name: p.value for p in self.params}
        seen: dict = {p.name: {p.value: self.current} for p in self.params}
        for key, got in self.problems.items():
            vals = dict(key)
            if key in self.probes or vals.keys() != written.keys():
                continue
            moved = [n for n, x in vals.items() if x != written[n]]
            if len(moved) == 1:
                seen[moved[0]][vals[moved[0]]] = got
        return seen

    def _open(self, p, a: float, b: float) -> bool:
        """Whether bisection has a value of ``p`` left to judge between ``a`` < ``b``: to the
        tolerance, or with a slider's ``step=`` to neighbouring steps (issue 104: an edge left
        1 % of the range wide hatched a clean value such as a mounting plate's width 70)."""
        if p.step > 0 and not p.integer:
            if not b - a > p.step * (1 + 1e-9):
                return False
        elif not (b - a > 1 if p.integer else b - a > self.tol * (p.hi - p.lo)):
            return False
        return p.at((a + b) / 2) not in (a, b)

    def _finish(self) -> None:
        """Each param's runs from every point judged alone; a change between neighbouring
        values judged that the budget left wider than the tolerance a run not judged (where
        the design starts to break there is not known: neither hatched nor clean).  A grid
        value never reached leaves the runs at the resolution reached (the sweep's
        ``skipped``), as a full scan leaves them at a thirty-second of the range."""
        alone = self._alone()
        self.runs = {}
        unreached = getattr(self, "unreached", {})
        for p in self.params:
            seen = alone[p.name]
            xs = sorted(seen)
            gaps = {(a, b) for a, b in zip(xs, xs[1:])
                    if bool(seen[a]) != bool(seen[b]) and self._open(p, a, b)}
            # a grid value the budget never reached between two values judged alike: not
            # judged either (issue 104: "checks clean" when 15 of 147 values were judged)
            left = sorted(unreached.get(p.name, ()))
            gaps |= {(a, b) for a, b in zip(xs, xs[1:])
                     if any(a < u < b and u not in seen for u in left)}
            self.runs[p.name] = _runs(seen, p.value, gaps)

    def _bisect_changes(self, p, written: dict, seen: dict) -> bool:
        """Each change between neighbouring judged values of ``p`` (clean / broken) bisected
        to the tolerance (a count: to neighbouring values); False when the budget stopped."""
        while True:
            xs = sorted(seen)
            todo = [(a, b) for a, b in zip(xs, xs[1:])
                    if bool(seen[a]) != bool(seen[b]) and self._open(p, a, b)]
            if not todo:
                return True
            for a, b in todo:
                m = p.at((a + b) / 2)
                got = self._judge(dict(written, **{p.name: m}))
                if got is None:
                    return False
                seen[m] = got


class _Both(_Scan):
    """:func:`scan_and_sweep`'s one object: the scan within its share of the work, then the
    sweep's plan (:meth:`aidl_lang.params.sweep._Sweep._sweep`) with what is left."""
    share = SCAN_SHARE

    def _sweep(self) -> None:
        total = self.work_left
        self.work_left = total * self.share
        self._scan()
        skipped = self.left
        self.work_left += total * (1 - self.share)
        _Sweep._sweep(self)
        self.left = skipped
        self.report.skipped += skipped
        self._finish()

    def _bisect(self, a: dict, b: dict) -> tuple[float, tuple | None, bool]:
        """One param moved: the bound from the scan's values judged when it bisected that
        change to the tolerance (no new point); else the sweep's bisection."""
        moved = [p for p in self.params if a[p.name] != b[p.name]]
        if len(moved) == 1:
            got = self._along(moved[0], a, b)
            if got is not None:
                return got
        return _Sweep._bisect(self, a, b)

    def _along(self, p, a: dict, b: dict):
        w, v = a[p.name], b[p.name]
        seen = self._alone()[p.name]
        if not seen.get(v):
            return None
        order = sorted((x for x in seen if min(w, v) <= x <= max(w, v)),
                       key=lambda x: abs(x - w))
        last = w
        for x in order:
            if not seen[x]:
                last = x
                continue
            if self._open(p, *sorted((last, x))):
                return None                 # not bisected there: the sweep's own bisection
            start = None if x == v else (dict(a, **{p.name: x}), seen[x])
            return (last - w) / (v - w), start, False
        return None


def _runs(seen: dict, value: float, gaps=frozenset()) -> list[Run]:
    """The judged values of a param (``{value: problems}``) as runs of one state; a broken
    run's problem is the one at its value nearest ``value`` (the first met moving away),
    ``far`` the one at its farthest; between neighbouring values in ``gaps`` a run not
    judged."""
    groups: list = []                       # lists of values judged; (a, b): not judged
    prev = None
    for x in sorted(seen):
        last = groups[-1] if groups else None
        if isinstance(last, list) and (prev, x) not in gaps \
                and bool(seen[last[0]]) == bool(seen[x]):
            last.append(x)
        else:
            if (prev, x) in gaps:
                groups.append((prev, x))
            groups.append([x])
        prev = x
    out = []
    for g in groups:
        if isinstance(g, tuple):
            out.append(Run(g[0], g[1], None))
            continue
        r = Run(g[0], g[-1], bool(seen[g[0]]))
        if r.broken:
            near, far = (g[-1], g[0]) if g[-1] < value else (g[0], g[-1])
            r.code, r.problem = seen[near][0]
            r.far = (far, *seen[far][0])
        out.append(r)
    return out
