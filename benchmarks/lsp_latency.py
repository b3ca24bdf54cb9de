"""Language-server latency over stdio, as an editor sees it (prints a table).

* cold start: from launching ``aidl lsp --stdio`` to the ``initialize`` answer, and to the first
  ``publishDiagnostics`` of a document opened right after ``initialized``;
* change to diagnostics: ``didChange`` (whole document, a new version) to the
  ``publishDiagnostics`` of that version, with the debounce off (``initializationOptions``
  ``{"debounce": 0}``), median and max over N edits;
* a stale expensive analysis: an edit that makes the program expensive (10^8 loop iterations),
  then an edit that fixes it: time to the fixed version's diagnostics.

Usage: ``python benchmarks/lsp_latency.py [FILE.aidl] [--edits N]``
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

ROOT = Path(__file__).resolve().parent.parent


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


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("file", nargs="?", default=str(ROOT / "examples" / "telephone.aidl"))
    ap.add_argument("--edits", type=int, default=20)
    a = ap.parse_args()
    path = Path(a.file).resolve()
    text = path.read_text()
    uri = path.as_uri()
    aidl = Path(sys.executable).with_name("aidl")
    c = Client([str(aidl), "lsp", "--stdio", f"--clientProcessId={os.getpid()}"])
    rid = c.send("initialize", {"processId": os.getpid(), "capabilities": {},
                                "initializationOptions": {"debounce": 0}}, request=True)
    t_init, _ = c.wait(lambda m: m.get("id") == rid)
    c.send("initialized", {})
    c.send("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "aidl-cad",
                                                     "version": 1, "text": text}})
    t_diag, first = c.diagnostics(uri, 1)
    rows = [("cold start to initialize answer", (t_init - c.t0) * 1000),
            ("cold start to first diagnostics", (t_diag - c.t0) * 1000)]
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
    rid = c.send("shutdown", None, request=True)
    c.wait(lambda m: m.get("id") == rid)
    c.send("exit", None)
    c.p.wait(10)
    print(f"`aidl lsp` over stdio, {path.name} ({len(text)} characters), "
          f"{len(first['params']['diagnostics'])} diagnostics")
    print(f"| {'measure':<48} | {'ms':>8} |\n|{'-' * 50}|{'-' * 10}|")
    for name, ms in rows:
        print(f"| {name:<48} | {ms:8.0f} |")


if __name__ == "__main__":
    main()
