"""``aidl mcp``'s first answers before the MCP SDK is loaded (issue 95: a client waited 0.9 s
for its first ``tools/list`` on a quiet machine, most of it the SDK's own import).

The SDK's answers to ``initialize`` (one per protocol version asked) and to ``tools/list``
depend on nothing but this code and the SDK's: :mod:`.stdio` keeps them, as the SDK sent
them, in the user's cache folder (:mod:`aidl_lang.host.cache`) under a key of the Python, SDK and
aidl versions and every aidl source file's size and time.  On the next start,
:func:`first_answers` reads the client's first lines from fd 0 itself, one byte at a time (so
nothing is read past them), while the SDK loads in a thread: an ``initialize`` of a known
version and then a ``tools/list`` are answered at once from the cache, with the client's
ids.  It stops at the first message it cannot answer so (anything else, a version not kept,
no cache) and returns every line it read; the SDK's server then reads those lines first
(the ``initialize`` too, so its session starts as always: its answer to an id already
answered is dropped) and the rest of stdin after them.  No cache, or a key that does not
match: the SDK answers everything, as before, and keeps its answers for the next start.
"""
from __future__ import annotations

import json
import os
import sys
import threading

CACHE_NAME = "mcp-first-answers.json"


def cache_key() -> str:
    """The versions and source files the first answers depend on, hashed."""
    import hashlib
    from importlib.metadata import PackageNotFoundError, version
    h = hashlib.sha256(sys.version.encode())
    for dist in ("mcp", "mcp-types", "pydantic", "aidl-lang"):
        try:
            h.update(f"{dist}={version(dist)};".encode())
        except PackageNotFoundError:
            h.update(f"{dist}=?;".encode())
    pkg = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for folder, dirs, names in sorted(os.walk(pkg)):
        dirs.sort()
        for n in sorted(names):
            if n.endswith(".py"):
                st = os.stat(os.path.join(folder, n))
                h.update(f"{folder}/{n}:{st.st_size}:{st.st_mtime_ns};".encode())
    return h.hexdigest()


def load() -> tuple[str, dict]:
    """``(key, answers)``: the kept answers (``{"initialize": {version: result},
    "tools/list": result}``) if they are this code's, else empty ones."""
    from ..host.cache import cache_dir, read_checked
    key = cache_key()
    d = cache_dir()
    text = read_checked(d / CACHE_NAME, key) if d is not None else None
    try:
        kept = json.loads(text) if text else {}
    except ValueError:
        kept = {}
    return key, kept if isinstance(kept, dict) else {}


def keep(key: str, answers: dict) -> None:
    """Store ``answers`` for the next start (quietly nothing when the cache folder is not
    usable)."""
    from ..host.cache import cache_dir, write_checked
    d = cache_dir()
    if d is not None:
        write_checked(d / CACHE_NAME, key, json.dumps(answers, separators=(",", ":")))


def _line(fd: int) -> bytes:
    """One line of ``fd`` (with its newline; b"" at the end of the input), read a byte at a
    time so that nothing after it is taken from the descriptor."""
    out = bytearray()
    while True:
        b = os.read(fd, 1)
        if not b:
            return bytes(out)
        out += b
        if b == b"\n":
            return bytes(out)


def _reply(msg_id, result: dict) -> bytes:
    return (json.dumps({"jsonrpc": "2.0", "id": msg_id, "result": result},
                       separators=(",", ":")) + "\n").encode("utf-8")


def first_answers(kept: dict, fd_in: int = 0, fd_out: int = 1) -> tuple[list[str], set]:
    """Answer the client's ``initialize`` and ``tools/list`` from ``kept`` (see the module
    text), reading ``fd_in`` and writing ``fd_out``; ``(lines read, ids answered)``."""
    read: list[str] = []
    answered: set = set()
    inits, listed = kept.get("initialize") or {}, kept.get("tools/list")
    if not inits or not isinstance(listed, dict):
        return read, answered
    started = False
    while True:
        raw = _line(fd_in)
        if not raw:
            return read, answered
        line = raw.decode("utf-8", errors="replace")
        read.append(line)
        try:
            msg = json.loads(line)
        except (ValueError, RecursionError):     # the SDK's server answers it (.stdio)
            return read, answered
        if not isinstance(msg, dict) or msg.get("jsonrpc") != "2.0":
            return read, answered
        method, msg_id = msg.get("method"), msg.get("id")
        fine_id = isinstance(msg_id, str) or (isinstance(msg_id, int)
                                              and not isinstance(msg_id, bool))
        params = msg.get("params") if isinstance(msg.get("params"), dict) else {}
        if method == "initialize" and fine_id and not started:
            result = inits.get(str(params.get("protocolVersion")))
            if not isinstance(result, dict):
                return read, answered
            os.write(fd_out, _reply(msg_id, result))
            answered.add(msg_id)
            started = True
        elif method == "notifications/initialized" and "id" not in msg and started:
            continue
        elif method == "tools/list" and fine_id and started and not params.get("cursor"):
            os.write(fd_out, _reply(msg_id, listed))
            answered.add(msg_id)
            read.pop()                      # answered: the SDK need not see it
            print("aidl mcp: initialize and tools/list answered from the cache while the SDK "
                  "loads", file=sys.stderr, flush=True)
            return read, answered
        else:
            return read, answered


def serve(root: str, budget: float, prompt) -> int:
    """``aidl mcp``: the first answers from the cache while the SDK loads, then the SDK's
    server (:func:`.server.main`), reading the lines read here first."""
    key, kept = load()                      # (before the thread: no import races)
    loaded: list = []

    def load_sdk() -> None:
        try:
            from . import server
            loaded.append(server)
        except BaseException as e:          # noqa: BLE001 - said when the server starts
            loaded.append(e)
    sdk = threading.Thread(target=load_sdk, name="aidl-mcp-import", daemon=True)
    sdk.start()
    read, answered = first_answers(kept)
    sdk.join()
    if isinstance(loaded[0], BaseException):
        raise loaded[0]
    return loaded[0].main(root, budget, prompt,
                          first=(read, answered, lambda got: keep(key, got), kept))
