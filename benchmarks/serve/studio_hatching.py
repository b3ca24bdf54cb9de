"""Does the studio's hatching match ``--set``?  For each gallery entry (or the ids given), the
sweep the studio's sliders show (:func:`aidl_lang.studio.hatching.sweep_ranges`, every slider
at its written value), then N seeded random values of each slider alone (the others at theirs),
each compiled with ``--set``: a value is *broken* when the compile has an error or a warning
the written values do not have (W0521 aside; W0510 unless it only counts openings), and it
should be hatched (inside one of the slider's ``bands``) exactly then.  A compile that fails
is taken as the studio draws it: the params whose ranges or steps follow the slider moved
into them as its form moves them (:func:`_as_drawn`).  Values within the bisection's
tolerance of a band's edge are not counted (the edge is known to that width), nor values
that leave a range following another param (E0124: the studio's form moves the dependent
param into its range, as the sweep does; a plain ``--set`` does not), nor values in a part
the budget left not judged (the row's ``unjudged``: neither hatched nor clean; counted
apart).  Prints each entry's agreement; exit 1 on a mismatch (issue 92: the rounded tab
hatched more than half of three sliders from one combination, each value clean alone).

    PYTHONPATH=$PWD python benchmarks/serve/studio_hatching.py [--n 20] [--seed 0] [ID ...]
"""
from __future__ import annotations

import argparse
import random
import sys
import tempfile
from pathlib import Path


def _said(r) -> set:
    """What a compile says that breaks the design: its errors and warnings, a part's change
    of topology (W0510) included unless it only counts openings (what a count is for:
    docs/language.md, "Sweeping the ranges")."""
    return {(d.code, d.span.line if d.span else None) for d in r.diagnostics
            if d.code not in ("W0521", "W0110") and d.severity != "info"
            and not (d.code == "W0510" and _openings_only(d.message))}


def _openings_only(message: str) -> bool:
    what = message.split(" changes: ", 1)[-1].split(" (not so with the defaults)")[0]
    return all(" openings instead of " in w or " opening instead of " in w
               for w in what.split("; "))


def _as_drawn(entry, name: str, text: str, units: dict):
    """The compile the studio draws for slider ``name`` at ``text``: ``--set``, and when that
    fails, with the params whose ranges or steps follow it moved into them as the form moves
    them (:func:`aidl_lang.studio.compiler.settle`; the sweep does the same): the planetary's
    planet at 32 teeth takes the sun onto its steps of 3 (13, not 12), where a plain ``--set``
    says E0405 (its planets would not sit evenly), a value a visitor never gets."""
    import os
    from aidl_lang.serve.session import Session
    from aidl_lang.studio import gallery
    from aidl_lang.studio.compiler import settle
    r = gallery.compile_entry(entry, {name: text})
    if r.ok:
        return r
    with tempfile.TemporaryDirectory(prefix="aidl-hatching-") as d:
        s = Session(os.path.join(d, "main.aidl"))
        s.load(entry.source)
        _, moved = settle(s.set_params, {name: text}, s.set_params({name: text}))
    if not moved:
        return r
    return gallery.compile_entry(entry, {name: text, **{
        k: f"{x:.12g} {units.get(k, '')}".strip() for k, x in moved.items() if k != name}})


def check_entry(entry, n: int, seed: int, folder: str) -> tuple[int, int, list[str]]:
    """``(values checked, agreeing, mismatches)`` for one gallery entry."""
    from aidl_lang.studio import gallery
    from aidl_lang.studio.compiler import sweep_ranges
    from aidl_lang.params.sweep import TOLERANCE
    got = sweep_ranges(folder, entry.source)
    if not got["ok"]:
        return 0, 0, []
    base = _said(gallery.compile_entry(entry, {}))
    rnd = random.Random(seed)
    checked = agree = 0
    bad, unjudged = [], []
    steps = {p["name"]: p.get("step") or 0 for p in entry.params}
    units = {p["name"]: p.get("unit") or "" for p in entry.params}
    for name, row in got["params"].items():
        step = steps.get(name) or 0
        tol = TOLERANCE * (row["max"] - row["min"])
        edges = [x for b in row["bands"] for x in (b["from"], b["to"]) if x is not None]
        gaps = [(g["from"], g["to"]) for g in row.get("unjudged", [])]
        for _ in range(n):
            x = rnd.uniform(row["min"], row["max"])
            if step > 0:                       # on the slider's steps, as a visitor sets it
                x = min(row["min"] + round((x - row["min"]) / step) * step, row["max"])
            if any(abs(x - e) <= tol for e in edges):
                continue
            if any(a < x < b for a, b in gaps):
                unjudged.append(x)
                continue
            text = f"{x:.6g} {row['unit']}".strip()
            r = _as_drawn(entry, name, text, units)
            new = _said(r) - base
            if any(c == "E0124" for c, _ in new):
                continue
            broken = not r.ok or bool(new)
            hatched = any((b["from"] is None or x > b["from"] + 1e-9)
                          and (b["to"] is None or x < b["to"] - 1e-9) for b in row["bands"])
            checked += 1
            if broken == hatched:
                agree += 1
            else:
                bad.append(f"{name}={text}: {'broken' if broken else 'clean'} but "
                           f"{'hatched' if hatched else 'not hatched'}"
                           + (f" {sorted(c for c, _ in new)}" if new else "")
                           + f" (bands {[(b['from'], b['to']) for b in row['bands']]})")
    if unjudged:
        bad.insert(0, f"({len(unjudged)} values in parts not judged, out of budget: not counted)")
    return checked, agree, bad


def main(argv=None) -> int:
    from aidl_lang.studio import gallery
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--n", type=int, default=20)
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args(argv)
    todo = [e for e in gallery.entries() if not a.ids or e.id in a.ids]
    total = same = 0
    with tempfile.TemporaryDirectory() as d:
        for e in todo:
            checked, agree, bad = check_entry(e, a.n, a.seed, str(Path(d)))
            total += checked
            same += agree
            print(f"{e.id}: {agree}/{checked} values agree", flush=True)
            for b in bad[:5]:
                print(f"    {b}", flush=True)
    print(f"{len(todo)} entries: {same}/{total} slider values agree with --set")
    return 0 if same == total else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
