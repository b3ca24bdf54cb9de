"""Issue 111's model runs aa-ab (round ten) and what run z7 left: an Align relation that
reads a point."""
from __future__ import annotations

from pathlib import Path

import pytest

import aidl_lang

RUNS = Path(__file__).resolve().parent.parent / "data" / "model_runs"


def _w(r, code):
    return [d for d in r.diagnostics if d.code == code]


def _num(r, name):
    return r.value(name).value


TAG = """solid stocking {
    sock = Spline([(-20, 75), (20, 75), (21, 45), (58, 6), (20, -12), (-25, 6)], closed=true,
                  corners=[0, 1])
    cuff = RoundedRectangle(center=(0, 78), width=56, height=20, corner_radius=4)
    Fixed(sock)
    AlignCenterX(cuff, sock.points[1])
    AlignBottom(cuff, sock.points[0])
}
"""


def test_an_align_relation_reads_a_point_as_its_coordinate():
    """Run z7's stocking tag wrote `AlignCenterX(cuff, sock.points[0])` and got E0108 ("must
    be a structure or geometry, got point"). A point is what a model reaches for to put a
    box's centre (or side) on it: each Align relation now reads a point as its x (center_x,
    left, right) or y (center_y, top, bottom), the first-named moving as with two boxes."""
    r = aidl_lang.compile(source=TAG)
    assert r.ok, [d.message for d in r.diagnostics]
    assert not [d for d in r.diagnostics if d.code.startswith("E")]
    c = r.value("stocking.cuff.center").value
    assert tuple(c) == pytest.approx((20.0, 85.0), abs=1e-9)    # points[1].x; points[0].y + 10
    assert _num(r, "stocking.cuff.width") == pytest.approx(56.0)   # the cuff kept its size
    # the spline did not move (it is Fixed; the cuff is the first-named)
    p = r.value("stocking.sock.p1").value
    assert tuple(p) == pytest.approx((20.0, 75.0), abs=1e-9)


@pytest.mark.parametrize("rel,side,want", [
    ("AlignLeft", "left", 30.0), ("AlignRight", "right", 30.0),
    ("AlignTop", "top", -12.0), ("AlignBottom", "bottom", -12.0),
    ("AlignCenterY", "center_y", -12.0)])
def test_each_align_relation_reads_the_points_own_axis(rel, side, want):
    src = f"""solid plate {{
    body = Rectangle(center=(0, 0), width=100, height=60)
    mark = Point(30 mm, -12 mm)
    Fixed(body)
    Fixed(mark)
    hole h {{ c = Circle(center=(0, 0), diameter=8) }}
    {rel}(h, mark.p)
    assert h.bb.{side} == {want} mm
}}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]


def test_a_relation_between_boxes_still_refuses_a_point():
    """`Above(lid, p)` has no meaning for a point (which side of it?): E0108 as before."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    mark = Point(30 mm, -12 mm)
    Above(body, mark.p)
}
"""
    r = aidl_lang.compile(source=src)
    assert not r.ok
    assert any(d.code == "E0108" and "got point" in d.message for d in r.diagnostics)


def test_divider_tray_lowers_its_dividers_for_a_lid():
    """Run z7's tea box: a lid's 3 mm locating plate sat on the 2 x 2 dividers (as high as
    the walls), so the lid stood 3 mm proud; the model reached for a lower divider.
    `divider_height=` sets the dividers' height above the bottom, their halvings half of it;
    the tray assembled stands on z = 0 (its docs say so), and nothing collides."""
    src = """import "std/boxes.aidl"
assembly tea {
    tray = divider_tray(length=160 mm, width=160 mm, height=60 mm, rows=2, cols=2,
                        divider_height=45 mm)
    assert tray.row_divider[0].plate.bb.height == 45 mm
    assert tray.col_divider[0].plate.bb.height == 45 mm
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    assert not _w(r, "W0517") and not _w(r, "W0518")
    bad = aidl_lang.compile(source=src.replace("45 mm)", "58 mm)"))
    assert not bad.ok            # past the walls less the bottom (57 mm): the template's assert
    assert any("at most as high as the walls" in d.message for d in bad.diagnostics)


def test_text_takes_halign_for_its_anchor():
    """`halign="center"` beside `valign=` is what a model writes (run z5's sign, E0105 "no
    argument `halign`"): it is `anchor`'s other name."""
    src = """solid sign {
    body = Rectangle(center=(0, 0), width=120, height=50)
    drawing d { t = Text("AB", position=(0, 0), size=10, halign="left", valign="middle") }
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    ref = aidl_lang.compile(source=src.replace("halign=", "anchor="))
    assert [d.message for d in r.diagnostics] == [d.message for d in ref.diagnostics]
    assert r.to_svg() == ref.to_svg()
