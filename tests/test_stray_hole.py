"""A hole declared in an assembly cuts nothing (W0109), and now no output cuts it either
(law 2 of docs/laws.md: `model_runs/requests_round3/before/01_finger_box.first_valid.aidl`, a
model's first try, wrote the circle on the lid in the laser SVG, the DXF, the PDF and the
G-code, so the machine cut a hole the part model, the meshes and the parts list did not have,
and the router left the disc as a second piece of `box.k.lid`).  The preview SVG draws it
dashed where it lies; W0109 names the lid and gives `CutInto`, which makes the hole real."""
from __future__ import annotations

import io
from pathlib import Path

import ezdxf
import pytest

import aidl_lang

ROOT = Path(__file__).resolve().parent.parent
FIRST = ROOT / "data/model_runs/requests_round3/before/01_finger_box.first_valid.aidl"


def _circles(dxf: bytes) -> list:
    doc = ezdxf.read(io.StringIO(dxf.decode()))
    return [(e.dxf.layer, round(e.dxf.radius, 6)) for e in doc.modelspace()
            if e.dxftype() == "CIRCLE"]


def test_a_hole_beside_a_template_is_cut_by_no_output():
    r = aidl_lang.compile(path=str(FIRST))
    assert [d.code for d in r.diagnostics if d.severity == "warning"] == ["W0109"]
    assert _circles(r.encode("dxf")) == []
    assert "lid_hole" not in r.encode("svg", style="laser").decode()
    assert "lid_hole" not in r.encode("pdf", kerf=0).decode("latin-1")
    for kerf in (0, 0.2):                       # drawn dashed where it lies, kerf or none
        preview = r.encode("svg", kerf=kerf).decode()
        assert "<title>box.lid_hole</title>" in preview, kerf
    gcode = r.encode("gcode", kerf=0).decode()
    # the lid's hole would be a 10 mm circle: G2/G3 with I/J of 10 mm, or none at all
    assert "I-10" not in gcode and "I10" not in gcode
    assert [p.name for p in r.output.parts if p.kind == "hole"] == []


def test_CutInto_makes_it_a_hole_of_the_lid():
    src = FIRST.read_text().replace("    CenterInside(lid_hole, k.lid)\n",
                                    "    CenterInside(lid_hole, k.lid)\n    CutInto(lid_hole, k.lid)\n")
    r = aidl_lang.compile(source=src, path=str(FIRST))
    assert [d.code for d in r.diagnostics if d.severity == "warning"] == []
    assert [c for c in _circles(r.encode("dxf")) if c[1] == 10.0], _circles(r.encode("dxf"))


@pytest.mark.parametrize("law", ["law_outputs", "law_machine"])
def test_the_laws_hold_on_the_first_try(law):
    import importlib
    from benchmarks.laws.corpus import iter_corpus
    mod = importlib.import_module(f"benchmarks.laws.{law}")
    (entry,) = [e for e in iter_corpus() if e.name.endswith(
        "requests_round3/before/01_finger_box.first_valid.aidl")]
    assert mod.check(entry) == []
