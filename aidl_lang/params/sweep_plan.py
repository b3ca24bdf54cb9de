"""What ``aidl check --sweep`` sweeps and how much (:mod:`aidl_lang.params.sweep`): each numeric
param's range (its declared ``min=``/``max=``, else the span the studio's sliders give it:
:func:`default_span`, which ``aidl serve``, the studio and the notebook share), whether a plain number counts (whole steps) or
is a real, the plan of points fixed before the sweep starts (ends, middles, a seeded Latin
hypercube), and the budget the points share, counted in work a compile does (interpreter
steps, objects and the model's unknowns, the same on any machine) rather than in seconds.
"""
from __future__ import annotations

import math


def default_span(kind: str, v: float, counts: bool | None = None) -> tuple[float, float, float]:
    """Slider span for a param without a declared range (``aidl serve``, the studio, the
    notebook: :mod:`aidl_lang.serve.params`; and the range ``aidl check --sweep`` sweeps it
    across): a quarter to twice a length or number, a
    full turn for an angle; a count (``counts``; None: any whole number) in whole steps from 1
    (0 for a count written 0) to twice it, at least 10 (a negative one: twice it to a
    quarter of it)."""
    if kind == "angle":
        return -180.0, 360.0 if v > 180 else 180.0, 1.0
    if counts is None:
        counts = kind == "number" and float(v).is_integer()
    if kind == "number" and counts:
        if v >= 1:
            return 1.0, float(math.ceil(max(2 * v, 10))), 1.0
        if v < 0:
            return float(math.floor(2 * v)), float(math.ceil(v / 4)), 1.0
        return 0.0, 10.0, 1.0
    if v == 0:
        return (-100.0, 100.0, 0.5) if kind == "length" else (-10.0, 10.0, 0.1)
    a, b = sorted((v / 4, v * 2)) if v > 0 else sorted((v * 2, v / 4))
    step = _nice((b - a) / 200)
    return math.floor(a / step) * step, math.ceil(b / step) * step, step


def _nice(x: float) -> float:
    """The 1-2-5 step not above ``x``."""
    if x <= 0:
        return 1.0
    e = math.floor(math.log10(x))
    for m in (5, 2, 1):
        if m * 10 ** e <= x:
            return m * 10 ** e
    return 10 ** e



# work units of one sweep at budget factor 1 (:func:`work`): each compile costs PER_COMPILE,
# its interpreter steps, PER_OBJECT a value or shape it made, PER_UNKNOWN the model's unknowns,
# PER_ITERATION a Newton step, PER_DIAGNOSTIC a thing it says, and what the booleans and the
# checks walk: PER_VERTEX a vertex of the parts' final outlines, PER_PART a part, a point of
# an engraved line, and the fit check's PER_FIT_VERTEX a vertex extruded and PER_BOOLEAN a 3D
# boolean or distance (the Manifold work the count missed before: tool_holder and
# board_enclosure spent 21-30 us a unit, the gallery's tiny designs 1.5).  The weights fitted
# by least squares over 1,500 compiles of the 48 gallery designs' sweeps and the 8,000-hole
# panel's; measured with them (benchmarks/checks/sweep_gallery.py --units: each design's
# default sweep to 40,000 units, its first compile left out, load 8-10 on 2 cores): 2.0 /
# 7.3 / 12.5 us of CPU a unit, min / median / max per design (before: 1.5 / 8.8 / 30.5).  A
# diagnostic counts 40 (the panel's overlaps: 280-670 us each).  WORK x the largest 12.5 us
# is 7.5 s, half the compile's 15 s guard (:func:`aidl_lang.base.limits.now`): a machine
# twice as slow as that busy one still ends a sweep by its work (what load adds: beside two
# busy loops the same compiles took 1.05-1.3x the CPU; at load 10-14 the heavy gallery
# sweeps spent 11.5-14.9 us a unit; h17's load 18-20 1.4x).  The suite's plans
# (tests/test_sweep_gallery.py) need 520,000 at most (tool_holder, divider_tray,
# board_enclosure); the planetary's about 1,500,000
WORK = 600_000
# a count whose range holds at most this many values is tried alone at every one of them
# (:func:`count_values`)
SMALL_COUNT = 12
PER_COMPILE = 1_000
PER_OBJECT = 5
PER_UNKNOWN = 0.25
PER_ITERATION = 80
PER_DIAGNOSTIC = 40
PER_VERTEX = 0.6
PER_PART = 120
PER_FIT_VERTEX = 0.5
PER_BOOLEAN = 50


def work(interp, model, sink=None, drawing=None, solved=None) -> int:
    """The load-independent cost of one compile (the constants above): :data:`PER_COMPILE` +
    the interpreter's steps and objects + the model's unknowns (0 for what was not built) +
    the solve's Newton iterations (``solved``, a :class:`~aidl_lang.solver.SolveResult`) +
    the diagnostics of ``sink`` + what the booleans made (``drawing``: its solid parts'
    outline vertices, its parts, its engraved lines' points) + the fit check's vertices
    extruded and booleans (``drawing.fit_counts``)."""
    n = 0 if model is None else len(getattr(model, "x", ()) or ())
    said = 0 if sink is None else len(sink.items)
    out = (PER_COMPILE + int(getattr(interp, "steps", 0))
           + PER_OBJECT * int(getattr(interp, "objects", 0)) + PER_UNKNOWN * n
           + PER_DIAGNOSTIC * said
           + PER_ITERATION * int(getattr(solved, "iterations", 0) or 0))
    if drawing is not None:
        solids = [p for p in drawing.parts if p.kind == "solid" and p.shape is not None]
        out += (PER_VERTEX * sum(int(p.shape.num_vert()) for p in solids)
                + PER_PART * len(solids) + sum(len(ln[1]) for ln in drawing.lines))
        fit = getattr(drawing, "fit_counts", None) or {}
        out += (PER_FIT_VERTEX * fit.get("vertices", 0)
                + PER_BOOLEAN * (fit.get("booleans", 0) + fit.get("gaps", 0)))
    return int(out)


class Param:
    """A swept param in display units (mm, deg, plain): its written value, the range swept
    (``lo``, ``hi``), ``step`` (0: none), ``integer`` (it counts: whole values only),
    ``declared`` (the range is the file's ``min=``/``max=``; else the sliders' default span),
    ``decl`` (its :class:`~aidl_lang.ast.ParamDecl`) and ``span``."""
    __slots__ = ("name", "unit", "k", "value", "lo", "hi", "step", "integer", "span",
                 "declared", "decl", "grid")

    def __init__(self, name, unit, k, value, lo, hi, step, integer, decl, declared=True):
        self.name, self.unit, self.k, self.decl = name, unit, k, decl
        self.span = decl.span if decl is not None else None
        self.value = round(value * k, 9)
        self.lo, self.hi = round(lo, 9), round(hi, 9)
        self.step = round(step, 9) if step else 0.0
        self.integer, self.declared = integer, declared
        self.grid = 0.0

    def on_grid(self, tolerance: float) -> None:
        """The values swept (a real's without ``step=``) on a grid of the 1-2-5 step under
        half ``tolerance`` x the range: clean bounds such as 12.6 mm, not 12.578125 mm."""
        if not self.integer and not self.step:
            self.grid = _nice(tolerance * (self.hi - self.lo) / 2)

    def at(self, x: float) -> float:
        """``x`` in the range, on the slider's steps (``step=``) when the param has them: the
        values a form offers (and no second compile to move a point onto them)."""
        x = min(max(x, self.lo), self.hi)
        if self.grid > 0:
            g = self.grid
            y = round(x / g) * g
            x = y if self.lo <= y <= self.hi else x
        if self.step > 0 and self.hi - self.lo > self.step:
            x = self.lo + round((x - self.lo) / self.step) * self.step
            if x > self.hi + 1e-9:
                x -= self.step
        return float(round(x)) if self.integer else round(x, 9)

    def text(self, x: float) -> str:
        return value_text(x, self.unit, self.integer)

    def range_text(self) -> str:
        """``14-42 mm``, ``-180 to 180 deg``, ``1-10``: the range swept."""
        a, b = self.text(self.lo), self.text(self.hi)
        return f"{a.split(' ')[0]}{' to ' if self.lo < 0 or self.hi < 0 else '-'}{b}"


def value_text(x: float, unit: str, integer: bool = False) -> str:
    """A value as ``--set`` reads it: ``12.5 mm``, ``30 deg``, ``6``."""
    return str(int(x)) if integer else f"{x:.12g} {unit}".strip()


def display(q) -> tuple[str, float] | None:
    """``(unit, factor)`` of a param's value (display unit = factor x the model's unit:
    mm, deg from radians, plain numbers); None for one that is not a known number."""
    from ..geometry.core.values import ANG, LEN, NUM, Q
    if isinstance(q, bool) or not isinstance(q, Q) or q.const() is None:
        return None
    return {LEN: ("mm", 1.0), ANG: ("deg", 180 / math.pi), NUM: ("", 1.0)}.get(q.dim)


def in_range_calls(program) -> set[str]:
    """The names used inside a ``range(...)`` call anywhere in ``program``: params that
    count (a loop's length takes whole numbers only)."""
    from .. import ast as A
    out: set[str] = set()
    for n in A.walk(program):
        if isinstance(n, A.Call) and isinstance(n.func, A.Name) and n.func.id == "range":
            for a in n.args:
                out.update(m.id for m in A.walk(a) if isinstance(m, A.Name))
    return out


def ambiguous(decl, q, rng: dict | None, counted: set[str]) -> bool:
    """Whether the param of ``decl`` (value ``q``, declared range ``rng`` in model units) is
    a plain whole number that may count or be a real: no unit, a whole value and whole
    bounds, no ``step=``, not used in ``range()`` (``counted``).  The sweep compiles it once
    at a half-way value to tell (:meth:`aidl_lang.params.sweep._Sweep._counts`)."""
    shown = display(q)
    if shown is None or shown[0] or decl.name in counted:
        return False
    rng = rng or {}
    lo, hi = rng.get("min"), rng.get("max")
    if rng.get("step") or (lo is not None and hi is not None and hi <= lo):
        return False
    return all(float(round(x, 9)).is_integer() for x in
               (q.const(), rng.get("min") or 0, rng.get("max") or 0))


def make_param(decl, q, rng: dict | None, counts: bool) -> tuple[Param | None, str]:
    """The :class:`Param` swept for the declaration ``decl`` whose value is ``q`` and whose
    declared range is ``rng`` (model units; None: none), and why it is not swept when it is
    not (``"fixed"``: ``min = max``; ``""``: swept, or not a number).  ``counts``: a plain
    number that takes whole values only (a whole ``step=``, used in ``range()``, or refused
    at a half-way value).  Without both ``min=`` and ``max=`` the range is the one the
    studio's slider offers (:func:`default_span`), a declared end kept."""
    shown = display(q)
    if shown is None:
        return None, ""
    unit, k = shown
    v = q.const()
    rng = rng or {}
    lo, hi, step = rng.get("min"), rng.get("max"), rng.get("step")
    counts = bool(counts) and not unit
    if lo is not None and hi is not None:
        if hi <= lo:
            return None, "fixed" if hi == lo else ""
        return Param(decl.name, unit, k, v, lo * k, hi * k, (step or 0) * k, counts, decl), ""
    kind = {"mm": "length", "deg": "angle"}.get(unit, "number")
    dlo, dhi, _ = default_span(kind, round(v * k, 9), counts=counts)
    a = lo * k if lo is not None else min(dlo, v * k)
    b = hi * k if hi is not None else max(dhi, v * k)
    if b <= a:
        return None, ""
    return Param(decl.name, unit, k, v, a, b, 0.0, counts, decl, declared=False), ""


def count_values(p: Param) -> list[float]:
    """The values of the count ``p`` tried alone (:func:`plan`): every value of a range that
    holds at most :data:`SMALL_COUNT` (a bracket's odd bolt counts), else none past its ends
    and middle."""
    step = p.step if p.step >= 1 else 1.0
    n = int(math.floor((p.hi - p.lo) / step + 1e-9)) + 1
    return [p.at(p.lo + k * step) for k in range(n)] if n <= SMALL_COUNT else []


def related(p: Param, q: Param) -> bool:
    """Whether the range of ``p`` reads ``q`` or the range of ``q`` reads ``p`` (``min=``,
    ``max=``, ``step=`` written over the other param: a dependency the author declared)."""
    return q.name in _reads(p) or p.name in _reads(q)


def _reads(p: Param) -> set:
    from .. import ast as A
    if p.decl is None:
        return set()
    return {n.id for o in p.decl.options for n in A.walk(o.value) if isinstance(n, A.Name)}


def plan(params: list[Param], n_lhs: int, seed: int, pairs: bool | str = True) -> list[dict]:
    """The points fixed before the sweep starts: each param at its low end, middle and high
    end (the others at their written values); then each count at each value of a short range
    (:func:`count_values`), and at either end with each other param at either end, the rest
    at their written values (a combination a random sample misses: a gear's fewest teeth with
    its largest bore); then ``n_lhs`` combinations of a Latin hypercube seeded ``seed`` (two
    or more params), each on the params' steps; the written values and repeats left out.
    ``pairs="related"``: a count at either end only with the params its range reads or whose
    ranges read it (:func:`related`: the dependencies the author declared, checked at their
    corners; the suite's cheaper plan, the full one in benchmarks/checks/sweep_gallery.py)."""
    written = {p.name: p.value for p in params}
    out, seen = [], {tuple(sorted(written.items()))}

    def add(vals):
        k = tuple(sorted(vals.items()))
        if k not in seen:
            seen.add(k)
            out.append(vals)
    for p in params:
        for x in (p.lo, (p.lo + p.hi) / 2, p.hi):
            add(dict(written, **{p.name: p.at(x)}))
    for p in params:
        if p.integer:
            for x in count_values(p):
                add(dict(written, **{p.name: x}))
            for x in (p.lo, p.hi):
                for q in params:
                    if q is not p and (pairs is True or related(p, q)):
                        for end in (q.lo, q.hi):
                            add(dict(written, **{p.name: x, q.name: q.at(end)}))
    if n_lhs and len(params) > 1:
        from scipy.stats import qmc
        u = qmc.LatinHypercube(d=len(params), seed=seed).random(n_lhs)
        for row in u:
            add({p.name: p.at(p.lo + r * (p.hi - p.lo)) for p, r in zip(params, row)})
    return out


def range_fix(source: str, p: Param, lo: float, hi: float):
    """A :class:`~aidl_lang.base.diagnostics.Fix` writing ``min = lo, max = hi`` into the
    declaration of ``p`` (its value kept, its ``step=`` kept; a declared ``min=``/``max=``
    replaced), or None without its spans."""
    from ..base.diagnostics import Fix, Span
    d = p.decl
    if d is None or d.value.span is None or d.span is None:
        return None
    keep = [source[o.span.start:o.span.end] for o in d.options if o.name == "step"]
    value = source[d.value.span.start:d.value.span.end]
    end = d.options[-1].span if d.options else d.value.span
    text = ", ".join([value, f"min = {p.text(lo)}", f"max = {p.text(hi)}"] + keep)
    s = d.value.span
    return Fix(Span(s.file, s.line, s.col, end.end_line, end.end_col, s.start, end.end), text)
