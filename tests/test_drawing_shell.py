"""A Shell in a drawing engraves its band (issue 111, run o's warning sign): the two loops of
`Shell(edge, -4, join="miter")` of an equilateral triangle, where the drawing engraved nothing
and `aidl check` said nothing.  Real files: the DXF written by the CLI's writer, re-read by
ezdxf; the SVG re-read by svgelements."""
from __future__ import annotations

import math

import pytest

from aidl_lang import api

SIGN = """solid sign {
    body = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=8)
    drawing hazard {
        edge = Triangle(center=(0, 20), base=90, height=90 * sqrt(3) / 2CONSTRUCTION)
        band = Shell(edge, -4, join="miter")
    }
}
"""


def _engraved(tmp_path, src: str) -> list:
    import ezdxf
    f = tmp_path / "sign.aidl"
    f.write_text(src)
    out = tmp_path / "sign.dxf"
    r = api.compile(source=src, path=str(f))
    assert r.ok, [d.message for d in r.diagnostics]
    r.write(out)
    doc = ezdxf.readfile(out)
    return [[(p[0], p[1]) for p in e.get_points("xy")] for e in doc.modelspace()
            if e.dxf.layer.upper().startswith("ENGRAVE")]


def _side(loop) -> float:
    xs = [p[0] for p in loop]
    return max(xs) - min(xs)


@pytest.mark.parametrize("construction", ["", ", construction=true"])
def test_a_shell_in_a_drawing_engraves_both_edges_of_its_band(tmp_path, construction):
    loops = _engraved(tmp_path, SIGN.replace("CONSTRUCTION", construction))
    assert len(loops) == 2
    # outer: the triangle's 90 mm sides; inner: its incircle 4 mm smaller, the side
    # 2 sqrt(3) (r - 4) with r = 90 / (2 sqrt(3))
    inner = 2 * math.sqrt(3) * (90 / (2 * math.sqrt(3)) - 4)
    assert sorted(_side(lp) for lp in loops) == pytest.approx([inner, 90], abs=1e-6)
    for lp in loops:
        assert len(set(lp)) == 3                        # sharp (miter) corners, 3 vertices


def test_a_shell_in_a_drawing_is_in_the_svg_and_the_description(tmp_path):
    import svgelements
    f = tmp_path / "sign.aidl"
    f.write_text(SIGN.replace("CONSTRUCTION", ""))
    out = tmp_path / "sign.svg"
    r = api.compile(source=f.read_text(), path=str(f))
    r.write(out)
    paths = [e for e in svgelements.SVG.parse(str(out)).elements()
             if isinstance(e, svgelements.Shape) and e.bbox() is not None]
    # (svgelements gives user units at 96 per inch: the file is in mm)
    widths = sorted(round((e.bbox()[2] - e.bbox()[0]) * 25.4 / 96, 3) for e in paths)
    assert round(2 * math.sqrt(3) * (90 / (2 * math.sqrt(3)) - 4), 3) in widths
    assert "engraving: Shell `sign.hazard.band`" in r.describe()
