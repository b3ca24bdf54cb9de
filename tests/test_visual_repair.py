"""`aidl generate --visual-rounds N` (issue 24 item 5) against a fake OpenAI-compatible server:
a Starlette app served by uvicorn on 127.0.0.1 (a free port) that checks every picture it is
sent is a decodable PNG and replies from a script: a program with a part floating apart, then
(shown its picture) the fixed program, then LOOKS RIGHT."""
import base64
import contextlib
import io
import json
import socket
import struct
import threading
import time

import pytest

pytest.importorskip("cairosvg")
uvicorn = pytest.importorskip("uvicorn")
from starlette.applications import Starlette  # noqa: E402
from starlette.responses import JSONResponse  # noqa: E402
from starlette.routing import Route  # noqa: E402

from aidl_lang.cli import main  # noqa: E402
from aidl_lang.llm.generate import (extract_code, generate, png_size,  # noqa: E402
                                    request_messages)

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"

# the loop sits apart from the tag: W0504 "falls apart into 2 separate pieces"
FLOATING = """A tag with a loop for the key ring:

```aidl
solid tag {
    body = Rectangle(center=(0, 0), width=60, height=30)
    loop = Circle(center=(60, 0), radius=8)
}
```
"""

JOINED = """The loop was floating off the tag; it now overlaps the right edge:

```aidl
solid tag {
    body = Rectangle(center=(0, 0), width=60, height=30)
    loop = Circle(center=(30, 0), radius=8)
}
```
"""

BROKEN = """```aidl
solid tag {
    body = Rectangle(center=(0, 0), width=60, height=30)
    loop = Circel(center=(30, 0), radius=8)
}
```
"""

LOOKS_RIGHT = "LOOKS RIGHT"


def image_parts(body: dict) -> list[dict]:
    return [p for m in body["messages"] if isinstance(m.get("content"), list)
            for p in m["content"] if p.get("type") == "image_url"]


def decode_png(url: str) -> bytes:
    """The PNG bytes of a ``data:image/png;base64,...`` URL; AssertionError if it is not one."""
    head, _, data = url.partition(",")
    assert head == "data:image/png;base64", head[:40]
    png = base64.b64decode(data, validate=True)
    assert png[:8] == PNG_SIGNATURE and png[12:16] == b"IHDR"
    w, h = struct.unpack(">II", png[16:24])
    assert 100 <= max(w, h) <= 2048 and min(w, h) >= 16, (w, h)
    return png


class FakeServer:
    """An OpenAI-compatible chat-completions endpoint replying from ``script`` in order."""

    def __init__(self, script: list[str]):
        self.script, self.requests, self.pictures, self.problems = list(script), [], [], []

        async def chat(request):
            body = await request.json()
            self.requests.append(body)
            for part in image_parts(body):
                try:
                    self.pictures.append(decode_png(part["image_url"]["url"]))
                except (AssertionError, ValueError) as e:
                    self.problems.append(repr(e))
                    return JSONResponse({"error": {"message": f"bad image: {e!r}"}}, 400)
            if not self.script:
                self.problems.append("more requests than scripted replies")
                return JSONResponse({"error": {"message": "script exhausted"}}, 500)
            reply = self.script.pop(0)
            return JSONResponse({"id": "chatcmpl-fake", "object": "chat.completion",
                                 "model": body["model"],
                                 "choices": [{"index": 0, "finish_reason": "stop",
                                              "message": {"role": "assistant",
                                                          "content": reply}}]})

        app = Starlette(routes=[Route("/v1/chat/completions", chat, methods=["POST"])])
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.sock.bind(("127.0.0.1", 0))
        self.url = f"http://127.0.0.1:{self.sock.getsockname()[1]}/v1"
        self.server = uvicorn.Server(uvicorn.Config(app, log_level="warning", lifespan="off"))
        self.thread = threading.Thread(target=self.server.run,
                                       kwargs={"sockets": [self.sock]}, daemon=True)

    def __enter__(self):
        self.thread.start()
        deadline = time.monotonic() + 10
        while not self.server.started:
            assert time.monotonic() < deadline, "the fake server did not start"
            time.sleep(0.01)
        return self

    def __exit__(self, *exc):
        self.server.should_exit = True
        self.thread.join(5)
        self.sock.close()


def run_cli(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()


def test_visual_round_fixes_a_floating_part(tmp_path, monkeypatch):
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)
    out = tmp_path / "tag.aidl"
    with FakeServer([FLOATING, JOINED, LOOKS_RIGHT]) as srv:
        rc, stdout, err = run_cli("generate", "a key tag: a 60 x 30 mm plate with a ring loop on "
                                  "its right edge", "-o", out, "--base-url", srv.url,
                                  "--model", "fake-vision", "--warning-rounds", "0",
                                  "--visual-rounds", "2")
    assert rc == 0, err
    assert srv.problems == [] and len(srv.requests) == 3
    # the final file is the fixed program, not the floating one
    assert out.read_text() == extract_code(JOINED)
    assert "round 3: LOOKS RIGHT" in err and "2 picture(s) checked, LOOKS RIGHT" in stdout
    # request 1: text only; requests 2 and 3: exactly one picture each (older ones left out)
    assert [len(image_parts(r)) for r in srv.requests] == [0, 1, 1]
    assert "(the picture of this earlier version is left out)" in json.dumps(srv.requests[2])
    # the first picture went with the request and the warning about the floating part
    first = srv.requests[1]["messages"][-1]["content"]
    assert first[0]["type"] == "text" and "LOOKS RIGHT" in first[0]["text"]
    assert "a key tag" in first[0]["text"] and "W0504" in first[0]["text"]
    assert first[1]["type"] == "image_url"
    assert "W0504" not in srv.requests[2]["messages"][-1]["content"][0]["text"]

    tr = json.loads((tmp_path / "tag.transcript.json").read_text())
    assert tr["ok"] and tr["visual_rounds"] == 2 and tr["looks_right"] and tr["rounds_used"] == 3
    r1, r2, r3 = tr["rounds"]
    assert r1["kind"] == "program" and r1["warning_codes"] == ["W0504"]
    assert r2["kind"] == "visual" and r2["verdict"] == "revised" and r2["ok"]
    assert r3["kind"] == "visual" and r3["verdict"] == "looks right"
    assert r1["picture"] == str(tmp_path / "tag.round1.png")
    assert r2["picture"] == str(tmp_path / "tag.round2.png") and r3["picture"] is None
    assert tr["pictures"] == [r1["picture"], r2["picture"]]
    # the pictures exist, are PNGs, and are the ones the server was sent
    for path, sent in zip(tr["pictures"], srv.pictures):
        data = open(path, "rb").read()
        assert data[:8] == PNG_SIGNATURE and png_size(data)[0] == 768 and data == sent
    # the transcript keeps paths, never the base64 data
    text = (tmp_path / "tag.transcript.json").read_text()
    assert "base64" not in text and len(text) < 60_000
    urls = [p["image_url"]["url"] for m in tr["messages"] if isinstance(m["content"], list)
            for p in m["content"] if p["type"] == "image_url"]
    assert urls == tr["pictures"]
    md = (tmp_path / "tag.transcript.md").read_text()
    assert "## Round 2: visual check: revised, valid" in md
    assert "## Round 3: visual check: LOOKS RIGHT" in md
    assert "](tag.round1.png)" in md and "](tag.round2.png)" in md


def test_no_picture_is_sent_without_visual_rounds(tmp_path):
    out = tmp_path / "tag.aidl"
    with FakeServer([FLOATING]) as srv:
        rc, stdout, err = run_cli("generate", "a key tag", "-o", out, "--base-url", srv.url,
                                  "--warning-rounds", "0")
    assert rc == 0, err
    assert len(srv.requests) == 1 and srv.pictures == []
    assert all(isinstance(m["content"], str) for m in srv.requests[0]["messages"])
    assert out.read_text() == extract_code(FLOATING)
    assert list(tmp_path.glob("*.png")) == []
    tr = json.loads((tmp_path / "tag.transcript.json").read_text())
    assert tr["visual_rounds"] == 0 and tr["pictures"] == [] and tr["rounds"][0]["picture"] is None


class Scripted:
    """A chat client that replies from a list and records what it was sent."""

    model = "scripted"

    def __init__(self, replies):
        self.replies, self.sent = list(replies), []

    def complete(self, messages):
        self.sent.append(messages)
        return self.replies.pop(0)


def test_a_visual_revision_that_breaks_keeps_the_last_good_program():
    # the revision does not compile, nor does its repair: the floating (valid) program stays
    c = Scripted([FLOATING, BROKEN, BROKEN])
    res = generate("a key tag", c, max_rounds=1, warning_rounds=0, visual_rounds=1)
    assert res.ok and res.code == extract_code(FLOATING) and not res.looks_right
    assert [r.kind for r in res.rounds] == ["program", "visual", "program"]
    assert res.rounds[1].error_codes and "Circel" in c.sent[2][-1]["content"]
    # the repair of a broken revision is compiled and then pictured again
    c = Scripted([FLOATING, BROKEN, JOINED, LOOKS_RIGHT])
    res = generate("a key tag", c, max_rounds=1, warning_rounds=0, visual_rounds=2)
    assert res.ok and res.code == extract_code(JOINED) and res.looks_right
    assert [r.picture is not None for r in res.rounds] == [True, False, True, False]
    assert res.visual_rounds == 2 and len(res.pictures) == 2


def test_visual_verdicts():
    # LOOKS RIGHT at once: the first program is kept, one round past max_rounds
    res = generate("a key tag", Scripted([JOINED, "Looks right."]), max_rounds=1,
                   visual_rounds=3)
    assert res.ok and res.looks_right and len(res.rounds) == 2 and res.visual_rounds == 1
    # the same program sent back counts as LOOKS RIGHT
    res = generate("a key tag", Scripted([JOINED, JOINED]), max_rounds=1, visual_rounds=1)
    assert res.looks_right and res.rounds[1].verdict == "looks right"
    # neither verdict nor program: asked again (the picture still travels), then LOOKS RIGHT
    c = Scripted([JOINED, "Hmm, nice plate.", LOOKS_RIGHT])
    res = generate("a key tag", c, max_rounds=1, visual_rounds=1)
    assert res.looks_right and res.rounds[1].verdict == "no verdict"
    assert "neither LOOKS RIGHT" in c.sent[2][-1]["content"]
    assert len([p for m in c.sent[2] if isinstance(m["content"], list) for p in m["content"]
                if p["type"] == "image_url"]) == 1
    # visual rounds used up: no LOOKS RIGHT needed, the revision is the result
    res = generate("a key tag", Scripted([FLOATING, JOINED]), max_rounds=1, warning_rounds=0,
                   visual_rounds=1)
    assert res.ok and res.code == extract_code(JOINED) and not res.looks_right


def test_request_messages_sends_only_the_newest_picture():
    pics = {"a.png": b"A", "b.png": b"B"}
    msgs = [{"role": "user", "content": [{"type": "text", "text": "x"},
                                         {"type": "image_url", "image_url": {"url": "a.png"}}]},
            {"role": "assistant", "content": "y"},
            {"role": "user", "content": [{"type": "text", "text": "z"},
                                         {"type": "image_url", "image_url": {"url": "b.png"}}]}]
    sent = request_messages(msgs, pics)
    assert sent[0]["content"][1]["type"] == "text"
    assert sent[2]["content"][1]["image_url"]["url"] == "data:image/png;base64,Qg=="
    assert msgs[2]["content"][1]["image_url"]["url"] == "b.png"        # the record is unchanged


def test_a_visual_revision_that_checks_replaces_the_program_even_with_a_warning():
    warned = JOINED.replace("radius=8)\n", "radius=8)\n    1 + 1\n")       # W0101
    res = generate("a key tag", Scripted([JOINED, warned]), max_rounds=1, warning_rounds=0,
                   visual_rounds=1)
    assert res.ok and res.code == extract_code(warned) and res.warnings == ["W0101"]


def test_an_endpoint_refusing_the_picture_keeps_the_valid_program(tmp_path):
    from aidl_lang.llm.client import LLMError

    class TextOnly(Scripted):
        def complete(self, messages):
            if any(isinstance(m["content"], list) for m in messages):
                raise LLMError("http://x/v1/chat/completions answered HTTP 400: no images")
            return super().complete(messages)

    res = generate("a key tag", TextOnly([JOINED]), max_rounds=1, visual_rounds=1)
    assert res.ok and res.code == extract_code(JOINED) and "HTTP 400" in res.visual_error
    # before any picture an endpoint failure still raises

    class Down(Scripted):
        def complete(self, messages):
            raise LLMError("cannot reach http://x/v1/chat/completions")

    with pytest.raises(LLMError):
        generate("a key tag", Down([]), max_rounds=1, visual_rounds=1)


def test_a_model_that_never_answers_the_picture_ends_with_the_rounds():
    c = Scripted([JOINED] + ["What a nice tag."] * 10)
    res = generate("a key tag", c, max_rounds=1, visual_rounds=1)
    assert res.ok and res.code == extract_code(JOINED) and not res.looks_right
    assert len(res.rounds) == 3 and [r.verdict for r in res.rounds] == [None, "no verdict",
                                                                          "no verdict"]
    c = Scripted([JOINED] + ["What a nice tag."] * 10)
    res = generate("a key tag", c, max_rounds=4, visual_rounds=1)
    assert len(res.rounds) == 4 and res.code == extract_code(JOINED)
