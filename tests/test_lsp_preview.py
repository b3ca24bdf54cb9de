"""`aidl/preview`: the editor preview's request, through a real client over stdio and as the
pure function; the SVG is re-read with svgelements."""
import io
import sys

import pytest
import pytest_lsp
import svgelements
from lsprotocol import types as T
from pytest_lsp import ClientServerConfig, LanguageClient

from aidl_lang.editor.lsp import preview as pv

from conftest import ROOT

TELEPHONE = ROOT / "examples" / "telephone.aidl"

PLATE = """\
param w = 40 mm
param r = 3 mm, min=1 mm, max=8 mm

solid plate {
    body = Rectangle(center=(0, 0), width=w, height=20)
    hole bore {
        c = Circle(center=(0, 0), radius=r)
    }
}
"""


def _shapes(svg: str) -> dict:
    """id -> (class, data-range, bbox) of the overlay elements, read back with svgelements."""
    doc = svgelements.SVG.parse(io.StringIO(svg), reify=True, ppi=25.4)  # 1 unit = 1 mm
    out = {}
    for e in doc.elements():
        if isinstance(e, svgelements.Path) and str(e.id or "").startswith("aidl-"):
            out[e.id] = (e.values.get("class"), e.values.get("data-range"), e.bbox())
    return out


def test_preview_svg_maps_shapes_to_source_and_sliders(tmp_path):
    path = str(tmp_path / "plate.aidl")
    cache = pv.Cache()
    r = pv.preview(PLATE, path, "file:///plate.aidl", 1, cache=cache)
    assert r["ok"] and not r["stale"]
    shapes = _shapes(r["svg"])
    by_range = {rng: (cls, bb) for cls, rng, bb in shapes.values()}
    # the circle's call (line 7, 0-based 6) and the rectangle's (line 5)
    line6 = PLATE.split("\n")[6]
    circle = f"6,{line6.index('Circle')},6,{line6.rindex(')') + 1}"
    assert circle in by_range, sorted(by_range)
    cls, (x0, y0, x1, y1) = by_range[circle]
    assert cls == "aidl-shape"
    assert (x1 - x0) == pytest.approx(6.0, abs=0.01) and (y1 - y0) == pytest.approx(6.0, abs=0.01)
    line4 = PLATE.split("\n")[4]
    rect = f"4,{line4.index('Rectangle')},4,{line4.rindex(')') + 1}"
    _, (u0, v0, u1, v1) = by_range[rect]
    assert (u1 - u0, v1 - v0) == pytest.approx((40, 20), abs=1e-3)
    # (page coordinates: the viewBox moves the origin) the bore sits at the body's centre
    assert ((x0 + x1) / 2, (y0 + y1) / 2) == pytest.approx(((u0 + u1) / 2, (v0 + v1) / 2), abs=0.01)
    # sliders: the declared range of r, a default span around w
    ps = {p["name"]: p for p in r["params"]}
    assert (ps["r"]["min"], ps["r"]["max"], ps["r"]["declared"]) == (1, 8, True)
    assert ps["w"]["value"] == 40 and ps["w"]["min"] < 40 < ps["w"]["max"]
    assert ps["w"]["range"] == [0, 0, 0, 15]

    # a slider value: the picture follows, the value is reported
    r2 = pv.preview(PLATE, path, "file:///plate.aidl", 1, {"r": "5 mm"}, cache=cache)
    _, (x0, y0, x1, y1) = {rng: (c, b) for c, rng, b in _shapes(r2["svg"]).values()}[circle]
    assert (x1 - x0) == pytest.approx(10.0, abs=0.01)
    assert {p["name"]: p["value"] for p in r2["params"]}["r"] == 5

    # broken: the last good picture stays, flagged stale, with the first error located
    bad = PLATE.replace("Circle(", "Circel(")
    r3 = pv.preview(bad, path, "file:///plate.aidl", 2, cache=cache)
    assert not r3["ok"] and r3["stale"] and r3["svg"] == r2["svg"]
    assert r3["drawn_version"] == 1
    first = r3["diagnostics"]["first"]
    assert first["code"] == "E0103" and first["range"][:2] == [6, line6.index("Circ")]
    assert r3["diagnostics"]["errors"] == 1
    assert [p["name"] for p in r3["params"]] == ["w", "r"]        # the last good params

    # nothing good yet: no picture, no exception
    r4 = pv.preview(bad, path, "file:///other.aidl", 1, cache=cache)
    assert r4["svg"] is None and r4["shapes"] == [] and not r4["ok"]


# one server for the module's two requests (each opens its own document): one start-up saved
@pytest_lsp.fixture(scope="module", config=ClientServerConfig(
    server_command=[sys.executable, "-m", "aidl_lang.cli", "lsp"]))
async def client(lsp_client: LanguageClient):
    # VS Code refreshes inlay hints and code lenses when the server asks (after each analysis)
    lsp_client.feature(T.WORKSPACE_INLAY_HINT_REFRESH)(lambda params: None)
    lsp_client.feature(T.WORKSPACE_CODE_LENS_REFRESH)(lambda params: None)
    await lsp_client.initialize_session(T.InitializeParams(
        capabilities=pytest_lsp.client_capabilities("visual-studio-code")))
    yield
    await lsp_client.shutdown_session()


@pytest.mark.asyncio(loop_scope="module")
async def test_preview_request_over_stdio(client: LanguageClient):
    uri = TELEPHONE.as_uri()
    text = TELEPHONE.read_text()
    client.text_document_did_open(T.DidOpenTextDocumentParams(
        text_document=T.TextDocumentItem(uri=uri, language_id="aidl-cad", version=1, text=text)))
    r = await client.protocol.send_request_async("aidl/preview", {"uri": uri})
    r = pv.plain(r)
    assert r["ok"] and r["version"] == 1 and r["svg"].startswith("<svg")
    assert [p["name"] for p in r["params"]] == ["base_w", "base_h", "dial_r", "handset_len"]
    assert any(s["name"].endswith("dial") or s["kind"] == "Circle" for s in r["shapes"])
    b1 = svgelements.SVG.parse(io.StringIO(r["svg"]), ppi=25.4).bbox()
    wide = await client.protocol.send_request_async(
        "aidl/preview", {"uri": uri, "values": {"base_w": "240 mm"}})
    b2 = svgelements.SVG.parse(io.StringIO(pv.plain(wide)["svg"]), ppi=25.4).bbox()
    assert (b2[2] - b2[0]) > (b1[2] - b1[0]) + 40
    with pytest.raises(Exception, match="invalid params"):
        await client.protocol.send_request_async("aidl/preview", {"values": 3})


def test_the_cache_keeps_the_last_documents_only(tmp_path):
    cache = pv.Cache()
    cache.KEEP = 2
    for name in ("a", "b", "c"):
        pv.preview(PLATE, str(tmp_path / f"{name}.aidl"), f"file:///{name}.aidl", 1, cache=cache)
    assert list(cache.good) == ["file:///b.aidl", "file:///c.aidl"]
    assert list(cache.params) == ["file:///b.aidl", "file:///c.aidl"]
    # b previewed again (broken): its last good picture is still there, and b is now the newest
    r = pv.preview(PLATE.replace("Circle(", "Circel("), str(tmp_path / "b.aidl"), "file:///b.aidl", 2,
                   cache=cache)
    assert r["stale"] and r["svg"] == cache.good["file:///b.aidl"]["svg"]
    assert list(cache.good) == ["file:///c.aidl", "file:///b.aidl"]


@pytest.mark.asyncio(loop_scope="module")
async def test_preview_request_assembled_carries_the_glb(client: LanguageClient):
    """`"assembled": true`: the result's `glb` is the phone stand placed in 3D (trimesh reads
    two named nodes; the foot turned a quarter about z); without it there is none."""
    import base64

    import trimesh
    path = ROOT / "examples" / "phone_stand.aidl"
    uri = path.as_uri()
    client.text_document_did_open(T.DidOpenTextDocumentParams(
        text_document=T.TextDocumentItem(uri=uri, language_id="aidl-cad", version=1,
                                         # the range stops at the sheet (3 mm): opened
                                         # to 1 mm to show the collision
                                         text=path.read_text().replace(
                                             "min = 3 mm, max = 6 mm", "min = 1 mm, max = 6 mm"))))
    r = pv.plain(await client.protocol.send_request_async("aidl/preview", {"uri": uri}))
    assert r["ok"] and "glb" not in r
    r = pv.plain(await client.protocol.send_request_async(
        "aidl/preview", {"uri": uri, "assembled": True, "values": {"slot": "2.5 mm"}}))
    assert r["ok"] and r["diagnostics"]["first"]["code"] == "W0517"
    sc = trimesh.load(io.BytesIO(base64.b64decode(r["glb"])), file_type="glb")
    assert sorted(sc.graph.nodes_geometry) == ["stand.foot", "stand.support"]
    T_, g = sc.graph["stand.foot"]
    v = trimesh.transform_points(sc.geometry[g].vertices, T_)
    assert abs(v[:, 0].min() + 1.5) < 1e-5 and abs(v[:, 1].max() - 35) < 1e-5


def test_the_preview_compiles_in_the_memory_limited_worker_not_the_server():
    """Issue 37: `aidl/preview` compiled in the server's own process, with no memory limit
    (four documents of large strings: 3.9 GB, kept after they closed).  It now runs in the
    diagnostics' worker process, whose address space is limited and which exits (giving
    its memory back) when it holds more than RETIRE_RSS after a job."""
    import asyncio
    import os

    from aidl_lang.editor.lsp import job
    from aidl_lang.editor.lsp.worker import Analyzer
    src = "units mm\nsolid plate { body = Rectangle(center=(0, 0), width=40, height=20) }\n"
    pv.CACHE.good.clear()

    async def run():
        a = Analyzer()
        try:
            calls = []
            out = await a.preview(src, "p.aidl", "file:///p.aidl", 1, {},
                                  lambda: calls.append(1) or {})
            limits = open(f"/proc/{a.proc.pid}/limits").read()
            return out, calls, a.proc.pid, limits
        finally:
            a.close()
    out, calls, pid, limits = asyncio.run(run())
    assert out["ok"] and "<svg" in out["svg"] and out["shapes"]
    assert pid != os.getpid() and calls == []          # not drawn here, and not kept here
    assert "file:///p.aidl" not in pv.CACHE.good
    line = next(ln for ln in limits.splitlines() if ln.startswith("Max address space"))
    assert str(job.MEMORY_LIMIT) in line.split()


def test_a_worker_holding_too_much_memory_answers_then_exits():
    """The memory goes back: past RETIRE_RSS after a job the worker says `retire` and exits
    (the Analyzer starts a fresh one for the next job); here with the bar at 1 byte."""
    import json
    import subprocess
    src = "units mm\nsolid plate { body = Rectangle(center=(0, 0), width=40, height=20) }\n"
    jobs = "".join(json.dumps({"id": i, "kind": "preview", "text": src, "path": "p.aidl",
                               "uri": "file:///p.aidl", "version": i, "values": {}}) + "\n"
                   for i in (1, 2))
    code = ("import sys; import aidl_lang.editor.lsp.job as j; j.RETIRE_RSS = 1; "
            "sys.exit(j._serve())")
    r = subprocess.run([sys.executable, "-c", code], input=jobs, capture_output=True,
                       text=True, timeout=120, cwd=ROOT)
    answers = [json.loads(ln) for ln in r.stdout.splitlines()]
    assert r.returncode == 0 and len(answers) == 1            # the second job is not read
    assert answers[0]["retire"] is True and answers[0]["preview"]["ok"]


def test_a_replaced_worker_keeps_the_last_good_picture():
    """The last good picture lived only in the worker: a worker killed for a newer edit (or
    retired for its memory) took it along, and the next broken version came back with no
    picture and ``stale: false`` (the VS Code extension's test failed so under CI load).
    The server now keeps its own copy."""
    import asyncio
    from types import SimpleNamespace

    from aidl_lang.editor.lsp.worker import Analyzer
    good = "units mm\nsolid plate { body = Rectangle(center=(0, 0), width=40, height=20) }\n"
    broken = good.replace("Rectangle(", "Rectangel(")
    uri = "file:///replaced.aidl"
    docs = {}
    ls = SimpleNamespace(workspace=SimpleNamespace(get_text_document=lambda u: docs[u]))

    async def run():
        a = Analyzer()
        try:
            docs[uri] = SimpleNamespace(source=good, path="replaced.aidl", version=1)
            first = await pv.handle(ls, {"uri": uri}, a)
            a.kill()                                     # a newer edit stopped this worker
            docs[uri] = SimpleNamespace(source=broken, path="replaced.aidl", version=2)
            second = await pv.handle(ls, {"uri": uri}, a)
            return first, second
        finally:
            a.close()
            pv.SERVER_GOOD.forget(uri)
    first, second = asyncio.run(run())
    assert first["ok"] and not first["stale"] and "<svg" in first["svg"]
    assert second["ok"] is False and second["diagnostics"]["first"]["code"] == "E0103"
    assert second["stale"] is True and second["svg"] == first["svg"]
    assert second["drawn_version"] == 1
