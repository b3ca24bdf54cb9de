"""The compiling tools of ``aidl mcp`` (check, render, values, describe) run in warm worker
processes, so that every call ends within its time limit whatever the program does: a thread
cannot be stopped, a process can (issue 37; ``aidl batch`` does the same with its workers).

:class:`Worker` keeps one process (``multiprocessing``, spawn) with its own
:class:`~.tools.Workspace`; a call is sent over a pipe and its answer (or its
:class:`~.tools.Refused`) comes back.  A call that has not answered after twice the budget's
wall time (15 s x the call's ``budget``, so 30 s by default) kills the process and is refused
with a message saying so; the next call starts a fresh process.  The compile's own deadline
normally ends it first, with a located ``E0304``: this is the last resort for what the
deadline cannot interrupt (one long call into a C library).

:class:`Pool` runs calls side by side in up to :data:`POOL_SIZE` workers (issue 48: one slow
compile made every other call wait): a call takes an idle worker (a warm one first; a
process is started on a worker's first call), and waits for one when all are busy.
"""
from __future__ import annotations

import multiprocessing
import queue
import threading

from . import tools as T

READY_SECONDS = 120.0       # a new worker imports the compiler (about a second on a quiet machine)
WALL_FACTOR = 2.0           # a call may run this many times the budget's wall time
POOL_SIZE = 3               # calls that may run at the same time (each in its own process)


def _main(conn, root: str, budget: float) -> None:
    """The worker: answer ``(name, args)`` requests with ``(True, result)`` or
    ``(False, Refused)`` until the pipe closes."""
    ws = T.Workspace(root, budget)
    conn.send("ready")
    while True:
        try:
            name, args = conn.recv()
        except (EOFError, OSError):
            return
        if name not in ("check", "render", "values", "describe"):
            conn.send((False, T.Refused(f"unknown tool `{name}`")))
            continue
        try:
            conn.send((True, getattr(T, name)(ws, *args)))
        except T.Refused as e:
            conn.send((False, T.Refused(str(e))))
        except BaseException as e:      # noqa: BLE001 - answered, never a silent worker
            conn.send((False, T.Refused(f"internal error: {type(e).__name__}: {e}")))


class Worker:
    """One warm process for the compiling tools of the server of ``root`` (default budget
    factor ``budget``); :meth:`call` runs one, one at a time."""

    def __init__(self, root: str, budget: float = 1.0) -> None:
        self.root, self.budget = str(root), budget
        self.proc = None
        self.conn = None
        self.lock = threading.Lock()
        self.restarts = 0

    def _start(self) -> None:
        ctx = multiprocessing.get_context("spawn")
        parent, child = ctx.Pipe()
        proc = ctx.Process(target=_main, args=(child, self.root, self.budget), daemon=True)
        proc.start()
        child.close()
        if not parent.poll(READY_SECONDS) or parent.recv() != "ready":
            proc.kill()
            proc.join()
            raise T.Refused("the compiler's worker process did not start")
        self.proc, self.conn = proc, parent

    def stop(self) -> None:
        """End the worker process (the next call starts another)."""
        proc, self.proc = self.proc, None
        if self.conn is not None:
            self.conn.close()
            self.conn = None
        if proc is not None and proc.is_alive():
            proc.kill()
        if proc is not None:
            proc.join()

    def seconds(self, budget: float | None) -> float:
        """The time limit of a call with ``budget`` (None: the server's)."""
        from ..limits import DEFAULT_BUDGET
        ok = isinstance(budget, (int, float)) and not isinstance(budget, bool) \
            and 0 < budget <= T.MAX_BUDGET
        k = budget if ok else self.budget        # a bad one is refused by the tool itself
        return WALL_FACTOR * DEFAULT_BUDGET.seconds * float(k)

    def call(self, name: str, *args, budget: float | None = None):
        """``tools.NAME(workspace, *args)`` in the worker; its result, or raises
        :class:`~.tools.Refused` (the tool's own refusal, a call past its time limit, or a
        worker that died)."""
        limit = self.seconds(budget)
        with self.lock:
            if self.proc is None or not self.proc.is_alive():
                self._start()
            try:
                self.conn.send((name, args))
                answered = self.conn.poll(limit)
            except (OSError, EOFError):
                answered = False
            if not answered:
                self.restarts += 1
                self.stop()
                raise T.Refused(f"the call took longer than {limit:g} s (twice the budget's "
                                "wall time) and was stopped; build less, or give a larger "
                                "`budget` (at most 4)")
            try:
                ok, value = self.conn.recv()
            except (OSError, EOFError):
                self.restarts += 1
                self.stop()
                raise T.Refused("the compile ended its worker process (out of memory?); "
                                "build less") from None
        if ok:
            return value
        raise value


class Pool:
    """Up to ``size`` workers (:class:`Worker`) for the server of ``root`` (default budget factor
    ``budget``), so that calls run at the same time: a slow call delays only itself.
    :meth:`call` takes an idle worker, the one used last first (its process is warm; a
    worker starts its process on its first call), and waits while all ``size`` are busy."""

    def __init__(self, root: str, budget: float = 1.0, size: int = POOL_SIZE) -> None:
        self.workers = [Worker(root, budget) for _ in range(max(1, size))]
        self.idle: queue.LifoQueue = queue.LifoQueue()
        for w in reversed(self.workers):
            self.idle.put(w)

    def call(self, name: str, *args, budget: float | None = None):
        """:meth:`Worker.call` in an idle worker (waiting for one when all are busy)."""
        w = self.idle.get()
        try:
            return w.call(name, *args, budget=budget)
        finally:
            self.idle.put(w)

    def stop(self) -> None:
        """End every worker's process."""
        for w in self.workers:
            w.stop()
