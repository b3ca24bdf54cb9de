"""The Dask engine: the same rows on a ``dask.distributed`` cluster (docs/batch.md).

``address`` is a scheduler (``tcp://host:8786``) or ``local``: a :class:`LocalCluster` of
``workers`` single-threaded worker processes on this machine, started and stopped here.
Every task runs :func:`run_task` on a Dask worker, which hands it to a warm worker process of
its own (:class:`.child.Slot`, one per worker thread) with the same hard time-out as the local
pool: a runaway program kills that process, not the Dask worker, and the row says
``timeout``.  Rows come back as they finish (:func:`distributed.as_completed`).
"""
from __future__ import annotations

import threading
from typing import Callable, Iterable

from .row import blank_row

_slots = threading.local()


def run_task(task: dict, cfg: dict, timeout: float) -> dict:
    """On a Dask worker: the row of one task, compiled in this thread's warm worker
    process."""
    from .child import Slot
    slot = getattr(_slots, "slot", None)
    if slot is None:
        slot = _slots.slot = Slot()
    return slot.run(task, cfg, timeout)


class MissingDask(RuntimeError):
    pass


def run_dask(tasks: Iterable[dict], cfg: dict, address: str, workers: int, timeout: float,
             on_row: Callable[[dict], None]) -> None:
    try:
        from dask.distributed import Client, LocalCluster, as_completed
    except ImportError as e:
        raise MissingDask(f"--scheduler needs Dask ({e.name} is missing): "
                          "pip install 'aidl-lang[dask]'") from None
    import signal
    import threading
    tasks = list(tasks)
    cluster = None
    on_main = threading.current_thread() is threading.main_thread()
    if address == "local":
        import logging
        # Ctrl-C goes to the whole foreground process group: the worker processes ignore it
        # (a disposition their exec keeps), so only this process stops, with one line
        # (batch/command.py), as the local pool's workers do (child.py)
        before = signal.signal(signal.SIGINT, signal.SIG_IGN) if on_main else None
        try:
            # the scheduler's HTTP server always starts; on its default port 8787, taken by
            # any other Dask on the machine, it printed a four-line UserWarning: a free
            # port of the loopback interface instead (no dashboard: bokeh is not a dependency)
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address="127.0.0.1:0", silence_logs=logging.ERROR)
        finally:
            if on_main:
                signal.signal(signal.SIGINT, before)
        client = Client(cluster)
    else:
        try:
            client = Client(address, timeout="20s")
        except OSError as e:
            raise OSError(f"cannot reach the Dask scheduler at {address}: {e}") from None
    if on_main:
        # Ctrl-C mutes Dask's loggers before the KeyboardInterrupt is raised: it is raised
        # inside distributed's `sync`, whose cancel callback runs on the event loop's thread
        # at once and could log its traceback before the handler below muted them (seen
        # under load)
        def interrupted(signum, frame):
            _quiet_shutdown()
            raise KeyboardInterrupt
        before_int = signal.signal(signal.SIGINT, interrupted)
    try:
        futures = [client.submit(run_task, t, cfg, timeout, pure=False,
                                 key=f"aidl-{i}-{t['sha256'][:12]}")
                   for i, t in enumerate(tasks)]
        task_of = {f.key: t for f, t in zip(futures, tasks)}
        try:
            for fut in as_completed(futures):
                try:
                    row = fut.result()
                except Exception as e:     # a Dask worker lost more than once (KilledWorker)
                    row = blank_row(task_of[fut.key], "crashed",
                                    f"dask: {type(e).__name__}: {e}")
                on_row(row)
                fut.release()
        except BaseException:
            _quiet_shutdown()
            client.cancel(futures)
            raise
    finally:
        if on_main:
            signal.signal(signal.SIGINT, before_int)
        client.close()
        if cluster is not None:
            cluster.close()


def _quiet_shutdown() -> None:
    """Mute Dask's and Tornado's loggers for an interrupted run's shutdown: cancelling
    mid-flight makes distributed's own callbacks log tracebacks at ERROR (a NameError in
    ``distributed.utils.sync``'s cancel, seen on a fresh clone), which reached the user
    beside the one line an interrupt prints (batch/command.py).  Every logger of those
    families is muted, the children Dask's config sets a level on included."""
    import logging
    # Dask's logging config gives some children their own level (``tornado.application``
    # at ERROR, ``distributed.client`` at WARNING): muting the parents alone left them on
    families = ("distributed", "tornado", "asyncio")
    names = [n for n in list(logging.root.manager.loggerDict)
             if n.split(".")[0] in families] + list(families)
    for name in names:
        logging.getLogger(name).setLevel(logging.CRITICAL + 1)
