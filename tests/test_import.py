"""Drawings brought in (issue 39): DXF and SVG read as exact curves, `aidl import` writing a
program that renders back to the same curves (re-read with ezdxf, 1e-9 mm)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import ezdxf
import pytest

from dxf_compare import curves, unmatched

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.aidl"))
AIDL = [sys.executable, "-m", "aidl_lang.cli"]
# Examples whose drawing holds curves the language's own forms cannot write exactly: the
# logo plate's SVG logo is cubic Béziers (kept exact by Drawing2D, but a Spline statement is
# the interpolating spline through points, which a free Bézier is not)
NOT_EXACT_IN_THE_LANGUAGE = {"logo_plate"}


def run(*args, cwd=None):
    return subprocess.run(AIDL + [str(a) for a in args], capture_output=True, text=True,
                          cwd=cwd, timeout=120)


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_round_trip_every_example(example, tmp_path):
    """render -> DXF -> import -> render: the same curves to 1e-9 mm (both DXFs re-read with
    ezdxf alone)."""
    import aidl_lang
    from aidl_lang.drawing.program import import_drawing
    first, second = tmp_path / "a.dxf", tmp_path / "b.dxf"
    res = aidl_lang.compile(path=example)
    assert res.ok
    first.write_text(res.to_dxf())
    text, notes = import_drawing(first.read_bytes(), "a.dxf")
    again = aidl_lang.compile(text, path=tmp_path / "a.aidl")
    assert again.ok, [str(d) for d in again.errors]
    second.write_text(again.to_dxf())
    a, b = curves(first), curves(second)
    assert a, "the example drew nothing"
    left, extra = unmatched(a, b)
    assert not extra, extra[:3]
    if example.stem in NOT_EXACT_IN_THE_LANGUAGE:
        # the SVG logo's cubic Béziers are no interpolating Spline: left out, said so, and
        # nothing else differs
        assert notes and all("not an interpolating spline" in n.message for n in notes)
        assert left and {c[0] for c in left} == {"S"}
        return
    assert not notes, notes
    assert not left, left[:3]


def test_cli_import_writes_a_program_that_checks(tmp_path):
    """`aidl import FILE.dxf -o part.aidl`, then `aidl check` and `aidl render` of it."""
    doc = _doc()
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0, 0), (40, 0, 0.4), (40, 20, 0), (0, 20, 0)], format="xyb",
                       close=True)
    msp.add_circle((10, 10), 3)
    doc.saveas(tmp_path / "plate.dxf")
    r = run("import", "plate.dxf", "-o", "plate.aidl", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "plate.aidl").read_text()
    assert "Arc(center=" in text and "hole hole" in text and "Circle(center=(10, 10), radius=3)" in text
    r = run("render", "plate.aidl", "-o", "back.dxf", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    left, extra = unmatched(curves(tmp_path / "plate.dxf"), curves(tmp_path / "back.dxf"))
    assert not left and not extra


def _doc():
    doc = ezdxf.new("R2010")
    doc.units = 4
    return doc


def test_bulges_splines_and_units(tmp_path):
    """An LWPOLYLINE with a bulge, a SPLINE and $INSUNITS = inches come in exactly."""
    from aidl_lang.drawing import read_drawing
    from aidl_lang.geometry.curves import Arc, Spline
    doc = ezdxf.new("R2010")
    doc.units = 1                               # inches
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0, 0), (2, 0, 1), (2, 2, 0), (0, 2, 0)], format="xyb", close=True)
    msp.add_open_spline([(5, 0), (6, 1), (7, -1), (8, 0)], degree=3)
    msp.add_circle((1, 1), 0.25)
    p = tmp_path / "d.dxf"
    doc.saveas(p)
    d = read_drawing(p.read_bytes(), "d.dxf")
    (o,) = d.outlines
    arcs = [s for s in o.segments if isinstance(s, Arc)]
    assert len(arcs) == 1
    # bulge 1 from (2, 0) to (2, 2) inches: a half circle of radius 1 in about (2, 1) in
    assert arcs[0].radius == pytest.approx(25.4, abs=1e-12)
    assert arcs[0].center == pytest.approx((50.8, 25.4), abs=1e-12)
    assert abs(arcs[0].sweep) == pytest.approx(3.141592653589793, abs=1e-12)
    (c,) = d.circles
    assert c.center == pytest.approx((25.4, 25.4), abs=1e-12) and c.radius == pytest.approx(6.35)
    (path,) = d.paths
    (s,) = path.segments
    assert isinstance(s, Spline)
    assert s.spans[0][1] == pytest.approx((6 * 25.4, 25.4), abs=1e-12)
    assert d.box() == pytest.approx((0, -0.5 * 25.4 + 0.0, 8 * 25.4, 2 * 25.4), abs=0.5 * 25.4)
