"""The live-preview web server: Starlette routes over one :class:`~.session.Session`.

Routes (all GET, plus one WebSocket):

* ``/`` and ``/static/NAME``: the page, from the package's ``static/`` folder (``NAME`` may
  name a file in a subfolder: ``vendor/three/build/three.module.min.js``).  Names are looked
  up in a fixed table read at start-up, never joined onto a filesystem path, so no request
  can reach another file (path traversal).
* ``/api/state``: the current view (SVG, diagnostics, params, degrees of freedom) as JSON.
* ``/download/FORMAT?set=NAME=VALUE...``: the watched file rendered with those values, in a
  format the output package writes (see :func:`writers`); a fresh compile, like ``aidl render``.
  ``/download/glb`` is the assembled product, which the page's 3D view (``static/view3d.js``,
  three.js vendored in ``static/vendor/three/``) loads on every new picture while it is shown.
* ``/ws``: a WebSocket.  The server pushes ``{"type": "view", ...}`` after every recompile (a
  save of the file, from any editor, seen by ``watchfiles``); the page sends
  ``{"type": "set", "id": N, "values": {NAME: "172.5mm"}}`` for the customizer and gets the
  view back with ``"id": N``.

Security: the server binds 127.0.0.1 only (:func:`serve`), and :class:`LocalOnly` refuses any
request whose ``Host`` is not this server's loopback address and port (DNS rebinding) or whose
``Origin``, when sent, is not this page (another site's script), with 403.
"""
from __future__ import annotations

import asyncio
import contextlib
import gc
import json
from importlib import resources
from pathlib import Path

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.responses import JSONResponse, PlainTextResponse, Response
from starlette.routing import Route, WebSocketRoute
from starlette.websockets import WebSocket, WebSocketDisconnect

from .. import output
from .session import Session

CHECKS_DELAY = 0.05     # s a slider must rest before its picture's geometry checks run
IDLE_DELAY = 0.2        # s without a compile before the cyclic garbage collector runs
MAX_UNCOLLECTED = 8     # compiles at most between two collections (a long drag of a slider)
MAX_PENDING = 1_000_000     # tracked objects made (less those freed) since the last collection
                            # that start one at once (a gear pair's move leaves ~35,000)
MAX_MESSAGE = 65_536    # characters of one WebSocket message
MAX_DEPTH = 8           # nesting of arrays and objects in one message ({"values": {...}} is 2)
MAX_VALUES = 256        # entries of one message's "values"
MAX_VALUE = 256         # characters of one value
# the page's own files, and every output format's (from the writers' registry)
TYPES = {"html": "text/html; charset=utf-8", "js": "text/javascript; charset=utf-8",
         "css": "text/css; charset=utf-8", "json": "application/json",
         "txt": "text/plain; charset=utf-8",
         **{suffix.lstrip("."): f.media for suffix, f in output.FORMATS.items()}}


def static_files() -> dict[str, bytes]:
    """The page's files (name -> bytes), read once from the package data ``serve/static``; a
    file in a subfolder is named by its path below it (``vendor/three/LICENSE``)."""
    files: dict[str, bytes] = {}

    def walk(folder, prefix: str) -> None:
        for f in folder.iterdir():
            if f.is_file():
                files[prefix + f.name] = f.read_bytes()
            elif f.is_dir() and f.name != "__pycache__":
                walk(f, prefix + f.name + "/")
    walk(resources.files(__package__) / "static", "")
    return files


def writers() -> dict[str, object]:
    """Output formats for downloads: extension -> ``f(drawing, title) -> bytes``.

    Every format of :data:`aidl_lang.output.FORMATS` (the ones ``aidl render`` writes by
    extension: svg, dxf, png, stl, 3mf, step, glb): the drawing becomes the exact output model
    (:func:`aidl_lang.output.build`), the cutting formats with the program's ``kerf`` applied,
    and is encoded by the same writer the CLI uses; GLB is the assembled product (every part
    placed by its ``Place``, as ``aidl render --assembled``), which the page's 3D view loads.  A format
    whose optional library is missing raises :class:`aidl_lang.output.MissingDependency`."""
    def writer(suffix: str):
        def write(d, title):
            out = output.build(d, title)
            if suffix in output.CUT_FORMATS:       # the program's `kerf`, as `aidl render`
                out = output.for_cutting(out)
            # GLB is the assembled product (the page's 3D view), the others as on the sheet
            return output.encode(out, suffix, output.Options(assembled=suffix == ".glb"))
        return write
    return {s.lstrip("."): writer(s) for s in output.FORMATS}


def parse_message(raw: dict, names: set[str] | None) -> tuple[dict | None, dict | None]:
    """Check one received WebSocket message (the ASGI ``websocket.receive`` event) before
    anything is compiled: ``(error, None)`` with an error frame to send back, ``(None, msg)``
    with a customizer message ``{"id": int | None, "values": {name: text}}``, or
    ``(None, None)`` for a message that is not a customizer message (ignored).  Refused: a
    binary frame, more than :data:`MAX_MESSAGE` characters, nesting deeper than
    :data:`MAX_DEPTH` (before ``json.loads``, which would recurse), text that is not JSON
    (with its line and column), values that are not text, numbers or booleans or are too
    long, and names that are not params of the program (``names``)."""
    def error(message: str, **where) -> tuple[dict, None]:
        return {"type": "error", "message": message, **where}, None
    text = raw.get("text")
    if text is None:
        return error("binary WebSocket messages are not accepted: send JSON text, e.g. "
                     '{"type": "set", "id": 1, "values": {"width": "40mm"}}')
    if len(text) > MAX_MESSAGE:
        return error(f"a message of {len(text):,} characters, more than the {MAX_MESSAGE:,} "
                     "accepted")
    depth, in_str, esc, line, col0 = 0, False, False, 1, -1
    for i, ch in enumerate(text):
        if in_str:
            if esc:
                esc = False
            elif ch == "\\":
                esc = True
            elif ch == '"':
                in_str = False
        elif ch == '"':
            in_str = True
        elif ch in "[{":
            depth += 1
            if depth > MAX_DEPTH:
                return error(f"the message nests arrays and objects more than {MAX_DEPTH} deep",
                             line=line, column=i - col0)
        elif ch in "]}":
            depth -= 1
        elif ch == "\n":
            line, col0 = line + 1, i
    try:
        msg = json.loads(text)
    except ValueError as e:
        return error(f"the message is not JSON: {getattr(e, 'msg', e)}",
                     line=getattr(e, "lineno", None), column=getattr(e, "colno", None))
    if not (isinstance(msg, dict) and msg.get("type") == "set"):
        return None, None
    mid = msg.get("id")
    mid = mid if isinstance(mid, int) and not isinstance(mid, bool) else None
    values = msg.get("values")
    if not isinstance(values, dict):
        return error('a "set" message needs "values": {NAME: VALUE, ...}', id=mid)
    if len(values) > MAX_VALUES:
        return error(f'"values" has {len(values)} entries, more than {MAX_VALUES}', id=mid)
    out = {}
    for k, v in values.items():
        if isinstance(v, bool):
            v = "true" if v else "false"
        elif isinstance(v, (int, float)):
            v = repr(v)
        if not isinstance(v, str) or len(v) > MAX_VALUE:
            return error(f"the value of `{k[:64]}` must be text, a number or a boolean of at "
                         f"most {MAX_VALUE} characters", id=mid)
        out[k] = v
    if names is not None:
        unknown = sorted(k for k in out if k not in names)
        if unknown:
            from ..base.diagnostics import did_you_mean
            shown = ", ".join(f"`{k[:64]}`" for k in unknown[:5])
            near = did_you_mean(unknown[0], names) if names else []
            return error(f"unknown param{'s' if len(unknown) > 1 else ''} {shown}: the program "
                         f"declares {', '.join(sorted(names)[:20]) or 'no params'}"
                         + (f"; did you mean `{near[0]}`?" if near else ""), id=mid)
    return None, {"id": mid, "values": out}


class LocalOnly:
    """ASGI middleware: only this server's own page may talk to it (see the module doc)."""

    def __init__(self, app, port_ref: dict):
        self.app = app
        self.port_ref = port_ref

    def allowed(self, scope) -> bool:
        port = self.port_ref.get("port")
        hosts = {f"127.0.0.1:{port}", f"localhost:{port}"}
        headers = {k.decode("latin-1").lower(): v.decode("latin-1")
                   for k, v in scope.get("headers") or []}
        if headers.get("host", "").lower() not in hosts:
            return False
        origin = headers.get("origin")
        if origin is not None and origin.lower() not in {f"http://{h}" for h in hosts}:
            return False
        return True

    async def __call__(self, scope, receive, send):
        if scope["type"] in ("http", "websocket") and not self.allowed(scope):
            if scope["type"] == "websocket":
                await send({"type": "websocket.close", "code": 1008})
                return
            await PlainTextResponse("forbidden: this server answers only its own page on "
                                    "127.0.0.1", status_code=403)(scope, receive, send)
            return
        await self.app(scope, receive, send)


class Hub:
    """The session plus the connected pages; one compile at a time.

    The cyclic garbage collector runs in the server's idle time, not inside a compile: the
    app disables its automatic runs while it serves (:func:`create_app`'s lifespan) and
    :meth:`compiled` schedules :meth:`collect` once no compile has come for
    :data:`IDLE_DELAY` s, or at once after :data:`MAX_UNCOLLECTED` compiles (a slider
    dragged for long) or once :data:`MAX_PENDING` more objects the collector tracks were made
    than freed since the last collection (``gc.get_count()[0]``: a large model, whose garbage
    should not wait for a rest), so each compile's garbage (a model's structures point at their
    parents: reference cycles) is freed without a collection stalling a slider's picture.  A
    compile holds :attr:`lock` until its result is sent, and a collection takes the lock, so
    none runs between the two; an idle collection waiting when a newer compile starts is
    dropped (the newer one schedules its own).
    Automatic collections used to run inside the moves: about 20 % of a ``gear_pair`` move,
    plus a full collection of 130-280 ms every ~6 moves (docs/dev/performance.md)."""

    def __init__(self, session: Session):
        self.session = session
        self.lock = asyncio.Lock()
        self.clients: set[WebSocket] = set()
        self.tasks: set[asyncio.Task] = set()      # pending checks, collections (referenced)
        self.started = 0            # compiles started (counted under the lock)
        self.uncollected = 0        # compiles since the last collection
        self.collections = 0        # collections run (read by the tests)

    def spawn(self, coro) -> None:
        task = asyncio.create_task(coro)
        self.tasks.add(task)
        task.add_done_callback(self.tasks.discard)

    def compiled(self) -> None:
        """Call after a compile's result was sent (outside the lock): schedules the
        collection."""
        self.uncollected += 1
        now = self.uncollected >= MAX_UNCOLLECTED or gc.get_count()[0] >= MAX_PENDING
        self.spawn(self.collect(self.started, now=now))

    async def collect(self, mark: int, now: bool = False) -> None:
        """The cyclic collection, under the lock, which a compile holds until its result is
        sent (so never between the two): ``now``, or once :data:`IDLE_DELAY` s have passed
        with no compile started after the one that counted ``mark``."""
        if not now:
            await asyncio.sleep(IDLE_DELAY)
            if self.started != mark:
                return                              # a newer compile schedules its own
        async with self.lock:
            if not self.uncollected or (not now and self.started != mark):
                return
            self.uncollected = 0
            await run_in_threadpool(gc.collect)
            self.collections += 1

    async def reload(self) -> dict:
        async with self.lock:
            self.started += 1
            view = await run_in_threadpool(self.session.load)
            await self.broadcast(view)
        async with self.lock:                       # then the DOF summary (SVDs), same version
            dof_view = await run_in_threadpool(self.session.update_dof)
        if dof_view is not None:
            await self.broadcast(dof_view)
            view = dof_view
        self.compiled()
        return view

    async def move(self, ws: WebSocket, msg: dict) -> None:
        """A customizer message ``msg`` from page ``ws``: compile it, answer ``ws`` with the
        view (``id`` echoed), show it to the other pages; then its shape checks and the
        collection are scheduled."""
        async with self.lock:
            self.started += 1
            view = await run_in_threadpool(self.session.set_params, msg["values"])
            await ws.send_text(json.dumps({"type": "view", "id": msg["id"], **view}))
            await self.broadcast(view, skip=ws)
        self.spawn(self.shape_checks())
        self.compiled()

    async def shape_checks(self) -> None:
        """After a slider's picture was sent: its geometry checks, once the slider has rested
        for :data:`CHECKS_DELAY` s (a drag does not queue a check per step), then broadcast
        when they add diagnostics."""
        await asyncio.sleep(CHECKS_DELAY)
        async with self.lock:
            view = await run_in_threadpool(self.session.update_checks)
        if view is not None:
            await self.broadcast(view)

    async def broadcast(self, view: dict, skip=None) -> None:
        msg = json.dumps({"type": "view", **view})
        for ws in list(self.clients):
            if ws is skip:
                continue
            try:
                await ws.send_text(msg)
            except Exception:
                self.clients.discard(ws)


def create_app(path: str | Path, port: int = 0, watch: bool = True) -> Starlette:
    """The ASGI app for ``aidl serve path``.  ``port``: the port the server listens on (for
    the Host/Origin check; :func:`serve` fills it in after binding).  ``watch``: recompile
    when the file (or an ``.aidl`` beside it) changes."""
    hub = Hub(Session(path))
    files = static_files()
    port_ref = {"port": port}

    async def index(request):
        return Response(files["index.html"], media_type=TYPES["html"],
                        headers={"Cache-Control": "no-store"})

    async def static(request):
        name = request.path_params["name"]
        body = files.get(name)                 # a fixed table: no path is ever opened
        if body is None:
            return PlainTextResponse("not found", status_code=404)
        ext = name.rsplit(".", 1)[-1]
        return Response(body, media_type=TYPES.get(ext, "application/octet-stream"),
                        headers={"Cache-Control": "no-store"})

    async def state(request):
        return JSONResponse(hub.session.view())

    async def download(request):
        fmt = request.path_params["fmt"].lower()
        table = writers()
        if fmt not in table:
            return PlainTextResponse(f"unknown format `{fmt}`; formats: {', '.join(sorted(table))}",
                                     status_code=404)
        values = {}
        for item in request.query_params.getlist("set"):
            if "=" not in item:
                return PlainTextResponse(f"`set` expects NAME=VALUE, got `{item}`", status_code=400)
            k, v = item.split("=", 1)
            values[k.strip()] = v.strip()
        try:
            async with hub.lock:
                hub.started += 1
                drawing, extra = await run_in_threadpool(hub.session.drawing, values)
                if drawing is None:
                    return JSONResponse({"ok": False, "diagnostics": extra}, status_code=422)
                try:
                    body = await run_in_threadpool(table[fmt], drawing, extra)
                except output.MissingDependency as e:
                    return PlainTextResponse(str(e), status_code=501)
                except output.OutputError as e:
                    return PlainTextResponse(str(e), status_code=422)
        finally:
            hub.compiled()
        if isinstance(body, str):
            body = body.encode("utf-8")
        stem = Path(hub.session.name).stem or "part"
        return Response(body, media_type=TYPES.get(fmt, "application/octet-stream"),
                        headers={"Content-Disposition": f'attachment; filename="{stem}.{fmt}"'})

    async def formats(request):
        return JSONResponse(sorted(writers()))

    async def ws_endpoint(ws: WebSocket):
        """Receives and checks messages (:func:`parse_message`: errors answered at once with
        an error frame); customizer messages are compiled one at a time by a worker, and
        the newest one waiting replaces any older one (a slider dragged faster than it
        compiles shows its last position; only that message's id is answered)."""
        await ws.accept()
        hub.clients.add(ws)
        slot: dict = {"msg": None}
        wake = asyncio.Event()

        async def worker():
            while True:
                await wake.wait()
                wake.clear()
                msg, slot["msg"] = slot["msg"], None
                if msg is None:
                    continue
                await hub.move(ws, msg)

        task = asyncio.create_task(worker())
        try:
            await ws.send_text(json.dumps({"type": "view", **hub.session.view()}))
            while True:
                raw = await ws.receive()
                if raw.get("type") == "websocket.disconnect":
                    break
                err, msg = parse_message(raw, hub.session.param_names())
                if err is not None:
                    await ws.send_text(json.dumps(err))
                elif msg is not None:
                    slot["msg"] = msg                     # the newest wins
                    wake.set()
        except (WebSocketDisconnect, RuntimeError):
            pass
        finally:
            task.cancel()
            hub.clients.discard(ws)

    async def watcher():
        from watchfiles import Change, awatch
        target = Path(path).resolve()
        # watch the folder (editors often save by writing a new file and renaming it)
        async for changes in awatch(target.parent, debounce=200, step=20, recursive=True,
                                    watch_filter=lambda c, p: p.endswith(".aidl")
                                    and c != Change.deleted or Path(p) == target):
            try:
                await hub.reload()
            except Exception:       # noqa: BLE001 - logged; the next save reloads again
                import sys
                import traceback
                print(f"aidl serve: reload failed:\n{traceback.format_exc()}", file=sys.stderr,
                      flush=True)

    @contextlib.asynccontextmanager
    async def lifespan(app):
        was = gc.isenabled()
        gc.disable()                # collections run in the idle time (Hub.collect)
        task = None
        try:
            await hub.reload()
            if watch:
                task = asyncio.create_task(watcher())
            yield
        finally:
            if task is not None:
                task.cancel()
            if was:
                gc.enable()

    app = Starlette(routes=[
        Route("/", index), Route("/static/{name:path}", static), Route("/api/state", state),
        Route("/api/formats", formats), Route("/download/{fmt}", download),
        WebSocketRoute("/ws", ws_endpoint),
    ], lifespan=lifespan)
    app.state.hub = hub
    app.state.port_ref = port_ref
    app.add_middleware(LocalOnly, port_ref=port_ref)
    return app
