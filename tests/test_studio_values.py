"""The studio's previews are made for the values they were asked with, of the program they
were asked for (issue 72), checked through HTTP on a real server with two real compile
workers (Starlette's test client, no browser):

* a program's defaults are its own, whichever worker answers and whatever values the
  session's requests carried before (the first compile a worker made for a session that
  carried values reported those values as the defaults; the other worker answered the true
  ones, and the page looped);
* a value belongs to one program: one whose param the program lacks, or whose default
  changed from the one the page chose it against, is dropped and named;
* an answer for a program that does not check holds no params and no picture of another one;
* one preview of a session compiles at a time and of those waiting only the newest: eight
  moves sent while a compile runs cost that compile and one more, not eight.

The browser side (the page drops stale answers, never shows a picture for other values) is
tests/test_studio_values_browser.py.
"""
from __future__ import annotations

import re
import threading
import time

import pytest

pytest.importorskip("starlette")
pytest.importorskip("limits")
from starlette.testclient import TestClient  # noqa: E402

from aidl_lang import api  # noqa: E402
from aidl_lang.serve.params import declared_params  # noqa: E402
from aidl_lang.studio import gallery  # noqa: E402
from aidl_lang.studio.app import Settings, create_app  # noqa: E402

LID = gallery.to_json(gallery.entry("generator/sliding_lid_box"), with_source=True)["source"]
TRAY = gallery.to_json(gallery.entry("generator/divider_tray"), with_source=True)["source"]
HANG = 120.0            # s: a guard against a hung request, not a speed limit


def own(source: str) -> dict:
    """The program's own param values, read by the interpreter alone (no session)."""
    return {p.name: p.value for p in declared_params(source, "x/main.aidl")}


def size(svg: str) -> tuple[float, float]:
    w = re.search(r'\bwidth="([-\d.e]+)mm"', svg)
    h = re.search(r'\bheight="([-\d.e]+)mm"', svg)
    return float(w.group(1)), float(h.group(1))


def cli_size(source: str, values: dict) -> tuple[float, float]:
    """The size of the flat picture ``aidl render --set`` draws (kerf 0, as the preview)."""
    res = api.compile(source=source, path="x/main.aidl", overrides=values)
    assert res.ok, res.diagnostics_json()
    return size(res.encode(".svg", 0).decode())


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    app = create_app(Settings(data=str(tmp_path_factory.mktemp("data")), compilers=2))
    with TestClient(app) as c:
        yield c, app.state.studio


def session(c) -> str:
    return c.post("/api/session").json()["sid"]


def view(c, sid, source, values=None, defaults=None):
    body = {"sid": sid, "source": source, "values": values or {}}
    if defaults is not None:
        body["defaults"] = defaults
    r = c.post("/api/view", json=body)
    assert r.status_code == 200, r.text
    return r.json()


def test_the_defaults_are_the_programs_whichever_worker_answers(server):
    c, st = server
    sid = session(c)
    defaults = own(LID)
    assert defaults["length"] == 80 and defaults["outside"] is True
    asked = [{"length": "150mm", "outside": "false"}, {}, {"length": "150mm"}, {},
             {"width": "300mm"}, {"width": "300mm", "length": "150mm"}]
    for i, values in enumerate(asked):
        # the two workers take turns: each answer comes from the other worker than the last
        st.affinity[sid] = st.pool.workers[i % 2]
        v = view(c, sid, LID, values)
        assert v["ok"], v["diagnostics"]
        got = {p["name"]: p for p in v["params"]}
        assert {k: p["default"] for k, p in got.items()} == defaults, (i, values)
        assert v["values"] == values and v["dropped"] == []
        want = dict(defaults, **{k: float(t[:-2]) if t.endswith("mm") else t == "true"
                                 for k, t in values.items()})
        assert {k: p["value"] for k, p in got.items()} == want
        assert size(v["svg"]) == pytest.approx(cli_size(LID, values), abs=1e-9)
    assert all(w.requests >= 3 for w in st.pool.workers)      # both workers answered


def test_a_value_belongs_to_its_program(server):
    c, st = server
    sid = session(c)
    v = view(c, sid, TRAY, {"length": "200mm", "outside": "false"})
    assert v["ok"] and v["values"] == {"length": "200mm", "outside": "false"}
    tray = own(TRAY)
    # the same values sent with the lid box, as chosen against the tray's defaults: the lid
    # box's length default (80) is not the tray's (160): dropped; `outside` has the same
    # default in both (true): an edit that kept it keeps the value
    v = view(c, sid, LID, {"length": "200mm", "outside": "false"},
             {"length": tray["length"], "outside": tray["outside"]})
    assert v["ok"] and v["dropped"] == ["length"] and v["values"] == {"outside": "false"}
    got = {p["name"]: p for p in v["params"]}
    assert got["length"]["value"] == got["length"]["default"] == 80
    assert got["outside"]["value"] is False and got["outside"]["default"] is True
    assert size(v["svg"]) == pytest.approx(cli_size(LID, {"outside": "false"}), abs=1e-9)
    # an edit of the program that changes length's default: the value chosen against 80 goes
    edited = LID.replace("param length = 80 mm", "param length = 90 mm")
    assert edited != LID
    v = view(c, sid, LID, {"length": "150mm"}, {"length": 80})
    assert v["values"] == {"length": "150mm"} and v["dropped"] == []
    v = view(c, sid, edited, {"length": "150mm"}, {"length": 80})
    assert v["dropped"] == ["length"] and v["values"] == {}
    assert {p["name"]: p["value"] for p in v["params"]}["length"] == 90
    # a value for a param the program does not have is dropped, not an error
    v = view(c, sid, LID, {"compartments": "4"})
    assert v["ok"] and v["dropped"] == ["compartments"] and v["values"] == {}


def test_a_program_that_does_not_check_shows_nothing_of_another(server):
    c, st = server
    sid = session(c)
    st.affinity[sid] = st.pool.workers[0]
    assert view(c, sid, TRAY, {"rows": "2"})["ok"]
    st.affinity[sid] = st.pool.workers[0]
    v = view(c, sid, LID.replace("param finger", "param finger finger"), {})
    assert not v["ok"] and any(d["severity"] == "error" for d in v["diagnostics"])
    # the worker's last good picture and params were the tray's: not this program's
    assert v["svg"] is None and v["params"] is None and v["values"] == {}


def test_moves_sent_while_a_compile_runs_cost_one_more_compile(server):
    """Eight previews of one session: the first compiles (held at its start until the
    others have arrived), the six between wait and are answered ``superseded`` without a
    compile, the last is compiled with its own values: 2 compiles, not 8."""
    c, st = server
    sid = session(c)
    assert view(c, sid, LID)["ok"]
    gate = threading.Event()
    real = st.compile
    held = []

    async def compile_held(request, sid_=None):
        from starlette.concurrency import run_in_threadpool
        if not held:
            held.append(request)
            await run_in_threadpool(gate.wait, HANG)
        return await real(request, sid_)
    st.compile = compile_held
    before = dict(st.served)
    answers: dict[int, dict] = {}

    def send(i):
        answers[i] = view(c, sid, LID, {"length": f"{100 + i}mm"})

    threads = []
    try:
        for i in range(8):
            t = threading.Thread(target=send, args=(i,))
            t.start()
            threads.append(t)
            # each request reaches the server in turn: waited for on its outcome, no clock
            # (its thread ends only with an answer, which the held first compile withholds
            # until the gate opens; an answer before it is registered is the failure)
            while not (sid in st.latest and st.latest[sid].ticket == i + 1):
                assert t.is_alive(), f"request {i} was answered before it reached the server"
                time.sleep(0.005)
        gate.set()
        for t in threads:
            t.join(HANG)
    finally:
        gate.set()
        st.compile = real
    assert answers[0]["ok"] and answers[0]["values"] == {"length": "100mm"}
    assert all(answers[i]["superseded"] and answers[i]["svg"] is None for i in range(1, 7))
    assert answers[7]["ok"] and answers[7]["values"] == {"length": "107mm"}
    assert {p["name"]: p["value"] for p in answers[7]["params"]}["length"] == 107
    assert st.served["compiles"] - before["compiles"] == 2
    assert st.served["superseded"] - before["superseded"] == 6
    assert sid not in st.latest                 # nothing kept once the session is quiet
    metrics = c.get("/metrics").text
    assert re.search(r"^aidl_studio_superseded_total (\d+)", metrics, re.M)


def test_a_session_given_values_before_its_first_load_keeps_the_programs_defaults():
    """:class:`~aidl_lang.serve.session.Session` (``aidl serve`` and the studio's workers):
    values set before the first load are drawn, and reported as values, not defaults."""
    from aidl_lang.serve.session import Session
    s = Session("x/main.aidl")
    s.values = {"length": "150mm", "outside": "false"}
    v = s.load(LID)
    assert v["ok"] and s.values == {"length": "150mm", "outside": "false"}
    got = {p["name"]: p for p in v["params"]}
    assert {k: p["default"] for k, p in got.items()} == own(LID)
    assert got["length"]["value"] == 150 and got["outside"]["value"] is False
    # a slider move after it keeps them
    v = s.set_params({"length": "160mm"})
    assert {p["name"]: p["default"] for p in v["params"]} == own(LID)
