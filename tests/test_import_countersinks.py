"""Countersinks follow their holes under `aidl import --infer` (issue 85, "countersink pairs"):
a plate's holes and the top circles of their countersinks on a CSK layer.  The marks used to
be written where the drawing put them, apart from the holes: `--set width=120` moved the
corner holes to x=114 and left their marks at x=74.  Now a mark concentric with a hole is
written with that hole (its centre the hole's, its diameter `countersink_d`), so every edit
keeps them together; a mark on no hole stays where it is.  Drawings made with ezdxf, the
compiled DXF read back with ezdxf."""
from __future__ import annotations

import io

import ezdxf
import pytest

import aidl_lang
from aidl_lang.drawing.infer import import_drawing
from test_import_layers_units import sink_plate

LONE = (40.0, 30.0)         # a mark on no hole


def _plate(path, layer: str = "CSK") -> bytes:
    """An 80 x 50 mm plate (OUTLINE), four 3.3 mm corner holes 6 mm in and a row of three
    4 mm holes 15 mm apart on the centre line (HOLES), 6.6 and 8 mm marks about each, and
    one 5 mm mark on no hole (``layer``)."""
    doc, m = sink_plate(layer)
    for c in [(6, 6), (74, 6), (74, 44), (6, 44)]:
        m.add_circle(c, 1.65, dxfattribs={"layer": "HOLES"})
        m.add_circle(c, 3.3, dxfattribs={"layer": layer})
    for x in (25, 40, 55):
        m.add_circle((x, 15), 2.0, dxfattribs={"layer": "HOLES"})
        m.add_circle((x, 15), 4.0, dxfattribs={"layer": layer})
    m.add_circle(LONE, 2.5, dxfattribs={"layer": layer})
    doc.saveas(path)
    return path.read_bytes()


def _circles(res, layer: str) -> list:
    """The circles of ``layer`` in the DXF ``res`` renders, read by ezdxf: (x, y, r)."""
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    return [(e.dxf.center.x, e.dxf.center.y, e.dxf.radius) for e in doc.modelspace()
            if e.dxf.layer == layer and e.dxftype() == "CIRCLE"]


EDITS = [{}, {"width": 120}, {"height": 70}, {"corner_inset": 9}, {"width": 100, "corner_inset": 4},
         {"holes_pitch": 18}, {"width": 150, "holes_pitch": 30}, {"corner_countersink_d": 7.5}]


@pytest.mark.parametrize("edit", EDITS, ids=lambda e: ",".join(f"{k}={v}" for k, v in e.items())
                         or "as_drawn")
def test_countersinks_move_with_their_holes(tmp_path, edit):
    text, _ = import_drawing(_plate(tmp_path / "csk.dxf"), "csk.dxf", infer=True)
    assert "param corner_countersink_d = 6.6 mm" in text, text
    assert "param countersink_d = 8 mm" in text, text
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl", overrides=edit)
    assert res.ok, [str(d) for d in res.errors]
    assert not [d for d in res.diagnostics if d.severity == "warning"], res.diagnostics
    holes = _circles(res, "CUT")
    # the marks on holes are their holes' `Countersink`s (issue 102: the COUNTERSINK layer),
    # the mark on no hole stays a drawing (ENGRAVE)
    sunk, marks = _circles(res, "COUNTERSINK"), _circles(res, "ENGRAVE")
    assert text.count("Countersink(") == 2, text
    assert len(holes) == 7 and len(sunk) == 7 and len(marks) == 1, (holes, sunk, marks)
    marks += sunk
    lone = [mk for mk in marks if abs(mk[2] - 2.5) < 1e-9]
    assert len(lone) == 1 and abs(lone[0][0] - LONE[0]) < 1e-9 and abs(lone[0][1] - LONE[1]) < 1e-9
    for x, y, r in holes:
        on = [mk for mk in marks if abs(mk[0] - x) <= 1e-9 and abs(mk[1] - y) <= 1e-9]
        assert len(on) == 1, ((x, y, r), marks)
        want = {1.65: edit.get("corner_countersink_d", 6.6) / 2, 2.0: 4.0}[round(r, 6)]
        assert abs(on[0][2] - want) <= 1e-9
