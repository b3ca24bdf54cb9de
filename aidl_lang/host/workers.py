"""Warm worker processes that always answer in time: the compile of a program runs in a process
that is killed when it runs past its limit, so one slow or hungry program never blocks a server
(issue 37 for the MCP server; issue 53 for the studio, which serves strangers).

:class:`Worker` keeps one process (``multiprocessing``: forkserver where the platform has it,
else spawn; :func:`context`).  It is started with a *target*,
a top-level function ``target(*args) -> handle`` run once in the new process (imports, warm
caches); ``handle(request) -> answer`` then answers every request sent over the pipe (and
``handle.idle()``, when the handler has one, runs after each answer is sent: work the asker
need not wait for, such as collecting the request's garbage; ``handle.quiet()`` when no
request came within :data:`QUIET` seconds of the answer: longer work, out of the way of the
requests that follow an answer at once).  Both
request and answer must pickle.  A request that has not answered within its ``seconds`` kills
the process (:class:`TimedOut`); a process that dies (out of memory: ``memory`` caps its
address space with ``RLIMIT_AS``) raises :class:`Died`; the next request starts a fresh one.

:class:`Pool` runs requests side by side in up to ``len(workers)`` processes: a request takes an
idle worker (the one it asks for first, then the one used last: its process is warm) and waits
for one while all are busy, at most ``wait`` seconds, then raises :class:`Busy`.

Errors: every failure is a :class:`WorkerError`; the front ends (``aidl mcp``, ``aidl studio``)
turn them into their own refusals.
"""
from __future__ import annotations

import multiprocessing
import os
import threading
import time

READY_SECONDS = 120.0       # a new worker imports the compiler (about a second on a quiet machine)


class WorkerError(Exception):
    """A request that got no answer."""


class TimedOut(WorkerError):
    """The request ran past its time limit (``seconds``); the process was killed."""

    def __init__(self, seconds: float) -> None:
        super().__init__(f"no answer within {seconds:g} s")
        self.seconds = seconds


class Died(WorkerError):
    """The process ended while answering (out of memory, or killed)."""


class NotReady(WorkerError):
    """A new process did not start within :data:`READY_SECONDS`."""


class Busy(WorkerError):
    """Every worker of the pool stayed busy for the request's whole ``wait``."""


def limit_memory(limit: int | None, raise_with: str | None = None) -> None:
    """Cap this process's address space at ``limit`` bytes (:func:`aidl_lang.base.memory.limit_memory`,
    Linux ``RLIMIT_AS``): a program that needs more gets a ``MemoryError`` or ends its
    worker, never the machine's memory."""
    from ..base.memory import limit_memory as cap
    cap(limit, raise_with)


def rss(pid: int | str = "self") -> int:
    """The resident memory of process ``pid`` (default: this one) in bytes (0 where /proc is
    missing)."""
    try:
        import os
        with open(f"/proc/{pid}/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


def context(preload: tuple[str, ...] = ()):
    """The start method of worker processes: ``forkserver`` where the platform has it, else
    ``spawn``.  A forkserver is one clean process (started on the first worker, from a fresh
    interpreter, as spawn starts one) that imports the modules named in ``preload`` once;
    each worker after it is a fork of it, its imports done: a new worker costs about 0.05 s
    of CPU instead of 1.9 s (numpy, scipy, trimesh, Manifold and the compiler imported again
    by every spawned process), so a worker replaced after a time-out, a death or its
    ``recycle`` count answers at once.  ``preload`` counts only until the forkserver
    starts (one per process); a module it lacks is imported by the worker itself."""
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    ctx = multiprocessing.get_context("forkserver")
    if preload:
        _PRELOAD.update(preload)
        ctx.set_forkserver_preload(sorted(_PRELOAD))
    return ctx


_PRELOAD: set[str] = set()
QUIET = 0.3     # s without a request after an answer before the handler's quiet() runs


def _main(conn, target, args: tuple, memory: int | None, env: dict | None = None,
          nice: int = 0) -> None:
    """The worker process: build the handler, then answer requests until the pipe closes.
    ``env``: the environment of the process that started it (a forkserver's fork has the
    environment the forkserver started with); ``nice``: added to the process's niceness (a
    background worker yields the CPU to those a visitor waits for)."""
    if nice > 0:
        try:
            os.nice(nice)
        except OSError:
            pass
    if env is not None and env != os.environ:
        import tempfile
        os.environ.clear()
        os.environ.update(env)
        tempfile.tempdir = None         # TMPDIR read again
    if memory:
        limit_memory(memory)
    handle = target(*args)
    try:
        conn.send("ready")
    except OSError:         # the parent left while this one warmed up (a server shut down
        return              # at once): nothing to answer, and no traceback on its stderr
    while True:
        try:
            request = conn.recv()
        except (EOFError, OSError):
            return
        try:
            conn.send(handle(request))
        except OSError:     # (BrokenPipeError: the parent stopped waiting)
            return
        idle = getattr(handle, "idle", None)
        if idle is not None:
            idle()
        quiet = getattr(handle, "quiet", None)
        if quiet is not None:
            try:
                asked = conn.poll(QUIET)
            except (EOFError, OSError):
                return
            if not asked:
                quiet()


class Worker:
    """One warm process answering requests with ``target(*args)``'s handler, one at a time
    (:meth:`request`); ``memory``: its address-space cap in bytes (None: none); ``nice``: its
    process's niceness added (0: as this process)."""

    def __init__(self, target, args: tuple = (), memory: int | None = None,
                 recycle: int = 0, preload: tuple[str, ...] = (), nice: int = 0) -> None:
        self.target, self.args, self.memory = target, tuple(args), memory
        self.nice = nice
        self.preload = tuple(preload)   # modules a forkserver imports once (:func:`context`)
        self.recycle = recycle      # > 0: a process retires after answering this many requests
        self.answered = 0           # requests the current process answered
        self.proc = None
        self.conn = None
        self.lock = threading.Lock()
        self.restarts = 0           # processes killed or lost (timeouts, deaths)
        self.requests = 0
        self.retiring = False       # set: the next request starts a fresh process
        self.cancelled = False      # set by cancel(): the request in flight (or starting) ends
        self.starting = None        # the process _start waits for (stop() ends it too)

    def _start(self) -> None:
        ctx = context(self.preload)
        parent, child = ctx.Pipe()
        proc = ctx.Process(target=_main, args=(child, self.target, self.args, self.memory,
                                               dict(os.environ), self.nice), daemon=True)
        proc.start()
        child.close()
        self.starting = proc
        try:
            ready = parent.poll(READY_SECONDS) and parent.recv() == "ready"
        except (EOFError, OSError):
            ready = False
        finally:
            self.starting = None
        if not ready:
            proc.kill()
            proc.join()
            raise NotReady("the compiler's worker process did not start")
        self.proc, self.conn = proc, parent
        self.answered = 0

    def stop(self) -> None:
        """End the worker process (the next request starts another), and one starting: its
        start fails at once (before, a studio stopped while a sweep worker restarted waited
        for it, up to READY_SECONDS, and was killed, its new worker orphaned)."""
        starting = self.starting
        if starting is not None and starting.is_alive():
            starting.kill()
        proc, self.proc = self.proc, None
        if self.conn is not None:
            self.conn.close()
            self.conn = None
        if proc is not None and proc.is_alive():
            proc.kill()
        if proc is not None:
            proc.join()

    def cancel(self) -> None:
        """Stop the request in flight (or starting) from another thread: its process is killed
        (the waiting :meth:`request` raises :class:`Died`; the next request starts a fresh
        process)."""
        self.cancelled = True
        proc = self.proc
        if proc is not None and proc.is_alive():
            proc.kill()

    def request(self, request, seconds: float):
        """Send ``request`` and return the handler's answer; raises :class:`TimedOut` past
        ``seconds`` (the process is killed), :class:`Died` or :class:`NotReady`."""
        with self.lock:
            if self.retiring:
                self.retiring = False
                self.stop()
            if self.proc is None or not self.proc.is_alive():
                self._start()
            if self.cancelled:              # cancelled while its process started
                self.cancelled = False
                raise Died("the request was cancelled")
            self.requests += 1
            try:
                self.conn.send(request)
                answered = self.conn.poll(seconds)
            except (OSError, EOFError):
                answered = False
            if not answered:
                self.restarts += 1
                self.stop()
                raise TimedOut(seconds)
            try:
                answer = self.conn.recv()
                self.answered += 1
                if self.recycle > 0 and self.answered >= self.recycle:
                    self.retiring = True    # its memory back: a fresh process takes over
                return answer
            except (OSError, EOFError):
                self.restarts += 1
                self.stop()
                if self.cancelled:
                    self.cancelled = False
                    raise Died("the request was cancelled") from None
                raise Died("the worker process ended while compiling (out of memory?)") from None

    def renew(self) -> bool:
        """Replace a retiring worker's process now (the answer that retired it is already
        given), so that its next request does not wait for a new process to start; True when
        a new process runs.  A request that comes meanwhile waits for it (nothing is lost)."""
        with self.lock:
            if not self.retiring:
                return False
            self.retiring = False
            self.stop()
            try:
                self._start()
            except NotReady:
                return False
            return True

    def rss(self) -> int:
        """The process's resident memory in bytes (0 when it is not running)."""
        proc = self.proc
        return rss(proc.pid) if proc is not None and proc.pid is not None else 0


class Pool:
    """Workers that answer side by side: :meth:`take` lends an idle one."""

    def __init__(self, workers: list[Worker]) -> None:
        if not workers:
            raise ValueError("a pool needs at least one worker")
        self.workers = list(workers)
        self.idle: list[Worker] = list(self.workers)    # the end is the most recently used
        self.cond = threading.Condition()
        self.waiting = 0

    def take(self, wait: float | None = None, prefer: Worker | None = None,
             stick: float = 0.0) -> Worker:
        """An idle worker (``prefer`` when idle, else the one used last), waiting while all are
        busy: at most ``wait`` seconds (None: as long as it takes), then :class:`Busy`.
        ``stick``: seconds to wait for ``prefer`` while it is busy and another is idle (a
        request it answers from what it kept, which another worker would compile again)."""
        end = None if wait is None else time.monotonic() + wait
        with self.cond:
            self.waiting += 1
            try:
                if stick > 0 and prefer is not None and prefer in self.workers:
                    until = time.monotonic() + (stick if wait is None else min(stick, wait))
                    while prefer not in self.idle:
                        left = until - time.monotonic()
                        if left <= 0:
                            break
                        self.cond.wait(left)
                while not self.idle:
                    left = None if end is None else end - time.monotonic()
                    if left is not None and left <= 0:
                        raise Busy(f"every worker stayed busy for {wait:g} s")
                    self.cond.wait(left)
            finally:
                self.waiting -= 1
            w = prefer if prefer is not None and prefer in self.idle else self.idle[-1]
            self.idle.remove(w)
            return w

    def give(self, w: Worker) -> None:
        """Return a worker lent by :meth:`take`."""
        with self.cond:
            self.idle.append(w)
            self.cond.notify_all()      # (a request sticking to another worker may be waiting)

    def request(self, request, seconds: float, wait: float | None = None,
                prefer: Worker | None = None, stick: float = 0.0):
        """:meth:`Worker.request` in an idle worker (:meth:`take`); returns ``(answer,
        worker)``."""
        w = self.take(wait, prefer, stick)
        try:
            return w.request(request, seconds), w
        finally:
            self.give(w)

    def stop(self) -> None:
        """End every worker's process."""
        for w in self.workers:
            w.stop()
