"""``aidl serve FILE``: a live preview in the browser with a customizer (docs/serve.md).

* :mod:`.session`: the warm compile of one file (no HTTP): reload after a save, re-solve for
  new param values with the warm solver, the view as JSON.
* :mod:`.app`: the Starlette app (page, state, downloads, WebSocket, file watching with
  ``watchfiles``) and the local-only guard.
* ``static/``: the page (HTML, JS, CSS), shipped in the package; no CDN, works offline.

Starlette, uvicorn, websockets and watchfiles are core dependencies, imported only here (in
:func:`serve`) and in :mod:`.app`, so the other commands do not load them.
"""
from __future__ import annotations

import socket
import sys

HOST = "127.0.0.1"      # never another interface: the preview is for this machine only


def listening(host: str, port: int, backlog: int) -> socket.socket | None:
    """A TCP socket bound to ``host``:``port`` (IPv6 when ``host`` has a ``:``; ``port`` 0: a
    free one) and listening; None after printing why it cannot be (the port is taken)."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    sock = socket.socket(family, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind((host, port))
    except OSError as e:
        sock.close()
        print(f"aidl: error: cannot listen on {host}:{port}: {e.strerror or e}; "
              "choose another with --port", file=sys.stderr)
        return None
    sock.listen(backlog)
    return sock


def serve(path: str, port: int = 8765, quiet: bool = False) -> int:
    """Serve the live preview of ``path`` on http://127.0.0.1:PORT/ until interrupted.
    ``port=0`` picks a free port.  Returns the exit status (2: the extra is not installed or
    the port is taken)."""
    # one BLAS thread: set by the `aidl` command (aidl_lang/cli/__init__.py)
    try:
        import uvicorn
        from .app import create_app
    except ImportError as e:
        print(f"aidl: error: `aidl serve` cannot import {e.name}, one of aidl's dependencies: "
              "reinstall aidl (pip install -e /path/to/aidl)", file=sys.stderr)
        return 2
    from ..library.sources import SourceRefused, read_program
    try:
        read_program(path)          # missing, a FIFO, a device, too large: E0004, never a hang
    except SourceRefused as e:
        print(f"aidl: error[E0004]: {e.message}", file=sys.stderr)
        return 2
    # connections wait in the backlog until the first compile is done
    sock = listening(HOST, port, 128)
    if sock is None:
        return 2
    port = sock.getsockname()[1]
    app = create_app(path, port)
    config = uvicorn.Config(app, log_level="warning", ws="websockets-sansio",
                            timeout_graceful_shutdown=1, lifespan="on")
    server = uvicorn.Server(config)
    print(f"aidl serve: http://{HOST}:{port}/  (watching {path}; Ctrl-C stops)", flush=True)
    server.run(sockets=[sock])
    return 0


__all__ = ["serve", "listening", "HOST"]
