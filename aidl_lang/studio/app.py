"""The studio's web server: Starlette routes over a pool of compile workers (issue 53).

Every route but the page's files answers JSON (or a file); the server keeps no program: the
page sends the program text with each request, so any process behind the port can answer any
request (several ``uvicorn`` workers, several machines).

Routes:

* ``GET /``, ``GET /embed``: the page (the embed shows one design's picture and sliders, for an
  ``<iframe>`` on another site).  ``GET /static/NAME``: its files, from a table read at start-up
  (no path is joined onto the filesystem).
* ``GET /api/config``: formats (``available``: this server can make it), machines, PDF paper
  sizes, limits, whether "Describe the part" is on.
* ``GET /api/gallery``, ``GET /api/gallery/ID``, ``GET /api/thumb/ID.svg``: the gallery.
* ``GET /api/docs?name=NAME``: ``aidl docs NAME`` (the code pane's hover).
* ``POST /api/session``, ``POST /api/close``: a tab's session (its upload folder).
* ``POST /api/upload?sid=..&name=..`` (the file as the body), ``GET /api/files?sid=..``,
  ``POST /api/delete``: a session's drawings and imports.  ``&import=infer`` (or
  ``pieces``) on the upload of a ``.dxf``/``.svg`` also answers the drawing as a program to
  edit (``aidl import [--infer]``): ``program`` and ``notes``, or ``import_error``;
  ``&import=drawing``: a program that uses it as it is (``Drawing2D``).
* ``GET /favicon.ico``: the page's icon.
* ``POST /api/view``: ``{"sid", "source", "values", "defaults"}`` -> the preview (SVG,
  diagnostics, params, the ``values`` it was drawn with, the ``dropped`` ones; see
  :func:`.compiler.view`).  One preview of a session compiles at a time; one that waited
  while a newer one of the session came is answered ``{"superseded": true}`` uncompiled.
  ``POST /api/download/FORMAT``: the same plus ``"settings"`` -> the file.
* ``POST /api/sweep``: ``{"sid", "source", "values"}`` -> the program checked across its
  params' ranges, each slider alone with the others at their ``values`` (:func:`.compiler.
  sweep_ranges`: each slider's clean range and what happens past it; the combinations in
  words), asked by the page in the background after a picture of a new program or values.
  Run by the sweep workers (``sweepers``, apart from the previews' compilers; on the cluster
  with ``--scheduler``), bounded by the sweep's budget, answered from a cache keyed by the
  program's text, the values and the bytes of the session's uploads (the same program is
  swept once), and the session's sweep in flight is stopped when it asks for another or
  its tab closes (``/api/close``) and no other session waits for it (:class:`Sweeps`).
* ``POST /api/glb``: ``{"sid", "source", "values", "settings"}`` -> the 3D view's GLB (a
  smaller mesh than the download, made from the preview's drawing; gzip when the browser
  takes it).
* ``POST /api/describe``: ``{"sid", "description"}`` -> the model loop's rounds as
  newline-delimited JSON (only when the operator set ``AIDL_STUDIO_MODEL_URL``).
* ``GET /healthz``, ``GET /metrics``: readiness and Prometheus metrics (:mod:`.metrics`).

Shared state (``--store redis://...``: uploads and rate counters in Redis, :mod:`.store`) and
compiles on a Dask cluster (``--scheduler``, :mod:`.remote`) let any process of any machine
answer any request.

Many users: each compile runs in a worker process (:mod:`aidl_lang.host.workers`) with the
compile's budget (CPU seconds), a wall-time limit (ten times that, and 10 s) and a memory cap; a request waits at most
``wait`` seconds for a worker and at most ``queue`` requests wait, past that the answer is
``503`` with ``Retry-After`` and a message the page shows.  Each client (its address; behind
a proxy, uvicorn's ``--forwarded-allow-ips``) has a rate limit (``limits``' moving window):
past it, ``429`` with ``Retry-After``.  No request reads or writes a file outside its
session's folder (:mod:`.sessions`); programs import only from there and the standard library.
"""
from __future__ import annotations

import base64
import contextlib
import hashlib
import json
import os
import re
import time
from dataclasses import dataclass, field
from importlib import resources

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.middleware import Middleware
from starlette.requests import Request
from starlette.responses import JSONResponse, PlainTextResponse, Response, StreamingResponse
from starlette.routing import Route

from ..host import workers as W
from ..base.limits import DEFAULT_BUDGET, MAX_SOURCE_BYTES, wall_limit
from . import compiler
from .metrics import Metrics, RequestMetrics
from .ahead import complete
from .sessions import MAX_UPLOAD, Refused, new_id
from .store import StoreDown, down, limiter_storage, open_store

TYPES = {"html": "text/html; charset=utf-8", "js": "text/javascript; charset=utf-8",
         "css": "text/css; charset=utf-8", "json": "application/json",
         "txt": "text/plain; charset=utf-8", "md": "text/plain; charset=utf-8",
         "svg": "image/svg+xml", "png": "image/png", "ico": "image/x-icon"}
MAX_VALUES = 256            # customizer values in one request
MAX_VALUE = 256             # characters of one value (and of a name)
MAX_BODY = MAX_SOURCE_BYTES + 65_536


@dataclass
class Settings:
    """The operator's settings (``aidl studio`` options, passed to every server process as
    ``AIDL_STUDIO_*`` environment variables, see :meth:`from_env`)."""

    data: str = ""                  # the sessions' folders live here
    compilers: int = 2              # compile worker processes per server process
    memory_mb: int = 1500           # address-space cap of one compile worker
    budget: float = 1.0             # factor of the default evaluation budget
    kill_after: float = 0.0         # s of wall time a compile may run; 0: limits.wall_limit
    wait: float = 10.0              # s a request waits for a free worker before "busy"
    queue: int = 16                 # requests that may wait at once before "busy" at once
    rate: str = "300/minute"        # per client (``limits`` notation)
    describes: int = 2              # model loops that may run at once
    sweepers: int = 1               # sweep worker processes per server process; 0: no sweeps
    recycle: int = 200              # a worker's process is replaced after this many answers
    store: str = ""                 # redis://HOST:PORT/DB: uploads and rate counters there
    scheduler: str = ""             # tcp://HOST:PORT: compiles on this Dask cluster
    ahead: str = "none"             # gallery designs swept ahead of time: all, none or ids
    model: dict | None = field(default=None, repr=False)   # describe.model_config()

    ENV = {"data": "AIDL_STUDIO_DATA", "compilers": "AIDL_STUDIO_COMPILERS",
           "memory_mb": "AIDL_STUDIO_MEMORY_MB", "budget": "AIDL_STUDIO_BUDGET",
           "wait": "AIDL_STUDIO_WAIT", "queue": "AIDL_STUDIO_QUEUE",
           "rate": "AIDL_STUDIO_RATE", "describes": "AIDL_STUDIO_DESCRIBES",
           "sweepers": "AIDL_STUDIO_SWEEPERS", "recycle": "AIDL_STUDIO_RECYCLE",
           "store": "AIDL_STUDIO_STORE", "scheduler": "AIDL_STUDIO_SCHEDULER",
           "ahead": "AIDL_STUDIO_AHEAD"}

    @classmethod
    def from_env(cls, env=os.environ) -> "Settings":
        s = cls()
        for key, var in cls.ENV.items():
            if env.get(var):
                kind = type(getattr(s, key))
                try:
                    setattr(s, key, kind(env[var]))
                except ValueError:
                    what = {int: "an integer", float: "a number"}.get(kind, "a text")
                    raise ValueError(f"{var}={env[var]!r} is not {what}") from None
        from .describe import model_config
        s.model = model_config(env)
        return s

    def to_env(self) -> dict[str, str]:
        return {var: str(getattr(self, key)) for key, var in self.ENV.items()}

    @property
    def seconds(self) -> float:
        """The wall-time limit of one compile request (:func:`~aidl_lang.base.limits.wall_limit`:
        its budget is CPU seconds, so a busy server does not refuse what a quiet one accepts)."""
        return self.kill_after or wall_limit(DEFAULT_BUDGET.seconds * self.budget)


def static_files() -> dict[str, bytes]:
    """The page's files: the studio's ``static/`` folder, and from ``aidl serve``'s the 3D view
    (``view3d.js``) and three.js (``vendor/three/...``)."""
    files: dict[str, bytes] = {}

    def walk(folder, prefix: str, keep) -> None:
        for f in folder.iterdir():
            name = prefix + f.name
            if f.is_file() and keep(name):
                files[name] = f.read_bytes()
            elif f.is_dir() and f.name != "__pycache__":
                walk(f, name + "/", keep)
    walk(resources.files("aidl_lang.serve") / "static", "",
         lambda n: n == "view3d.js" or n.startswith("vendor/three/"))
    walk(resources.files(__package__) / "static", "", lambda n: True)
    return files


def _csp(page: bytes, embed: bool) -> str:
    """The page's Content-Security-Policy: scripts only from this server (and the page's own
    inline scripts by hash), pictures from here, data: and blob: (the preview is an SVG blob);
    the embed may be framed by any site, the studio only by itself."""
    hashes = " ".join(
        "'sha256-" + base64.b64encode(hashlib.sha256(m.group(1)).digest()).decode() + "'"
        for m in re.finditer(rb"<script[^>]*>(.*?)</script>", page, re.S) if m.group(1).strip())
    return ("default-src 'self'; script-src 'self' " + hashes + "; "
            "style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; "
            "connect-src 'self' blob: data:; worker-src 'self' blob:; object-src 'none'; "
            "base-uri 'none'; form-action 'self'; "
            + ("frame-ancestors *" if embed else "frame-ancestors 'self'"))


class Limited(Exception):
    """A request refused for the server's sake: ``status`` 429 or 503, ``retry`` seconds."""

    def __init__(self, status: int, message: str, retry: int) -> None:
        super().__init__(message)
        self.status, self.message, self.retry = status, message, retry


def refusal(status: int, message: str, retry: int | None = None, **extra) -> JSONResponse:
    headers = {"Retry-After": str(retry)} if retry is not None else None
    return JSONResponse({"error": message, **extra}, status_code=status, headers=headers)


async def read_json(request: Request) -> dict:
    """The request's JSON object, at most :data:`MAX_BODY` bytes.  Raises :class:`Refused`."""
    size = request.headers.get("content-length")
    if size is not None and (not size.isdigit() or int(size) > MAX_BODY):
        raise Refused(f"a request has at most {MAX_BODY:,} bytes")
    body = bytearray()
    async for chunk in request.stream():
        body += chunk
        if len(body) > MAX_BODY:
            raise Refused(f"a request has at most {MAX_BODY:,} bytes")
    try:
        doc = json.loads(body)
    except ValueError:
        raise Refused("the request is not JSON") from None
    except RecursionError:          # [[[[...]]]] 100,000 deep: json's parser recurses
        raise Refused("the request is nested too deeply: it is not what this address "
                      "takes") from None
    if not isinstance(doc, dict):
        raise Refused("the request is not a JSON object")
    return doc


def _text(v: str, what: str) -> str:
    """``v`` checked as text the answer may quote: a lone UTF-16 surrogate (``"\\ud800"`` in
    the JSON) cannot be written back as UTF-8.  Raises :class:`Refused`."""
    try:
        v.encode("utf-8")
    except UnicodeEncodeError:
        raise Refused(f"{what} is not valid text (it holds a lone UTF-16 surrogate)") from None
    return v


def program_of(doc: dict) -> tuple[str, dict]:
    """``(source, values)`` of a view or download request, checked.  Raises :class:`Refused`."""
    source = doc.get("source")
    if not isinstance(source, str):
        raise Refused("give the program as `source` (text)")
    _text(source, "the program")
    if len(source.encode("utf-8", "surrogatepass")) > MAX_SOURCE_BYTES:
        raise Refused(f"a program has at most {MAX_SOURCE_BYTES:,} bytes")
    values = doc.get("values") or {}
    if not isinstance(values, dict) or len(values) > MAX_VALUES:
        raise Refused(f"`values` is an object of at most {MAX_VALUES} param values")
    out = {}
    for k, v in values.items():
        _text(k, "a param's name")
        if isinstance(v, bool):         # a checkbox (the sweep sends them as they are)
            v = "true" if v else "false"
        if not isinstance(v, (str, int, float)) or len(k) > MAX_VALUE:
            raise Refused(f"the value of “{str(k)[:40]}” is a number, a text or true/false")
        if len(str(v)) > MAX_VALUE:     # (issue 113: the limit said, no backticks)
            raise Refused(f"“{k}” takes at most {MAX_VALUE} characters (this one has "
                          f"{len(str(v)):,}): shorten it")
        out[k] = _text(str(v), f"the value of `{k[:40]}`")
    return source, out


def settings_of(fmt: str, doc: dict) -> None:
    """Check a download's format and ``settings`` before any compile (:func:`.compiler.
    download_settings`).  Raises :class:`Refused`."""
    from ..output import FORMATS
    suffix = "." + str(fmt).lower().lstrip(".")
    if suffix not in FORMATS:
        raise Refused(f"`{fmt[:40]}` is not a format this studio makes; it makes "
                      + ", ".join(sorted({f[1:] for f in FORMATS})))
    try:
        compiler.download_settings(suffix, doc.get("settings"))
    except ValueError as e:
        raise Refused(str(e)) from None


def defaults_of(doc: dict) -> dict:
    """The ``defaults`` of a view request (``{name: default}``: the params' defaults the page's
    values were chosen against; numbers, booleans or short texts), checked.  Raises
    :class:`Refused`."""
    got = doc.get("defaults") or {}
    if not isinstance(got, dict) or len(got) > MAX_VALUES:
        raise Refused(f"`defaults` is an object of at most {MAX_VALUES} param defaults")
    for k, v in got.items():
        _text(k, "a param's name")
        if not isinstance(v, (str, int, float, bool)) or len(k) > MAX_VALUE \
                or len(str(v)) > MAX_VALUE:
            raise Refused(f"the default of “{str(k)[:40]}” is a number, a text or true/false "
                          f"of at most {MAX_VALUE} characters")
        if isinstance(v, str):
            _text(v, f"the default of `{k[:40]}`")
    return got


class Latest:
    """One session's previews: at most one compiles at a time, and of those that wait for
    it only the newest is compiled (the others are answered ``superseded``): a drag costs
    the compile in flight and one for its last values, however many moves it sent."""

    def __init__(self) -> None:
        import asyncio
        self.lock = asyncio.Lock()
        self.ticket = 0                 # the newest request's number
        self.users = 0                  # requests holding or waiting for the lock


SUPERSEDED = {"ok": False, "superseded": True, "svg": None, "params": None, "diagnostics": [],
              "error": "a newer change of this design was asked for: this one was not compiled"}
STICK = 2.0                 # s a picture's 3D or checks wait for the worker that drew it
SWEPT = 256                 # sweeps a server process keeps (by the program's hash)
# the sweep workers' niceness: a range sweep (a planetary's: 5 s of CPU, asked at each pause)
# runs on what the compile workers leave, never beside the next slider move's picture at
# the same share (issue 104); its budget is work and CPU time, its wall guard 160 s
SWEEP_NICE = 10
SWEEP_WAIT = 60.0           # s a sweep waits for a free sweep worker before "busy"
SWEEP_SUPERSEDED = {"ok": None, "superseded": True, "params": {},
                    "error": "the design changed: the check of its ranges was stopped"}


class SweepJob:
    """One program's sweep in flight: the sessions waiting for it, the worker running it."""

    def __init__(self) -> None:
        self.task = None
        self.sids: set = set()
        self.cancelled = False
        self.worker = None


def _uploads_digest(folder: str) -> bytes:
    """sha256 over the session folder's regular files (name and bytes, sorted by name); empty
    bytes for a folder that cannot be read."""
    h = hashlib.sha256()
    try:
        with os.scandir(folder) as it:
            entries = sorted((e for e in it if e.is_file(follow_symlinks=False)),
                             key=lambda e: e.name)
            for e in entries:
                h.update(e.name.encode("utf-8", "surrogatepass") + b"\0")
                with open(e.path, "rb") as f:
                    for chunk in iter(lambda: f.read(1 << 20), b""):
                        h.update(chunk)
                h.update(b"\0")
    except OSError:
        return b""
    return h.digest()


_NO_UPLOADS = hashlib.sha256().digest()     # (the digest of a session folder with no file)


class Sweeps:
    """The sweeps of a server process: ``done`` (program key -> answer, the last
    :data:`SWEPT`), ``running`` (key -> :class:`SweepJob`: a second session asking for the
    same program waits for the same sweep) and ``of`` (session -> the key it asked last)."""

    def __init__(self) -> None:
        from collections import OrderedDict
        self.done: OrderedDict = OrderedDict()
        self.running: dict = {}
        self.of: dict = {}

    @staticmethod
    def key(source: str, folder: str, budget: float, values: dict | None = None) -> str:
        """The program's hash with the sliders' ``values`` and the bytes of the session's
        uploads (each file's name and content): the same text may read other files (a name
        built by an expression too), and two sessions' uploads of one name differ."""
        h = hashlib.sha256(f"{budget!r}\0{source}\0".encode("utf-8", "surrogatepass"))
        h.update(json.dumps(values or {}, sort_keys=True, default=str).encode())
        h.update(_uploads_digest(folder))
        return h.hexdigest()

    def keep(self, key: str, answer: dict) -> None:
        self.done[key] = answer
        self.done.move_to_end(key)
        while len(self.done) > SWEPT:
            self.done.popitem(last=False)


class Studio:
    """The server's state: settings, compile workers, session folders, rate limiter, the
    gallery's thumbnails."""

    def __init__(self, settings: Settings) -> None:
        from limits import parse
        from limits.strategies import MovingWindowRateLimiter
        self.settings = settings
        self.folders = open_store(settings.data, settings.store)
        memory = settings.memory_mb << 20 if settings.memory_mb > 0 else None
        if settings.scheduler:
            from .remote import Remote
            self.pool = Remote(settings.scheduler, settings.budget, memory, settings.queue)
        else:
            self.pool = W.Pool([W.Worker(compiler.handler, (settings.budget,), memory,
                                         settings.recycle, compiler.PRELOAD)
                                for _ in range(max(1, settings.compilers))])
        self.limiter = MovingWindowRateLimiter(limiter_storage(self.folders))
        self.rate = parse(settings.rate)
        self.sweepers = None if settings.scheduler or settings.sweepers <= 0 else W.Pool(
            [W.Worker(compiler.handler, (settings.budget,), memory, settings.recycle,
                      compiler.PRELOAD, nice=SWEEP_NICE)
             for _ in range(settings.sweepers)])
        self.sweeps = Sweeps()
        from .ahead import Ahead, wanted
        self.ahead = Ahead(wanted(settings.ahead) if self.sweepers is not None else [],
                           settings.budget, settings.seconds, memory)
        self.affinity: dict[str, W.Worker] = {}
        self.latest: dict[str, Latest] = {}       # sid -> its previews in flight
        self.thumbs: dict[str, str] = {}
        self.describing = 0
        self.static = static_files()
        self.served = {"busy": 0, "limited": 0, "compiles": 0, "timeouts": 0, "superseded": 0,
                       "sweeps": 0, "sweeps_cached": 0, "sweeps_stopped": 0}
        self.metrics = Metrics(self)

    def check_rate(self, request: Request, cost: int = 1) -> None:
        """Raises :class:`Limited` (429) when the client is past its rate."""
        who = request.client.host if request.client else "?"
        if not self.limiter.hit(self.rate, who, cost=cost):
            self.served["limited"] += 1
            reset, _ = self.limiter.get_window_stats(self.rate, who)
            retry = max(1, int(reset - time.time()) + 1)
            raise Limited(429, f"too many requests from your address: at most {self.rate} "
                               f"(this studio's limit); try again in {retry} s", retry)

    async def compile(self, request_data: tuple, sid: str | None = None):
        """Run one request in a compile worker; raises :class:`Limited` (503) when every
        worker stays busy, and returns ``{"error": ...}`` for a compile stopped past its
        time or memory.  A picture's 3D and its checks (``glb``, ``checks``) wait up to
        :data:`STICK` for the worker that drew it (it answers them from the drawing it kept;
        another worker compiles the picture again: a planetary's 0.5-3 s of CPU beside the
        next slider move's compile, issue 104)."""
        s = self.settings
        if self.pool.waiting >= s.queue:
            self.served["busy"] += 1
            raise Limited(503, f"the studio is busy: {self.pool.waiting} changes are waiting "
                               "for a compiler. Your design is kept here; it is compiled "
                               "again in a few seconds.", 5)
        prefer = self.affinity.get(sid) if sid else None
        t0 = time.perf_counter()
        try:
            args = (request_data, s.seconds, s.wait, prefer)
            if prefer is not None and request_data[0] in ("glb", "checks") \
                    and isinstance(self.pool, W.Pool):
                args += (STICK,)
            answer, w = await run_in_threadpool(self.pool.request, *args)
            self.metrics.compiled(request_data[0], time.perf_counter() - t0)
        except W.Busy:
            self.served["busy"] += 1
            raise Limited(503, "the studio is busy: every compiler stayed busy for "
                               f"{s.wait:g} s. Your design is kept here; it is compiled again "
                               "in a few seconds.", 5) from None
        except W.TimedOut:
            self.served["timeouts"] += 1
            return {"error": f"the compile took longer than {s.seconds:g} s and was stopped: "
                             "build less (fewer copies, holes or constraints)"}
        except W.Died:
            return {"error": "the compile ran out of memory and was stopped: build less "
                             "(fewer copies, holes or constraints)"}
        except W.NotReady as e:
            raise Limited(503, f"{e}; try again in a few seconds", 5) from None
        self.served["compiles"] += 1
        if sid:
            if len(self.affinity) > 10_000:
                self.affinity.clear()
            self.affinity[sid] = w
        if isinstance(answer, dict) and answer.pop("retire", False):
            w.retiring = True           # its memory grew: a fresh process for its next request
        if getattr(w, "retiring", False) and hasattr(w, "renew"):   # replaced now, in the background
            import asyncio
            asyncio.get_running_loop().run_in_executor(None, w.renew)
        return answer

    async def newest(self, sid: str, request_data: tuple) -> dict:
        """Compile the preview ``request_data`` of session ``sid`` once every earlier one of
        the session has answered, unless a newer one came meanwhile: then answer
        :data:`SUPERSEDED` without compiling (:class:`Latest`)."""
        slot = self.latest.get(sid)
        if slot is None:
            slot = self.latest[sid] = Latest()
        slot.ticket += 1
        slot.users += 1
        me = slot.ticket
        try:
            async with slot.lock:
                if me != slot.ticket:
                    self.served["superseded"] += 1
                    return dict(SUPERSEDED)
                return await self.compile(request_data, sid)
        finally:
            slot.users -= 1
            if not slot.users and self.latest.get(sid) is slot:
                del self.latest[sid]

    @property
    def sweeping(self) -> bool:
        """Whether this studio sweeps programs (``sweepers`` > 0, or a cluster)."""
        return self.sweepers is not None or bool(self.settings.scheduler)

    async def sweep(self, sid: str, folder: str, source: str, values: dict | None = None) -> dict:
        """The sweep of ``source`` for session ``sid`` (:func:`.compiler.sweep_ranges`): from
        the cache when this program was swept, else run by a sweep worker (one sweep per
        program however many sessions ask).  A session's earlier sweep of another program that
        no other session waits for is stopped (its worker process killed).  Raises
        :class:`Limited` (503) when the sweep workers stay busy."""
        import asyncio
        sw = self.sweeps
        got = self.ahead.answer(source, values, _uploads_digest(folder) not in (b"", _NO_UPLOADS))
        if got is not None:             # a gallery design at its own values: swept whole
            self.leave_sweep(sid)       # (the session's sweep of another program: not wanted)
            self.served["sweeps_cached"] += 1
            return got
        key = sw.key(source, folder, self.settings.budget, values)
        if key in sw.done:
            sw.done.move_to_end(key)
            self.served["sweeps_cached"] += 1
            return {**sw.done[key], "cached": True}
        if sw.of.get(sid) != key:
            self.leave_sweep(sid)
        if len(sw.of) > 10_000:
            sw.of.clear()
        sw.of[sid] = key
        job = sw.running.get(key)
        if job is None:
            pool = self.sweepers or self.pool
            if pool.waiting >= self.settings.queue:
                self.served["busy"] += 1
                raise Limited(503, "the studio is busy: the check of your design's ranges "
                                   "waits for a free worker; it is asked again in a few "
                                   "seconds", 10)
            job = sw.running[key] = SweepJob()
            job.task = asyncio.ensure_future(self._sweep_job(key, job, (
                "sweep", sid, folder, source, dict(values or {}))))
        job.sids.add(sid)
        answer = await asyncio.shield(job.task)
        if answer.get("busy"):
            raise Limited(503, answer["error"], 10)
        return answer

    def leave_sweep(self, sid: str) -> None:
        """Session ``sid`` no longer waits for the sweep it asked for last (it asks for another
        program, or its tab closed): that sweep is stopped when no other session waits for it
        (before, a closed tab's sweep ran on to its end in the only sweep worker, and the next
        visitor's sweep waited for it)."""
        old = self.sweeps.of.pop(sid, None)
        job = self.sweeps.running.get(old) if old is not None else None
        if job is not None:
            job.sids.discard(sid)
            if not job.sids:
                self.stop_sweep(job)

    def stop_sweep(self, job: SweepJob) -> None:
        """Stop the sweep ``job``: not started, or its worker process killed."""
        job.cancelled = True
        self.served["sweeps_stopped"] += 1
        w = job.worker
        if w is not None:
            w.cancel()

    async def _sweep_job(self, key: str, job: SweepJob, request: tuple) -> dict:
        t0 = time.perf_counter()
        try:
            answer = await run_in_threadpool(self._sweep_in_worker, job, request)
        finally:
            if self.sweeps.running.get(key) is job:
                del self.sweeps.running[key]
        if not answer.get("superseded") and not answer.get("busy"):
            self.metrics.compiled("sweep", time.perf_counter() - t0)
            self.served["sweeps"] += 1
            if complete(answer):        # (issue 113: a sweep the budget cut short is never
                self.sweeps.keep(key, answer)   # kept as the design's answer)
        return answer

    def _sweep_in_worker(self, job: SweepJob, request: tuple) -> dict:
        """Run ``request`` in a sweep worker (on the cluster with ``--scheduler``); a dict
        answer, never an exception."""
        s = self.settings
        busy = {"busy": True, "error": "the studio is busy: every worker that checks ranges "
                                       f"stayed busy for {SWEEP_WAIT:g} s; the check is asked "
                                       "again in a few seconds"}
        try:
            if self.sweepers is None:           # the cluster's workers
                answer, _ = self.pool.request(request, s.seconds, SWEEP_WAIT)
                return dict(SWEEP_SUPERSEDED) if job.cancelled else answer
            w = self.sweepers.take(SWEEP_WAIT)
        except (W.Busy, W.NotReady):
            return busy
        except W.WorkerError:
            return {"error": "the check of the ranges stopped (out of time or memory)"}
        try:
            if job.cancelled:
                return dict(SWEEP_SUPERSEDED)
            job.worker = w
            answer = w.request(request, s.seconds)
        except W.NotReady:
            return busy
        except W.WorkerError:
            return dict(SWEEP_SUPERSEDED) if job.cancelled else {
                "error": "the check of the ranges stopped (out of time or memory)"}
        finally:
            job.worker = None
            w.cancelled = False             # a cancel that came after the answer
            self.sweepers.give(w)
        if isinstance(answer, dict) and answer.pop("retire", False):
            w.retiring = True
        return answer

    def stop(self) -> None:
        self.ahead.stop()
        self.pool.stop()
        if self.sweepers is not None:
            self.sweepers.stop()


def create_app(settings: Settings | None = None) -> Starlette:
    """The studio app (``settings`` None: from the environment, as each ``uvicorn`` worker
    process builds it)."""
    if settings is None:
        settings = Settings.from_env()
    made = not settings.data
    if made:
        import tempfile
        settings.data = tempfile.mkdtemp(prefix="aidl-studio-")
    st = Studio(settings)
    guarded = _guard(st)
    routes = (_page_routes(st) + _reference_routes(st, guarded) + _session_routes(st, guarded)
              + _compile_routes(st, guarded) + _operator_routes(st))

    @contextlib.asynccontextmanager
    async def lifespan(app):
        st.ahead.start()
        try:
            yield
        finally:
            await run_in_threadpool(st.stop)
            if made:                    # the sessions' folder this app made, not a given one
                import shutil
                shutil.rmtree(settings.data, ignore_errors=True)

    app = Starlette(routes=routes, lifespan=lifespan,
                    middleware=[Middleware(RequestMetrics, metrics=st.metrics, routes=routes)])
    app.state.studio = st
    return app


def _guard(st: Studio):
    """``guarded(handler, cost)``: the handler behind the client's rate (``cost`` hits) and the
    sessions' sweep, its refusals (:class:`Limited`, :class:`Refused`, the store down) as JSON
    answers."""
    def guarded(handler, cost: int = 1):
        async def endpoint(request: Request):
            try:
                if cost:                # (0: what browsing reads; never a drag's rate)
                    st.check_rate(request, cost)
                st.folders.sweep()
                return await handler(request)
            except Limited as e:
                return refusal(e.status, e.message, e.retry, busy=e.status == 503)
            except Refused as e:
                return refusal(400, str(e))
            except Exception as e:
                if not down(e):
                    raise
                return refusal(503, str(e) if isinstance(e, StoreDown) else
                               "the studio's store (Redis) does not answer; your design is "
                               "kept in this page, try again in a few seconds", 5, busy=True)
        return endpoint
    return guarded


def _page_routes(st: Studio) -> list[Route]:
    """``/``, ``/embed`` (the page, with its Content-Security-Policy) and ``/static/NAME``."""
    page = st.static["index.html"]
    csp = {False: _csp(page, False), True: _csp(page, True)}

    def page_response(embed: bool) -> Response:
        return Response(page, media_type=TYPES["html"],
                        headers={"Content-Security-Policy": csp[embed],
                                 "Cache-Control": "no-cache",
                                 "X-Content-Type-Options": "nosniff",
                                 "Referrer-Policy": "no-referrer"})

    async def index(request):
        return page_response(False)

    async def embed(request):
        return page_response(True)

    async def static(request):
        name = request.path_params["name"]
        data = st.static.get(name)
        if data is None:
            return PlainTextResponse("not found", status_code=404)
        kind = TYPES.get(name.rsplit(".", 1)[-1], "application/octet-stream")
        return Response(data, media_type=kind, headers={"Cache-Control": "public, max-age=3600",
                                                        "X-Content-Type-Options": "nosniff"})

    async def favicon(request):         # browsers ask for it whatever the page links
        return Response(st.static["favicon.ico"], media_type="image/x-icon",
                        headers={"Cache-Control": "public, max-age=86400"})

    return [Route("/", index), Route("/embed", embed), Route("/static/{name:path}", static),
            Route("/favicon.ico", favicon)]


def _reference_routes(st: Studio, guarded) -> list[Route]:
    """What the page reads and no session holds: ``/api/config``, the gallery
    (``/api/gallery``, ``/api/gallery/ID``, ``/api/thumb/ID.svg``) and ``/api/docs``."""
    settings = st.settings

    async def config(request):
        from ..output import FORMATS
        from .wording import for_page
        formats, seen = [], set()
        for k, f in FORMATS.items():        # one button per writer (.stp is .step, .nc .gcode)
            if (f.module, f.function) not in seen:
                seen.add((f.module, f.function))
                formats.append({"ext": k.lstrip("."), "about": for_page(f.about), "cut": f.cut,
                                "assembled": f.assembled, "available": compiler.can_make(k)})
        return JSONResponse({
            "formats": formats,
            "pages": compiler.PAGES,
            "machines": list(compiler.MACHINES),
            "model": {"model": settings.model.get("model")} if settings.model else None,
            "sweep": st.sweeping,
            "limits": {"source_bytes": MAX_SOURCE_BYTES, "rate": settings.rate,
                       "seconds": settings.seconds,
                       "upload_bytes": MAX_UPLOAD}})

    async def gallery_list(request):
        from . import gallery
        return JSONResponse([gallery.to_json(e, with_source=False) for e in gallery.entries()])

    async def gallery_entry(request):
        from . import gallery
        e = gallery.entry(request.path_params["id"])
        if e is None:
            return refusal(404, "no such design in the gallery")
        return JSONResponse(gallery.to_json(e, with_source=True))

    async def thumb(request):
        from . import gallery
        eid = request.path_params["id"]
        if gallery.entry(eid) is None:
            return refusal(404, "no such design in the gallery")
        svg = st.thumbs.get(eid)
        if svg is None:         # made once for every server of this build (the disk cache)
            e = gallery.entry(eid)
            svg = gallery.kept_thumbnail(e)
            if svg is None:
                svg = await st.compile(("thumb", eid))
                if not isinstance(svg, str):
                    svg = ""
                if svg:
                    gallery.keep_thumbnail(e, svg)
            st.thumbs[eid] = svg
        if not svg:
            return refusal(404, "this design has no picture")
        return Response(svg, media_type=TYPES["svg"],
                        headers={"Cache-Control": "public, max-age=3600",
                                 "Content-Security-Policy": "default-src 'none'; style-src 'unsafe-inline'"})

    async def docs(request):
        from ..library.reference import lookup_text
        name = request.query_params.get("name", "")
        if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.]{0,63}", name):
            return JSONResponse({"text": None})
        text, found = lookup_text(name)
        return JSONResponse({"text": text if found else None})

    # browsing costs no rate (issue 104: after four designs' galleries, thumbnails and hovers,
    # a 20 s drag had 8 of 30 requests refused): each answer is a table lookup, the
    # thumbnails made once per build (kept on disk), the docs a lookup
    return [Route("/api/config", config),
            Route("/api/gallery", guarded(gallery_list, 0)),
            Route("/api/gallery/{id:path}", guarded(gallery_entry, 0)),
            Route("/api/thumb/{id:path}.svg", guarded(thumb, 0)),
            Route("/api/docs", guarded(docs, 0))]


def _session_routes(st: Studio, guarded) -> list[Route]:
    """A tab's session and its files: ``/api/session``, ``/api/close``, ``/api/files``,
    ``/api/upload`` (with ``&import=`` the drawing as a program) and ``/api/delete``."""
    async def session(request):
        sid = new_id()
        st.folders.folder(sid)
        return JSONResponse({"sid": sid})

    async def close(request):
        doc = await read_json(request)
        sid = doc.get("sid")
        if not isinstance(sid, str):
            raise Refused("give the page's session as `sid` (text)")
        with contextlib.suppress(Refused):
            st.folders.close(sid)
        st.affinity.pop(sid, None)
        st.leave_sweep(sid)
        return JSONResponse({"closed": True})

    async def files(request):
        return JSONResponse({"files": st.folders.files(request.query_params.get("sid", ""))})

    async def upload(request):
        sid = request.query_params.get("sid", "")
        name = request.query_params.get("name", "")
        size = request.headers.get("content-length")
        if size is not None and size.isdigit() and int(size) > MAX_UPLOAD:
            raise Refused(f"`{name[:64]}` has {int(size):,} bytes; an upload has at most "
                          f"{MAX_UPLOAD:,}")
        body = bytearray()
        async for chunk in request.stream():
            body += chunk
            if len(body) > MAX_UPLOAD:
                raise Refused(f"an upload has at most {MAX_UPLOAD:,} bytes")
        doc = st.folders.upload(sid, name, bytes(body))
        how = request.query_params.get("import")
        if how in ("infer", "pieces", "drawing"):
            got = await st.compile(("import", st.folders.folder(sid), doc["name"],
                                    "drawing" if how == "drawing" else how == "infer"), sid)
            if "program" in got:
                doc.update(program=got["program"], notes=got["notes"])
            else:
                doc["import_error"] = got.get("error", "the import failed")
        return JSONResponse(doc)

    async def delete(request):
        doc = await read_json(request)
        st.folders.delete(doc.get("sid", ""), doc.get("name", ""))
        return JSONResponse({"files": st.folders.files(doc.get("sid", ""))})

    return [Route("/api/session", guarded(session), methods=["POST"]),
            Route("/api/close", guarded(close), methods=["POST"]),
            Route("/api/files", guarded(files)),
            Route("/api/upload", guarded(upload, 4), methods=["POST"]),
            Route("/api/delete", guarded(delete), methods=["POST"])]


def _compile_routes(st: Studio, guarded) -> list[Route]:
    """What a compile worker answers: ``/api/view``, ``/api/download/FORMAT``, ``/api/glb``,
    and the model loop ``/api/describe``."""
    settings = st.settings

    async def view(request):
        doc = await read_json(request)
        sid = doc.get("sid", "")
        folder = st.folders.folder(sid)
        source, values = program_of(doc)
        later = doc.get("checks") == "later"        # the shape checks asked apart (/api/checks)
        answer = await st.newest(sid, ("view", sid, folder, source, values, defaults_of(doc),
                                        later))
        if "error" in answer and "svg" not in answer:
            return JSONResponse({"ok": False, "svg": None, "params": None, "diagnostics": [],
                                 "error": answer["error"]})
        return JSONResponse(answer)

    async def checks(request):
        doc = await read_json(request)
        sid = doc.get("sid", "")
        folder = st.folders.folder(sid)
        source, values = program_of(doc)
        answer = await st.compile(("checks", sid, folder, source, values), sid)
        if "error" in answer and "diagnostics" not in answer:
            return JSONResponse({"ok": False, "diagnostics": [], "error": answer["error"]})
        return JSONResponse(answer)

    async def download(request):
        doc = await read_json(request)
        folder = st.folders.folder(doc.get("sid", ""))
        source, values = program_of(doc)
        fmt = request.path_params["fmt"]
        settings_of(fmt, doc)
        answer = await st.compile(("download", folder, source, values, fmt,
                                   doc.get("settings") or {}), doc.get("sid"))
        if isinstance(answer, dict):
            return JSONResponse(answer, status_code=422)
        data, name, media = answer
        return Response(data, media_type=media,
                        headers={"Content-Disposition": f'attachment; filename="{name}"',
                                 "X-Content-Type-Options": "nosniff"})

    async def sweep(request):
        doc = await read_json(request)
        sid = doc.get("sid", "")
        folder = st.folders.folder(sid)
        source, values = program_of(doc)
        if not st.sweeping:
            return JSONResponse({"ok": None, "off": True, "params": {},
                                 "error": "this studio does not check ranges (sweepers 0)"})
        return JSONResponse(await st.sweep(sid, folder, source, values))

    async def glb(request):
        doc = await read_json(request)
        sid = doc.get("sid", "")
        folder = st.folders.folder(sid)
        source, values = program_of(doc)
        try:
            compiler.download_settings(".glb", doc.get("settings"))
        except ValueError as e:
            raise Refused(str(e)) from None
        answer = await st.compile(("glb", sid, folder, source, values,
                                   doc.get("settings") or {}), sid)
        if isinstance(answer, dict):
            return JSONResponse(answer, status_code=422)
        data, headers = answer[0], {"Cache-Control": "no-store", "X-Content-Type-Options": "nosniff",
                                    "Vary": "Accept-Encoding"}
        if "gzip" in request.headers.get("accept-encoding", ""):
            import gzip
            data = await run_in_threadpool(gzip.compress, data, 6)
            headers["Content-Encoding"] = "gzip"
        return Response(data, media_type=answer[2], headers=headers)

    async def describe(request):
        if not settings.model:
            return refusal(404, "this studio has no model endpoint (the operator sets "
                                "AIDL_STUDIO_MODEL_URL)")
        doc = await read_json(request)
        folder = st.folders.folder(doc.get("sid", ""))
        text = doc.get("description")
        if not isinstance(text, str) or not text.strip():
            raise Refused("give what the part is as `description` (text)")
        _text(text, "the description")
        if st.describing >= settings.describes:
            raise Limited(503, "the studio is busy: every model conversation slot is taken; "
                               "try again in a minute", 30)
        from .describing import stream
        st.describing += 1

        async def events():
            try:
                async for event in stream(text, settings.model, folder):
                    yield (json.dumps(event) + "\n").encode()
            finally:
                st.describing -= 1
        return StreamingResponse(events(), media_type="application/x-ndjson",
                                 headers={"Cache-Control": "no-store"})

    return [Route("/api/view", guarded(view), methods=["POST"]),
            Route("/api/checks", guarded(checks), methods=["POST"]),
            Route("/api/download/{fmt}", guarded(download, 4), methods=["POST"]),
            Route("/api/glb", guarded(glb), methods=["POST"]),
            Route("/api/sweep", guarded(sweep, 2), methods=["POST"]),
            Route("/api/describe", guarded(describe, 20), methods=["POST"])]


def _operator_routes(st: Studio) -> list[Route]:
    """For the operator: ``/api/stats`` (this machine only), ``/healthz`` and ``/metrics``."""
    async def stats(request):
        # for the operator and the load test: answered to this machine only
        if not request.client or request.client.host not in ("127.0.0.1", "::1"):
            return PlainTextResponse("not found", status_code=404)
        return JSONResponse({**st.served, "waiting": st.pool.waiting, "ahead": st.ahead.stats,
                             "workers": [{"pid": w.proc.pid if w.proc else None,
                                          "rss": w.rss(), "requests": w.requests,
                                          "restarts": w.restarts} for w in st.pool.workers]})

    async def healthz(request):
        live = request.query_params.get("probe") == "live"
        return await run_in_threadpool(st.metrics.health, live)

    async def metrics(request):
        return await run_in_threadpool(st.metrics.response)

    return [Route("/api/stats", stats), Route("/healthz", healthz), Route("/metrics", metrics)]
