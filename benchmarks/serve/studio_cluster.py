"""The studio as an operator deploys it, on this machine: Debian's ``redis-server``, studio
processes started by the image's entry script (``deploy/studio/entrypoint.sh``), and Debian's
``nginx`` in front with the configuration docs/studio.md gives (its ``nginx`` block, ports
filled in).  Shared by ``tests/test_studio_ops.py`` and ``benchmarks/serve/studio_nginx_load.py``.

Every helper is a context manager that starts a real server on a free port of 127.0.0.1 and
stops it after (SIGTERM, then SIGKILL); none leaves a process or a file behind.
"""
from __future__ import annotations

import contextlib
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
ENTRY = ROOT / "deploy" / "studio" / "entrypoint.sh"
DOC = ROOT / "docs" / "studio.md"


def redis_server_path() -> str | None:
    return shutil.which("redis-server")


def nginx_path() -> str | None:
    return shutil.which("nginx") or next(
        (p for p in ("/usr/sbin/nginx",) if os.access(p, os.X_OK)), None)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _stop(proc: subprocess.Popen, group: bool = False) -> None:
    if proc.poll() is None:
        try:
            os.killpg(proc.pid, signal.SIGTERM) if group else proc.terminate()
        except ProcessLookupError:
            pass
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(proc.pid, signal.SIGKILL) if group else proc.kill()
            proc.wait()


def get(url: str, timeout: float = 10.0) -> tuple[int, bytes]:
    """``(status, body)`` of a GET (an HTTP error status is returned, not raised)."""
    try:
        with urllib.request.urlopen(url, timeout=timeout) as r:
            return r.status, r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.read()


def post(url: str, doc=None, data: bytes | None = None, timeout: float = 60.0):
    """``(status, JSON answer)`` of a POST of ``doc`` as JSON (or of the bytes ``data``)."""
    body = data if data is not None else json.dumps(doc or {}).encode()
    req = urllib.request.Request(url, data=body, method="POST",
                                 headers={"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            return r.status, json.loads(r.read() or b"null")
    except urllib.error.HTTPError as e:
        raw = e.read()
        try:
            return e.code, json.loads(raw)
        except ValueError:
            return e.code, {"error": raw.decode(errors="replace")}


@contextlib.contextmanager
def redis_server(timeout: float = 10.0):
    """Debian's ``redis-server`` on a free port, nothing saved to disk; yields its URL
    (``redis://127.0.0.1:PORT/0``)."""
    exe = redis_server_path()
    if exe is None:
        raise FileNotFoundError("redis-server (apt-get install redis-server)")
    port = free_port()
    with tempfile.TemporaryDirectory(prefix="aidl-redis-") as tmp:
        proc = subprocess.Popen([exe, "--port", str(port), "--bind", "127.0.0.1",
                                 "--save", "", "--appendonly", "no", "--dir", tmp,
                                 "--daemonize", "no", "--loglevel", "warning"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            deadline = time.monotonic() + timeout
            while True:
                with contextlib.suppress(OSError), \
                        socket.create_connection(("127.0.0.1", port), 0.5) as s:
                    s.sendall(b"PING\r\n")
                    if s.recv(16).startswith(b"+PONG"):
                        break
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise RuntimeError(f"redis-server did not start on port {port}")
                time.sleep(0.05)
            yield f"redis://127.0.0.1:{port}/0", proc
        finally:
            _stop(proc)


@contextlib.contextmanager
def studio_processes(ports: list[int], env: dict | None = None, *args: str,
                     ready: float = 90.0):
    """``aidl studio`` on each of ``ports``, started side by side by the image's entry script
    (this Python's ``aidl`` first on PATH; ``env``: their ``AIDL_STUDIO_*`` settings); waits
    for each ``/healthz`` to say ready (a compile worker up, the store reachable); yields the
    processes (each the leader of its process group)."""
    bindir = str(Path(sys.executable).parent)
    procs = []
    try:
        for port in ports:
            e = {**os.environ, "PATH": bindir + os.pathsep + os.environ.get("PATH", ""),
                 "PORT": str(port), "AIDL_STUDIO_HOST": "127.0.0.1",
                 "AIDL_STUDIO_AHEAD": "none", **(env or {})}
            procs.append(subprocess.Popen(["/bin/sh", str(ENTRY), *args], env=e,
                                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                          start_new_session=True))
        deadline = time.monotonic() + ready
        for port, proc in zip(ports, procs):
            while True:
                if proc.poll() is not None:
                    raise RuntimeError(f"the studio on port {port} ended: "
                                       f"{proc.stderr.read().decode(errors='replace')[-2000:]}")
                with contextlib.suppress(OSError):
                    if get(f"http://127.0.0.1:{port}/healthz", 5)[0] == 200:
                        break
                if time.monotonic() > deadline:
                    raise RuntimeError(f"the studio on port {port} was not ready in {ready:g} s")
                time.sleep(0.1)
        yield procs
    finally:
        for proc in procs:
            _stop(proc, group=True)
            proc.stderr.close()


def nginx_config(front: int, backends: list[int]) -> str:
    """The ``nginx`` block of docs/studio.md with this run's ports: ``listen`` on ``front``,
    the ``upstream``'s servers on ``backends``."""
    m = re.search(r"```nginx\n(.*?)```", DOC.read_text(), re.S)
    if m is None:
        raise ValueError("docs/studio.md has no ```nginx block")
    block = m.group(1)
    lines, first = [], True
    for ln in block.splitlines():
        if re.match(r"\s*server 127\.0\.0\.1:\d+", ln):
            if first:
                lines += [re.sub(r"127\.0\.0\.1:\d+", f"127.0.0.1:{p}", ln) for p in backends]
            first = False
            continue
        lines.append(re.sub(r"listen \d+;", f"listen 127.0.0.1:{front};", ln))
    return "\n".join(lines)


@contextlib.contextmanager
def nginx(front: int, backends: list[int], timeout: float = 10.0):
    """Debian's ``nginx`` on ``front`` with docs/studio.md's configuration over ``backends``
    (its temporary files, pid and logs in a temporary folder); yields the base URL."""
    exe = nginx_path()
    if exe is None:
        raise FileNotFoundError("nginx (apt-get install nginx)")
    with tempfile.TemporaryDirectory(prefix="aidl-nginx-") as tmp:
        user = "" if os.getuid() else "user root;\n"
        conf = Path(tmp) / "nginx.conf"
        conf.write_text(
            f"{user}daemon off;\nworker_processes 1;\npid {tmp}/nginx.pid;\n"
            f"error_log {tmp}/error.log warn;\nevents {{ worker_connections 1024; }}\n"
            f"http {{\n  access_log off;\n"
            + "".join(f"  {k}_temp_path {tmp}/{k};\n" for k in
                      ("client_body", "proxy", "fastcgi", "uwsgi", "scgi"))
            + nginx_config(front, backends) + "\n}\n")
        proc = subprocess.Popen([exe, "-c", str(conf), "-p", tmp, "-e", f"{tmp}/error.log"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        try:
            deadline = time.monotonic() + timeout
            while True:
                with contextlib.suppress(OSError), \
                        socket.create_connection(("127.0.0.1", front), 0.5):
                    break
                if proc.poll() is not None or time.monotonic() > deadline:
                    log = (Path(tmp) / "error.log")
                    raise RuntimeError("nginx did not start: " + proc.stderr.read().decode()
                                       + (log.read_text() if log.exists() else ""))
                time.sleep(0.05)
            yield f"http://127.0.0.1:{front}/"
        finally:
            _stop(proc)
            proc.stderr.close()
