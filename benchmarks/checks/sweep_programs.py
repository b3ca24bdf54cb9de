"""``aidl check --sweep`` over every example (examples/*.aidl, examples/generators/*.aidl) and
every program models wrote
(data/model_runs/**/*.aidl), ranges declared or not, params or not (issue 92): each file that
compiles is swept (a param without a range across its slider's span; a program without a
numeric param by the numbers that size its parts, :mod:`aidl_lang.params.sweep_literals`), and each
finding is checked by a plain compile at the values it names (``--set``; for a lifted number
the file itself with the value written in place of the literal, the edit a maker makes: the
finding's code must be there) and at the clean end it gives (no error, no warning the written
values do not have).  Prints one line a file and the totals; exit 1 when a file that compiles
says "nothing swept", or a finding does not hold.  Not in the suite (minutes of CPU); the
suite's small pass is tests/test_sweep_programs.py.

    PYTHONPATH=$PWD python benchmarks/checks/sweep_programs.py [FILE ...]
"""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOT_COMPARED = {"W0510", "W0521", "W0110"}


def files() -> list[Path]:
    return (sorted(ROOT.glob("examples/*.aidl")) + sorted(ROOT.glob("examples/generators/*.aidl"))
            + sorted(ROOT.glob("data/model_runs/**/*.aidl")))


def _texts(values: dict, units: dict) -> dict:
    return {n: f"{x:.12g} {units.get(n, '')}".strip() for n, x in values.items()}


def _said(r) -> set:
    return {(d.code, d.span.line if d.span else None) for d in r.diagnostics}


def _at(source: str, path: str, rep, values: dict):
    """The plain compile at ``values``: ``--set``, or for a program whose numbers were lifted
    the file with the values written in place of its literals, its parts compared with the
    file's as ``--set`` compares them with the defaults (W0510, the pipeline's
    ``check_topology``)."""
    import aidl_lang
    from aidl_lang.output.checks import check_topology
    from aidl_lang.params.sweep_literals import written
    texts = _texts(values, rep.units)
    if not rep.lifted:
        return aidl_lang.compile(source=source, path=path, overrides=texts)
    r = aidl_lang.compile(source=written(source, rep.lifted, texts), path=path)
    base = aidl_lang.compile(source=source, path=path)
    if r.ok and base.ok:
        check_topology(base.compiled.drawing, r.compiled.drawing, texts, r.sink)
    return r


def verify(source: str, path: str, rep) -> list[str]:
    """What does not hold of ``rep``'s findings under a plain compile at their values
    (:func:`_at`): the finding's code missing at its values, or a problem at the clean end
    it names."""
    import aidl_lang
    base = _said(aidl_lang.compile(source=source, path=path))
    bad = []
    for f in rep.findings:
        r = _at(source, path, rep, f.values)
        codes = {d.code for d in r.diagnostics}
        if f.code not in codes and not (f.first and f.first[1] in codes):
            bad.append(f"{_texts(f.values, rep.units)}: no {f.code} ({sorted(codes)})")
        end = {}
        for n, (lo, hi) in f.clean.items():
            end[n] = hi if f.values[n] > hi else lo
        r = _at(source, path, rep, end)
        new = [d.code for d in r.diagnostics if d.code not in NOT_COMPARED
               and (d.code, d.span.line if d.span else None) not in base
               and d.severity != "info"]
        if not r.ok or new:
            bad.append(f"clean end {_texts(end, rep.units)}: {new or 'does not compile'}")
    return bad


def main(argv=None) -> int:
    from aidl_lang.params.sweep import sweep
    todo = [Path(a) for a in (argv or [])] or files()
    total = found = wrong = nothing = skipped = lifted = 0
    for p in todo:
        src = p.read_text(encoding="utf-8")
        rep = sweep(src, str(p))
        if not rep.ok:
            skipped += 1
            continue
        total += rep.seconds
        found += len(rep.findings)
        bad = verify(src, str(p), rep)
        wrong += len(bad)
        nothing += not rep.swept and not rep.fixed
        lifted += bool(rep.lifted)
        rel = p.relative_to(ROOT) if p.is_absolute() else p
        print(f"{rel}: {len(rep.swept)} params" + (" (lifted)" if rep.lifted else "")
              + f", {rep.points} points, {rep.seconds:.1f} s, "
              f"{len(rep.findings)} finding(s)" + (f", {len(bad)} NOT HOLDING" if bad else "")
              + ("" if rep.swept else ", NOTHING SWEPT"), flush=True)
        for b in bad:
            print(f"    {b}", flush=True)
    print(f"{len(todo)} files ({skipped} not compiling, {lifted} swept by their numbers: no "
          f"numeric param), {found} findings, {wrong} not holding at their values, {nothing} "
          f"not swept, {total:.0f} s CPU")
    return 1 if wrong or nothing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
