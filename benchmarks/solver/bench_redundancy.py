"""What W0401's search costs on a plain ``aidl check`` (issue 23): the redundancy search
(``pipeline.report_redundancies``: :func:`aidl_lang.solver.diagnosis.redundancy.redundancies`) next to the
whole compile of the same file, CPU milliseconds, best of 10 (the compile: mean of 3), and
whether SciPy was imported (it is not below 250 000 Jacobian cells).

Run:  .venv/bin/python benchmarks/solver/bench_redundancy.py [FILE.aidl ...]   (default: examples)
"""
from __future__ import annotations

import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main(paths: list[str]) -> None:
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.pipeline import compile_source, report_redundancies
    files = paths or sorted(str(p) for p in (ROOT / "examples").glob("*.aidl"))
    print(f"{'file':24s} {'W0401 ms':>9s} {'compile ms':>11s} {'found':>6s}  scipy")
    for p in files:
        src = pathlib.Path(p).read_text()
        c = compile_source(src, p)
        if not c.ok:
            print(f"{pathlib.Path(p).name:24s} does not compile")
            continue
        best, found = 1e9, 0
        for _ in range(10):
            sink = DiagnosticSink()
            t0 = time.process_time()
            report_redundancies(sink, c.solve)
            best = min(best, time.process_time() - t0)
            found = len(sink.items)
        t0 = time.process_time()
        for _ in range(3):
            compile_source(src, p)
        comp = (time.process_time() - t0) / 3
        print(f"{pathlib.Path(p).name:24s} {1e3 * best:9.1f} {1e3 * comp:11.1f} {found:6d}  "
              f"{'scipy' in sys.modules}")


if __name__ == "__main__":
    main(sys.argv[1:])
