"""The local engine: a pool of ``workers`` warm worker processes (:class:`.child.Slot`) on this
machine, each compiling one program at a time, with a hard per-task time-out.

The loop hands the next task to each idle worker and waits (:func:`multiprocessing.connection.
wait`) for the first row or the nearest deadline.  A worker past its deadline is killed and
its row recorded as ``timeout``; a worker that died is recorded as ``crashed``; either is
replaced by a fresh one when it gets its next task, and the batch goes on.
"""
from __future__ import annotations

import time
from collections import deque
from multiprocessing.connection import wait
from typing import Callable, Iterable

from .child import Slot


def run_local(tasks: Iterable[dict], cfg: dict, workers: int, timeout: float,
              on_row: Callable[[dict], None]) -> None:
    """Run every task; ``on_row`` is called with each row as it finishes (in finishing
    order).  On an exception (Ctrl-C included) every worker is killed and it propagates."""
    pending = deque(tasks)
    slots = [Slot() for _ in range(max(1, min(workers, len(pending))))]
    busy: dict = {}                  # the read end of a busy slot -> the slot
    try:
        while pending or busy:
            for slot in slots:
                if slot.task is None and pending:
                    slot.send(pending.popleft(), cfg, timeout)
                    busy[slot.rx] = slot
            nearest = min(s.deadline for s in busy.values())
            readable = wait(list(busy), timeout=max(0.0, nearest - time.monotonic()))
            for conn in readable:
                slot = busy[conn]
                row = slot.receive()
                if row is not None:
                    del busy[conn]
                    on_row(row)
            now = time.monotonic()
            for conn, slot in list(busy.items()):
                if slot.task is not None and now >= slot.deadline and conn not in readable:
                    del busy[conn]
                    on_row(slot.expire())
    finally:
        for slot in slots:
            if busy:
                slot.kill()          # interrupted: do not wait for programs in flight
            else:
                slot.close()
