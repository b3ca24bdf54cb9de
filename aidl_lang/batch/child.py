"""The warm worker process and its handle, :class:`Slot` (docs/batch.md, "Time-outs").

A worker is ``python -m aidl_lang.batch.child RFD WFD``: it imports the compiler once, says
``"ready"``, then compiles task after task sent over a pipe (:class:`multiprocessing.connection.
Connection` framing: pickled ``(task, cfg)`` in, a row out).  The task's clock starts when the
worker is ready, so its start-up (~0.5 s of imports) never counts against a program.  A program
that outlives its time-out is stopped by killing its worker (a thread cannot be stopped), and
the next task gets a fresh one.

It is a plain subprocess rather than a :mod:`multiprocessing` child because Dask's worker
processes are daemonic, and daemonic processes may not start :mod:`multiprocessing` children;
the same :class:`Slot` then serves the local pool (:mod:`.local`) and Dask (:mod:`.cluster`).
The worker runs in a session of its own, so a Ctrl-C at the terminal reaches only the batch,
which then stops its workers; a worker whose batch died reads end-of-file and exits.
"""
from __future__ import annotations

import os
import subprocess
import sys
import time
from multiprocessing.connection import Connection

from .row import blank_row

STARTUP_TIMEOUT = 120.0           # seconds for a fresh worker to import the compiler


class Slot:
    """One worker process, started on demand; at most one task in flight."""

    def __init__(self) -> None:
        self.proc: subprocess.Popen | None = None
        self.tx: Connection | None = None
        self.rx: Connection | None = None
        self.ready = False
        self.task: dict | None = None
        self.timeout = 0.0
        self.deadline = 0.0            # when the task in flight runs out of time
        self.started = 0.0             # when the task in flight started (the worker ready)

    # ---- the process
    def spawn(self) -> None:
        r1, w1 = os.pipe()             # batch -> worker
        r2, w2 = os.pipe()             # worker -> batch
        env = dict(os.environ)
        for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
            env.setdefault(var, "1")    # small matrices: one BLAS thread (cli/__init__.py)
        # the package the batch runs from, also when it is a source checkout not installed
        here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        env["PYTHONPATH"] = os.pathsep.join(p for p in (here, env.get("PYTHONPATH")) if p)
        debug = bool(os.environ.get("AIDL_DEBUG"))
        try:
            self.proc = subprocess.Popen(
                [sys.executable, "-m", "aidl_lang.batch.child", str(r1), str(w2)],
                pass_fds=(r1, w2), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                stderr=None if debug else subprocess.DEVNULL, env=env,
                start_new_session=True)
        finally:
            os.close(r1)
            os.close(w2)
        self.tx = Connection(w1, readable=False)
        self.rx = Connection(r2, writable=False)
        self.ready = False
        self.deadline = time.monotonic() + STARTUP_TIMEOUT

    @property
    def alive(self) -> bool:
        return self.proc is not None

    def kill(self) -> None:
        """End the worker (a runaway program, the end of the batch)."""
        if self.proc is None:
            return
        for conn in (self.tx, self.rx):
            try:
                conn.close()
            except OSError:
                pass
        try:
            self.proc.kill()
        except OSError:
            pass
        self.proc.wait()
        self.proc = self.tx = self.rx = None
        self.ready = False

    def close(self) -> None:
        """Ask the worker to exit after its task (end of input), else kill it."""
        if self.proc is None:
            return
        try:
            self.tx.send(None)
            self.proc.wait(timeout=2)
        except (OSError, subprocess.TimeoutExpired):
            pass
        self.kill()

    # ---- one task
    def send(self, task: dict, cfg: dict, timeout: float) -> None:
        if self.proc is None:
            self.spawn()
        self.task, self.timeout = task, timeout
        if self.ready:
            self._start_clock()
        try:
            self.tx.send((task, cfg))
        except OSError:
            pass               # the worker died before reading: :meth:`receive` says so

    def _start_clock(self) -> None:
        self.started = time.monotonic()
        self.deadline = self.started + self.timeout

    def receive(self) -> dict | None:
        """After :attr:`rx` is readable: the row of the task in flight, or None when the
        message was the worker's ``ready`` (its task's clock starts now).  A worker that died
        gives a ``crashed`` row and is replaced on the next :meth:`send`."""
        try:
            msg = self.rx.recv()
        except (EOFError, OSError):
            code = self.proc.poll() if self.proc is not None else None
            self.kill()
            return self._finish("crashed", f"the worker process died (exit status {code}): "
                                "out of memory, or a crash in a native library "
                                "(AIDL_DEBUG=1 shows the workers' stderr)")
        if msg == "ready":
            self.ready = True
            if self.task is not None:
                self._start_clock()
            return None
        task, self.task = self.task, None
        return msg

    def expire(self) -> dict:
        """The task in flight is past its deadline: kill the worker, the row says why."""
        ready = self.ready
        self.kill()
        if not ready:
            return self._finish("crashed", f"the worker did not start within "
                                f"{STARTUP_TIMEOUT:.0f} s")
        return self._finish("timeout", f"timed out after {self.timeout:g} s (the worker was "
                            "stopped)", compile_s=time.monotonic() - self.started)

    def _finish(self, status: str, failure: str, **extra) -> dict:
        task, self.task = self.task, None
        return blank_row(task, status, failure, **extra)

    def run(self, task: dict, cfg: dict, timeout: float) -> dict:
        """Send one task and wait for its row (the Dask side: one task at a time)."""
        self.send(task, cfg, timeout)
        while True:
            left = self.deadline - time.monotonic()
            if left <= 0 or not self.rx.poll(max(left, 0)):
                return self.expire()
            row = self.receive()
            if row is not None:
                return row


WARM_UP = """solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole bore { c = Circle(center=(0, 0), radius=5) }
}
"""


def _warm_up(rows) -> None:
    """Compile a small program once (the parser's table, the lazy imports of the stages),
    then move everything alive to the collector's permanent generation (:func:`gc.freeze`):
    the objects of the imported modules are never scanned again by the collections that
    each program's allocations set off."""
    import gc
    task = {"id": "warm-up", "path": None, "source": WARM_UP, "sha256": "", "options": "",
            "overrides": {}, "budget": 1.0, "stem": "warm-up"}
    try:
        rows.run_one(task, {})
    except Exception:
        pass
    gc.collect()
    gc.freeze()


def main(argv: list[str]) -> int:
    import signal
    signal.signal(signal.SIGINT, signal.SIG_IGN)       # the batch decides when to stop
    rx = Connection(int(argv[1]), writable=False)
    tx = Connection(int(argv[2]), readable=False)
    # import everything a row needs once, before saying ready
    from . import row as rows
    from .. import pipeline  # noqa: F401
    from ..output import build, encode  # noqa: F401
    from ..solver.diagnosis import diagnose, freedom, redundancy, sliding  # noqa: F401
    _warm_up(rows)
    tx.send("ready")
    while True:
        try:
            msg = rx.recv()
        except (EOFError, OSError):
            return 0
        if msg is None:
            return 0
        task, cfg = msg
        oom = False
        try:
            row = rows.run_one(task, cfg)
        except Exception as e:              # a bug in aidl: this row says so, the batch goes on
            from ..base.limits import is_out_of_memory
            oom = is_out_of_memory(e)
            if not oom:
                row = blank_row(task, "crashed", f"internal error: {type(e).__name__}: {e}")
        if oom:                             # out of memory anywhere: the program's E0304
            row = out_of_memory_row(task)
        tx.send(row)


def out_of_memory_row(task: dict) -> dict:
    """The row of a task that ran out of memory outside the compile's own handler (the
    freedom count, the exact outlines, a writer): an ``error`` row with the program's located
    ``E0304`` (:func:`aidl_lang.pipeline.out_of_memory_sink`), as any program error."""
    from ..pipeline import out_of_memory_sink
    sink = out_of_memory_sink(task.get("path") or task["id"], task.get("source"))
    d = sink.items[0]
    return blank_row(task, "error", errors=[{"code": d.code,
                                             "line": d.span.line if d.span else None,
                                             "column": d.span.col if d.span else None,
                                             "message": d.message}])


if __name__ == "__main__":
    code = main(sys.argv)
    sys.stdout.flush()
    os._exit(code)
