"""Compiles on a Dask cluster: ``aidl studio --scheduler tcp://HOST:PORT`` (issue 62;
docs/studio.md, "Compiles on Dask").

:class:`Remote` stands where the local :class:`~aidl_lang.host.workers.Pool` stands (the same
``request(request, seconds, wait, prefer) -> (answer, worker)``, ``waiting``, ``workers``,
``stop``), so :meth:`.app.Studio.compile` treats both alike.  Each request becomes one task,
:func:`run_remote`, on a ``dask.distributed`` worker, which hands it to a warm compile process
of its own (:class:`~aidl_lang.host.workers.Worker`, one per worker thread) with the same budget,
wall-time limit (``seconds``, then the process is killed) and memory cap (``RLIMIT_AS``) as
the local workers, and the same no-file-access rule: the program is compiled from memory
under the name ``SESSION/main.aidl`` in a folder of the Dask worker's machine that holds
exactly the session's uploads, sent with the task (:func:`.store.write_files`).

Saturation is answered, never waited out: the cluster's load (tasks running and queued on the
scheduler, against its worker threads) is read at most once a second; past ``threads + queue``
the request is refused at once (``503`` with ``Retry-After``, :class:`~aidl_lang.host.workers.Busy`),
and a task without an answer within ``wait + seconds`` is cancelled and refused the same way.
An unreachable scheduler is :class:`~aidl_lang.host.workers.NotReady` (``503``).
"""
from __future__ import annotations

import os
import tempfile
import threading
import time

from ..host import workers as W
from .compiler import PRELOAD, handler
from .store import read_files, write_files

PROBE_EVERY = 1.0               # s between two reads of the cluster's load
CONNECT_TIMEOUT = 5.0           # s to reach the scheduler

_local = threading.local()      # on a Dask worker: this thread's compile processes


def run_remote(request: tuple, files: dict, budget: float, seconds: float,
               memory: int | None) -> tuple:
    """On a Dask worker: ``request`` (:mod:`.compiler`'s tuples) answered by this thread's
    warm compile process; ``files``: the session's uploads ({name: bytes}).  Returns
    ``("ok", answer)``, ``("timeout", seconds)``, ``("died", message)`` or
    ``("notready", message)``."""
    import multiprocessing
    me = multiprocessing.current_process()
    if me.daemon:
        # A Dask nanny starts its worker as a daemonic process, and multiprocessing refuses
        # children to those (they would be orphaned when it is killed).  The compile process
        # reads its requests from a pipe and exits when the pipe closes, so it cannot outlive
        # this one by more than the compile in flight (at most ``seconds``); the same
        # reasoning as distributed's own `distributed.worker.daemon: False` setting.
        me._config["daemon"] = False
    pool = getattr(_local, "workers", None)
    if pool is None:
        pool = _local.workers = {}
    w = pool.get((budget, memory))
    if w is None:
        w = pool[(budget, memory)] = W.Worker(handler, (budget,), memory, preload=PRELOAD)
    at = folder_at(request)
    if at is not None:
        folder = _mirror(os.path.basename(str(request[at])), files)
        request = request[:at] + (folder,) + request[at + 1:]
    try:
        answer = w.request(request, seconds)
    except W.TimedOut as e:
        return ("timeout", e.seconds)
    except W.Died as e:
        return ("died", str(e))
    except W.NotReady as e:
        return ("notready", str(e))
    if isinstance(answer, dict) and answer.pop("retire", False):
        w.retiring = True
    return ("ok", answer)


def folder_at(request: tuple) -> int | None:
    """Where a :mod:`.compiler` request holds its session's folder: item 1 of a
    ``download``, item 2 of the others that have one (``view``, ...), none in a ``thumb``."""
    if request[0] == "thumb" or len(request) <= 2:
        return None
    return 1 if request[0] == "download" else 2


def _mirror(sid: str, files: dict) -> str:
    """A folder of this machine (mode 0700) holding exactly ``files``, for session ``sid``;
    the folders of sessions idle for :data:`.store.MIRROR_IDLE` s are removed."""
    from .sessions import _ID, Folders
    from .store import MIRROR_IDLE
    if not _ID.fullmatch(sid):
        sid = "x" * 24
    with _mirrors_lock:
        global _mirrors
        if _mirrors is None:
            _mirrors = Folders(os.path.join(tempfile.gettempdir(),
                                            f"aidl-studio-dask-{os.getuid()}"))
            _mirrors.idle = MIRROR_IDLE
        _mirrors.sweep()
    path = _mirrors.folder(sid)
    write_files(path, files)
    return path


_mirrors = None                 # on a Dask worker: the sessions' folders (sessions.Folders)
_mirrors_lock = threading.Lock()


def _load(dask_scheduler=None) -> tuple[int, int]:
    """On the scheduler: ``(worker threads, tasks running or waiting)``."""
    s = dask_scheduler
    threads = sum(ws.nthreads for ws in s.workers.values())
    tasks = sum(len(ws.processing) for ws in s.workers.values())
    tasks += len(getattr(s, "queued", ())) + len(getattr(s, "unrunnable", ()))
    return threads, tasks


class Remote:
    """Compiles sent to the Dask scheduler at ``address`` with ``budget`` (factor of the
    default evaluation budget) and ``memory`` (bytes, each compile process's cap)."""

    def __init__(self, address: str, budget: float = 1.0, memory: int | None = None,
                 queue: int = 16) -> None:
        self.address, self.budget, self.memory, self.queue = address, budget, memory, queue
        self.client = None
        self.lock = threading.Lock()
        self.inflight = 0
        self.probed = (0.0, 0, 0)          # (when, threads, tasks)
        self.workers: list = []            # no local compile processes
        self.restarts = 0                  # compile processes killed on the cluster

    def connect(self):
        """The Dask client (connected on first use); raises :class:`W.NotReady`."""
        with self.lock:
            if self.client is None:
                try:
                    from dask.distributed import Client
                except ImportError as e:
                    raise W.NotReady(f"--scheduler needs Dask ({e.name} is missing: pip "
                                     "install 'aidl-lang[studio]')") from None
                try:
                    self.client = Client(self.address, timeout=f"{CONNECT_TIMEOUT:g}s",
                                         set_as_default=False)
                except (OSError, TimeoutError) as e:
                    raise W.NotReady(f"the compile cluster ({self.address}) cannot be reached: "
                                     f"{e}") from None
            return self.client

    def load(self) -> tuple[int, int]:
        """``(worker threads, tasks running or waiting)`` of the cluster, at most
        :data:`PROBE_EVERY` s old."""
        when, threads, tasks = self.probed
        if time.monotonic() - when > PROBE_EVERY:
            client = self.connect()
            try:
                threads, tasks = client.run_on_scheduler(_load)
            except Exception as e:  # noqa: BLE001 - the scheduler went away
                raise W.NotReady(f"the compile cluster ({self.address}) does not answer: "
                                 f"{type(e).__name__}") from None
            self.probed = (time.monotonic(), threads, tasks)
        return threads, tasks

    @property
    def waiting(self) -> int:
        """Compiles waiting for a thread of the cluster, from the last reading of its load
        (no call to the scheduler: this is asked on the server's event loop)."""
        _, threads, tasks = self.probed
        return max(0, max(tasks, self.inflight) - threads) if threads else 0

    def ready(self) -> tuple[bool, str]:
        """Whether the cluster takes compiles: ``(ok, why not)``."""
        try:
            threads, _ = self.load()
        except W.NotReady as e:
            return False, str(e)
        return (threads > 0, "" if threads else "the compile cluster has no workers")

    def request(self, request: tuple, seconds: float, wait: float | None = None,
                prefer=None):
        """``(answer, None)`` of ``request`` compiled on the cluster; raises
        :class:`W.Busy`, :class:`W.TimedOut`, :class:`W.Died` or :class:`W.NotReady`."""
        wait = 10.0 if wait is None else wait
        client = self.connect()
        threads, tasks = self.load()
        if max(tasks, self.inflight) >= threads + self.queue:
            raise W.Busy(f"every compiler of the cluster is busy ({tasks} compiles)")
        files = {}
        at = folder_at(request)
        if at is not None and os.path.isdir(str(request[at])):
            files = read_files(request[at])
        with self.lock:
            self.inflight += 1
        fut = None
        try:
            fut = client.submit(run_remote, request, files, self.budget, seconds, self.memory,
                                pure=False)
            try:
                said = fut.result(timeout=wait + seconds)
            except TimeoutError:
                fut.cancel()
                raise W.Busy(f"no compiler of the cluster answered within {wait + seconds:g} s")
            except (OSError, ConnectionError) as e:
                raise W.NotReady(f"the compile cluster ({self.address}) does not answer: "
                                 f"{e}") from None
            except W.WorkerError:
                raise
            except Exception as e:  # noqa: BLE001 - KilledWorker, a cancelled or lost task
                # not the program's doing (it runs in a process of its own there): a 503 to
                # try again, not "out of memory"
                raise W.NotReady(f"the compile cluster ({self.address}) lost the compile "
                                 f"({type(e).__name__})") from None
        finally:
            with self.lock:
                self.inflight -= 1
            if fut is not None:
                fut.release()
        status, value = said
        if status == "timeout":
            self.restarts += 1
            raise W.TimedOut(value)
        if status == "died":
            self.restarts += 1
            raise W.Died(value)
        if status == "notready":
            raise W.NotReady(value)
        return value, None

    def stop(self) -> None:
        with self.lock:
            client, self.client = self.client, None
        if client is not None:
            client.close(timeout=5)
