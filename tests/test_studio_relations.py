"""An imported drawing's inferred relations as the studio's sliders (issue 94,
aidl_lang/studio/relations.py): a round flange opened as an editable design has a bolt circle
whose range follows the outline's diameter and the bore, so the holes follow a smaller flange
instead of breaking through its edge; and a download is the design or an error, never an
empty file.

Every drawing is re-read by ezdxf (the outline, the bore and the holes as the DXF holds them).
Cost: one import and about 25 compiles (under 10 s of CPU on a loaded 2-core machine).
"""
from __future__ import annotations

import io
import math
from collections import OrderedDict

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from aidl_lang.studio import compiler
from aidl_lang.studio.relations import WALL, with_relations
from maker_drawings import flange

ezdxf = pytest.importorskip("ezdxf")


@pytest.fixture(scope="module")
def imported(tmp_path_factory):
    """The flange (100 mm, 40 mm bore, 8 holes of 8 mm on 75 mm) as the studio opens it."""
    folder = tmp_path_factory.mktemp("flange")
    (folder / "flange.dxf").write_bytes(flange())
    doc = compiler.import_upload(str(folder), "flange.dxf", True)
    assert "program" in doc, doc
    return str(folder), doc


def circles(data: bytes) -> list[tuple[float, float, float]]:
    """``(x, y, r)`` of every circle of a DXF download, the largest first."""
    d = ezdxf.read(io.StringIO(data.decode()))
    found = [(c.dxf.center.x, c.dxf.center.y, c.dxf.radius) for c in d.modelspace().query("CIRCLE")]
    return sorted(found, key=lambda c: -c[2])


def test_the_bolt_circle_follows_the_diameter(imported):
    folder, doc = imported
    src = doc["program"]
    assert any("bolt circle follows" in n for n in doc["notes"])
    assert "param bolt_circle_pcd = 75 mm, min = bore_d + bolt_circle_d + 2 mm, " \
           "max = diameter - bolt_circle_d - 2 mm" in src
    sessions = OrderedDict()
    view = compiler.view(sessions, "f", folder, src, {"diameter": "70mm"})
    assert view["ok"], view["diagnostics"]
    assert view["clamped"] == {"bolt_circle_pcd": pytest.approx(60)}       # 70 - 8 - 2 x 1
    assert not [d for d in view["diagnostics"] if d["severity"] == "warning"]
    data, name, _ = compiler.download(folder, src, view["values"], "dxf", {})
    (cx, cy, big), *rest = circles(data)
    assert big == pytest.approx(35) and len(rest) == 9                     # 8 holes, the bore
    holes = [c for c in rest if c[2] == pytest.approx(4)]
    assert len(holes) == 8
    for x, y, r in holes:           # on the 60 mm circle, 1 mm of material to the edge
        assert math.hypot(x - cx, y - cy) == pytest.approx(30)
        assert big - (math.hypot(x - cx, y - cy) + r) == pytest.approx(WALL)


def test_the_drawing_s_own_program_is_kept_when_nothing_is_related():
    text = "units mm\nparam width = 40 mm\nsolid s { r = Rectangle(center=(0, 0), width=width, height=20) }\n"
    assert with_relations(text) == (text, [])


@settings(max_examples=8, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(diameter=st.floats(18, 200), hole=st.floats(2, 16), bore=st.floats(10, 80),
       pcd=st.floats(19, 150), n=st.integers(1, 16))
def test_at_any_slider_values_the_holes_stay_inside(imported, diameter, hole, bore, pcd, n):
    """Whatever the sliders hold (each within its slider's span), the worker moves the
    dependent ones into their ranges and the DXF's holes are inside the outline, clear of the
    bore and of each other."""
    folder, doc = imported
    values = {"diameter": f"{diameter:.3f}mm", "bolt_circle_d": f"{hole:.3f}mm",
              "bore_d": f"{bore:.3f}mm", "bolt_circle_pcd": f"{pcd:.3f}mm", "bolt_circle_n": str(n)}
    view = compiler.view(OrderedDict(), "f", folder, doc["program"], values)
    assert view["ok"], [d["message"] for d in view["diagnostics"]]
    got = compiler.download(folder, doc["program"], view["values"], "dxf", {})
    assert not isinstance(got, dict), got
    (cx, cy, big), *rest = circles(got[0])
    v = {p["name"]: p["value"] for p in view["params"]}
    assert big == pytest.approx(v["diameter"] / 2)
    bore_r = v["bore_d"] / 2
    holes = [c for c in rest if not (c[2] == pytest.approx(bore_r) and
                                     math.hypot(c[0] - cx, c[1] - cy) < 1e-6)]
    assert len(holes) == v["bolt_circle_n"]
    for i, (x, y, r) in enumerate(holes):
        at = math.hypot(x - cx, y - cy)
        assert at + r <= big - WALL + 1e-6 and at - r >= bore_r + WALL - 1e-6
        for x2, y2, r2 in holes[i + 1:]:
            assert math.hypot(x - x2, y - y2) >= r + r2 + WALL - 1e-6


def test_a_download_of_nothing_is_an_error_not_an_empty_file(imported):
    """The flange as ``aidl import --infer`` writes it (no ranges) at 25 mm: its 40 mm bore
    removes all of it. Before: a 15 kB DXF of 0 entities and a 22-byte ZIP, both HTTP 200."""
    folder, _ = imported
    from aidl_lang.drawing.infer import import_drawing
    bare, _ = import_drawing(flange(), "flange.dxf", infer=True)
    for settings_ in ({}, {"layout": True}):
        got = compiler.download(folder, bare, {"diameter": "25mm"}, "dxf", settings_)
        assert isinstance(got, dict) and got["error"].startswith("nothing to make"), got
        assert "removes all of" in got["error"]
        assert got["diagnostics"][0]["code"] == "W0503"


def test_a_bolt_circle_off_the_body_s_centre_is_not_related():
    """The ranges hold only for a bolt circle about the outline's centre."""
    from aidl_lang.drawing.infer import import_drawing
    text, _ = import_drawing(flange(), "flange.dxf", infer=True)
    moved = text.replace("bore_c = (50, 50)", "bore_c = (60, 50)")
    assert moved != text and with_relations(moved) == (moved, [])
    assert with_relations(text)[1]
