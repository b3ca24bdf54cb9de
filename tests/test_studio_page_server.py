"""The studio's server for the page's missing pieces (issue 72), no browser: only the formats
this server makes are offered, the PDF tiled on paper, G-code on the sheet's origin with
nesting off, a drawing opened as it is (``Drawing2D``), standard-library messages located in
the library file (never the install's path), and ``/favicon.ico``.  Every file is re-read by
an independent reader (pdfplumber, plain parsing of G-code, ezdxf)."""
from __future__ import annotations

import importlib.util
import io
import re
from pathlib import Path

import pytest

pytest.importorskip("starlette")
pytest.importorskip("limits")
from starlette.testclient import TestClient  # noqa: E402

from aidl_lang.studio.app import Settings, create_app  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
# a 300 x 200 mm plate centred on the origin (x -150..150, y -100..100) with a 20 mm hole
PLATE = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=300, height=200)\n"
         "    hole h { c = Circle(center=(60, 0), radius=10) }\n}\n")


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    app = create_app(Settings(data=str(tmp_path_factory.mktemp("studio") / "data"), compilers=1))
    with TestClient(app) as c:
        yield c


@pytest.fixture(scope="module")
def sid(client):
    return client.post("/api/session").json()["sid"]


def download(client, sid, fmt, source=PLATE, **settings):
    return client.post(f"/api/download/{fmt}", json={"sid": sid, "source": source, "values": {},
                                                     "settings": settings})


def test_only_the_formats_this_server_makes_are_offered(client):
    doc = client.get("/api/config").json()
    formats = {f["ext"]: f for f in doc["formats"]}
    has_ocp = importlib.util.find_spec("OCP") is not None
    assert formats["step"]["available"] is has_ocp
    assert all(f["available"] for e, f in formats.items() if e != "step")
    assert {"A4", "Letter"} <= set(doc["pages"])


def test_the_pdf_is_tiled_on_a4_and_letter_as_the_cli_tiles_it(client, sid, tmp_path):
    import subprocess
    import sys

    pdfplumber = pytest.importorskip("pdfplumber")

    def pages(data):
        with pdfplumber.open(io.BytesIO(data)) as pdf:
            return [(float(p.width), float(p.height)) for p in pdf.pages]
    assert len(pages(download(client, sid, "pdf", kerf=0).content)) == 1    # one page: its size
    src = tmp_path / "plate.aidl"
    src.write_text(PLATE)
    for paper, (w, h) in {"A4": (595.28, 841.89), "Letter": (612.0, 792.0)}.items():
        r = download(client, sid, "pdf", kerf=0, page=paper)
        assert r.status_code == 200, r.text
        tiles = pages(r.content)
        # 300 x 200 mm does not fit one sheet of paper: tiled 1:1 over several
        assert len(tiles) > 1
        for size in tiles:
            assert sorted(size) == pytest.approx(sorted((w, h)), abs=0.5)
        if paper == "A4":           # the same pages as `aidl render --page A4`
            out = tmp_path / "plate-A4.pdf"
            subprocess.run([sys.executable, "-m", "aidl_lang.cli", "render", str(src), "-o",
                            str(out), "--page", paper], check=True, capture_output=True,
                           timeout=300)
            assert len(pages(out.read_bytes())) == len(tiles)
    bad = download(client, sid, "pdf", page="A9")
    assert bad.status_code == 400 and "A4" in bad.json()["error"]   # before any compile


def gcode_xy(data: bytes) -> tuple[list[float], list[float]]:
    """The X and Y words of the moves (G0-G3) of a G-code file, read as plain text."""
    xs, ys = [], []
    for line in data.decode().splitlines():
        code = line.split(";", 1)[0].upper()
        if re.match(r"\s*G0*[0-3]\b", code):
            xs += [float(v) for v in re.findall(r"X(-?[\d.]+)", code)]
            ys += [float(v) for v in re.findall(r"Y(-?[\d.]+)", code)]
    return xs, ys


@pytest.mark.parametrize("machine", ["laser", "router"])
def test_gcode_with_nesting_off_starts_at_the_sheets_origin(client, sid, machine):
    r = download(client, sid, "gcode", kerf=0, layout=False, machine=machine)
    assert r.status_code == 200, r.text
    xs, ys = gcode_xy(r.content)
    assert xs and ys
    # before: the plate's own coordinates, x from -150 mm, y from -100 mm
    assert min(xs) == pytest.approx(0, abs=1e-6) and min(ys) == pytest.approx(0, abs=1e-6)
    if machine == "laser":          # the beam on the outline: the plate's 300 x 200 mm
        assert max(xs) == pytest.approx(300, abs=1e-3) and max(ys) == pytest.approx(200, abs=1e-3)
    else:                           # the router's tool outside it: wider by its diameter
        assert max(xs) > 300 and max(ys) > 200


def test_a_drawing_opens_as_it_is_with_drawing2d(client, sid):
    import ezdxf
    doc = ezdxf.new(units=4)                        # millimetres ($INSUNITS 4)
    msp = doc.modelspace()
    msp.add_lwpolyline([(10, 5), (110, 5), (110, 65), (10, 65)], close=True)
    msp.add_circle((30, 35), 5)
    buf = io.StringIO()
    doc.write(buf)
    r = client.post(f"/api/upload?sid={sid}&name=my_plate.dxf&import=drawing",
                    content=buf.getvalue().encode())
    assert r.status_code == 200, r.text
    got = r.json()
    assert 'Drawing2D("my_plate.dxf")' in got["program"] and "solid my_plate" in got["program"]
    assert "100 x 60 mm" in got["program"]
    v = client.post("/api/view", json={"sid": sid, "source": got["program"], "values": {}}).json()
    assert v["ok"], v["diagnostics"]
    dxf = download(client, sid, "dxf", source=got["program"], kerf=0, layout=False)
    from ezdxf import bbox
    back = ezdxf.read(io.StringIO(dxf.content.decode()))
    box = bbox.extents(e for e in back.modelspace() if e.dxf.layer.upper() == "CUT")
    assert (box.size.x, box.size.y) == (pytest.approx(100, abs=1e-6), pytest.approx(60, abs=1e-6))
    # open lines only: a drawing (engraved), not a solid that cannot close
    doc = ezdxf.new(units=4)
    doc.modelspace().add_line((0, 0), (50, 20))
    buf = io.StringIO()
    doc.write(buf)
    got = client.post(f"/api/upload?sid={sid}&name=line.dxf&import=drawing",
                      content=buf.getvalue().encode()).json()
    assert "drawing line {" in got["program"]
    v = client.post("/api/view", json={"sid": sid, "source": got["program"], "values": {}}).json()
    assert v["ok"], v["diagnostics"]


def test_a_standard_library_message_is_located_at_the_call(client, sid):
    """The planetary set with a sun of 13 (ring 49 + sun 13 does not divide by its 3
    planets) has a message raised in std/gears.aidl (E0405, the spacing rule): it is at the
    call of `planetary` in the program (issue 86), the library's line named in its text as
    the program imports it (std/gears.aidl:359:5), never the server's path to it.  (It was
    planet = 8 until h18-gears cut the ring's tips for small planets: that compiles clean.)"""
    # (the sun's range follows its steps, which keep the rule, in the form: a plain range here)
    lines = (ROOT / "aidl_lang" / "studio" / "forms" / "planetary.aidl").read_text().splitlines()
    form = "\n".join("param sun = 12, min = 8, max = 48" if x.startswith("param sun =") else x
                     for x in lines) + "\n"
    v = client.post("/api/view", json={"sid": sid, "source": form, "values": {"sun": "13"}}).json()
    assert [d["code"] for d in v["diagnostics"]] == ["E0405"], v["diagnostics"]
    spans = [d["span"] for d in v["diagnostics"] if d.get("span")]
    assert spans, v["diagnostics"]
    assert all(not s["file"].startswith("/") for s in spans), spans
    call = form.splitlines().index(next(x for x in form.splitlines() if "= planetary(" in x)) + 1
    assert {(s["file"], s["line"]) for s in spans} == {("SESSION/main.aidl", call)}
    assert all("  --> std/gears.aidl:" in d["rendered"] for d in v["diagnostics"])
    text = str(v)
    assert str(ROOT) not in text


def test_the_favicon_is_an_icon(client):
    r = client.get("/favicon.ico")
    assert r.status_code == 200 and r.headers["content-type"] == "image/x-icon"
    assert r.content[:4] == b"\0\0\1\0"             # an ICO with one image
    assert '<link rel="icon" href="/favicon.ico">' in client.get("/").text
