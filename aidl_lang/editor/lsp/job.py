"""The analysis worker process (``python -m aidl_lang.editor.lsp.job``, started by
:func:`.worker.spawn`): one JSON job per line on stdin, one answer per line on stdout.

A job is the diagnostics of a document (``{"id", "text", "path", "uri", "solve"}``,
:func:`.worker.diagnostics_json`) or, with ``"kind": "preview"``, its ``aidl/preview``
picture (:func:`.preview.preview`).  Both compile here, not in the language server: the
server can stop a stale or runaway job by killing this process, the process's address space
is limited (:data:`MEMORY_LIMIT`: a program that needs more is an error, not a server of
gigabytes), and a worker that still holds more than :data:`RETIRE_RSS` after a job answers
with ``"retire": true`` and exits, so the memory goes back to the system and the next job
starts a fresh worker.
"""
from __future__ import annotations

import json
import sys
import threading
import time

from .preview import preview
from .worker import diagnostics_json
from ...host.workers import limit_memory, rss

# four previews of large strings took the server to 3.9 GB, kept after the documents closed
MEMORY_LIMIT = 3 << 30
RETIRE_RSS = 768 << 20


def _serve() -> int:
    """The worker's loop: read a job per line, answer per line, until stdin closes."""
    import os

    parent = os.getppid()

    def watch():                      # end with the server, even in the middle of a job
        while True:
            time.sleep(2)
            if os.getppid() != parent:
                os._exit(0)
    threading.Thread(target=watch, daemon=True).start()
    _limit_memory()
    out, sys.stdout = sys.stdout, sys.stderr       # nothing but answers on the real stdout
    diagnostics_json("solid warm {\n    c = Circle(center=(0, 0), radius=1)\n}\n", "warm.aidl",
                     values={}, extra={})
    for line in sys.stdin:
        job = None
        try:
            job = json.loads(line)
            if job.get("kind") == "preview":       # aidl/preview: compiled here, not in the server
                answer = {"id": job["id"], "preview": preview(
                    job["text"], job["path"], job["uri"], job.get("version"), job.get("values"),
                    assembled=job.get("assembled") is True)}
            else:
                values: dict[str, str] = {}
                extra: dict = {}
                diags = diagnostics_json(job["text"], job["path"], job.get("solve", True),
                                         job.get("uri"), values, extra)
                answer = {"id": job["id"], "diagnostics": diags, "values": values,
                          "facts": extra}
        except Exception as e:        # answered, never a dead worker
            from ...base.limits import is_out_of_memory
            answer = {"id": job.get("id") if isinstance(job, dict) else None,
                      "oom" if is_out_of_memory(e) else "error": f"{type(e).__name__}: {e}"}
        if "oom" in answer:           # once the failed frames are gone: the located E0304
            answer = out_of_memory(job, answer["id"])
        retire = rss() > RETIRE_RSS
        if retire:                    # give the memory back: a fresh worker takes over
            answer["retire"] = True
        out.write(json.dumps(answer) + "\n")
        out.flush()
        if retire:
            return 0
    return 0


def out_of_memory(job, job_id) -> dict:
    """The answer to a job that ran out of memory anywhere (values, hints, the preview): the
    document's diagnostics are its located ``E0304`` (:func:`aidl_lang.pipeline.out_of_memory_sink`),
    the preview a message naming it."""
    from ...pipeline import out_of_memory_sink
    from .plain import sink_json
    ok = isinstance(job, dict) and isinstance(job.get("text"), str)
    text = job["text"] if ok else None
    path = job.get("path") or "untitled.aidl" if ok else "untitled.aidl"
    sink = out_of_memory_sink(path, text)
    if ok and job.get("kind") == "preview":
        d = sink.items[0]
        return {"id": job_id, "error": f"{d.code}: {d.message}"}
    return {"id": job_id, "diagnostics": sink_json(text or "", path, sink.items,
                                                     job.get("uri") if ok else None),
            "values": {}, "facts": {}, "retire": True}


def _limit_memory() -> None:
    limit_memory(MEMORY_LIMIT)


if __name__ == "__main__":
    sys.exit(_serve())
