"""`aidl studio`'s server with real compile workers (Starlette's test client, no browser):
the import sandbox per session, uploads and their limits, a planted link, the per-client rate
limit, the busy answer, a compile stopped past its time, downloads re-read by their readers,
and the page's security headers."""
from __future__ import annotations

import io
import json
import os
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip("starlette")
pytest.importorskip("limits")
from starlette.testclient import TestClient  # noqa: E402

from aidl_lang.studio.app import Settings, create_app  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
BRACKET = (ROOT / "examples" / "bracket.aidl").read_text()
BOARD = (ROOT / "examples" / "parts" / "pcb_board.dxf").read_bytes()
USES_BOARD = ('units mm\nsolid s {\n    d = Drawing2D("board.dxf", layer="Edge.Cuts")\n'
              '    Fixed(d.origin)\n}\n')
SLOW = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
        "    for i in range(3000) { hole h { c = Circle(center=(i * 0.001, 0), radius=1) } }\n}\n")

# a program that runs until its wall limit on any machine: 100,000,000 loop iterations (a
# few minutes of evaluation; the budget's 100,000,000 steps at --budget 400), stopped at LIMIT
SPIN = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
        "    for i in range(10000) { for j in range(10000) { k = i * j } }\n}\n")
SPIN_BUDGET = 400
LIMIT = 3.0             # s: the wall limit set for SPIN (kill_after), far below its minutes


@pytest.fixture
def client(tmp_path):
    app = create_app(Settings(data=str(tmp_path / "data"), compilers=1))
    with TestClient(app) as c:
        yield c


def session(c) -> str:
    return c.post("/api/session").json()["sid"]


def view(c, sid, source, values=None):
    r = c.post("/api/view", json={"sid": sid, "source": source, "values": values or {}})
    assert r.status_code == 200, r.text
    return r.json()


def test_a_view_then_a_warm_slider_move_and_a_dxf_read_back(client):
    import ezdxf
    sid = session(client)
    v = view(client, sid, BRACKET)
    assert v["ok"] and "<svg" in v["svg"] and {p["name"] for p in v["params"]} >= {"pitch"}
    pitch = next(p for p in v["params"] if p["name"] == "pitch")
    moved = view(client, sid, BRACKET, {"pitch": f"{pitch['value'] + 4}mm"})
    assert moved["ok"] and moved["svg"] != v["svg"]
    # the same worker's session took the move: the program was not parsed and checked again
    assert moved["version"] == v["version"] + 1
    r = client.post("/api/download/dxf", json={"sid": sid, "source": BRACKET, "values": {},
                                               "settings": {"layout": False, "kerf": 0}})
    assert r.status_code == 200 and r.headers["content-disposition"].endswith('.dxf"')
    doc = ezdxf.read(io.StringIO(r.content.decode()))
    from aidl_lang import api
    res = api.compile(source=BRACKET)
    x0, y0, x1, y1 = res.parts[0].bbox
    from ezdxf import bbox
    box = bbox.extents(e for e in doc.modelspace() if e.dxf.layer.upper() == "CUT")
    assert box.size.x == pytest.approx(x1 - x0, abs=1e-6)
    assert box.size.y == pytest.approx(y1 - y0, abs=1e-6)


RANGED = ("units mm\nparam w = 40 mm, min=20 mm, max=80 mm\n"
          "solid p { body = Rectangle(center=(0, 0), width=w, height=20) }\n")


def test_a_form_value_out_of_range_or_of_the_wrong_kind_is_said_without_the_cli(client):
    """The page's values come from its fields and sliders: a value out of its range is moved
    into it by the view and by the download alike (issue 104: the view drew 80 mm, the
    download refused 95 mm with a 422); a value of the wrong kind is said naming the field
    `w`, never the command line's `--set` (issue 83)."""
    import svgelements
    sid = session(client)
    v = view(client, sid, RANGED, {"w": "95mm"})     # the view moves it in: 80 mm, drawn
    assert v["ok"] and v["clamped"] == {"w": 80.0}
    r = client.post("/api/download/svg", json={"sid": sid, "source": RANGED,
                                               "values": {"w": "95mm"}})
    assert r.status_code == 200, r.text
    import xml.etree.ElementTree as ET
    [d] = [e.get("d") for e in ET.fromstring(r.content).iter("{http://www.w3.org/2000/svg}path")]
    x0, _, x1, _ = svgelements.Path(d).bbox()       # user units: mm
    assert x1 - x0 == pytest.approx(80, abs=1e-9)
    v = view(client, sid, RANGED, {"w": "50 deg"})
    assert not v["ok"] and "--set" not in json.dumps(v)
    [d] = v["diagnostics"]
    assert d["code"] == "E0113" and d["message"].startswith("the field `w` = `50 deg`: ")
    assert d["hint"] == "give it in a length unit, e.g. `40mm` in the field `w`"


def test_the_svg_download_is_a_cutting_file_and_each_format_has_its_own_name(client):
    """Issue 104: the SVG download is `aidl render --svg-style laser` (red cut and blue engrave
    hairlines of 0.01 mm, nothing filled, no sheet outline), the picture only when asked
    (`style: preview`, named `-preview`); a finger box nested on several sheets downloads its
    DXF, SVG and PDF sheets under three names (all three were `finger_box-sheets.zip`)."""
    import zipfile
    import ezdxf
    import svgelements
    from aidl_lang.studio import gallery
    sid = session(client)
    box = gallery.entry("generator/finger_box").source
    nested = {"layout": True, "sheet": [150, 120], "name": "finger_box"}
    names, inside = {}, {}
    for fmt in ("dxf", "svg", "pdf"):
        r = client.post(f"/api/download/{fmt}", json={"sid": sid, "source": box,
                                                      "settings": nested})
        assert r.status_code == 200, r.text
        names[fmt] = r.headers["content-disposition"].split('filename="')[1].rstrip('"')
        inside[fmt] = zipfile.ZipFile(io.BytesIO(r.content))
    # (the sheet's size in the names: not the default 600 x 400, issue 113)
    assert names == {f: f"finger_box-sheets-150x120-{f}.zip" for f in ("dxf", "svg", "pdf")}
    for fmt, z in inside.items():
        assert z.namelist() == [f"finger_box-sheet-{i}-150x120.{fmt}" for i in range(1, 5)]
    # every sheet's SVG: stroke-only hairlines, no fill, no sheet rectangle; its outlines those
    # of the DXF of the same sheet (ezdxf: the same number of closed cut loops)
    for i in range(1, 5):
        text = inside["svg"].read(f"finger_box-sheet-{i}-150x120.svg").decode()
        svg = svgelements.SVG.parse(io.StringIO(text))
        shapes = [e for e in svg.elements() if isinstance(e, svgelements.Shape)]
        assert shapes and not any(isinstance(e, svgelements.Rect) for e in shapes)
        assert all(e.fill is None or e.fill.value is None for e in shapes)
        assert {e.stroke.hex for e in shapes} == {"#ff0000"}
        # the stroke in user units (the viewBox is in mm): a hairline of 0.01 mm
        assert 'id="cut" stroke="#ff0000" stroke-width="0.01"' in text
        doc = ezdxf.read(io.StringIO(inside["dxf"].read(f"finger_box-sheet-{i}-150x120.dxf")
                                     .decode()))
        loops = [e for e in doc.modelspace().query("LWPOLYLINE") if e.closed]
        assert len(loops) == len(shapes) > 0
    # the picture: asked for, filled, named as what it is
    r = client.post("/api/download/svg", json={"sid": sid, "source": box, "settings": {
        "layout": False, "style": "preview", "name": "finger_box"}})
    assert r.status_code == 200 and 'filename="finger_box-preview.svg"' in \
        r.headers["content-disposition"]
    assert 'fill="#cfd8dc"' in r.text


def test_files_of_different_settings_have_different_names(client):
    """Issue 113: the name carries what the settings change in the file (the kerf, the sheet's
    size, the G-code's machine, the PDF's paper); files of the defaults keep their names.
    Each file is read back, so two names are two different files: the kerf's DXF outline
    wider by the kerf (ezdxf), the router's G-code with a spindle (gcodeparser), the tiled
    PDF on A4 pages (pdfplumber)."""
    import ezdxf
    import pdfplumber
    from ezdxf import bbox
    from gcodeparser import parse_gcode_lines
    from aidl_lang.studio import gallery
    sid = session(client)
    box = gallery.entry("generator/finger_box").source

    def get(fmt, **settings):
        r = client.post(f"/api/download/{fmt}", json={"sid": sid, "source": box, "settings": {
            "name": "finger_box", **settings}})
        assert r.status_code == 200, r.text
        return r.headers["content-disposition"].split('filename="')[1].rstrip('"'), r.content

    big = {"layout": True, "sheet": [1000, 1000]}
    plain, kerfed = get("dxf", **big), get("dxf", kerf=0.2, **big)
    assert (plain[0], kerfed[0]) == ("finger_box-sheet-1000x1000.dxf",
                                     "finger_box-sheet-kerf0.2-1000x1000.dxf")

    def width(data):
        doc = ezdxf.read(io.StringIO(data.decode()))
        loops = [e for e in doc.modelspace().query("LWPOLYLINE") if e.closed]
        return max(bbox.extents([e]).size.x for e in loops)
    assert width(kerfed[1]) - width(plain[1]) == pytest.approx(0.2, abs=1e-6)
    assert get("dxf", layout=True)[0] == "finger_box-sheet.dxf"        # 600 x 400: the default
    laser, router = get("gcode", machine="laser"), get("gcode", machine="router")
    assert (laser[0], router[0]) == ("finger_box.gcode", "finger_box-router.gcode")
    def commands(data):
        return {ln.command for ln in parse_gcode_lines(data.decode())}
    assert ("M", 3) in commands(router[1]) and ("M", 3) not in commands(laser[1])
    page, tiles = get("pdf"), get("pdf", page="A4")
    assert (page[0], tiles[0]) == ("finger_box.pdf", "finger_box-a4tiles.pdf")
    with pdfplumber.open(io.BytesIO(tiles[1])) as pdf:
        assert len(pdf.pages) > 1 and {(round(p.width), round(p.height))
                                       for p in pdf.pages} == {(595, 842)}
    with pdfplumber.open(io.BytesIO(page[1])) as pdf:
        assert len(pdf.pages) == 1


EDGE = ("units mm\nparam w = 120 mm, min = 20 mm, max = 220 mm, step = 0.5 mm\n"
        "solid p {\n    body = Rectangle(center=(0, 0), width=w, height=30)\n"
        "    hole h { c = Circle(center=(35.15 mm, 0), radius=5 mm) }\n}\n")


def test_a_moves_shape_checks_come_after_its_picture(client):
    """Issue 104: the page asks a slider move's picture without its shape checks (`"checks":
    "later"`: the answer says `"checks": "pending"`, 0.2 of a planetary move's 0.5 s) and then
    `/api/checks` for the picture's values: the warnings the one request gave (W0507: a wall
    0.35 mm wide at 81 mm), from the worker's session, or compiled again by a worker without
    it (another session id)."""
    sid = session(client)
    assert view(client, sid, EDGE)["ok"]
    r = client.post("/api/view", json={"sid": sid, "source": EDGE, "values": {"w": "81mm"},
                                       "checks": "later"})
    moved = r.json()
    assert moved["ok"] and moved["checks"] == "pending" and moved["svg"]
    assert [d["code"] for d in moved["diagnostics"]] == []
    whole = view(client, session(client), EDGE, {"w": "81mm"})      # one request: all of it
    assert [d["code"] for d in whole["diagnostics"]] == ["W0507"] and "checks" not in whole
    for who in (sid, session(client)):
        got = client.post("/api/checks", json={"sid": who, "source": EDGE,
                                               "values": moved["values"]}).json()
        assert got["ok"] and [d["code"] for d in got["diagnostics"]] == ["W0507"], got
        assert got["diagnostics"][0]["message"] == whole["diagnostics"][0]["message"]


def test_a_program_reads_only_its_own_sessions_uploads(client, tmp_path):
    a, b = session(client), session(client)
    assert not view(client, a, USES_BOARD)["ok"]       # not uploaded yet
    r = client.post(f"/api/upload?sid={a}&name=board.dxf", content=BOARD)
    assert r.status_code == 200 and r.json() == {"name": "board.dxf", "bytes": len(BOARD)}
    assert view(client, a, USES_BOARD)["ok"]            # the same program, compiled again
    other = view(client, b, USES_BOARD)                 # another tab cannot see it
    assert not other["ok"] and other["diagnostics"][0]["code"] == "E0130"
    for src in ['solid s {\n    d = Drawing2D("../' + a + '/board.dxf")\n}\n',
                'solid s {\n    d = Drawing2D("/etc/passwd.dxf")\n}\n',
                'import "../../x.aidl"\nsolid s {}\n']:
        v = view(client, b, src)
        assert not v["ok"] and v["diagnostics"][0]["code"] in ("E0130", "E0114"), v["diagnostics"]
        assert "leaves the project folder" in v["diagnostics"][0]["message"]
    # an .aidl upload is importable
    client.post(f"/api/upload?sid={b}&name=knob.aidl",
                content=b"def knob(r=4 mm) -> solid {\n    c = Circle(center=(0, 0), radius=r)\n}\n")
    assert view(client, b, 'units mm\nimport "knob.aidl"\nk = knob(r=5 mm)\n')["ok"]
    assert [f["name"] for f in client.get(f"/api/files?sid={b}").json()["files"]] == ["knob.aidl"]
    # an upload may come back as a program to edit (aidl import --infer), which compiles
    r = client.post(f"/api/upload?sid={a}&name=board2.dxf&import=infer", content=BOARD)
    doc = r.json()
    assert r.status_code == 200 and doc["name"] == "board2.dxf", doc
    assert doc["program"].startswith("# imported from board2.dxf by `aidl import --infer`")
    assert view(client, a, doc["program"])["ok"]
    r = client.post(f"/api/upload?sid={a}&name=bad.svg&import=infer", content=b"<svg")
    assert "error[E0130]" in r.json()["import_error"]
    # closing the tab removes its folder
    folder = tmp_path / "data" / a
    assert folder.is_dir()
    client.post("/api/close", json={"sid": a})
    assert not folder.exists()


def test_uploads_are_checked_and_never_written_through_a_link(client, tmp_path):
    from aidl_lang.studio import sessions
    sid = session(client)
    for name, body, words in [("../x.dxf", b"0", "letters, digits"),
                              ("main.aidl", b"x", "program's own name"),
                              ("notes.txt", b"x", ".dxf or .svg"),
                              ("big.dxf", b"0" * (sessions.MAX_UPLOAD + 1), "at most")]:
        r = client.post(f"/api/upload?sid={sid}&name={name}", content=body)
        assert r.status_code == 400 and words in r.json()["error"], (name, r.text)
    r = client.post("/api/upload?sid=../../etc&name=a.dxf", content=b"0")
    assert r.status_code == 400 and "reload the page" in r.json()["error"]
    # a link planted where an upload goes is replaced, its target untouched
    target = tmp_path / "precious.dxf"
    target.write_bytes(b"keep me")
    os.symlink(target, tmp_path / "data" / sid / "board.dxf")
    assert client.post(f"/api/upload?sid={sid}&name=board.dxf", content=BOARD).status_code == 200
    assert target.read_bytes() == b"keep me"
    assert not os.path.islink(tmp_path / "data" / sid / "board.dxf")


def test_a_client_past_its_rate_gets_429_with_retry_after_and_browsing_costs_none(tmp_path):
    """The rate counts what compiles; browsing (the gallery, its thumbnails, a hover's docs)
    costs none (issue 104: after four designs' galleries a 20 s drag had 8 of 30 refused)."""
    app = create_app(Settings(data=str(tmp_path / "d"), compilers=1, rate="5/minute"))
    with TestClient(app) as c:
        for _ in range(3):
            assert c.get("/api/docs?name=Circle").status_code == 200
            assert c.get("/api/gallery").status_code == 200
            assert c.get("/api/gallery/example/bracket").status_code == 200
            assert c.get("/api/thumb/nope.svg").status_code == 404
        sid = session(c)
        codes = [c.post("/api/view", json={"sid": sid, "source": RANGED}).status_code
                 for _ in range(6)]
        assert codes[:4] == [200] * 4 and codes[4:] == [429, 429]      # (the session: 1)
        r = c.post("/api/view", json={"sid": sid, "source": RANGED})
        assert int(r.headers["retry-after"]) >= 1 and "too many requests" in r.json()["error"]


@pytest.mark.timing
def test_a_full_studio_answers_busy_and_a_long_compile_is_stopped(tmp_path):
    """The one worker busy with a compile that runs until its wall limit on any machine
    (SPIN); a second request waits 0.3 s for a worker and is told the studio is busy; the
    long one is stopped at its limit, and the next one runs.  Only SPIN runs under the
    short limit (LIMIT): the bracket's compiles, each the first in a fresh process, run
    under the default one (a first compile in a fresh process is the slowest, and slower
    still on a loaded machine), and the second request is sent once the worker is taken,
    not after a sleep."""
    app = create_app(Settings(data=str(tmp_path / "d"), compilers=1, wait=0.3,
                              budget=SPIN_BUDGET))
    studio = app.state.studio
    pool, generous = studio.pool, studio.settings.kill_after
    with TestClient(app) as c:
        sid = session(c)
        view(c, sid, BRACKET)                              # the worker is warm
        studio.settings.kill_after = LIMIT     # a compile's limit: LIMIT
        slow: dict = {}
        t = threading.Thread(target=lambda: slow.update(
            r=c.post("/api/view", json={"sid": sid, "source": SPIN, "values": {}})))
        t.start()
        import time
        while pool.idle:                                   # until SPIN has the worker (it
            assert t.is_alive(), slow                      # ends at LIMIT: no hang)
            time.sleep(0.02)
        r = c.post("/api/view", json={"sid": session(c), "source": BRACKET, "values": {}})
        assert r.status_code == 503 and r.headers["retry-after"] == "5"
        assert r.json()["busy"] and "busy" in r.json()["error"]
        assert not slow                                    # still running
        t.join(300)                                        # a hang guard
        doc = slow["r"].json()
        assert slow["r"].status_code == 200 and not doc["ok"]
        assert doc["error"].startswith(f"the compile took longer than {LIMIT:g} s"), doc
        studio.settings.kill_after = generous
        assert view(c, sid, BRACKET)["ok"]                 # and the next one runs


def test_the_page_and_the_embed_and_their_headers(client):
    r = client.get("/")
    assert r.status_code == 200 and "AIDL Studio" in r.text
    csp = r.headers["content-security-policy"]
    assert "frame-ancestors 'self'" in csp and "script-src 'self' 'sha256-" in csp
    e = client.get("/embed")
    assert "frame-ancestors *" in e.headers["content-security-policy"]
    assert client.get("/static/vendor/three/build/three.module.min.js").status_code == 200
    assert client.get("/static/view3d.js").status_code == 200
    assert client.get("/static/../app.py").status_code == 404
    cfg = client.get("/api/config").json()
    assert {"dxf", "svg", "gcode", "glb"} <= {f["ext"] for f in cfg["formats"]}
    assert cfg["model"] is None or set(cfg["model"]) == {"model"}      # never the key


def test_requests_that_are_not_programs_are_refused_clearly(client):
    sid = session(client)
    for body, words in [({"sid": sid}, "give the program"),
                        ({"sid": sid, "source": "x" * 1_000_001}, "at most"),
                        ({"sid": sid, "source": "", "values": {"a": [1]}},
                         "a number, a text or true/false"),
                        ({"sid": "nope", "source": ""}, "reload the page")]:
        r = client.post("/api/view", json=body)
        assert r.status_code == 400 and words in r.json()["error"], (body.keys(), r.text)
    r = client.post("/api/view", content=b"{not json", headers={"content-type": "application/json"})
    assert r.status_code == 400 and "not JSON" in r.json()["error"]
    r = client.post("/api/download/doc", json={"sid": sid, "source": BRACKET})
    assert r.status_code == 400 and r.json()["error"].startswith(
        "`doc` is not a format this studio makes; it makes 3mf, dxf")
    for settings, said in [({"kerf": 50}, "kerf expects a number between 0 and 10 mm, got 50"),
                           ({"style": "fancy"}, "style expects laser (the cutting file) or "
                                                "preview (the picture), got `fancy`"),
                           ({"layout": True, "sheet": [1e400]}, "sheet expects [width, height]"),
                           ({"layout": True, "sheet": [1e400, 5]}, "sheet expects a number between"),
                           ({"kerf": 10 ** 400}, "kerf expects a number in mm"),
                           ({"name": ["x"]}, "name expects a text"),
                           ([1, 2], "`settings` is an object")]:
        body = json.dumps({"sid": sid, "source": BRACKET, "settings": settings})   # (Infinity)
        r = client.post("/api/download/dxf", content=body,
                        headers={"content-type": "application/json"})
        assert r.status_code == 400 and r.json()["error"].startswith(said), r.text


def test_two_server_processes_behind_one_port_share_the_uploads(tmp_path):
    """`aidl studio --processes 2`: uvicorn workers behind one port; a request carries its
    program, so either process answers; an upload made through one is read by the other."""
    import json
    import urllib.request
    from benchmarks.serve.studio_server import studio

    def call(url, path, body=None, raw=None):
        data = raw if raw is not None else (json.dumps(body).encode() if body is not None else None)
        req = urllib.request.Request(url + path, data=data, method="POST" if data is not None else "GET",
                                     headers={"Content-Type": "application/json"})
        with urllib.request.urlopen(req, timeout=60) as r:
            return json.loads(r.read())

    with studio("--processes", "2", "--compilers", "1") as (url, _proc):
        sid = call(url, "api/session", {})["sid"]
        call(url, f"api/upload?sid={sid}&name=board.dxf", raw=BOARD)
        oks = [call(url, "api/view", {"sid": sid, "source": USES_BOARD, "values": {}})["ok"]
               for _ in range(6)]
        assert all(oks)
        doc = call(url, "api/docs?name=divider_tray")
        assert "compartments" in doc["text"]


def test_the_operators_budget_bounds_every_compile(tmp_path):
    """`aidl studio --budget K`: each compile gets K times the default evaluation budget; at
    0.1 a loop of 3,000 holes is refused with the budget's located error (the default takes
    it, and runs past its time in the shape checks)."""
    app = create_app(Settings(data=str(tmp_path / "d"), compilers=1, budget=0.1))
    with TestClient(app) as c:
        v = view(c, session(c), SLOW)
        assert not v["ok"], v
        d = v["diagnostics"][0]
        assert d["code"] == "E0301" and "limit of 1000" in d["message"], d
        assert d["span"]["line"] == 4
        r = c.post("/api/download/dxf", json={"sid": session(c), "source": SLOW})
        assert r.status_code == 422 and r.json()["diagnostics"][0]["code"] == "E0301"


def test_a_worker_marked_retiring_answers_its_next_request_from_a_fresh_process():
    """A compile worker whose memory grew past compiler.RETIRE_RSS says so with its answer;
    the server marks it, and its next request starts a new process (the memory goes back)."""
    from aidl_lang.host import workers as W
    from aidl_lang.studio import compiler
    w = W.Worker(compiler.handler, (1.0,))
    try:
        assert w.request(("thumb", "no/such"), 60) == ""
        first = w.proc.pid
        assert w.request(("thumb", "no/such"), 60) == "" and w.proc.pid == first   # warm
        w.retiring = True
        assert w.request(("thumb", "no/such"), 60) == ""
        assert w.proc.pid != first and not w.retiring and w.restarts == 0
    finally:
        w.stop()


def test_a_worker_stopped_while_its_process_starts_ends_that_process_at_once():
    """A studio stopped while a sweep worker restarts (after a stopped sweep): stop() ends the
    starting process, and the request waiting for it fails at once (before, it waited up to
    READY_SECONDS; the studio was killed and its new worker orphaned).  A start that takes
    ten minutes (time.sleep as the handler's maker); about 0.5 s of CPU."""
    import time
    from aidl_lang.host import workers as W
    w = W.Worker(time.sleep, (600,))
    got: dict = {}

    def ask():
        try:
            w.request("x", 60)
        except W.NotReady as e:
            got["refused"] = e
    t = threading.Thread(target=ask)
    t.start()
    for _ in range(1200):                   # until its process is starting (a hang guard)
        if w.starting is not None:
            break
        time.sleep(0.05)
    proc = w.starting
    assert proc is not None
    w.stop()
    t.join(60)
    assert not t.is_alive() and isinstance(got.get("refused"), W.NotReady)
    proc.join(10)
    assert not proc.is_alive() and w.proc is None


def test_a_worker_is_replaced_after_its_recycle_count_and_no_answer_is_lost(tmp_path):
    """Worker memory stays flat (issue 94: 195 -> 530 MB over 2,000 compiles): a compile
    worker's process answers ``recycle`` requests (``AIDL_STUDIO_RECYCLE``, 200), then the
    studio replaces it in the background (:meth:`Worker.renew`) after the answer that reached
    the count. By counts, at recycle 2: 5 previews, every one answered and drawn, by 3
    processes (2 + 2 + 1); the one renewed before a request answers it at once."""
    from aidl_lang.host import workers as W
    from aidl_lang.studio import compiler
    assert Settings.from_env({"AIDL_STUDIO_RECYCLE": "7"}).recycle == 7
    assert Settings().recycle == 200
    w = W.Worker(compiler.handler, (1.0,), recycle=2)
    src = "units mm\nparam w = 40 mm\nsolid p { body = Rectangle(center=(0, 0), width=w, height=20) }\n"
    pids, answers = [], []
    try:
        for k in range(5):
            answers.append(w.request(("view", "s", str(tmp_path), src, {"w": f"{40 + k}mm"}), 120))
            pids.append(w.proc.pid)
            if w.retiring:                  # as Studio.compile does, after the answer
                assert w.answered == 2 and w.renew() and not w.retiring
        assert [a["ok"] for a in answers] == [True] * 5
        assert [a["values"] for a in answers] == [{"w": f"{40 + k}mm"} for k in range(5)]
        assert pids[0] == pids[1] != pids[2] == pids[3] != pids[4] and len(set(pids)) == 3
        assert w.restarts == 0 and w.answered == 1
    finally:
        w.stop()


def test_the_recycle_option_reaches_every_worker_of_the_server_process(tmp_path, monkeypatch,
                                                                       capsys):
    """`aidl studio --recycle N` (AIDL_STUDIO_RECYCLE without the environment): the command
    line, through studio()'s environment, to the app a server process builds (uvicorn's run
    stands in: it builds the app as a worker does and serves it through the test client).
    At --recycle 1, 2 previews are answered by 2 processes (a process started per answer);
    every compile and sweep worker carries the count; a negative count is a usage error."""
    import signal
    import uvicorn
    from aidl_lang.cli.main import main
    from aidl_lang.host import workers as W
    for var, value in Settings(data=str(tmp_path / "d")).to_env().items():
        monkeypatch.setenv(var, value)      # undone after the test (studio() sets them all)
    monkeypatch.setattr(signal, "signal", lambda *a: None)
    starts, seen = [], {}
    start = W.Worker._start
    monkeypatch.setattr(W.Worker, "_start", lambda w: (starts.append(1), start(w))[1])

    def run(server, sockets=None):
        for s in sockets or ():
            s.close()
        app = create_app()                  # from the environment, as a server process
        st = app.state.studio
        seen["recycle"] = [w.recycle for w in st.pool.workers + st.sweepers.workers]
        with TestClient(app) as c:
            sid = session(c)
            seen["ok"] = [view(c, sid, BRACKET, {})["ok"] for _ in range(2)]
            for w in st.pool.workers:       # the renewal after the last answer, done before
                while w.retiring:           # the app stops (renew() clears it, holding the
                    time.sleep(0.05)        # lock while the new process starts)
                with w.lock:
                    pass
    monkeypatch.setattr(uvicorn.Server, "run", run)
    assert main(["studio", "--port", "0", "--compilers", "2", "--recycle", "1"]) == 0
    assert seen == {"recycle": [1, 1, 1], "ok": [True, True]} and len(starts) >= 2
    assert main(["studio", "--port", "0", "--recycle", "-1"]) == 2
    assert "--recycle takes 0 (never) to 1000000 answers, got -1" in capsys.readouterr().err


def test_sigterm_stops_a_studio_of_several_processes_and_its_workers():
    """`aidl studio --processes 2` ends on SIGTERM within seconds and its uvicorn workers with
    it (the supervisor's own SIGTERM handler; replaced by a plain exit, the studio waited on
    its workers for ever and, once killed, left them running)."""
    import signal
    import subprocess
    import time
    from benchmarks.serve.studio_server import studio

    def children(pid):
        out = set()
        for f in Path(f"/proc/{pid}/task").glob("*/children"):
            out.update(int(p) for p in f.read_text().split())
        return out

    if not Path("/proc/self/task").is_dir():
        pytest.skip("reads /proc (Linux)")
    with studio("--processes", "2", "--compilers", "1") as (_url, proc):
        deadline = time.monotonic() + 30                 # the two servers start after the URL
        while len(workers := {p for p in children(proc.pid) if b"spawn_main" in
                              Path(f"/proc/{p}/cmdline").read_bytes()}) < 2 \
                and time.monotonic() < deadline:
            time.sleep(0.1)
        assert len(workers) == 2, workers
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            pytest.fail("aidl studio --processes 2 did not end within 20 s of SIGTERM")
        deadline = time.monotonic() + 10
        while any(Path(f"/proc/{p}").exists() and "Z" not in
                  Path(f"/proc/{p}/stat").read_text().rsplit(")", 1)[-1][:3]
                  for p in workers) and time.monotonic() < deadline:
            time.sleep(0.1)
        left = [p for p in workers if Path(f"/proc/{p}").exists()
                and "Z" not in Path(f"/proc/{p}/stat").read_text().rsplit(")", 1)[-1][:3]]
        assert not left, f"workers still running after the studio ended: {left}"


def test_an_app_without_a_data_folder_removes_the_one_it_made():
    """`create_app` without `data` makes a sessions' folder and removes it when the app ends
    (they were left in /tmp, one per app); a folder it was given is kept."""
    made = Settings(compilers=1)
    with TestClient(create_app(made)) as c:
        assert c.post("/api/session").status_code == 200
        folder = Path(made.data)
        assert folder.is_dir() and folder.name.startswith("aidl-studio-")
    assert not folder.exists()


def test_an_app_keeps_the_data_folder_it_was_given(tmp_path):
    given = tmp_path / "data"
    with TestClient(create_app(Settings(data=str(given), compilers=1))) as c:
        assert c.post("/api/session").status_code == 200
    assert given.is_dir() and any(given.iterdir())


def test_what_a_visitor_reads_has_no_internals(client):
    """Issue 113: the page showed a template's assertion source for `fit = "tight"` (with a
    blank list and a broken picture), "internal error ... RecursionError ... the next save is
    compiled again" for a 40,000-term expression, "not a short text, number or true/false"
    with backticks and no limit for a 10,000-character field, and "division by zero" for a
    name tag with an empty name.  Each is now a sentence a visitor acts on: the value moved
    to one of its choices (and said), the program's E0302 (as `aidl check` says it), the
    limit, the example's own reason."""
    from aidl_lang.studio import gallery
    sid = session(client)
    plate = gallery.entry("generator/mounting_plate").source
    r = client.post("/api/view", json={"sid": sid, "source": plate, "values": {"fit": '"tight"'},
                                       "defaults": {"fit": "medium"}})
    v = r.json()
    assert v["ok"] and v["svg"] and v["clamped"] == {"fit": "medium"}
    assert v["moved"] == {"fit": "fit is fine, medium or coarse: “tight” is none of them, so "
                                 "medium is used"}
    tight = view(client, sid, plate.replace('param fit = "medium"', 'param fit = "tight"'))
    [d] = [d for d in tight["diagnostics"] if d["severity"] == "error"]
    assert (d["code"], d["message"]) == ("E0405", 'fit is "fine", "medium" or "coarse"')
    deep = view(client, sid, "units mm\nsolid p { body = Rectangle(center=(0, 0), width="
                + "+".join(["1"] * 40000) + ", height=5) }\n")
    [d] = deep["diagnostics"]
    assert (d["code"], d["message"]) == ("E0302", "the program is nested too deeply to compile")
    assert d["span"]["line"] == 2
    tag = gallery.entry("example/name_tag").source
    r = client.post("/api/view", json={"sid": sid, "source": tag,
                                       "values": {"name": '"' + "A" * 10_000 + '"'}})
    assert r.status_code == 400
    assert r.json()["error"] == "“name” takes at most 256 characters (this one has 10,002): " \
                                "shorten it"
    empty = view(client, sid, tag, {"name": '""'})
    assert [(d["code"], d["message"]) for d in empty["diagnostics"]
            if d["severity"] == "error"] == [("E0405", "the name cannot be empty")]
    for answer in (v, tight, deep, empty, r.json()):
        said = json.dumps([answer.get("error"), answer.get("moved")] + [
            (d["message"], d["hint"]) for d in answer.get("diagnostics", [])], ensure_ascii=False)
        for inside in ("`", "Error", "Traceback", "(1 if", "division", " save"):
            assert inside not in said, (inside, said)
