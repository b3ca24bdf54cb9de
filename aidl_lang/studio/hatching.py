"""What the studio's sliders hatch (``POST /api/sweep``, issue 92): each slider alone, the others
at their values, scanned across its range (:func:`aidl_lang.params.sweep_scan.scan`: a band between
clean values and scattered counts included, each change bisected), and the combinations that
break the design only together from the program's sweep (:func:`aidl_lang.params.sweep.sweep`), said
in words and hatching no slider; the two within one budget
(:func:`aidl_lang.params.sweep_scan.scan_and_sweep`), what it cut said as not judged.  Run by the studio's sweep workers
(:mod:`aidl_lang.studio.compiler`).  Not part of the stable API.
"""
from __future__ import annotations

import math
import os


def sweep_ranges(folder: str, source: str, budget=None, values: dict | None = None) -> dict:
    """``source`` (named ``folder/main.aidl``: its imports from the session's uploads) as its
    sliders mark it, within one sweep budget for the whole request (a param with no declared
    range across its slider's span), each slider alone at the others' ``values`` (``--set``
    texts; None: the written values): ``{"ok", "swept", "points", "skipped", "work",
    "summary", "combinations", "params": {name: {"min", "max", "unit", "clean": [lo, hi],
    "below", "above", "bands", "unjudged"}}}`` (display units: mm, deg, plain).  ``bands``:
    every part of the range where that slider alone breaks the design, ``{"from", "to",
    "lo", "hi", "code", "text"}``: the values strictly between ``from`` and ``to`` (the clean
    values judged on either side; None: from the range's end) and those from ``lo`` to ``hi``
    (the broken values judged at the band's ends, both included: a band next to a part not
    judged ends at its own value, ``from == lo``, and a value broken alone between two such
    parts is a band ``lo == hi``, a point), ``text`` as the page says it (``32.2-39.6 mm: a
    ledge ...``, ``at 215 mm: ...``, ``from 320 mm: ...``).  ``clean``: the clean part that holds the slider's
    value (else the nearest one; empty: none), its ends on the slider's steps (inward); ``below``/``above``: None, or the band
    next to it on that side (``{"at": its clean end, "from"/"to", "code", "text"}``,
    ``text`` as ``above 26.4 mm: a wall of `plate` ...``).  ``unjudged``: the parts of the
    range where the budget cut the bisection between a clean and a broken value
    (``{"from", "to", "text"}``, the values strictly between: neither hatched nor in
    ``clean``); ``skipped``: the points planned and not judged; ``points``, ``work``: what
    the request judged and spent (:func:`aidl_lang.params.sweep_scan.scan_and_sweep`).  A
    combination (two or more sliders away from their values together) hatches no slider:
    ``combinations`` says it in words, each bound judged on both sides with the other sliders
    at the failing values (``off above 24 mm with r = 18 mm; r above 4.5 mm with off = 25 mm:
    a wall ...``, :meth:`~aidl_lang.params.sweep.SweepReport.combinations`: the page words
    it as its other texts).
    ``ok`` false: the program does not compile at these values (nothing swept)."""
    from ..serve.params import declared_params
    from ..serve.wording import for_forms
    from ..params.sweep_scan import scan_and_sweep
    path = os.path.join(folder, "main.aidl")
    declared = {p.name: p for p in declared_params(source, path) or []}
    spans = {n: (p.min, p.max) for n, p in declared.items()
             if not p.declared and p.min is not None and p.max is not None}
    values = {k: v for k, v in (values or {}).items() if k in declared}
    alone, rep = scan_and_sweep(source, path, budget=budget, values=values, spans=spans)
    out = {"ok": rep.ok, "swept": list(rep.swept), "points": rep.points,
           "skipped": rep.skipped, "work": rep.work, "summary": rep.text(), "params": {},
           "combinations": _combinations(rep, for_forms)}
    if not rep.ok:
        return out
    for name in alone.swept:
        p = declared.get(name)
        if p is not None and p.min is not None and p.max is not None:
            out["params"][name] = _row(p, alone, name, for_forms)
    out["complete"] = not rep.skipped and not any(q["unjudged"] for q in out["params"].values())
    return out


def _combinations(rep, for_forms) -> list[str]:
    """Each combination of the sweep ``rep`` in words: which sliders, past which values (each
    judged on both sides, the others held), and what breaks there (``off above 24 mm with r =
    18 mm; ...: a wall ...``), not a code."""
    combos = [f for f in rep.findings if len(f.clean) >= 2]
    return [for_forms(f"{line.rsplit(': ', 1)[0]}: {f.problem or f.code}")
            for line, f in zip(rep.combinations(), combos)]


def _row(p, alone, name: str, for_forms) -> dict:
    """The slider row of param ``p`` from the scan ``alone``."""
    value = alone.values.get(name, p.value)
    hatches = alone.broken(name)
    runs = alone.runs.get(name, [])
    # the clean part that holds the slider's value, else the one nearest it (the value in a
    # band); none: the slider alone breaks the design everywhere (``clean`` empty)
    cleans = [r for r in runs if r.broken is False]
    cur = min(cleans, default=None, key=lambda r: max(r.lo - value, value - r.hi, 0.0))
    clean = [] if cur is None and runs else [
        _stop(p, p.min if cur is None or cur is runs[0] else cur.lo, up=True),
        _stop(p, p.max if cur is None or cur is runs[-1] else cur.hi, up=False)]
    row = {"min": p.min, "max": p.max, "unit": p.unit, "clean": clean,
           "below": None, "above": None, "bands": [],
           "unjudged": [{"from": a, "to": b, "text": f"{_shown(a, '')}–{_shown(b, p.unit)}: "
                         "not checked in the time allowed"} for a, b in alone.unjudged(name)]}
    for after, before, r in hatches:
        a = None if after is None else _stop(p, after, up=False)
        b = None if before is None else _stop(p, before, up=True)
        below = b is not None and b <= value + 1e-9
        # an end next to a part not judged is the band's own broken value (issue 113: the
        # telephone's `base_w` broken at 215 alone, and from 320 at the slider's end, were
        # bands of no value strictly between their ends, drawn as nothing)
        shut_a, shut_b = after is not None and after == r.lo, before is not None and before == r.hi
        where = (f"{_shown(p.min, '')}–{_shown(p.max, p.unit)}" if a is None and b is None else
                 f"at {_shown(b, p.unit)}" if a is None and shut_b and b <= p.min else
                 f"up to {_shown(b, p.unit)}" if a is None and shut_b else
                 f"below {_shown(b, p.unit)}" if a is None else
                 f"at {_shown(a, p.unit)}" if b is None and shut_a and a >= p.max else
                 f"from {_shown(a, p.unit)}" if b is None and shut_a else
                 f"above {_shown(a, p.unit)}" if b is None else
                 f"at {_shown(a, p.unit)}" if shut_a and shut_b and a == b else
                 f"at {_shown(r.lo, p.unit)}" if r.lo == r.hi and p.step and p.step > 0
                 and abs(b - a - 2 * p.step) <= 1e-9 * max(1.0, abs(b)) else
                 f"{_shown(a, '')}–{_shown(b, p.unit)}")
        text = f"{where}: {for_forms(r.problem)}"
        far = r.far
        if far and far[1] != r.code:
            text += f"; at {_shown(far[0], p.unit)}: {for_forms(far[2])}"
        band = {"from": a, "to": b, "lo": r.lo, "hi": r.hi, "code": r.code, "text": text}
        row["bands"].append(band)
        if not clean:
            continue
        if below and b == clean[0]:
            row["below"] = {"at": b, "from": a, "code": r.code, "text": text}
        elif not below and a == clean[1]:
            row["above"] = {"at": a, "to": b, "code": r.code, "text": text}
    return row


def _stop(p, x: float, up: bool) -> float:
    """``x`` moved onto the slider of param ``p`` (its ``min + k * step``), up or down: a clean
    value is shown where the slider stops, on the clean side."""
    if not p.step or p.step <= 0:
        return x
    for end in (p.min, p.max):      # a slider's end is a stop (the grid may not reach it):
        if abs(x - end) <= 1e-9 * max(1.0, abs(end)):   # a clean range runs to the end
            return end
    k = (x - p.min) / p.step
    k = math.ceil(k - 1e-9) if up else math.floor(k + 1e-9)
    return round(min(max(p.min + k * p.step, p.min), p.max), 9)


def _shown(x: float, unit: str) -> str:
    """A number as the sliders show it: ``26.4 mm``, ``30 deg``, ``6``."""
    return f"{float(x):.6f}".rstrip("0").rstrip(".") + (f" {unit}" if unit else "")
