""""Describe the part" on the server: the model loop (:func:`.describe.describe`) runs in its
own process, memory-capped like a compile worker and killed at its deadline, because the
programs the model writes are compiled there and are as untrusted as a visitor's.  Its events
come back over a pipe and are yielded here, one by one, as the rounds finish.

:func:`stream` is an async generator of the events of :func:`.describe.describe` (``round``,
``done``, ``error``); it always ends with ``done`` or ``error``, also when the process dies
(``error``: "the model loop stopped: ...").
"""
from __future__ import annotations

import multiprocessing
import time

from starlette.concurrency import run_in_threadpool

from ..host import workers as W

DEADLINE = 180.0            # s the whole loop may take (model calls included)
MEMORY = 1500 << 20         # bytes: the loop process's address-space cap


def _main(conn, description, config, folder, deadline) -> None:
    W.limit_memory(MEMORY)
    from .compiler import hide_paths
    from .describe import describe
    try:
        for event in describe(description, config, folder, deadline_s=deadline):
            conn.send(hide_paths(event, folder))        # no server path reaches a visitor
    except MemoryError:
        conn.send({"type": "error", "message": "the model's program needs more memory than "
                                              "the studio gives a compile (E0304)"})
    except Exception as e:          # noqa: BLE001 - an event, never a silent end
        conn.send(hide_paths({"type": "error",
                              "message": f"internal error: {type(e).__name__}: {e}"}, folder))
    conn.close()


async def stream(description, config: dict, folder: str, deadline: float = DEADLINE):
    """The loop's events for ``description`` (the visitor's text) against the operator's
    model ``config``, compiling in the session's ``folder``."""
    ctx = multiprocessing.get_context("spawn")
    parent, child = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_main, args=(child, description, config, folder, deadline - 5),
                       daemon=True)
    proc.start()
    child.close()
    end = time.monotonic() + deadline

    def next_event():
        left = end - time.monotonic()
        if left <= 0 or not parent.poll(left):
            return {"type": "error", "message": f"the model loop took longer than "
                                                f"{deadline:g} s and was stopped"}
        try:
            return parent.recv()
        except (EOFError, OSError):
            return {"type": "error", "message": "the model loop stopped: its process ended "
                                                "(out of memory?)"}
    try:
        while True:
            event = await run_in_threadpool(next_event)
            yield event
            if event.get("type") in ("done", "error"):
                return
    finally:
        parent.close()
        if proc.is_alive():
            proc.kill()
        await run_in_threadpool(proc.join)
