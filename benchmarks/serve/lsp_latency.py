"""Language-server latency over stdio, as an editor sees it (prints a table).

* cold start: from launching ``aidl lsp --stdio`` to the ``initialize`` answer, to the first
  ``publishDiagnostics`` of a document opened right after ``initialized`` (parse and check,
  published before pygls is loaded, see ``aidl_lang/editor/lsp/boot.py``), to the first answer
  of pygls (a hover), and to the full diagnostics (the second publish of that version: solved);
  beside ``python -c "import numpy"`` (the yardstick: the first diagnostics should take at most
  3x it) and, with ``--compare``, the same for the server started without the boot front
  (pygls imported first: how ``aidl lsp`` started before), run alternately in one run;
* change to diagnostics: ``didChange`` (whole document, a new version) to the
  ``publishDiagnostics`` of that version, with the debounce off (``initializationOptions``
  ``{"debounce": 0}``), median and max over N edits;
* a stale expensive analysis: an edit that makes the program expensive (10^8 loop iterations),
  then an edit that fixes it: time to the fixed version's diagnostics.

Usage: ``python benchmarks/serve/lsp_latency.py [FILE.aidl] [--edits N] [--starts K] [--compare]``
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


class Client:
    def __init__(self, cmd):
        self.t0 = time.perf_counter()
        self.p = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL)
        self.msgs: list[tuple[float, dict]] = []
        self.cv = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()
        self.seq = 0

    def _read(self):
        f = self.p.stdout
        while True:
            line = f.readline()
            if not line:
                return
            n = 0
            while line.strip():
                if line.lower().startswith(b"content-length:"):
                    n = int(line.split(b":")[1])
                line = f.readline()
            body = json.loads(f.read(n))
            with self.cv:
                self.msgs.append((time.perf_counter(), body))
                self.cv.notify_all()

    def send(self, method, params, request=False):
        msg = {"jsonrpc": "2.0", "method": method, "params": params}
        if request:
            self.seq += 1
            msg["id"] = self.seq
        b = json.dumps(msg).encode()
        self.p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(b) + b)
        self.p.stdin.flush()
        return msg.get("id")

    def wait(self, pred, timeout=120):
        end = time.perf_counter() + timeout
        with self.cv:
            while True:
                for t, m in self.msgs:
                    if pred(m):
                        self.msgs.remove((t, m))
                        return t, m
                left = end - time.perf_counter()
                if left <= 0:
                    raise TimeoutError
                self.cv.wait(left)

    def diagnostics(self, uri, version):
        return self.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics"
                         and m["params"]["uri"] == uri and m["params"].get("version") == version)


OLD_START = ("from aidl_lang.editor.lsp.worker import spawn; w = spawn(); "
             "from aidl_lang.editor.lsp.server import main; main(w)")


def numpy_ms() -> float:
    t = time.perf_counter()
    subprocess.run([sys.executable, "-c", "import numpy"], check=True)
    return (time.perf_counter() - t) * 1000


def cold(cmd, uri: str, text: str, rows: list | None = None):
    """One cold start: (ms to initialize answer, to first diagnostics, to pygls' first answer,
    to the full diagnostics) and the client, still open."""
    c = Client(cmd)
    rid = c.send("initialize", {"processId": os.getpid(), "capabilities": {},
                                "initializationOptions": {"debounce": 0}}, request=True)
    t_init, _ = c.wait(lambda m: m.get("id") == rid)
    c.send("initialized", {})
    c.send("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "aidl-cad",
                                                     "version": 1, "text": text}})
    t_diag, first = c.diagnostics(uri, 1)
    hid = c.send("textDocument/hover", {"textDocument": {"uri": uri},
                                        "position": {"line": 0, "character": 0}}, request=True)
    t_hover, _ = c.wait(lambda m: m.get("id") == hid)
    try:
        t_full, _ = c.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics"
                           and m["params"]["uri"] == uri and m["params"].get("version") == 1,
                           timeout=5 if t_diag < t_hover else 0.01)
    except TimeoutError:          # one publish only: the first was the full one
        t_full = t_diag
    ms = [(t - c.t0) * 1000 for t in (t_init, t_diag, t_hover, t_full)]
    return ms, c, first


def close(c: Client) -> None:
    rid = c.send("shutdown", None, request=True)
    c.wait(lambda m: m.get("id") == rid)
    c.send("exit", None)
    c.p.wait(10)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("file", nargs="?", default=str(ROOT / "examples" / "telephone.aidl"))
    ap.add_argument("--edits", type=int, default=20)
    ap.add_argument("--starts", type=int, default=3, help="cold starts measured (median)")
    ap.add_argument("--compare", action="store_true",
                    help="also start the server the old way (pygls first), alternately")
    a = ap.parse_args()
    path = Path(a.file).resolve()
    text = path.read_text()
    uri = path.as_uri()
    aidl = Path(sys.executable).with_name("aidl")
    cmd = [str(aidl), "lsp", "--stdio", f"--clientProcessId={os.getpid()}"]
    starts, old, numpys = [], [], []
    for k in range(a.starts):
        numpys.append(numpy_ms())
        if a.compare:
            ms, c, _ = cold([sys.executable, "-c", OLD_START], uri, text)
            close(c)
            old.append(ms)
        ms, c, first = cold(cmd, uri, text)
        starts.append(ms)
        if k < a.starts - 1:
            close(c)
    np_ms = statistics.median(numpys)
    rows = [(f"python -c 'import numpy' (yardstick), median of {a.starts}", np_ms)]
    names = ["initialize answer", "first diagnostics", "first pygls answer (hover)",
             "full (solved) diagnostics"]
    for label, runs in (("", starts), ("old start: ", old)):
        if not runs:
            continue
        for i, name in enumerate(names):
            v = statistics.median(r[i] for r in runs)
            rows.append((f"{label}cold start to {name}", v))
        rows.append((f"{label}first diagnostics / numpy", statistics.median(r[1] for r in runs) / np_ms))
    times = []
    for v in range(2, 2 + a.edits):
        edited = text + f"\nedit_{v} = {v} mm\n"
        t = time.perf_counter()
        c.send("textDocument/didChange", {"textDocument": {"uri": uri, "version": v},
                                          "contentChanges": [{"text": edited}]})
        t1, _ = c.diagnostics(uri, v)
        times.append((t1 - t) * 1000)
    rows.append((f"change to diagnostics, median of {a.edits}", statistics.median(times)))
    rows.append((f"change to diagnostics, max of {a.edits}", max(times)))
    v = 2 + a.edits
    slow = text + "\nsolid slow {\n    for i in range(10000) {\n        for j in range(10000) {\n" \
                  "            x = i * j\n        }\n    }\n}\n"
    c.send("textDocument/didChange", {"textDocument": {"uri": uri, "version": v},
                                      "contentChanges": [{"text": slow}]})
    time.sleep(0.5)
    t = time.perf_counter()
    c.send("textDocument/didChange", {"textDocument": {"uri": uri, "version": v + 1},
                                      "contentChanges": [{"text": text}]})
    t1, _ = c.diagnostics(uri, v + 1)
    rows.append(("stale expensive analysis, fix to diagnostics", (t1 - t) * 1000))
    close(c)
    print(f"`aidl lsp` over stdio, {path.name} ({len(text)} characters), "
          f"{len(first['params']['diagnostics'])} diagnostics")
    print(f"| {'measure':<58} | {'ms':>8} |\n|{'-' * 60}|{'-' * 10}|")
    for name, ms in rows:
        print(f"| {name:<58} | {ms:8.2f} |" if "/" in name else f"| {name:<58} | {ms:8.0f} |")


if __name__ == "__main__":
    main()
