"""The first half-second of ``aidl lsp``: answer ``initialize`` and publish the first
diagnostics before pygls is loaded, then hand the connection to the pygls server.

Importing pygls and lsprotocol costs about 0.45 s (``lsprotocol.types`` alone ~0.4 s: hundreds
of attrs classes), four times ``import numpy``; the parser and checker cost 0.07 s.  So
``aidl lsp`` starts here, with the standard library only:

1. a reader thread reads the client's messages (``Content-Length`` framing) from stdin;
2. ``initialize`` is answered at once with the server's capabilities
   (:data:`._capabilities.CAPABILITIES`, generated from the pygls server by
   ``python editors/gen_lsp_capabilities.py``; a test keeps them equal);
3. a ``textDocument/didOpen`` gets its parse-and-check diagnostics
   (:func:`.plain.quick_diagnostics`) published at once (the first one, and any others that
   arrive while pygls loads, as when an editor restores several tabs; documents up to
   :data:`QUICK_MAX` characters); the first one is also given to the worker process started
   beside this one, and its full diagnostics (interpretation and solve) are published for the
   same version as soon as the worker answers, while pygls may still be loading (the server
   reads the worker's answers only after that one, see ``hold`` in :class:`.worker.Analyzer`;
   when the answer is in before pygls sees that ``didOpen``, the server takes it instead of
   analysing the document again);
4. then :mod:`.server` is imported and pygls serves the connection: every message read so far
   is replayed to it in order, ``initialize`` included (pygls builds its workspace from it; its
   answer, a copy of the one sent, is dropped), then the rest of stdin.

Only the standard library, :mod:`pygls.uris` (plain Python) and :mod:`.plain` with the parser
and checker are imported before step 4.
"""
from __future__ import annotations

import json
import sys
import threading

#: seconds after start to wait for the first ``didOpen`` before loading pygls anyway
IDLE = 1.0
#: characters: larger documents get no parse-and-check pass here (~20 ms per kilobyte)
QUICK_MAX = 50_000


class Feed:
    """A blocking byte stream (``readline``, ``read``) fed by another thread: what pygls
    reads instead of stdin."""

    def __init__(self) -> None:
        self._buf = bytearray()
        self._eof = False
        self._cv = threading.Condition()

    def put(self, data: bytes) -> None:
        with self._cv:
            self._buf += data
            self._cv.notify_all()

    def close(self) -> None:
        with self._cv:
            self._eof = True
            self._cv.notify_all()

    def readline(self) -> bytes:
        with self._cv:
            while True:
                i = self._buf.find(b"\n")
                if i >= 0 or self._eof:
                    n = i + 1 if i >= 0 else len(self._buf)
                    out = bytes(self._buf[:n])
                    del self._buf[:n]
                    return out
                self._cv.wait()

    def read(self, n: int = -1) -> bytes:
        with self._cv:
            while len(self._buf) < n and not self._eof:
                self._cv.wait()
            n = len(self._buf) if n < 0 else min(n, len(self._buf))
            out = bytes(self._buf[:n])
            del self._buf[:n]
            return out


class Writer:
    """stdout for both halves: whole messages under a lock; drops the pygls answer to an
    ``initialize`` already answered here."""

    def __init__(self, out) -> None:
        self.out = out
        self.lock = threading.Lock()
        self.drop_id = None

    def send(self, msg: dict) -> None:
        body = json.dumps(msg).encode()
        self.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def write(self, data: bytes) -> None:
        if self.drop_id is not None and b'"id"' in data:
            body = data[data.find(b"\r\n\r\n") + 4:]
            try:
                msg = json.loads(body)
            except ValueError:
                msg = None
            if isinstance(msg, dict) and "method" not in msg and msg.get("id") == self.drop_id:
                self.drop_id = None
                return
        with self.lock:
            self.out.write(data)
            self.out.flush()

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


def read_message(stream) -> bytes | None:
    """One message body (bytes) of the base protocol, or None at the end of the stream."""
    length = None
    while True:
        line = stream.readline()
        if not line:
            return None
        line = line.strip()
        if not line:
            if length is not None:
                break
            continue
        name, _, value = line.partition(b":")
        if name.strip().lower() == b"content-length":
            try:
                length = int(value)
            except ValueError:
                length = None
    body = stream.read(length)
    return body if len(body) == length else None


def initialize_result(params) -> dict:
    """The ``initialize`` answer pygls would give (see :mod:`._capabilities`)."""
    from ._capabilities import CAPABILITIES, SERVER_INFO
    caps = json.loads(json.dumps(CAPABILITIES))
    prepare = False
    try:
        prepare = bool(params["capabilities"]["textDocument"]["rename"]["prepareSupport"])
    except (KeyError, TypeError):
        pass
    if "renameProvider" in caps and not prepare:
        caps["renameProvider"] = True          # RenameOptions only for a client that prepares
    try:
        sync = params["capabilities"]["textDocument"]["synchronization"]
    except (KeyError, TypeError):
        sync = None
    if isinstance(sync, dict) and isinstance(caps.get("textDocumentSync"), dict):
        for key in ("willSave", "willSaveWaitUntil"):     # pygls: the client's and ours (no)
            if sync.get(key) is not None:
                caps["textDocumentSync"][key] = False
    return {"capabilities": caps, "serverInfo": dict(SERVER_INFO)}


class Boot:
    """The reader thread's state (see the module doc)."""

    def __init__(self, stdin, writer: Writer, feed: Feed, worker=None) -> None:
        self.stdin = stdin
        self.writer = writer
        self.feed = feed
        self.worker = worker                  # the analysis worker process (or None)
        self.worker_free = threading.Event()  # the worker's stdout is the server's from now
        self.lock = threading.Lock()
        self.job_sent = False
        self.answers: dict[str, tuple] = {}   # uri -> (version, text, the worker's answer)
        self.go = threading.Event()           # load pygls now
        self.handed = False                   # pygls reads the feed from now on
        self.published: dict[str, list[dict]] = {}

    def run(self) -> None:
        try:
            while True:
                body = read_message(self.stdin)
                if body is None:
                    break
                if not self.handed:
                    self._see(body)
                self.feed.put(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        finally:
            self.feed.close()
            self.go.set()

    def _see(self, body: bytes) -> None:
        try:
            msg = json.loads(body)
        except ValueError:
            self.go.set()
            return
        if not isinstance(msg, dict):
            self.go.set()
            return
        method = msg.get("method")
        if self.go.is_set() and method != "textDocument/didOpen":
            return
        if method == "initialize" and "id" in msg:
            try:
                result = initialize_result(msg.get("params") or {})
            except Exception:                 # let pygls answer it
                self.go.set()
                return
            self.writer.send({"jsonrpc": "2.0", "id": msg["id"], "result": result})
            self.writer.drop_id = msg["id"]          # pygls' copy of this answer
        elif method == "textDocument/didOpen":
            try:
                self._quick(msg["params"]["textDocument"])
            except Exception:                 # the full analysis will say it
                pass
            self.go.set()
        elif "id" in msg:
            self.go.set()                     # a request: pygls' to answer
        # other notifications (initialized, didChangeConfiguration, $/setTrace, ...) wait
        # for pygls in the feed; VS Code sends some between `initialized` and `didOpen`

    def _quick(self, doc: dict) -> None:
        from .plain import quick_diagnostics
        uri, text = doc["uri"], doc["text"]
        if len(text) > QUICK_MAX:
            return
        path = _path(uri)
        diags = quick_diagnostics(text, path, uri)
        if diags is None:
            return
        self.published[uri] = diags
        self.writer.send({"jsonrpc": "2.0", "method": "textDocument/publishDiagnostics",
                          "params": {"uri": uri, "version": doc.get("version"),
                                     "diagnostics": diags}})
        self._full(uri, doc.get("version"), text, path)

    def _full(self, uri: str, version, text: str, path: str) -> None:
        """Give the first opened document to the worker now (it is warming up beside this
        process) and publish its solved diagnostics when they come, rather than after pygls
        has loaded; the server's analysis of the same version follows (same answer)."""
        with self.lock:
            if self.job_sent or self.handed or self.worker is None or self.worker.poll() is not None:
                return
            self.job_sent = True
        try:
            job = {"id": 0, "text": text, "path": path, "uri": uri, "solve": True}
            self.worker.stdin.write((json.dumps(job) + "\n").encode())
            self.worker.stdin.flush()
        except (OSError, ValueError):
            self.worker_free.set()
            return
        threading.Thread(target=self._await_full, args=(uri, version, text), daemon=True).start()

    def _await_full(self, uri: str, version, text: str) -> None:
        try:
            line = self.worker.stdout.readline()
            answer = json.loads(line) if line else {}
            if isinstance(answer, dict) and answer.get("id") == 0 and "diagnostics" in answer:
                self.answers[uri] = (version, text, answer)
                self.writer.send({"jsonrpc": "2.0", "method": "textDocument/publishDiagnostics",
                                  "params": {"uri": uri, "version": version,
                                             "diagnostics": answer["diagnostics"]}})
        except (OSError, ValueError):
            pass
        finally:
            self.worker_free.set()


def _path(uri: str) -> str:
    """The file path of ``uri`` as pygls gives it (``Document.path``; :mod:`pygls.uris` is
    plain Python, no lsprotocol), else ``untitled.aidl``."""
    from pygls.uris import to_fs_path
    try:
        return to_fs_path(uri) or "untitled.aidl"
    except Exception:
        return "untitled.aidl"


def main(worker=None, stdin=None, stdout=None) -> int:
    """Serve over stdin/stdout (see the module doc). ``worker``: a diagnostics worker process
    already started (:func:`.worker.spawn`)."""
    stdin = stdin or sys.stdin.buffer
    writer = Writer(stdout or sys.stdout.buffer)
    feed = Feed()
    boot = Boot(stdin, writer, feed, worker)
    threading.Thread(target=boot.run, name="aidl-lsp-boot", daemon=True).start()
    try:                                      # while the client answers: the parser, checker
        from . import plain                   # noqa: F401
        from ... import parser, typecheck     # noqa: F401
    except Exception:
        pass
    boot.go.wait(IDLE)
    boot.go.set()
    from .server import main as serve
    with boot.lock:
        boot.handed = True
        if not boot.job_sent:
            boot.worker_free.set()
    code = serve(worker, stdin=feed, stdout=writer, published=boot.published,
                 hold=boot.worker_free, early=boot.answers)
    # the reader thread is blocked reading stdin: end here rather than in an interpreter
    # shutdown that would wait for it
    sys.stdout.flush()
    sys.stderr.flush()
    import os
    os._exit(code)


def pygls_initialize_result(client_capabilities: dict | None = None) -> dict:
    """The ``initialize`` answer the pygls server (:mod:`.server`) computes from its registered
    features for a client with ``client_capabilities`` (JSON), as JSON: what
    :func:`initialize_result` must equal (imports pygls; for the generator and the tests)."""
    from lsprotocol import types as T
    from pygls.capabilities import ServerCapabilitiesBuilder

    from .server import server
    proto = server.protocol
    conv = proto._converter
    caps = conv.structure(client_capabilities or {}, T.ClientCapabilities)
    fm = proto.fm
    built = ServerCapabilitiesBuilder(
        caps, set({**fm.features, **fm.builtin_features}.keys()), fm.feature_options,
        list(fm.commands.keys()), server._text_document_sync_kind,
        server._notebook_document_sync, T.PositionEncodingKind.Utf16).build()
    result = T.InitializeResult(capabilities=built, server_info=proto.server_info)
    return json.loads(json.dumps(conv.unstructure(result)))


def capabilities_module() -> str:
    """The text of :mod:`._capabilities` (for ``editors/gen_lsp_capabilities.py``)."""
    import pprint
    full = pygls_initialize_result({"textDocument": {"rename": {"prepareSupport": True}}})
    return ('"""The ``initialize`` answer of ``aidl lsp`` (capabilities and server info), generated\n'
            'from the pygls server by ``python editors/gen_lsp_capabilities.py``: do not edit.\n'
            ':mod:`.boot` sends it before pygls is loaded; tests/test_lsp_features.py keeps it\n'
            'equal to what pygls computes."""\n\n'
            f"CAPABILITIES = {pprint.pformat(full['capabilities'], width=96, sort_dicts=True)}\n\n"
            f"SERVER_INFO = {pprint.pformat(full['serverInfo'], width=96)}\n")
