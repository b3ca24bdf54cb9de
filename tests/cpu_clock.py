"""A compile's clock that does not depend on how busy the machine is, for the tests of budgets.

Since issue 83 the compile's budget is CPU seconds itself (aidl_lang/base/limits.py ``now``,
``Deadline``; tests/test_budget_clock.py), with wall time only as its outer guard at
``limits.WALL_GUARD`` times the seconds, and the servers' wall-time limits
(``limits.wall_limit``) far beyond it.  This helper remains for the tests that time their own
work or wait on ``time.monotonic`` beside a compile: on a machine at load 4-6 on 2 cores a
process gets a third of a core, and a wall-clock figure is three times the quiet one.  Here
``time.monotonic`` is replaced by :func:`clock`: this
process's CPU seconds (``time.process_time``), so the same work reaches the same deadline
however loaded the machine is; it never runs slower than a tenth of the wall clock, so a loop
that waits (sleeps) on ``time.monotonic`` still ends.

* in-process: the ``cpu_clock`` fixture (tests/conftest.py) installs it for one test;
* a child ``aidl``: ``subprocess.run(AIDL_CPU + ["check", "p.aidl"], ...)`` runs the command
  line with this clock (``python tests/cpu_clock.py ARGS`` = ``aidl ARGS``);
* :func:`child_cpu` measures the CPU seconds of the children waited for in its block
  (``resource.getrusage(RUSAGE_CHILDREN)``), the figure to compare with a budget.
"""
from __future__ import annotations

import contextlib
import resource
import sys
import time
from pathlib import Path

AIDL_CPU = [sys.executable, str(Path(__file__).resolve())]
# the wall clock's pace at least: 1/10 (a process given less than a tenth of a core for a
# whole compile is not a machine any test here runs on; a sleep still ends)
WALL_FLOOR = 0.1

_real = time.monotonic


def make_clock():
    """A ``time.monotonic`` stand-in: starts at the real value, then advances with this
    process's CPU seconds (or a tenth of the wall seconds, when that is more)."""
    m0, c0 = _real(), time.process_time()

    def clock() -> float:
        m = _real()
        return m0 + max(time.process_time() - c0, (m - m0) * WALL_FLOOR)
    return clock


@contextlib.contextmanager
def cpu_time(*names: str):
    """``with cpu_time():`` the block runs with ``time.monotonic`` (and each of ``names``,
    e.g. ``"perf_counter"``) on :func:`make_clock`'s clock; for a test that cannot take a
    fixture (a Hypothesis test runs its body many times under one)."""
    clock = make_clock()
    names = ("monotonic",) + names
    saved = {n: getattr(time, n) for n in names}
    for n in names:
        setattr(time, n, clock)
    try:
        yield clock
    finally:
        for n, f in saved.items():
            setattr(time, n, f)


@contextlib.contextmanager
def child_cpu():
    """``with child_cpu() as cpu: subprocess.run(...)``; then ``cpu()`` is the user + system
    CPU seconds of the child processes that ended (and were waited for) inside the block."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    got: list[float] = []

    def cpu() -> float:
        return got[0]
    try:
        yield cpu
    finally:
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        got.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)


if __name__ == "__main__":
    time.monotonic = make_clock()
    sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != Path(__file__).parent]
    from aidl_lang.cli import entry
    sys.argv[0] = "aidl"
    entry()
