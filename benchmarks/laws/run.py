"""The law runner (issue 109): every law of ``benchmarks/laws/law_*.py`` over the corpus
(:mod:`benchmarks.laws.corpus`) and over the programs each law generates, with a report per
law: how many programs it was checked on, held, was not applicable to, failed (each named with
its first violation line), and those whose check ran out of time (skipped, named).

    python -m benchmarks.laws.run [--law NAME ...] [--sample K] [--kinds examples,gallery,...]
                                  [--generated N] [--jobs J] [--timeout S] [--json out.json]

A law is a module ``law_<short>.py`` with ``NAME`` (the promise, one line), ``TOLERANCE``
(text), ``applies(entry) -> bool`` and ``check(entry) -> list[str]`` (one line per violation;
``[]``: held), and optionally ``generated(n) -> Iterator[Entry]`` (programs of kind
``generated`` made for it; only that law checks them).  For each program and law:

* ``applies`` false, or ``NotApplicable`` (:mod:`benchmarks.laws.common`) raised: *not
  applicable*;
* ``check`` returns ``[]``: *held*; lines: *failed* (violated), its first line reported;
* any other exception from ``applies`` or ``check``: *failed* (crashed) with the traceback's
  last line: a law that crashes did not hold;
* the check's CPU time past ``--timeout`` seconds (a ``SIGPROF`` timer in the worker; a worker
  that does not answer within four times that plus a minute of wall time is killed as a
  backstop): *timed out*, skipped and named in the report.

Checks run in ``--jobs`` worker processes (forked; 0: in this process), each program's laws
one after another in one worker (they may share its compile: :func:`corpus.compiled`).  The
report's order is the corpus's, whatever the scheduling.  Exit status 1 when a law failed on a
program, else 0.
"""
from __future__ import annotations

import argparse
import gc
import importlib
import json
import multiprocessing as mp
import os
import pkgutil
import signal
import sys
import time
import traceback
from dataclasses import dataclass, field
from multiprocessing.connection import wait as wait_ready
from pathlib import Path
from types import ModuleType
from typing import Iterable

from .common import NotApplicable
from .corpus import KINDS, Entry, counts, iter_corpus

HERE = Path(__file__).resolve().parent
DEFAULT_TIMEOUT = 60.0          # CPU seconds per check
DEFAULT_GENERATED = 100         # programs each law's `generated(n)` is asked for
STATUSES = ("held", "violated", "crashed", "not applicable", "timed out")


class CheckTimeout(BaseException):
    """A check's CPU time ran out (raised by the ``SIGPROF`` timer; a ``BaseException`` so a
    law's ``except Exception`` does not swallow it)."""


@dataclass
class Law:
    """One law: ``short`` (``compiles`` of ``law_compiles.py``), ``name`` (the promise),
    ``tolerance``, and its module's ``applies``, ``check`` and ``generated`` (or ``None``)."""
    short: str
    name: str
    tolerance: str
    applies: object
    check: object
    generated: object = None

    @classmethod
    def of(cls, module: ModuleType | object, short: str | None = None) -> "Law":
        """The law of a module (or any object with the module's names)."""
        if short is None:
            short = getattr(module, "__name__", "law").rsplit(".", 1)[-1]
            short = short[4:] if short.startswith("law_") else short
        return cls(short, getattr(module, "NAME", short), getattr(module, "TOLERANCE", ""),
                   getattr(module, "applies", lambda entry: True), module.check,
                   getattr(module, "generated", None))


def discover(names: Iterable[str] | None = None) -> list[Law]:
    """The laws of ``benchmarks/laws/law_*.py``, by module name; only those whose short name
    (``compiles``) or module name (``law_compiles``) is in ``names`` when given.  Raises
    ``ValueError`` naming a requested law that does not exist."""
    found = sorted(m.name for m in pkgutil.iter_modules([str(HERE)]) if m.name.startswith("law_"))
    wanted = None if not names else set(names)
    if wanted is not None:
        missing = {n for n in wanted if n not in found and f"law_{n}" not in found}
        if missing:
            raise ValueError(f"no such law: {', '.join(sorted(missing))} (laws: "
                             f"{', '.join(m[4:] for m in found) or 'none'})")
    out = []
    for m in found:
        if wanted is None or m in wanted or m[4:] in wanted:
            out.append(Law.of(importlib.import_module(f"{__package__}.{m}")))
    return out


# ------------------------------------------------------------------------ one check
def _last_line(exc: BaseException) -> str:
    lines = traceback.format_exception_only(type(exc), exc)
    text = "".join(lines).strip().splitlines()
    return text[-1] if text else type(exc).__name__


def _on_prof(signum, frame):
    raise CheckTimeout()


def check_one(law: Law, entry: Entry, timeout: float | None) -> dict:
    """``{"status", "line", "violations", "cpu"}`` of ``law`` on ``entry`` (see the module's
    docstring); ``timeout`` in CPU seconds of this process (``None``: none; the timer is only
    set in the main thread)."""
    timer = timeout is not None and timeout > 0 and _main_thread()
    t0 = time.process_time()
    violations: list[str] = []
    try:
        if timer:
            old = signal.signal(signal.SIGPROF, _on_prof)
            signal.setitimer(signal.ITIMER_PROF, timeout)
        try:
            if not law.applies(entry):
                status, line = "not applicable", ""
            else:
                violations = [str(v) for v in (law.check(entry) or [])]
                status = "violated" if violations else "held"
                line = violations[0] if violations else ""
        finally:
            if timer:
                signal.setitimer(signal.ITIMER_PROF, 0)
                signal.signal(signal.SIGPROF, old)
    except CheckTimeout:
        gc.enable()                 # whatever the interrupted stage had paused
        status, line = "timed out", f"more than {timeout:g} s of CPU"
    except NotApplicable as e:
        status, line = "not applicable", str(e)
    except Exception as e:          # a law that crashes did not hold
        status, line = "crashed", _last_line(e)
    return {"status": status, "line": line, "violations": violations[:20],
            "cpu": time.process_time() - t0}


def _main_thread() -> bool:
    import threading
    return threading.current_thread() is threading.main_thread()


# ------------------------------------------------------------------------ workers
def _worker(conn, laws: list[Law], timeout: float | None) -> None:
    """Answer each task ``(index, entry, [law index, ...])`` with one message ``(index, law
    index, result)`` per check, until ``None``.  After a check that timed out, exit: the
    interrupted compile may still run on a thread of its own (``pipeline.run_deep``) and its
    CPU time would count against the next checks; the pool starts a new worker for the
    rest."""
    while True:
        task = conn.recv()
        if task is None:
            return
        i, entry, which = task
        for j in which:
            r = check_one(laws[j], entry, timeout)
            conn.send((i, j, r))
            if r["status"] == "timed out":
                return


def _result(status: str, line: str) -> dict:
    return {"status": status, "line": line, "violations": [], "cpu": 0.0}


class _Pool:
    """``jobs`` forked workers fed one program at a time.  A worker that dies (its pipe
    closes) is a crash of the law it was checking; one past the wall backstop is killed and
    that check reported timed out; either way, and after a timed-out check, a new worker
    takes the program's remaining laws."""

    def __init__(self, jobs: int, laws: list[Law], timeout: float | None):
        self.ctx = mp.get_context("fork")
        self.laws, self.timeout = laws, timeout
        self.backstop = None if not timeout else 4 * timeout + 60
        self.slots = [self._start() for _ in range(jobs)]

    def _start(self):
        parent, child = self.ctx.Pipe()
        p = self.ctx.Process(target=_worker, args=(child, self.laws, self.timeout), daemon=True)
        p.start()
        child.close()
        return {"proc": p, "conn": parent, "task": None, "left": [], "since": 0.0}

    def _stop(self, s) -> None:
        if s["proc"].is_alive():
            s["proc"].kill()
        s["proc"].join()
        s["conn"].close()

    def _give(self, n: int, t) -> None:
        s = self.slots[n]
        try:
            s["conn"].send(t)
        except (BrokenPipeError, OSError):
            self._stop(s)
            s = self.slots[n] = self._start()
            s["conn"].send(t)
        s["task"], s["left"], s["since"] = t, list(t[2]), time.monotonic()

    def _answers(self, n: int, ready) -> tuple[list, bool]:
        """The checks slot ``n`` finished (``[(index, law index, result)]``) and whether its
        worker must be replaced."""
        s = self.slots[n]
        i = s["task"][0]
        out = []
        if s["conn"] in ready:
            try:
                while True:
                    i2, j, r = s["conn"].recv()
                    out.append((i2, j, r))
                    s["left"].remove(j)
                    s["since"] = time.monotonic()
                    if r["status"] == "timed out":
                        return out, True
                    if not s["left"] or not s["conn"].poll():
                        return out, False
            except (EOFError, OSError):
                s["proc"].join(timeout=5)
                j = s["left"].pop(0)
                return out + [(i, j, _result("crashed", "the worker process died (exit "
                                                        f"code {s['proc'].exitcode})"))], True
        if self.backstop and time.monotonic() - s["since"] > self.backstop:
            j = s["left"].pop(0)
            return [(i, j, _result("timed out", f"no answer within {self.backstop:g} s of "
                                                "wall time"))], True
        return out, False

    def run(self, tasks: list[tuple[int, Entry, list[int]]]):
        """Yield ``(index, law index, result)`` as checks finish."""
        todo = list(reversed(tasks))
        try:
            while todo or any(s["task"] is not None for s in self.slots):
                for n, s in enumerate(self.slots):
                    if s["task"] is None and todo:
                        self._give(n, todo.pop())
                ready = wait_ready([s["conn"] for s in self.slots if s["task"] is not None],
                                   timeout=5.0)
                for n, s in enumerate(self.slots):
                    if s["task"] is None:
                        continue
                    out, replace = self._answers(n, ready)
                    yield from out
                    if replace:
                        t, left = s["task"], s["left"]
                        self._stop(s)
                        self.slots[n] = self._start()
                        if left:
                            todo.append((t[0], t[1], left))
                    elif not s["left"]:
                        s["task"] = None
        finally:
            for s in self.slots:
                try:
                    s["conn"].send(None)
                except (BrokenPipeError, OSError):
                    pass
            for s in self.slots:
                s["proc"].join(timeout=5)
                self._stop(s)


# ------------------------------------------------------------------------ the run
@dataclass
class LawReport:
    """What one law did over the run: ``counts`` by status (:data:`STATUSES`), ``failed``
    and ``timed_out`` as ``(program name, status, first line)`` in corpus order, ``checked``
    (held + failed: the programs it applied to and judged), ``generated`` (its own programs),
    ``cpu`` (CPU seconds of its checks)."""
    law: Law
    counts: dict = field(default_factory=lambda: {s: 0 for s in STATUSES})
    failed: list = field(default_factory=list)
    timed_out: list = field(default_factory=list)
    by_kind: dict = field(default_factory=dict)
    generated: int = 0
    cpu: float = 0.0

    @property
    def checked(self) -> int:
        return self.counts["held"] + self.counts["violated"] + self.counts["crashed"]

    @property
    def ok(self) -> bool:
        return not self.failed

    def to_json(self) -> dict:
        return {"law": self.law.short, "promise": self.law.name,
                "tolerance": self.law.tolerance, "checked": self.checked,
                "held": self.counts["held"], "not_applicable": self.counts["not applicable"],
                "failed": [{"program": n, "status": s, "line": ln} for n, s, ln in self.failed],
                "timed_out": [{"program": n, "line": ln} for n, _, ln in self.timed_out],
                "by_kind": self.by_kind, "generated": self.generated,
                "cpu_seconds": round(self.cpu, 3)}


@dataclass
class Report:
    """The run: the laws' reports, the corpus's counts by kind (``corpus``), the generated
    programs' count, the CPU seconds of the checks (summed over the workers) and of making
    the corpus and the generated programs (``setup_cpu``)."""
    laws: list[LawReport]
    corpus: dict
    generated: int
    cpu: float
    setup_cpu: float
    timeout: float | None

    @property
    def ok(self) -> bool:
        return all(r.ok for r in self.laws)

    def to_json(self) -> dict:
        return {"corpus": {"programs": sum(self.corpus.values()), "by_kind": self.corpus,
                           "generated": self.generated},
                "timeout_cpu_seconds": self.timeout, "cpu_seconds": round(self.cpu, 3),
                "setup_cpu_seconds": round(self.setup_cpu, 3),
                "laws": [r.to_json() for r in self.laws]}

    def text(self) -> str:
        size = sum(self.corpus.values())
        kinds = ", ".join(f"{k} {n}" for k, n in self.corpus.items())
        out = [f"corpus: {size} programs ({kinds}) + {self.generated} generated "
               f"= {size + self.generated}"]
        for r in self.laws:
            c = r.counts
            out += ["", f"law {r.law.short}: {r.law.name}"]
            if r.law.tolerance:
                out.append(f"  tolerance: {r.law.tolerance}")
            out.append(f"  {r.checked} checked: {c['held']} held, "
                       f"{c['violated'] + c['crashed']} failed ({c['crashed']} crashed); "
                       f"{c['not applicable']} not applicable; {c['timed out']} timed out; "
                       f"{r.generated} of them generated; {r.cpu:.1f} s CPU")
            for n, s, ln in r.failed:
                out.append(f"  FAILED {n}: {'crashed: ' if s == 'crashed' else ''}{ln}")
            for n, _, ln in r.timed_out:
                out.append(f"  timed out (skipped) {n}: {ln}")
        out += ["", f"{len(self.laws)} laws, {sum(r.checked for r in self.laws)} checks judged, "
                f"{sum(len(r.failed) for r in self.laws)} failed; {self.cpu:.1f} s CPU in the "
                f"checks, {self.setup_cpu:.1f} s making the corpus"]
        return "\n".join(out)


def run(laws: list, entries: Iterable[Entry], jobs: int = 2,
        timeout: float | None = DEFAULT_TIMEOUT, generated: int = DEFAULT_GENERATED,
        progress=None) -> Report:
    """Run ``laws`` (:class:`Law` or law modules) over ``entries`` and each law's
    ``generated(generated)`` programs; ``jobs`` worker processes (0: in this process);
    ``timeout``: CPU seconds per check (``None``: none).  ``progress(done, total)`` is called
    as programs finish.  Returns the :class:`Report`."""
    t0 = time.process_time()
    laws = [x if isinstance(x, Law) else Law.of(x) for x in laws]
    entries = list(entries)
    corpus_counts = counts(entries)
    tasks: list[tuple[int, Entry, list[int]]] = [(i, e, list(range(len(laws))))
                                                 for i, e in enumerate(entries)]
    reports = [LawReport(law) for law in laws]
    n_gen = 0
    names = {e.name for e in entries}
    for j, law in enumerate(laws):
        if law.generated is None or generated <= 0:
            continue
        try:
            made = list(law.generated(generated))
        except Exception as e:            # a generator that crashes: the law failed
            reports[j].failed.append((f"generated/{law.short}", "crashed", _last_line(e)))
            reports[j].counts["crashed"] += 1
            continue
        for e in made:
            name = e.name if e.name not in names else f"{e.name}#{law.short}"
            if name != e.name:
                e = Entry(name, e.source, e.path, dict(e.overrides), e.kind)
            names.add(name)
            tasks.append((len(entries) + n_gen, e, [j]))
            reports[j].generated += 1
            n_gen += 1
    setup = time.process_time() - t0
    results: dict[int, list] = {}
    if jobs <= 0:
        for done, (i, e, which) in enumerate(tasks, 1):
            results[i] = [(j, check_one(laws[j], e, timeout)) for j in which]
            if progress:
                progress(done, len(tasks))
    else:
        pool = _Pool(min(jobs, max(1, len(tasks))), laws, timeout)
        finished = 0
        for i, j, r in pool.run(tasks):
            results.setdefault(i, []).append((j, r))
            if len(results[i]) == len(tasks[i][2]):
                finished += 1
                if progress:
                    progress(finished, len(tasks))
    cpu = 0.0
    for i, e, which in tasks:                      # corpus order, then each law's generated
        for j, r in results.get(i, []):
            rep = reports[j]
            rep.counts[r["status"]] += 1
            rep.cpu += r["cpu"]
            cpu += r["cpu"]
            k = rep.by_kind.setdefault(e.kind, {s: 0 for s in STATUSES})
            k[r["status"]] += 1
            if r["status"] in ("violated", "crashed"):
                rep.failed.append((e.name, r["status"], r["line"]))
            elif r["status"] == "timed out":
                rep.timed_out.append((e.name, r["status"], r["line"]))
    return Report(reports, corpus_counts, n_gen, cpu, setup, timeout)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.laws.run",
                                 description=__doc__.splitlines()[0])
    ap.add_argument("--law", action="append", default=[],
                    help="a law to run, by short name (compiles) or module (law_compiles); "
                         "repeat for several (default: every law_*.py)")
    ap.add_argument("--sample", type=int, default=None,
                    help="K programs of the corpus spread over its kinds (default: all)")
    ap.add_argument("--kinds", default=None,
                    help=f"comma-separated corpus kinds (of {', '.join(KINDS[:-1])}; "
                         "default: all)")
    ap.add_argument("--generated", type=int, default=DEFAULT_GENERATED,
                    help="programs to ask each law's generated(n) for (0: none; default "
                         f"{DEFAULT_GENERATED})")
    ap.add_argument("--jobs", type=int, default=2, help="worker processes (0: this process)")
    ap.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT,
                    help=f"CPU seconds per check (0: none; default {DEFAULT_TIMEOUT:g})")
    ap.add_argument("--json", default=None, help="also write the report as JSON here")
    ap.add_argument("--quiet", action="store_true", help="no progress line on stderr")
    a = ap.parse_args(argv)
    try:
        laws = discover(a.law)
        kinds = None if a.kinds is None else [k.strip() for k in a.kinds.split(",") if k.strip()]
        t0 = time.process_time()
        entries = list(iter_corpus(sample=a.sample, kinds=kinds))
        corpus_cpu = time.process_time() - t0
    except ValueError as e:
        ap.error(str(e))
    if not laws:
        ap.error("no laws found (benchmarks/laws/law_*.py)")

    def progress(done, total):
        if not a.quiet and (done % 25 == 0 or done == total):
            print(f"\r{done}/{total} programs", end="\n" if done == total else "",
                  file=sys.stderr, flush=True)

    rep = run(laws, entries, jobs=a.jobs, timeout=a.timeout or None, generated=a.generated,
              progress=progress)
    rep.setup_cpu += corpus_cpu
    print(rep.text())
    if a.json:
        Path(a.json).write_text(json.dumps(rep.to_json(), indent=1) + "\n", encoding="utf-8")
    return 0 if rep.ok else 1


if __name__ == "__main__":
    sys.exit(main())
