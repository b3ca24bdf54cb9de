"""aidl studio's "Describe the part" (aidl_lang/studio/describe.py): the operator's endpoint
from the environment, and the validate-until-correct loop streamed as events, against
tests/model_double.py (a TEST DOUBLE replaying recorded answers, not a model)."""
import json
import socket

import pytest

from aidl_lang.llm.prompt import system_prompt
from aidl_lang.studio.describe import MAX_DESCRIPTION, describe, model_config
from model_double import recorded, replaying

TRAY = recorded("tray_3x4")


def config(url, key="sk-studio-secret", model="replay-model", rounds=4):
    env = {"AIDL_STUDIO_MODEL_URL": url, "AIDL_STUDIO_MODEL_KEY": key,
           "AIDL_STUDIO_MODEL": model, "AIDL_STUDIO_MODEL_ROUNDS": str(rounds)}
    return model_config(env)


def closed_port() -> int:
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


# ------------------------------------------------------------------ model_config
def test_model_config_unset_or_blank_is_none():
    assert model_config({}) is None
    assert model_config({"AIDL_STUDIO_MODEL_URL": ""}) is None
    assert model_config({"AIDL_STUDIO_MODEL_URL": "   ", "AIDL_STUDIO_MODEL_KEY": "k"}) is None


def test_model_config_reads_the_environment_and_keeps_the_key_private():
    env = {"AIDL_STUDIO_MODEL_URL": " http://10.1.2.3:8000/v1 ", "AIDL_STUDIO_MODEL_KEY": "sk-x1",
           "AIDL_STUDIO_MODEL": "qwen2.5-coder", "AIDL_STUDIO_MODEL_ROUNDS": "6"}
    c = model_config(env)
    assert c == {"url": "http://10.1.2.3:8000/v1", "key": "sk-x1", "model": "qwen2.5-coder",
                 "rounds": 6}
    assert c.public() == {"model": "qwen2.5-coder"}
    assert "sk-x1" not in json.dumps(c.public()) and "10.1.2.3" not in json.dumps(c.public())
    assert "sk-x1" not in repr(c) and "sk-x1" not in str(c)
    # defaults: no key, the model `aidl generate` uses, 4 rounds
    c = model_config({"AIDL_STUDIO_MODEL_URL": "https://api.example.com/v1"})
    assert c == {"url": "https://api.example.com/v1", "key": None, "model": "gpt-4o", "rounds": 4}
    assert c.public() == {"model": "gpt-4o"}


@pytest.mark.parametrize("raw,rounds", [("0", 1), ("-3", 1), ("1", 1), ("8", 8), ("99", 8),
                                        ("", 4), ("four", 4), ("2.5", 4)])
def test_model_config_clamps_the_rounds(raw, rounds):
    c = model_config({"AIDL_STUDIO_MODEL_URL": "http://h/v1", "AIDL_STUDIO_MODEL_ROUNDS": raw})
    assert c["rounds"] == rounds


def test_model_config_reads_os_environ_by_default(monkeypatch):
    monkeypatch.delenv("AIDL_STUDIO_MODEL_URL", raising=False)
    assert model_config() is None
    monkeypatch.setenv("AIDL_STUDIO_MODEL_URL", "http://127.0.0.1:1/v1")
    monkeypatch.setenv("AIDL_STUDIO_MODEL", "m")
    assert model_config().public() == {"model": "m"}


# ------------------------------------------------------------------ describe
def test_describe_streams_two_rounds_then_done(tmp_path):
    with replaying(TRAY["answers"]) as (url, requests):
        events = list(describe(TRAY["request"], config(url), tmp_path))
    assert [e["type"] for e in events] == ["round", "round", "done"]
    r1, r2, done = events
    # round 1: the wrong argument name, located
    want = TRAY["expect"][0]
    assert r1["n"] == 1 and r1["ok"] is False and r1["svg"] is None
    assert "columns=4" in r1["code"]
    d = r1["diagnostics"][0]
    assert set(d) == {"code", "severity", "message", "line", "col", "rendered"}
    assert (d["code"], d["severity"], d["line"], d["col"]) == (want["code"], "error",
                                                              want["line"], want["col"])
    assert "columns" in d["message"]
    assert d["rendered"].startswith(f"main.aidl:{want['line']}:{want['col']}: error[E0105]")
    assert "did you mean `cols`?" in d["rendered"]
    # round 2: the corrected program checks and is drawn
    assert r2["n"] == 2 and r2["ok"] is True and "cols=4" in r2["code"]
    assert not [x for x in r2["diagnostics"] if x["severity"] == "error"]
    assert r2["svg"].startswith("<svg") and "<path" in r2["svg"]
    assert done == {"type": "done", "ok": True, "code": r2["code"], "rounds": 2,
                    "warnings": [], "message": "the program checks (round 2 of 2 rounds)"}
    # everything is JSON, and no server-side name reaches the browser
    text = json.dumps(events)
    assert str(tmp_path) not in text and "sk-studio-secret" not in text and url not in text
    # what the endpoint was sent: the system prompt and the request, then the feedback
    assert len(requests) == 2
    assert all(r["path"] == "/v1/chat/completions" for r in requests)
    assert all(r["auth"] == "Bearer sk-studio-secret" for r in requests)
    assert requests[0]["body"]["model"] == "replay-model"
    first = requests[0]["body"]["messages"]
    assert first == [{"role": "system", "content": system_prompt()},
                     {"role": "user", "content": TRAY["request"]}]
    second = requests[1]["body"]["messages"]
    assert [m["role"] for m in second] == ["system", "user", "assistant", "user"]
    assert second[2]["content"] == TRAY["answers"][0]
    feedback = second[3]["content"]
    assert "error[E0105]: `divider_tray` has no parameter `columns`" in feedback
    assert "did you mean `cols`?" in feedback and "rather than deleting it" in feedback


def test_describe_compiles_inside_the_folder(tmp_path):
    """The program is FOLDER/main.aidl: its imports resolve from the folder (and std/)."""
    (tmp_path / "tabs.aidl").write_text(
        "def tab(w=20 mm) -> solid {\n    body = Rectangle(center=(0, 0), width=w, height=10 mm)\n}\n")
    answer = ('```aidl\nimport "tabs.aidl"\n\nsolid plate {\n    t = tab(w=30 mm)\n}\n```\n'
              'and a look outside it: ```aidl\nimport "../tabs.aidl"\nsolid p {\n}\n```')
    # the last block of a reply is the program: first the one that leaves the folder
    with replaying([answer, answer.split("and a look")[0]]) as (url, requests):
        events = list(describe("a plate of a tab", config(url), tmp_path))
    r1, r2, done = events
    assert not r1["ok"] and r1["diagnostics"][0]["code"] == "E0114"
    assert "leaves the project folder" in r1["diagnostics"][0]["message"]
    assert r2["ok"] and "<path" in r2["svg"] and done["ok"]


def test_describe_out_of_rounds_is_done_not_ok(tmp_path):
    answers = [TRAY["answers"][0]] * 2
    with replaying(answers) as (url, requests):
        events = list(describe(TRAY["request"], config(url, rounds=2), tmp_path))
    assert [e["type"] for e in events] == ["round", "round", "done"]
    assert events[-1]["ok"] is False and events[-1]["code"] is None and events[-1]["rounds"] == 2
    assert events[-1]["message"] == "no program checked within 2 rounds; the last one had errors E0105"
    assert len(requests) == 2


def test_describe_a_reply_without_code_is_a_round(tmp_path):
    with replaying(["I cannot draw that.", TRAY["answers"][1]]) as (url, _):
        events = list(describe(TRAY["request"], config(url), tmp_path))
    r1 = events[0]
    assert r1["code"] is None and not r1["ok"] and r1["svg"] is None
    assert r1["diagnostics"][0]["code"] == "E0000" and r1["diagnostics"][0]["line"] is None
    assert events[-1]["type"] == "done" and events[-1]["ok"]


def test_describe_an_unreachable_endpoint_is_one_error_event(tmp_path, capsys):
    url = f"http://127.0.0.1:{closed_port()}/v1"
    events = list(describe(TRAY["request"], config(url), tmp_path))
    assert len(events) == 1 and events[0]["type"] == "error"
    msg = events[0]["message"]
    assert msg.startswith("cannot reach the model endpoint") and url not in msg
    out = capsys.readouterr()
    assert "Traceback" not in out.out + out.err


def test_describe_an_endpoint_failing_mid_loop_ends_with_an_error(tmp_path):
    # one answer only: the second request gets HTTP 500
    with replaying(TRAY["answers"][:1]) as (url, requests):
        events = list(describe(TRAY["request"], config(url), tmp_path))
    assert [e["type"] for e in events] == ["round", "error"]
    assert "answered HTTP 500" in events[1]["message"] and url not in events[1]["message"]
    assert len(requests) == 2


@pytest.mark.parametrize("description,why", [
    ("x" * (MAX_DESCRIPTION + 1), "at most 2,000"),
    ("", "empty"),
    ("   \n ", "empty"),
    (None, "must be text"),
    (42, "must be text"),
])
def test_describe_refuses_a_bad_description(tmp_path, description, why):
    with replaying(TRAY["answers"]) as (url, requests):
        events = list(describe(description, config(url), tmp_path))
    assert len(events) == 1 and events[0]["type"] == "error" and why in events[0]["message"]
    assert requests == []


def test_describe_takes_a_description_of_the_largest_size(tmp_path):
    text = TRAY["request"] + " " + "y" * (MAX_DESCRIPTION - len(TRAY["request"]) - 1)
    assert len(text) == MAX_DESCRIPTION
    with replaying(TRAY["answers"]) as (url, requests):
        events = list(describe(text, config(url), tmp_path))
    assert events[-1]["type"] == "done" and requests[0]["body"]["messages"][1]["content"] == text


def test_describe_without_an_endpoint_or_with_a_bad_url(tmp_path):
    events = list(describe("a plate", None, tmp_path))
    assert events == [{"type": "error",
                       "message": "no model endpoint is configured (set AIDL_STUDIO_MODEL_URL)"}]
    events = list(describe("a plate", config("file:///etc/passwd"), tmp_path))
    assert len(events) == 1 and "http:// or https://" in events[0]["message"]
    with pytest.raises(ValueError):
        next(describe("a plate", config("http://127.0.0.1:1/v1"), tmp_path, deadline_s=0))


@pytest.mark.timing
def test_describe_stops_at_the_deadline(tmp_path):
    """The model takes 300 s to answer (the double's wait ends when it is shut down): the
    describe stops at its 1 s deadline with that said, and returns while the double still
    holds the answer back (its request not yet answered: it did not wait for it).  No clock
    is read here: a slow machine only stops later."""
    with replaying(TRAY["answers"], delay=300) as (url, requests):
        events = list(describe(TRAY["request"], config(url), tmp_path, deadline_s=1.0))
        assert [r["sent"] for r in requests] == [False]       # returned before the answer
    assert len(events) == 1 and events[0]["type"] == "error"
    assert events[0]["message"] == "the model did not finish within 1 s (0 rounds done); stopped"
    assert len(requests) == 1


@pytest.mark.timing
def test_describe_deadline_after_a_round_keeps_the_rounds_sent(tmp_path):
    """A slow second answer: round 1 is streamed, then the deadline's error.  Round 1 (the
    first answer compiled) takes 0.24 s of CPU here (cold; 0.01 s warm): a 4 s deadline
    leaves a machine 16 times slower room for it (10 s before: the test spent 9.8 s of its
    10 asleep, waiting for the deadline); the second answer would take 300 s, and the
    describe returns while the double still holds it back."""
    with replaying(TRAY["answers"], delay=[0, 300]) as (url, requests):
        events = list(describe(TRAY["request"], config(url), tmp_path, deadline_s=4.0))
        assert [r["sent"] for r in requests] == [True, False]  # returned before answer 2
    assert [e["type"] for e in events] == ["round", "error"] and events[0]["n"] == 1
    assert events[1]["message"] == "the model did not finish within 4 s (1 round done); stopped"
    assert len(requests) == 2
