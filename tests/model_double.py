"""TEST DOUBLE, not a model: a tiny local OpenAI-compatible chat-completions server that
replays recorded answers.

It listens on 127.0.0.1 on a free port (port 0) in a background thread and answers
``POST /v1/chat/completions`` (and ``POST /chat/completions``) with the next answer of a list
it was given, in order, whatever it is asked: the answers are recorded model replies
(``tests/data/studio_model_replay.json``), so a test can run the validate-until-correct loop
end to end (HTTP, JSON, the client's error handling) without a model or a network.  It records
every request it got (path, ``Authorization`` header, JSON body) so that a test can check what
the loop sent.  Once the answers run out it answers HTTP 500 ("the replay has no more
answers"); any other path is 404.

``delay`` (seconds; or a list, one per answer, 0 past its end) makes answers slow, for
deadline tests; the wait ends early when the server is shut down, so a test never waits for a
sleeping answer.

>>> with replaying(["```aidl\\nsolid a {\\n}\\n```"]) as (base_url, requests):
...     ...   # ChatClient(base_url=base_url, model="m").complete([...])
"""
from __future__ import annotations

import contextlib
import json
import threading
from collections.abc import Iterator
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

REPLAY_FILE = Path(__file__).resolve().parent / "data" / "studio_model_replay.json"
PATHS = ("/v1/chat/completions", "/chat/completions")


def recorded(name: str = "tray_3x4") -> dict:
    """One recorded conversation of :data:`REPLAY_FILE`: ``{"request", "model", "answers",
    ...}``."""
    return json.loads(REPLAY_FILE.read_text(encoding="utf-8"))["replays"][name]


class ReplayServer:
    """The server; use :func:`replaying`.  ``requests``: ``[{"path", "auth", "body"}]`` in the
    order received; ``answered``: how many answers were given."""

    def __init__(self, answers: list[str], delay: float | list[float] = 0.0,
                 model: str = "replay-double"):
        self.answers = list(answers)
        self.delay = delay
        self.model = model
        self.requests: list[dict] = []
        self.answered = 0
        self.closing = threading.Event()
        self.lock = threading.Lock()
        double = self

        class Handler(BaseHTTPRequestHandler):
            def do_POST(self):                                  # noqa: N802 (http.server's name)
                n = int(self.headers.get("Content-Length") or 0)
                raw = self.rfile.read(n)
                try:
                    body = json.loads(raw)
                except ValueError:
                    body = {"unreadable": raw[:200].decode("utf-8", "replace")}
                path = self.path.split("?", 1)[0].rstrip("/")
                wait = 0.0
                with double.lock:
                    # "sent": the answer was written to the client (False while it waits,
                    # or when the client went away first)
                    request = {"path": path, "auth": self.headers.get("Authorization"),
                               "body": body, "sent": False}
                    double.requests.append(request)
                    if path not in PATHS:
                        status, doc = 404, {"error": {"message": f"no route {path}"}}
                    elif double.answered >= len(double.answers):
                        status, doc = 500, {"error": {"message": "the replay has no more answers"}}
                    else:
                        answer = double.answers[double.answered]
                        wait = double.delay_for(double.answered)
                        double.answered += 1
                        status, doc = 200, {
                            "id": f"replay-{double.answered}", "object": "chat.completion",
                            "model": double.model,
                            "choices": [{"index": 0, "finish_reason": "stop",
                                         "message": {"role": "assistant", "content": answer}}]}
                if wait > 0 and double.closing.wait(wait):
                    return                                       # shut down while waiting
                data = json.dumps(doc).encode("utf-8")
                try:
                    self.send_response(status)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                    request["sent"] = True
                except OSError:                                  # the client went away
                    pass

            def log_message(self, *args):
                pass

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.server.daemon_threads = True
        self.base_url = f"http://127.0.0.1:{self.server.server_address[1]}/v1"
        self.thread = threading.Thread(target=self.server.serve_forever, args=(0.05,),
                                       name="model-double", daemon=True)

    def delay_for(self, i: int) -> float:
        """Seconds before answer ``i`` (0-based)."""
        if isinstance(self.delay, (list, tuple)):
            return float(self.delay[i]) if i < len(self.delay) else 0.0
        return float(self.delay)

    def start(self) -> ReplayServer:
        self.thread.start()
        return self

    def stop(self) -> None:
        self.closing.set()
        self.server.shutdown()
        self.server.server_close()
        self.thread.join(timeout=5)


@contextlib.contextmanager
def replaying(answers: list[str], delay: float | list[float] = 0.0
              ) -> Iterator[tuple[str, list[dict]]]:
    """Serve ``answers`` in order; yields ``(base_url, requests)``: the OpenAI-style base URL
    (``http://127.0.0.1:PORT/v1``) and the live list of requests received (each
    ``{"path", "auth", "body", "sent"}``, ``sent`` once its answer is written).  ``delay``: seconds before each answer (a list: per
    answer)."""
    double = ReplayServer(answers, delay).start()
    try:
        yield double.base_url, double.requests
    finally:
        double.stop()
