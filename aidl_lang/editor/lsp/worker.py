"""Diagnostics off the server's process: a worker process that runs the pipeline, so that a
newer version of a document can stop a stale analysis.

The language server answers hover, completion and the rest on its event loop; the pipeline
(parse, check, interpret, solve) can take long on an expensive program, and a Python thread
cannot be stopped. So diagnostics are computed by ``python -m aidl_lang.editor.lsp.worker``, one
JSON request per line on its stdin (``{"id", "text", "path", "uri", "solve"}``) and one JSON
answer per line on its stdout (``{"id", "diagnostics": [...]}``, LSP diagnostics).

:class:`Analyzer` (in the server) keeps one worker warm and sends it one job at a time. When a
job becomes stale (a newer edit of the same document), it is abandoned: if it has already run
for :data:`Analyzer.GRACE` seconds the worker is killed and a new one started (about a second
of imports), else its answer is read and dropped. A job that runs past
:data:`Analyzer.TIMEOUT` seconds is killed and reported as one diagnostic. If no worker can be
started, the analysis runs in a thread of the server instead (no preemption, same answers).
"""
from __future__ import annotations

import asyncio
import json
import sys
import time


def _serve() -> int:
    """The worker's loop: read a job per line, answer per line, until stdin closes."""
    import os
    import threading

    from lsprotocol import converters

    from .analysis import diagnostics
    parent = os.getppid()

    def watch():                      # end with the server, even in the middle of a job
        while True:
            time.sleep(2)
            if os.getppid() != parent:
                os._exit(0)
    threading.Thread(target=watch, daemon=True).start()
    conv = converters.get_converter()
    out, sys.stdout = sys.stdout, sys.stderr       # nothing but answers on the real stdout
    for line in sys.stdin:
        try:
            job = json.loads(line)
            diags = diagnostics(job["text"], job["path"], job.get("solve", True), job.get("uri"))
            answer = {"id": job["id"], "diagnostics": conv.unstructure(diags)}
        except Exception as e:        # answered, never a dead worker
            answer = {"id": job.get("id") if isinstance(job, dict) else None,
                      "error": f"{type(e).__name__}: {e}"}
        out.write(json.dumps(answer) + "\n")
        out.flush()
    return 0


class AnalysisTimeout(Exception):
    """The pipeline ran longer than :data:`Analyzer.TIMEOUT` seconds and was stopped."""


class Analyzer:
    """One warm worker process computing diagnostics, one job at a time (see the module doc)."""

    GRACE = 1.0            # seconds a stale job may keep running before its worker is killed
    TIMEOUT = 60.0         # seconds after which any job is stopped
    LIMIT = 1 << 30        # longest answer line (bytes)

    def __init__(self) -> None:
        self.proc: asyncio.subprocess.Process | None = None
        self.lock = asyncio.Lock()
        self.seq = 0
        self.inflight: tuple[int, float, asyncio.Future] | None = None   # id, start, answer
        self.failed = False
        self.restarts = 0

    async def start(self) -> None:
        """Start the worker (called once the server is up, so it warms while the editor opens)."""
        if self.proc is not None and self.proc.returncode is None:
            return
        try:
            self.proc = await asyncio.create_subprocess_exec(
                sys.executable, "-m", "aidl_lang.editor.lsp.worker",
                stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE, limit=self.LIMIT)
        except (OSError, NotImplementedError, RuntimeError):
            self.proc, self.failed = None, True

    async def kill(self) -> None:
        proc, self.proc = self.proc, None
        if proc is not None and proc.returncode is None:
            proc.kill()
            try:
                await asyncio.wait_for(proc.wait(), 5)
            except asyncio.TimeoutError:
                pass
        if self.inflight is not None and not self.inflight[2].done():
            self.inflight[2].cancel()
        self.inflight = None

    async def close(self) -> None:
        await self.kill()

    async def _settle(self) -> None:
        """Before a new job: drop the answer of an abandoned one, or kill its worker if it has
        been running for more than GRACE seconds."""
        if self.inflight is None:
            return
        _, started, fut = self.inflight
        if not fut.done():
            left = self.GRACE - (time.monotonic() - started)
            if left > 0:
                try:
                    await asyncio.wait_for(asyncio.shield(fut), left)
                except (asyncio.TimeoutError, asyncio.CancelledError, Exception):
                    pass
            if not fut.done():
                self.restarts += 1
                await self.kill()
        self.inflight = None

    async def _read(self, job_id: int) -> dict:
        assert self.proc is not None and self.proc.stdout is not None
        while True:
            line = await self.proc.stdout.readline()
            if not line:
                raise EOFError("the analysis worker exited")
            answer = json.loads(line)
            if answer.get("id") == job_id:
                return answer

    async def diagnostics(self, text: str, path: str, uri: str | None, solve: bool = True):
        """The diagnostics of ``text`` as LSP dicts (``Diagnostic`` unstructured); raises
        :class:`AnalysisTimeout` after TIMEOUT seconds. Cancelling the awaiting task abandons
        the job (see :meth:`_settle`)."""
        async with self.lock:
            await self._settle()
            if self.proc is None or self.proc.returncode is not None:
                await self.start()
            if self.proc is None:                        # no subprocess here: a thread
                from lsprotocol import converters

                from .analysis import diagnostics
                d = await asyncio.get_running_loop().run_in_executor(
                    None, diagnostics, text, path, solve, uri)
                return converters.get_converter().unstructure(d)
            self.seq += 1
            job = self.seq
            data = json.dumps({"id": job, "text": text, "path": path, "uri": uri,
                               "solve": solve}) + "\n"
            self.proc.stdin.write(data.encode())
            await self.proc.stdin.drain()
            fut = asyncio.ensure_future(self._read(job))
            self.inflight = (job, time.monotonic(), fut)
        try:
            answer = await asyncio.wait_for(asyncio.shield(fut), self.TIMEOUT)
        except asyncio.TimeoutError:
            async with self.lock:
                if self.inflight is not None and self.inflight[0] == job:
                    self.restarts += 1
                    await self.kill()
            raise AnalysisTimeout(f"the analysis took longer than {self.TIMEOUT:g} s") from None
        async with self.lock:
            if self.inflight is not None and self.inflight[0] == job:
                self.inflight = None
        if "error" in answer:
            raise RuntimeError(answer["error"])
        return answer["diagnostics"]


if __name__ == "__main__":
    sys.exit(_serve())
