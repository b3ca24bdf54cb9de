"""Every body that is not what a studio endpoint takes is a 400 with a sentence, never a 500
(issue 104: a JSON body nested 100,000 deep was a 500, a RecursionError).

A law over generated bodies: JSON of any shape (objects with the endpoints' own keys and
others, lists, numbers, texts with lone surrogates), bytes that are no JSON, a nest 100,000
deep, sent to `/api/view`, `/api/download/FORMAT`, `/api/glb`, `/api/sweep`, `/api/close` and
`/api/delete` of a real studio (one compile worker, Starlette's test client): the answer is 200
(what it takes), 422 (a program that does not compile, said) or 400 with an `error` that is a
sentence (words, no exception's name, no traceback).
"""
from __future__ import annotations

import json
import re

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

pytest.importorskip("starlette")
from starlette.testclient import TestClient  # noqa: E402

from aidl_lang.studio.app import Settings, create_app  # noqa: E402

PLATE = ("units mm\nparam w = 40 mm, min=20 mm, max=80 mm\nparam holes = true\n"
         "solid p { body = Rectangle(center=(0, 0), width=w, height=20) }\n")
ENDPOINTS = ["/api/view", "/api/download/dxf", "/api/download/svg", "/api/download/nope",
             "/api/glb", "/api/sweep", "/api/checks", "/api/close", "/api/delete"]
KEYS = ["sid", "source", "values", "defaults", "settings", "name", "w", "holes", "kerf",
        "sheet", "layout", "style", "thickness", "machine", "page", "description"]


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    app = create_app(Settings(data=str(tmp_path_factory.mktemp("data")), compilers=1,
                              sweepers=0))
    with TestClient(app, raise_server_exceptions=False) as c:
        c.sid = c.post("/api/session").json()["sid"]
        yield c


texts = st.one_of(st.text(max_size=12), st.sampled_from(["\ud800", "40mm", "95 mm", "true", PLATE,
                                                        "hex", "A4", "laser", "preview"]))
scalars = st.one_of(st.none(), st.booleans(), st.integers(-10**30, 10**30),
                    st.floats(allow_nan=True, allow_infinity=True), texts)
json_values = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=3),
    st.dictionaries(st.one_of(st.sampled_from(KEYS), st.text(max_size=4)), inner, max_size=4)),
    max_leaves=10)


@st.composite
def bodies(draw):
    """(endpoint, raw bytes): mostly objects with the endpoints' keys, the session's id or
    another, a program or no program; sometimes any JSON or bytes that are none."""
    path = draw(st.sampled_from(ENDPOINTS))
    kind = draw(st.sampled_from(["object", "object", "object", "json", "bytes"]))
    if kind == "bytes":
        return path, draw(st.binary(max_size=40))
    if kind == "json":
        return path, json.dumps(draw(json_values)).encode()
    doc = draw(st.dictionaries(st.sampled_from(KEYS), json_values, max_size=5))
    if draw(st.booleans()):
        doc["sid"] = "SID"
    if draw(st.booleans()):
        doc["source"] = PLATE
    return path, json.dumps(doc).replace('"SID"', '"@SID@"').encode()


def sentence(text) -> bool:
    return (isinstance(text, str) and len(text.split()) >= 3 and "Traceback" not in text
            and not re.search(r"\b[A-Z][a-z]+(Error|Exception)\b", text))


def check(client, path: str, body: bytes) -> None:
    body = body.replace(b"@SID@", client.sid.encode())
    r = client.post(path, content=body, headers={"content-type": "application/json"})
    assert r.status_code in (200, 400, 422), (path, body[:200], r.status_code, r.text[:300])
    if r.status_code != 200 or r.headers["content-type"].startswith("application/json"):
        doc = r.json()
        if r.status_code in (400, 422):
            assert sentence(doc.get("error")), (path, body[:200], doc)


DEEP = b"[" * 100_000 + b"]" * 100_000


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(bodies())
@example(("/api/view", DEEP))
@example(("/api/download/dxf", b'{"sid": "@SID@", "source": ' + b"[" * 100_000 + b"]" * 100_000 + b"}"))
@example(("/api/view", b'{"sid": "@SID@", "source": "\\ud800"}'))
@example(("/api/view", b'{"sid": "@SID@", "source": "x", "values": {"\\udc00": 1}}'))
@example(("/api/close", b'{"sid": [1]}'))
@example(("/api/glb", b'{"sid": "@SID@", "source": "x", "settings": {"thickness": "thick"}}'))
@example(("/api/download/svg", b'{"sid": "@SID@", "source": "x", "settings": {"kerf": 1e999}}'))
@example(("/api/view", b'\xff\xfe{"sid"'))
def test_every_body_that_is_not_what_an_endpoint_takes_is_a_400_with_a_sentence(client, case):
    check(client, *case)


def test_a_nest_100000_deep_is_said(client):
    r = client.post("/api/view", content=DEEP, headers={"content-type": "application/json"})
    assert r.status_code == 400 and r.json()["error"] == (
        "the request is nested too deeply: it is not what this address takes")


def test_a_checkbox_s_value_is_taken_as_it_is_sent(client):
    """The sweep sends a checkbox's value as JSON's true/false (the finger box's `outside`
    unticked was refused: "not a short text or number", and its ranges stopped being
    checked)."""
    r = client.post("/api/view", json={"sid": client.sid, "source": PLATE,
                                       "values": {"holes": False}})
    assert r.status_code == 200 and r.json()["ok"], r.text
    assert r.json()["values"] == {"holes": "false"}
