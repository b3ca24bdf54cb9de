"""``aidl studio``: AIDL in the browser for people who write no code, served to many at once
(issue 53; docs/studio.md).

A gallery of every example and standard-library generator (:mod:`.gallery`), each opened with
its parameters as a form; a code pane (CodeMirror 6, vendored) with diagnostics as you type and
``aidl docs`` on hover; the flat sheet and the assembled 3D view side by side; material and
machine settings and a download of every output format, the cutting sheet included; "Describe
the part" (the model loop, :mod:`.describe`, when the operator configures an endpoint); share
links and embeds that carry the program in the URL.

* :mod:`.app`: the Starlette routes, rate limits and the busy answer.
* :mod:`.compiler`: what a compile worker does (preview, download, thumbnail).
* :mod:`.sessions`: a tab's upload folder, the only files its program can read.
* :mod:`.store`: the uploads and rate counters in Redis (``--store``), mirrored into folders.
* :mod:`.remote`: compiles on a Dask cluster (``--scheduler``).
* :mod:`.metrics`: ``/healthz`` and ``/metrics`` (Prometheus) for the operator.
* ``static/``: the page (HTML, JS, CSS; CodeMirror under ``static/vendor/``).

A separate command from ``aidl serve``: ``serve FILE`` previews one file of this machine for its
owner (bound to 127.0.0.1, reading and watching that file); the studio reads no file of the
machine, keeps each visitor's work in their page, and is built to face strangers.
"""
from __future__ import annotations

import os
import shutil
import signal
import sys
import tempfile

HOST = "127.0.0.1"


def studio(host: str = HOST, port: int = 8780, processes: int = 1, compilers: int = 2,
           quiet: bool = False, **settings) -> int:
    """Serve the studio on http://HOST:PORT/ until interrupted: ``processes`` server processes
    (uvicorn workers) behind the one port, each with ``compilers`` compile worker processes;
    ``settings``: the other fields of :class:`.app.Settings` (``rate``, ``wait``, ``budget``,
    ``memory_mb``, ...).  ``port=0`` picks a free port.  Returns the exit status (2: the port
    is taken or a setting is wrong)."""
    try:
        import uvicorn
        from uvicorn.supervisors import Multiprocess
        import limits  # noqa: F401 - the rate limiter (a core dependency)
    except ImportError as e:
        print(f"aidl: error: `aidl studio` cannot import {e.name}, one of aidl's dependencies: "
              "reinstall aidl (pip install -e /path/to/aidl)", file=sys.stderr)
        return 2
    from .app import Settings
    try:
        s = Settings.from_env()
    except ValueError as e:
        print(f"aidl: error: {e}; correct it or unset it (the default is used then)",
              file=sys.stderr)
        return 2
    if not os.environ.get("AIDL_STUDIO_AHEAD"):
        s.ahead = "all"                 # the gallery swept ahead of time (issue 113)
    s.compilers = compilers
    for k, v in settings.items():
        if v is not None:
            setattr(s, k, v)
    problem = _reachable(s)
    if problem:
        print(f"aidl: error: {problem}", file=sys.stderr)
        return 2
    from ..serve import listening
    sock = listening(host, port, 1024)
    if sock is None:
        return 2
    port = sock.getsockname()[1]
    made = not s.data
    if made:
        s.data = tempfile.mkdtemp(prefix="aidl-studio-")
    os.environ.update(s.to_env())           # every server process reads its settings from here
    config = uvicorn.Config("aidl_lang.studio.app:create_app", factory=True,
                            log_level="warning", timeout_graceful_shutdown=2, lifespan="on",
                            workers=max(1, processes), proxy_headers=True)
    server = uvicorn.Server(config)
    supervisor = None
    if processes > 1:
        try:            # uvicorn's supervisor runs the server itself in each worker process
            supervisor = Multiprocess(config, sockets=[sock])
        except TypeError:                       # older uvicorn: it is given the server's run
            supervisor = Multiprocess(config, target=server.run, sockets=[sock])
    shown = f"[{host}]" if ":" in host else host
    print(f"aidl studio: http://{shown}:{port}/  ({max(1, processes)} process"
          f"{'es' if processes > 1 else ''} x {compilers} compilers; Ctrl-C stops)", flush=True)
    if supervisor is None:
        # uvicorn raises a SIGTERM again after its graceful shutdown: end through `finally`
        # then, so the sessions' folder is removed (the default action would skip it).  Not
        # with several processes: the supervisor's own SIGTERM handler stops and joins its
        # workers; replacing it left them running, and the interpreter's exit waiting on them
        # (the studio never ended; killed, its workers were orphaned)
        signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    try:
        if supervisor is not None:
            supervisor.run()
        else:
            server.run(sockets=[sock])
    finally:
        if made:
            shutil.rmtree(s.data, ignore_errors=True)
    return 0


def _reachable(s) -> str:
    """Why the settings' store or cluster cannot be used ('' when they can): its client is
    missing, or Redis does not answer (checked once at start; later outages are ``503``s
    and ``/healthz`` says so)."""
    if s.scheduler:
        try:
            import dask.distributed  # noqa: F401
        except ImportError as e:
            return (f"--scheduler needs Dask ({e.name} is missing): "
                    "pip install 'aidl-lang[studio]'")
    if not s.store:
        return ""
    try:
        import redis
    except ImportError:
        return "--store needs the redis client: pip install 'aidl-lang[studio]'"
    from .store import TIMEOUT
    try:
        redis.Redis.from_url(s.store, socket_timeout=TIMEOUT,
                             socket_connect_timeout=TIMEOUT).ping()
    except (redis.exceptions.RedisError, OSError, ValueError) as e:
        return (f"cannot reach the store at {s.store}: {str(e).rstrip('.')}; start Redis "
                "or correct --store")
    return ""


__all__ = ["studio", "HOST"]
