"""The MCP server's calls in the order they were made, and the files they write (issue 91).

A render's worker process makes the file's bytes; the server writes them, here, in the order
the calls were made: each call is numbered as it comes in (:meth:`Calls.arrive`), and a file
is written only when no call made later has written it already (:meth:`Calls.write`), so of
two renders to one path the one called last wins, whatever finishes last.  The calls that edit a
program (``write_program``, ``set_params``) take it one at a time (:meth:`Calls.program`),
so two edits made together both land.  A call the
client cancels (``notifications/cancelled``) writes nothing: its worker process is stopped
(:meth:`Calls.cancel`) and whatever it made is dropped.  Each of these is said on the server's
log (stderr), one line each: ``aidl mcp: #3 render cancelled by the client: ...``.
"""
from __future__ import annotations

import functools
import sys
import threading
from dataclasses import dataclass
from pathlib import Path


def log(text: str) -> None:
    """One line on the server's log (stderr: stdout is the protocol's)."""
    print(f"aidl mcp: {text}", file=sys.stderr, flush=True)


@dataclass
class Call:
    """One tool call: ``seq`` (1, 2, ... in the order they came in), its tool, whether the
    client cancelled it and the worker running it (None when none is)."""
    seq: int
    tool: str
    cancelled: bool = False
    worker: object = None


class Calls:
    """The calls of one server and the files they wrote: file -> the number of the call that
    wrote it last.  ``write_file(target, data, program, shown)`` writes one file."""

    def __init__(self, write_file) -> None:
        self.write_file = write_file
        self.lock = threading.Lock()
        self.count = 0
        self.last: dict[Path, int] = {}
        self.locks: dict = {}

    def program(self, path: str):
        """A lock for the program file ``path`` (as the agent wrote it, normalised): the calls
        that edit it (``write_program`` patches, ``set_params``) read, change and write it
        one at a time, in the order they were made, so no edit is lost to another made at
        the same time."""
        import asyncio
        import os
        key = os.path.normpath(str(path))
        lock = self.locks.get(key)
        if lock is None:
            lock = self.locks[key] = asyncio.Lock()
        return lock

    def arrive(self, tool: str) -> Call:
        """Number a call as it comes in."""
        with self.lock:
            self.count += 1
            return Call(self.count, tool)

    async def work(self, call: Call, pool, name: str, *args, budget: float | None = None):
        """``pool.call(name, *args)`` (:class:`.worker.Pool`) in a thread, for ``call``; when
        the call is cancelled while it waits, its worker process is stopped
        (:meth:`cancel`) and the cancellation goes on."""
        import anyio
        try:
            return await anyio.to_thread.run_sync(
                functools.partial(self._run, call, pool, name, args, budget),
                abandon_on_cancel=True)
        except anyio.get_cancelled_exc_class():
            self.cancel(call)
            raise

    def _run(self, call: Call, pool, name: str, args: tuple, budget: float | None):
        from .tools import Refused
        w = pool.take()
        try:
            with self.lock:
                if call.cancelled:
                    raise Refused("the call was cancelled", "worker_died")
                call.worker = w
            return w.call(name, *args, budget=budget)
        finally:
            with self.lock:
                call.worker = None
                w.cancelled = False         # a cancel that came after the answer
            pool.give(w)

    def cancel(self, call: Call) -> None:
        """The client cancelled ``call``: stop its worker process (if one runs it) and mark it,
        so it writes nothing."""
        with self.lock:
            if call.cancelled:
                return
            call.cancelled = True
            w = call.worker
            if w is not None:
                w.cancel()
        log(f"#{call.seq} {call.tool} cancelled: "
            + ("its worker process was stopped" if w is not None else "before it ran")
            + "; it writes nothing")

    def write(self, call: Call, files: list[tuple]) -> list[tuple[Path, str, int]]:
        """Write ``files`` (``(target, data, program, shown)`` each) of ``call``, in the order
        the calls were made: a file a later call has written already is left as it is.
        Returns ``(target, shown, seq)`` of each file not written, with the later call's
        number (0: ``call`` was cancelled).  Raises ``OSError`` from the first write that
        fails."""
        kept: list[tuple[Path, str, int]] = []
        with self.lock:
            for target, data, program, shown in files:
                later = 0 if call.cancelled else self.last.get(Path(target), 0)
                if call.cancelled or later > call.seq:
                    kept.append((Path(target), shown, later))
                    log(f"#{call.seq} {call.tool}: {shown} not written: "
                        + ("the call was cancelled" if call.cancelled else
                           f"#{later}, called later, wrote it"))
                    continue
                self.write_file(target, data, program, shown)
                self.last[Path(target)] = call.seq
                log(f"#{call.seq} {call.tool} wrote {shown}")
        return kept
