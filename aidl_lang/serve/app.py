"""The live-preview web server: Starlette routes over one :class:`~.session.Session`.

Routes (all GET, plus one WebSocket):

* ``/`` and ``/static/NAME``: the page, from the package's ``static/`` folder.  Names are
  looked up in a fixed table read at start-up, never joined onto a filesystem path, so no
  request can reach another file (path traversal).
* ``/api/state``: the current view (SVG, diagnostics, params, degrees of freedom) as JSON.
* ``/download/FORMAT?set=NAME=VALUE...``: the watched file rendered with those values, in a
  format the output package writes (see :func:`writers`); a fresh compile, like ``aidl render``.
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
TYPES = {"html": "text/html; charset=utf-8", "js": "text/javascript; charset=utf-8",
         "css": "text/css; charset=utf-8", "svg": "image/svg+xml", "png": "image/png",
         "dxf": "application/dxf", "stl": "model/stl", "json": "application/json",
         "3mf": "model/3mf", "step": "model/step", "stp": "model/step"}


def static_files() -> dict[str, bytes]:
    """The page's files (name -> bytes), read once from the package data ``serve/static``."""
    root = resources.files(__package__) / "static"
    return {f.name: f.read_bytes() for f in root.iterdir() if f.is_file()}


def writers() -> dict[str, object]:
    """Output formats for downloads: extension -> ``f(drawing, title) -> bytes``.

    Every format of :data:`aidl_lang.output.FORMATS` (the ones ``aidl render`` writes by
    extension: svg, dxf, png, stl, 3mf, step): the drawing becomes the exact output model
    (:func:`aidl_lang.output.build`) and is encoded by the same writer the CLI uses.  A format
    whose optional library is missing raises :class:`aidl_lang.output.MissingDependency`."""
    def writer(suffix: str):
        return lambda d, title: output.encode(output.build(d, title), suffix)
    return {s.lstrip("."): writer(s) for s in output.FORMATS}


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
    """The session plus the connected pages; one compile at a time."""

    def __init__(self, session: Session):
        self.session = session
        self.lock = asyncio.Lock()
        self.clients: set[WebSocket] = set()
        self.tasks: set[asyncio.Task] = set()      # pending shape checks (kept referenced)

    async def reload(self) -> dict:
        async with self.lock:
            view = await run_in_threadpool(self.session.load)
        await self.broadcast(view)
        async with self.lock:                       # then the DOF summary (SVDs), same version
            dof_view = await run_in_threadpool(self.session.update_dof)
        if dof_view is not None:
            await self.broadcast(dof_view)
            view = dof_view
        return view

    async def set_params(self, values: dict) -> dict:
        async with self.lock:
            return await run_in_threadpool(self.session.set_params, values)

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
        async with hub.lock:
            drawing, extra = await run_in_threadpool(hub.session.drawing, values)
            if drawing is None:
                return JSONResponse({"ok": False, "diagnostics": extra}, status_code=422)
            try:
                body = await run_in_threadpool(table[fmt], drawing, extra)
            except output.MissingDependency as e:
                return PlainTextResponse(str(e), status_code=501)
            except output.OutputError as e:
                return PlainTextResponse(str(e), status_code=422)
        if isinstance(body, str):
            body = body.encode("utf-8")
        stem = Path(hub.session.name).stem or "part"
        return Response(body, media_type=TYPES.get(fmt, "application/octet-stream"),
                        headers={"Content-Disposition": f'attachment; filename="{stem}.{fmt}"'})

    async def formats(request):
        return JSONResponse(sorted(writers()))

    async def ws_endpoint(ws: WebSocket):
        await ws.accept()
        hub.clients.add(ws)
        try:
            await ws.send_text(json.dumps({"type": "view", **hub.session.view()}))
            while True:
                msg = json.loads(await ws.receive_text())
                if isinstance(msg, dict) and msg.get("type") == "set" \
                        and isinstance(msg.get("values"), dict):
                    view = await hub.set_params(msg["values"])
                    await ws.send_text(json.dumps({"type": "view", "id": msg.get("id"), **view}))
                    await hub.broadcast(view, skip=ws)
                    checks = asyncio.create_task(hub.shape_checks())
                    hub.tasks.add(checks)
                    checks.add_done_callback(hub.tasks.discard)
        except (WebSocketDisconnect, json.JSONDecodeError, RuntimeError):
            pass
        finally:
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
        await hub.reload()
        task = asyncio.create_task(watcher()) if watch else None
        try:
            yield
        finally:
            if task is not None:
                task.cancel()

    app = Starlette(routes=[
        Route("/", index), Route("/static/{name}", static), Route("/api/state", state),
        Route("/api/formats", formats), Route("/download/{fmt}", download),
        WebSocketRoute("/ws", ws_endpoint),
    ], lifespan=lifespan)
    app.state.hub = hub
    app.state.port_ref = port_ref
    app.add_middleware(LocalOnly, port_ref=port_ref)
    return app
