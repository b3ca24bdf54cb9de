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
where the design changes between clean and broken.  Shares the sweep's machinery (one
parse, the solver reused, the work budget counted the same on any machine, dependent ranges
moved into place as the studio's forms move them: :class:`aidl_lang.params.sweep._Sweep`).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..base.limits import DEFAULT_BUDGET, Budget
from .sweep import TOLERANCE, _Sweep
from .sweep_plan import WORK

# intervals of a slider's range judged (SCAN + 1 values): a band of a thirty-second of
# the range is never missed
SCAN = 32


@dataclass
class Run:
    """Consecutive judged values of one param in one state: ``lo``/``hi`` the first and the
    last value judged (display units), ``broken`` (None: not judged), and for a broken run
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
        side; None: from the range's end) broken."""
        runs = self.runs.get(name, [])
        out = []
        for i, r in enumerate(runs):
            if r.broken:
                before = next((x.lo for x in runs[i + 1:] if x.broken is False), None)
                after = next((x.hi for x in reversed(runs[:i]) if x.broken is False), None)
                if out and out[-1][1] == before and out[-1][0] == after:
                    continue
                out.append((after, before, r))
        return out


def scan(source: str, path: str = "<source>", budget: float | Budget | None = None,
         values: dict | None = None, spans: dict | None = None, only=None,
         n: int = SCAN, tolerance: float = TOLERANCE, work: float | None = None,
         seconds: float | None = None) -> ScanReport:
    """Each numeric param of ``source`` alone across its range, the others at ``values``
    (``--set`` texts; the sliders' values), as the module's docstring says; ``spans``,
    ``only``, ``budget``, ``work``, ``seconds`` and ``tolerance`` as
    :func:`aidl_lang.params.sweep.sweep`'s.  Never raises for a mistake in the program."""
    from ..pipeline import run_deep
    b = budget if isinstance(budget, Budget) else (
        DEFAULT_BUDGET if budget is None else DEFAULT_BUDGET.scaled(float(budget)))
    w = WORK * b.steps / DEFAULT_BUDGET.steps if work is None else float(work)
    s = _Scan(source, path, b, 0, 0, tolerance, w, True, dict(values or {}),
              dict(spans or {}), only)
    s.n = max(2, int(n))
    rep = run_deep(lambda: s.run(b.seconds if seconds is None else float(seconds)))
    out = ScanReport(ok=rep.ok, swept=list(rep.swept), ranges=dict(rep.ranges),
                     units=dict(rep.units), points=rep.points, work=rep.work,
                     errors=list(rep.errors))
    out.runs, out.skipped, out.cut = getattr(s, "runs", {}), getattr(s, "left", 0), \
        getattr(s, "cut_params", [])
    out.values = {p.name: p.value for p in getattr(s, "params", [])}
    return out


class _Scan(_Sweep):
    n = SCAN

    def _fixes(self) -> None:
        pass

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
        written = {p.name: p.value for p in self.params}
        grids = {p.name: self._grid(p) for p in self.params}
        plan, depth = [], max(len(g) for g in grids.values())
        # coarse to fine, the params in turn: the ends of each, then each middle, ...
        for i in range(depth):
            for p in self.params:
                if i < len(grids[p.name]):
                    plan.append((p, grids[p.name][i]))
        judged: dict = {p.name: {p.value: []} for p in self.params}
        self.left = 0
        for k, (p, x) in enumerate(plan):
            got = self._judge(dict(written, **{p.name: x}))
            if got is None:
                self.left = len(plan) - k
                break
            judged[p.name][x] = got
        self.cut_params = []
        for p in self.params:
            if not self._bisect_changes(p, written, judged[p.name]):
                self.cut_params.append(p.name)
        self.runs = {p.name: _runs(judged[p.name], p.value) for p in self.params}

    def _bisect_changes(self, p, written: dict, seen: dict) -> bool:
        """Each change between neighbouring judged values of ``p`` (clean / broken) bisected
        to the tolerance (a count: to neighbouring values); False when the budget stopped."""
        width = self.tol * (p.hi - p.lo)
        while True:
            xs = sorted(seen)
            todo = [(a, b) for a, b in zip(xs, xs[1:]) if bool(seen[a]) != bool(seen[b])
                    and (b - a > 1 if p.integer else b - a > width)]
            if not todo:
                return True
            progressed = False
            for a, b in todo:
                m = p.at((a + b) / 2)
                if m in seen:
                    continue
                got = self._judge(dict(written, **{p.name: m}))
                if got is None:
                    return False
                seen[m] = got
                progressed = True
            if not progressed:
                return True


def _runs(seen: dict, value: float) -> list[Run]:
    """The judged values of a param (``{value: problems}``) as runs of one state; a broken
    run's problem is the one at its value nearest ``value`` (the first met moving away),
    ``far`` the one at its farthest."""
    groups: list[list] = []
    for x in sorted(seen):
        if groups and bool(seen[groups[-1][0]]) == bool(seen[x]):
            groups[-1].append(x)
        else:
            groups.append([x])
    out = []
    for g in groups:
        r = Run(g[0], g[-1], bool(seen[g[0]]))
        if r.broken:
            near, far = (g[-1], g[0]) if g[-1] < value else (g[0], g[-1])
            r.code, r.problem = seen[near][0]
            r.far = (far, *seen[far][0])
        out.append(r)
    return out
