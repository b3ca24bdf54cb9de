"""``aidl check --sweep`` over every example (examples/*.aidl) and every program models wrote
(data/model_runs/**/*.aidl), ranges declared or not (issue 92): each file that compiles is
swept (a param without a range across its slider's span), and each finding is checked by a
plain compile with ``--set`` at the values it names (the finding's code must be there) and
at the clean end it gives (no error, no warning the written values do not have).  Prints one
line a file and the totals; exit 1 when a file says "nothing swept" while it has a numeric
param, or a finding does not hold under ``--set`` (a file with no numeric param has nothing to
sweep: counted apart).  Not in the suite (minutes of CPU); the
suite's small pass is tests/test_sweep_programs.py.

    PYTHONPATH=$PWD python benchmarks/checks/sweep_programs.py [FILE ...]
"""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOT_COMPARED = {"W0510", "W0521", "W0110"}


def files() -> list[Path]:
    return sorted(ROOT.glob("examples/*.aidl")) + sorted(ROOT.glob("data/model_runs/**/*.aidl"))


def _texts(values: dict, units: dict) -> dict:
    return {n: f"{x:.12g} {units.get(n, '')}".strip() for n, x in values.items()}


def _said(r) -> set:
    return {(d.code, d.span.line if d.span else None) for d in r.diagnostics}


def verify(source: str, path: str, rep) -> list[str]:
    """What does not hold of ``rep``'s findings under a plain ``--set`` compile: the
    finding's code missing at its values, or a problem at the clean end it names."""
    import aidl_lang
    base = _said(aidl_lang.compile(source=source, path=path))
    bad = []
    for f in rep.findings:
        r = aidl_lang.compile(source=source, path=path, overrides=_texts(f.values, rep.units))
        codes = {d.code for d in r.diagnostics}
        if f.code not in codes and not (f.first and f.first[1] in codes):
            bad.append(f"{_texts(f.values, rep.units)}: no {f.code} ({sorted(codes)})")
        end = {}
        for n, (lo, hi) in f.clean.items():
            end[n] = hi if f.values[n] > hi else lo
        r = aidl_lang.compile(source=source, path=path, overrides=_texts(end, rep.units))
        new = [d.code for d in r.diagnostics if d.code not in NOT_COMPARED
               and (d.code, d.span.line if d.span else None) not in base
               and d.severity != "info"]
        if not r.ok or new:
            bad.append(f"clean end {_texts(end, rep.units)}: {new or 'does not compile'}")
    return bad


def main(argv=None) -> int:
    from aidl_lang.params.sweep import sweep
    todo = [Path(a) for a in (argv or [])] or files()
    total = found = wrong = nothing = skipped = none = 0
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
        if not rep.swept and not rep.fixed:
            numeric = any(ln.lstrip().startswith("param ") and '"' not in ln
                          and "true" not in ln and "false" not in ln
                          for ln in src.splitlines())
            nothing += numeric
            none += not numeric
        rel = p.relative_to(ROOT) if p.is_absolute() else p
        print(f"{rel}: {len(rep.swept)} params, {rep.points} points, {rep.seconds:.1f} s, "
              f"{len(rep.findings)} finding(s)" + (f", {len(bad)} NOT HOLDING" if bad else "")
              + ("" if rep.swept else ", no numeric param"), flush=True)
        for b in bad:
            print(f"    {b}", flush=True)
    print(f"{len(todo)} files ({skipped} not compiling, {none} with no numeric param), {found} "
          f"findings, {wrong} not holding under --set, {nothing} with a numeric param not "
          f"swept, {total:.0f} s CPU")
    return 1 if wrong or nothing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
