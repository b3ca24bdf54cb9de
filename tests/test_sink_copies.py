"""A pattern copies a sunk hole with its head (issue 111's third fresh-model run: a tea-light
tray's `CornerPattern(screw, plate, inset=6 mm)` then `Countersink(screw, diameter=6 mm)` sank
one of the four screw holes, and only the note "1 countersink head" said so).  Now every copy a
pattern, a mirror or a copied structure makes of a sunk hole is sunk alike, as a CAD pattern
copies a countersunk hole feature whole; a copy sunk by a call of its own keeps that head.
Read back: `aidl parts`, the DXF's COUNTERSINK layer (ezdxf), the router's plunges
(gcodeparser, as law 5 reads them), and the law itself."""
from __future__ import annotations

import io

import ezdxf
import pytest

import aidl_lang

pytest.importorskip("gcodeparser")
from benchmarks.laws import law_counted as law  # noqa: E402

TRAY = """thickness 4 mm
solid tray {
    plate = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=8)
    hole screw { c = Circle(center=(-94, -29), diameter=3) }
    CornerPattern(screw, plate, inset=6 mm)
    Countersink(screw, diameter=6 mm)
}
"""


def _heads(src):
    r = aidl_lang.compile(source=src)
    assert r.ok, [d.message for d in r.diagnostics]
    doc = ezdxf.read(io.StringIO(r.encode("dxf").decode()))
    dxf = sorted((round(e.dxf.center.x, 6), round(e.dxf.center.y, 6), e.dxf.layer)
                 for e in doc.modelspace() if e.dxftype() == "CIRCLE"
                 and e.dxf.layer in ("COUNTERSINK", "COUNTERBORE"))
    return r, dxf


def test_a_corner_patterns_copies_are_sunk_with_their_original():
    r, dxf = _heads(TRAY)
    corners = [(-94.0, -29.0), (-94.0, 29.0), (94.0, -29.0), (94.0, 29.0)]
    assert dxf == [(x, y, "COUNTERSINK") for x, y in corners]
    assert len(r.output.drawing.sinks) == 4
    # the router (its 3.175 mm bit is too wide for 3 mm holes: 4.5 mm ones) plunges each once
    r = aidl_lang.compile(source=TRAY.replace("diameter=3)", "diameter=4.5)"))
    gcode = r.encode("gcode", kerf=0, machine="router").decode()
    assert law.sink_plunges(gcode) == {c: 1 for c in corners}


def test_a_mirrored_copy_and_a_copied_structure_follow_and_an_own_head_stays():
    src = """thickness 6 mm
solid plate {
    body = Rectangle(center=(0, 0), width=120, height=60)
    hole a { c = Circle(center=(-40, 0), diameter=4.5) }
    axis = Line((0, -30), (0, 30), construction=true)
    Mirrored(a, axis)
    solid boss {
        ring = Circle(center=(0, 15), radius=8)
        hole b { c = Circle(center=(0, 15), diameter=4.5) }
    }
    row = LinearPattern(boss, 2, (0, -30))
    Countersink(a, diameter=9 mm)
    Countersink(boss.b, diameter=9 mm)
    Counterbore(row[1].b, diameter=8 mm, depth=2 mm)
}
"""
    r, dxf = _heads(src)
    assert dxf == [(-40.0, 0.0, "COUNTERSINK"), (0.0, -15.0, "COUNTERBORE"),
                   (0.0, 15.0, "COUNTERSINK"), (40.0, 0.0, "COUNTERSINK")]


def test_the_law_holds_on_the_tray(tmp_path):
    from test_law_outputs import Entry
    f = tmp_path / "tray.aidl"
    f.write_text(TRAY)
    assert law.check(Entry("tray.aidl", TRAY, str(f))) == []
