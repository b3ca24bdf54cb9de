"""Long run of generated nasty programs (benchmarks/checks/nasty.py) through the real pipeline and
the SVG writer, under an address-space limit; prints cases, failures by kind and timings.

Run:  .venv/bin/python benchmarks/checks/fuzz_nasty.py --start 0 --count 2000 [--mem-gb 2]
      (chunks of a few thousand stay under 10 minutes; seeds start..start+count-1)
      --budget default: the default budget (issue 26: 0 programs over --slow 20 s)

Each program runs under a reduced budget (20 000 steps, 5 000 objects, 100 000 characters,
10 s) unless ``--budget default``, so that the run measures the same laws in less time: no
exception, every diagnostic located (except whole-model ones), never ``ok`` without a
converged solve, no NaN/inf in an SVG, finished within ``--slow`` seconds, memory bounded
by ``--mem-gb`` of address space (``MemoryError`` counts as a failure).  Programs are checked as
``nasty.aidl`` in a temporary folder that holds an import diamond (``nasty.diamond_dir``).
The summary gives the kinds of failure, the slowest program and the peak resident memory.
"""
from __future__ import annotations

import argparse
import collections
import pathlib
import resource
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.base.limits import DEFAULT_BUDGET, Budget  # noqa: E402
from benchmarks.checks.nasty import RandomChooser, diamond_dir, program, verdict  # noqa: E402

BUDGET = Budget(steps=20_000, objects=5_000, size=100_000, seconds=10.0)


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--start", type=int, default=0)
    ap.add_argument("--count", type=int, default=1000)
    ap.add_argument("--mem-gb", type=float, default=2.0)
    ap.add_argument("--show", type=int, default=3, help="failing programs to print")
    ap.add_argument("--budget", choices=["small", "default"], default="small")
    ap.add_argument("--slow", type=float, default=None,
                    help="seconds over which a program counts as slow (default: budget + 5)")
    ap.add_argument("--max-seconds", type=float, default=540,
                    help="stop starting programs after this long (the summary says where)")
    a = ap.parse_args()
    lim = int(a.mem_gb * 2**30)
    resource.setrlimit(resource.RLIMIT_AS, (lim, lim))
    budget = BUDGET if a.budget == "small" else DEFAULT_BUDGET
    slow = a.slow if a.slow is not None else budget.seconds + 5
    tmp = tempfile.TemporaryDirectory()
    diamond_dir(tmp.name)
    path = str(pathlib.Path(tmp.name) / "nasty.aidl")
    kinds: collections.Counter = collections.Counter()
    slowest = (0.0, -1)
    t_all = time.perf_counter()
    shown = 0
    done = 0
    for seed in range(a.start, a.start + a.count):
        if time.perf_counter() - t_all > a.max_seconds:
            break
        done += 1
        src = program(RandomChooser(seed))
        t0 = time.perf_counter()
        v = verdict(src, path, budget=budget, seconds=slow)
        dt = time.perf_counter() - t0
        slowest = max(slowest, (dt, seed))
        kinds[v.split(":")[0] if v else "pass"] += 1
        if v and shown < a.show:
            shown += 1
            print(f"--- seed {seed}: {v}\n{src}")
    total = time.perf_counter() - t_all
    print(f"seeds {a.start}..{a.start + done - 1}: {done} programs in {total:.0f} s "
          f"({total / max(done, 1) * 1e3:.0f} ms each); slowest {slowest[0]:.1f} s (seed {slowest[1]}); "
          f"memory limit {a.mem_gb:g} GB; peak resident "
          f"{resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20:.2f} GB; "
          f"{a.budget} budget, slow over {slow:g} s")
    for k, n in kinds.most_common():
        print(f"  {k:24} {n:6d}")
    return 0 if set(kinds) == {"pass"} else 1


if __name__ == "__main__":
    raise SystemExit(main())
