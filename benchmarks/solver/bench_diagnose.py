"""Conflict reports: how long finding the conflicting constraint sets (E0401) takes.

Run:  .venv/bin/python benchmarks/solver/bench_diagnose.py

Families (n points, about 2n constraints):

* ``star``: n points each both ``Fixed`` and ``Coincident`` with one fixed point q (issue 15's
  reproducer: 500 points took 138 s before the vectorised pass);
* ``chain-end``: a chain of n points, each ``HorizontalDistance``/``VerticalDistance`` from the
  previous, and one ``HorizontalDistance`` between the ends that contradicts it, written last
  (the conflict is found only after the whole pass).

Columns: rows of the Jacobian, the solve without diagnosis, ``conflicts()`` alone (all failed
attempts), and how many sets were found; milliseconds, best of 3, on this machine.
"""
from __future__ import annotations

import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.pipeline import compile_source  # noqa: E402
from aidl_lang.solver import Solver, run  # noqa: E402
from aidl_lang.solver.diagnosis.diagnose import conflicts  # noqa: E402


def star(n: int) -> str:
    lines = ["solid s {", "    q = Point((0, 0))", "    Fixed(q)"]
    for i in range(n):
        lines += [f"    p{i} = Point(({i}, 1))", f"    Fixed(p{i})", f"    Coincident(p{i}, q)"]
    return "\n".join(lines + ["}"]) + "\n"


def chain_end(n: int) -> str:
    lines = ["solid s {", "    p0 = Point((0, 0))", "    Fixed(p0)"]
    for i in range(1, n):
        lines += [f"    p{i} = Point(({i}, 0))", f"    HorizontalDistance(p{i - 1}, p{i}, 1)",
                  f"    VerticalDistance(p{i - 1}, p{i}, 0)"]
    lines.append(f"    HorizontalDistance(p0, p{n - 1}, 5)")
    return "\n".join(lines + ["}"]) + "\n"


def measure(src: str):
    c = compile_source(src, "bench.aidl", do_solve=False)
    assert c.ok, [d.message for d in c.sink.items]
    best_solve = best_diag = float("inf")
    found = rows = 0
    for _ in range(3):
        c = compile_source(src, "bench.aidl", do_solve=False)
        solver = Solver(c.model)
        t0 = time.perf_counter()
        res = run(solver, diagnose=False)
        t1 = time.perf_counter()
        sets = []
        for f in solver.trace.failures:
            sets += conflicts(solver, f.attempt.rows, f.attempt.cols, solver.x)
        t2 = time.perf_counter()
        assert not res.converged
        best_solve, best_diag = min(best_solve, t1 - t0), min(best_diag, t2 - t1)
        found, rows = len(sets), res.n_equations
    return rows, best_solve * 1e3, best_diag * 1e3, found


def main() -> None:
    print(f"{'family':10} {'n':>5} {'rows':>6} {'solve ms':>9} {'conflicts ms':>13} {'sets':>5}")
    for name, fam in (("star", star), ("chain-end", chain_end)):
        for n in (100, 300, 500, 1000):
            rows, ts, td, found = measure(fam(n))
            print(f"{name:10} {n:5d} {rows:6d} {ts:9.1f} {td:13.1f} {found:5d}")


if __name__ == "__main__":
    main()
