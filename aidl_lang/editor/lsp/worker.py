"""Diagnostics off the server's process: a worker process that runs the pipeline, so that a
newer version of a document can stop a stale analysis.

The language server answers hover, completion and the rest on its event loop; the pipeline
(parse, check, interpret, solve) can take long on an expensive program, and a Python thread
cannot be stopped. So diagnostics are computed by ``python -m aidl_lang.editor.lsp.job``
(:mod:`.job`: the worker's loop, its memory limit; it also draws ``aidl/preview``), one
JSON request per line on its stdin (``{"id", "text", "path", "uri", "solve"}``) and one JSON
answer per line on its stdout (``{"id", "diagnostics": [...], "values": {...}, "facts": {...}}``,
LSP diagnostics (:mod:`.plain`, no lsprotocol import) and, when the document solves, its
solved values for hover and :func:`.hints.solved_facts` for inlay hints and code lenses).

:class:`Analyzer` (in the server) keeps one worker warm and sends it one job at a time. When a
job becomes stale (a newer edit of the same document), it is abandoned: if it has already run
for :data:`Analyzer.GRACE` seconds the worker is killed and a warm spare takes over (the spare
is started after the first answer once a document has been changed, so a session that only
reads files runs one worker; a new worker needs about half a second of imports),
else its answer is read and dropped. A job that runs past
:data:`Analyzer.TIMEOUT` seconds is killed and reported as one diagnostic. If no worker can be
started, the analysis runs in a thread of the server instead (no preemption, same answers).
"""
from __future__ import annotations

import asyncio
import json
import subprocess
import sys
import threading
import time

from ...base.limits import DEFAULT_BUDGET, wall_limit


def diagnostics_json(src: str, path: str, solve: bool = True, uri: str | None = None,
                     values: dict[str, str] | None = None, extra: dict | None = None) -> list[dict]:
    """The pipeline's diagnostics for ``src`` (a file at ``path``) as LSP ``Diagnostic`` dicts
    (:mod:`.plain`; no lsprotocol import, so the worker process starts without it): those
    ``aidl check`` reports, the redundant constraints (``W0401``) included, looked for within
    the same bounds (:data:`aidl_lang.api.REDUNDANCY_SECONDS`, ``REDUNDANCY_ROWS``).

    ``solve=False`` stops after interpretation (cheaper while typing). A diagnostic raised
    inside a template of another file is at its call, the template's place in
    ``relatedInformation``; one still located in another file is put on line 1 with its
    location in the message.  When the
    file solves and ``values`` is a dict, it receives the solved values of the named entities
    (name -> ``Value.text()``, :mod:`aidl_lang.api`) for :func:`.analysis.value_hover`; ``extra``, a
    dict, receives what :func:`.hints.solved_facts` makes of the solved model (inlay hints and
    degrees of freedom per structure).
    """
    from ...pipeline import compile_source
    res = compile_source(src, path, do_solve=solve)
    if res.ok and res.solve is not None:
        from ...api import Result
        result = Result(res, path, src)
        # the redundant constraints (W0401) `aidl check` reports, within its bounds and budget
        result.find_redundant(deadline=res.deadline.at if res.deadline is not None else None)
    if res.ok and res.solve is not None and res.solve.converged and (
            values is not None or extra is not None):
        if values is not None:
            values.update((v.name, v.text()) for v in result.values)
        if extra is not None:
            from .hints import solved_facts
            extra.update(solved_facts(result))
    from .plain import sink_json
    return sink_json(src, path, res.sink.items, uri, res.sink.sources)


class AnalysisTimeout(Exception):
    """The pipeline ran longer than :data:`Analyzer.TIMEOUT` seconds and was stopped."""


def spawn() -> subprocess.Popen | None:
    """Start a worker process (it warms up, importing the pipeline, while the server starts);
    None if no process can be started here."""
    try:
        return subprocess.Popen([sys.executable, "-m", "aidl_lang.editor.lsp.job"],
                                stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    except (OSError, ValueError):
        return None


class Analyzer:
    """One warm worker process computing diagnostics, one job at a time (see the module doc).

    A thread per worker reads its answers and hands them to the waiting coroutine; jobs are
    written from a thread too, so a large document never blocks the event loop."""

    GRACE = 0.5            # seconds a stale job may keep running before its worker is killed
    # seconds of wall time after which any job is stopped: the compile's own budget (CPU
    # seconds) ends it first, with its E0304; this is the wall guard (limits.wall_limit)
    TIMEOUT = wall_limit(DEFAULT_BUDGET.seconds)
    SPARE = True           # keep a second warm worker to take over from a killed one

    def __init__(self, proc: subprocess.Popen | None = None,
                 hold: threading.Event | None = None) -> None:
        self.proc: subprocess.Popen | None = None
        self.lock = asyncio.Lock()
        self.seq = 0
        self.waiting: dict[int, tuple[subprocess.Popen, asyncio.Future]] = {}
        self.inflight: tuple[int, float, asyncio.Future] | None = None   # id, start, answer
        self.restarts = 0
        self.editing = False                 # set by the server on the first change
        self._loop: asyncio.AbstractEventLoop | None = None
        self._proc0 = proc
        self._hold = hold          # set when the start-up front has read its answer from proc
        self.values: dict[str, dict[str, str]] = {}   # uri -> its last analysis' solved values
        self.facts: dict[str, dict] = {}              # uri -> its last solved analysis' solved_facts

    def start(self) -> None:
        """Adopt the worker started early (:func:`spawn`) or start one."""
        self._loop = asyncio.get_running_loop()
        if self.proc is not None and self.proc.poll() is None:
            return
        proc, self._proc0 = self._proc0, None
        hold, self._hold = self._hold, None
        if proc is None or proc.poll() is not None:
            proc, hold = spawn(), None
        self.proc = proc
        if proc is not None:
            threading.Thread(target=self._reader, args=(proc, hold), daemon=True).start()

    def _reader(self, proc: subprocess.Popen, hold: threading.Event | None = None) -> None:
        if hold is not None:       # the front's job comes first; its answer is the front's
            hold.wait()
        for line in proc.stdout:
            try:
                answer = json.loads(line)
            except ValueError:
                continue
            entry = self.waiting.pop(answer.get("id"), None)
            if entry is not None:
                self._loop.call_soon_threadsafe(_settle_future, entry[1], answer, None)
        for job, (p, fut) in list(self.waiting.items()):     # this worker is gone
            if p is proc:
                self.waiting.pop(job, None)
                self._loop.call_soon_threadsafe(_settle_future, fut, None,
                                                EOFError("the analysis worker exited"))

    def kill(self) -> None:
        proc, self.proc = self.proc, None
        if proc is not None and proc.poll() is None:
            proc.kill()
            try:
                proc.wait(5)
            except subprocess.TimeoutExpired:
                pass
        if self.inflight is not None and not self.inflight[2].done():
            self.inflight[2].cancel()
        self.inflight = None

    def close(self) -> None:
        self.kill()
        if self._proc0 is not None and self._proc0.poll() is None:
            self._proc0.kill()

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
                self.kill()
        self.inflight = None

    async def diagnostics(self, text: str, path: str, uri: str | None, solve: bool = True):
        """The diagnostics of ``text`` as LSP dicts (``Diagnostic`` unstructured); raises
        :class:`AnalysisTimeout` after TIMEOUT seconds. Jobs run one at a time; cancelling the
        awaiting task abandons its job (killed at once if it has run GRACE seconds, else the next
        job gives it the rest of GRACE to finish, see :meth:`_settle`)."""
        def here() -> dict:
            values: dict[str, str] = {}
            extra: dict = {}
            d = diagnostics_json(text, path, solve, uri, values, extra)
            return {"diagnostics": d, "values": values, "facts": extra}
        answer = await self._ask({"text": text, "path": path, "uri": uri, "solve": solve}, here)
        self.values[uri] = answer.get("values") or {}
        if answer.get("facts"):                  # a program that does not solve keeps the
            self.facts[uri] = answer["facts"]    # last solved hints (no flicker while typing)
        return answer["diagnostics"]

    async def preview(self, text: str, path: str, uri: str, version, values, here,
                      assembled: bool = False) -> dict:
        """The ``aidl/preview`` result (:func:`.preview.preview`), compiled in the worker like
        the diagnostics: within its memory limit, stopped after TIMEOUT seconds, and the
        pictures it keeps (the last good one per document) in its memory, not the server's.
        ``here()``: the same result computed in this process (when no worker can run)."""
        answer = await self._ask({"kind": "preview", "text": text, "path": path, "uri": uri,
                                  "version": version, "values": values,
                                  "assembled": assembled},
                                 lambda: {"preview": here()})
        return answer["preview"]

    async def _ask(self, payload: dict, here) -> dict:
        """Send one job to the worker and wait for its answer (``here()`` computes it in a
        thread when no worker process can run)."""
        loop = asyncio.get_running_loop()
        async with self.lock:
            await self._settle()
            self.start()
            if self.proc is None:                        # no subprocess here: a thread
                return await loop.run_in_executor(None, here)
            self.seq += 1
            job = self.seq
            fut = loop.create_future()
            self.waiting[job] = (self.proc, fut)
            started = time.monotonic()
            self.inflight = (job, started, fut)
            data = (json.dumps({"id": job, **payload}) + "\n").encode()
            try:
                await loop.run_in_executor(None, _write, self.proc, data)
                answer = await asyncio.wait_for(asyncio.shield(fut), self.TIMEOUT)
            except asyncio.TimeoutError:
                self.restarts += 1
                self.kill()
                raise AnalysisTimeout(f"the analysis took longer than {self.TIMEOUT:g} s") from None
            except asyncio.CancelledError:               # abandoned: a newer edit wants the worker
                if time.monotonic() - started >= self.GRACE:
                    self.restarts += 1
                    self.kill()
                raise
            except OSError:                              # it died: the next job starts another
                self.kill()
                raise EOFError("the analysis worker exited") from None
            self.inflight = None
            if answer.get("retire"):                     # it gave its memory back by exiting
                self.restarts += 1
                self.kill()
            if self._proc0 is None and self.SPARE and self.editing:
                self._proc0 = spawn()        # a warm spare, once the document is being edited
        if "error" in answer:
            raise RuntimeError(answer["error"])
        return answer


def _write(proc: subprocess.Popen, data: bytes) -> None:
    proc.stdin.write(data)
    proc.stdin.flush()


def _settle_future(fut: asyncio.Future, result, exc) -> None:
    if fut.done():
        return
    if exc is not None:
        fut.set_exception(exc)
    else:
        fut.set_result(result)

