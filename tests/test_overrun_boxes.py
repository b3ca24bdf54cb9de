"""Issue 111: a joint template's box is its cut within the part.

A cut that opens a panel's edge runs 1 mm past it so the boolean opens cleanly; that run is
drawn as its own shape with ``overrun=true`` (the member ``overrun`` of ``cross_halving``,
``finger_edge``, ``tab_and_slot``, ``dovetail``, ``t_slot``), which counts in no structure's
box.  So ``AlignTop(cross_halving(depth=30 mm), body)`` cuts 30 mm deep (it cut 31: the box
the relation aligned held the overrun), and a dovetail's sockets are as deep as asked (9 mm of
10 before, with a 1 mm step at each tail's root).  Depths are measured on the part as cut,
read back from the SVG by svgelements and from the DXF by ezdxf (tests/exact_geometry.py).
Each program also holds law 3, *members are the geometry* (benchmarks/laws/law_members.py):
a shape's own ``.bb``, the overrun's too, is its drawn outline.
"""
from __future__ import annotations

import pytest

import aidl_lang
from benchmarks.laws import law_members

HALVING = """units mm
import "std/joints.aidl"
solid divider {{
    body = Rectangle(center=(0, 0), width=100, height=60)
    slot = cross_halving(depth=30 mm, thickness=3 mm, rotation={rot} deg)
    {align}(slot, self)
    AlignCenter{across}(slot, self)
}}
"""

DOVETAIL = """units mm
import "std/joints.aidl"
solid lid {
    panel = Rectangle(center=(0, 0), width=100, height=60)
    sock = dovetail(part="socket", length=60 mm, depth=10 mm)
    AlignBottom(sock, self)
    AlignCenterX(sock, self)
}
solid side {
    panel = Rectangle(center=(0, -80), width=60, height=40)
    tails = dovetail(part="tail", length=60 mm, depth=10 mm)
    AlignTop(tails, self)
    AlignCenterX(tails, self)
}
"""


def _mm(v: float):
    return pytest.approx(v, abs=1e-6)


def _compiled(src: str):
    r = aidl_lang.compile(src)
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    warned = [f"{d.code} {d.message}" for d in r.diagnostics if d.code.startswith("W")]
    assert not warned, warned
    assert law_members.violations(r) == []
    return r


def _svg_points(r, tmp_path) -> list[tuple[float, float]]:
    from exact_geometry import read_svg_loops
    path = tmp_path / "part.svg"
    path.write_text(r.to_svg(), encoding="utf-8")
    return [sg.start for loop in read_svg_loops(path) for sg in loop]


def _dxf_points(r, tmp_path) -> list[tuple[float, float]]:
    from exact_geometry import read_dxf
    path = tmp_path / "part.dxf"
    path.write_text(r.to_dxf(), encoding="utf-8")
    return [sg.start for e in read_dxf(path) for sg in e.segments]


def _both(r, tmp_path):
    return [("svg", _svg_points(r, tmp_path)), ("dxf", _dxf_points(r, tmp_path))]


def test_align_top_of_a_30_mm_cross_halving_cuts_30_mm(tmp_path):
    r = _compiled(HALVING.format(rot=0, align="AlignTop", across="X"))
    for fmt, pts in _both(r, tmp_path):
        slot = [p for p in pts if abs(p[0]) < 2]        # the slot's corners (3 mm wide)
        assert len(slot) == 4, (fmt, pts)
        assert max(p[1] for p in slot) == _mm(30.0), fmt     # opens the top edge
        assert 30.0 - min(p[1] for p in slot) == _mm(30.0), fmt   # was 31
    vals = {v.name: v.mm for v in r.values}
    assert vals["divider.slot.bbox"][3] == _mm(30.0)
    assert vals["divider.slot.bbox"][1] == _mm(0.0)
    assert vals["divider.slot.overrun.top_right"][1] == _mm(31.0)   # drawn, 1 mm past
    assert vals["divider.bbox"][3] == _mm(30.0)     # the panel's box: its material


def test_a_turned_cross_halving_aligned_to_the_left_edge(tmp_path):
    # rotation 90 deg: the slot runs toward +x from its mouth on the left edge
    r = _compiled(HALVING.format(rot=90, align="AlignLeft", across="Y"))
    for fmt, pts in _both(r, tmp_path):
        slot = [p for p in pts if abs(p[1]) < 2]
        assert len(slot) == 4, (fmt, pts)
        assert min(p[0] for p in slot) == _mm(-50.0), fmt
        assert max(p[0] for p in slot) + 50.0 == _mm(30.0), fmt


def test_dovetail_sockets_and_tails_are_as_deep_as_asked(tmp_path):
    r = _compiled(DOVETAIL)
    for fmt, pts in _both(r, tmp_path):
        lid = [p for p in pts if -30.0 - 1e-6 <= p[1] < 29.0 and abs(p[0]) < 49.0]
        # the sockets: from the lid's bottom edge (y = -30) 10 mm in, no step at the roots
        assert {round(p[1], 6) for p in lid} == {-30.0, -20.0}, (fmt, lid)
        side = [p for p in pts if p[1] < -50.0 and p[1] > -100.0 + 1e-6]
        # the tails' sockets in the side: from its top edge (y = -60) 10 mm down
        assert {round(p[1], 6) for p in side} == {-60.0, -70.0}, (fmt, side)
    vals = {v.name: v.mm for v in r.values}
    assert vals["lid.sock.bbox"][1] == _mm(-30.0)
    assert vals["lid.sock.bbox"][3] == _mm(-20.0)
    assert vals["side.tails.bbox"][3] == _mm(-60.0)
    assert vals["side.tails.bbox"][1] == _mm(-70.0)


def test_a_shape_drawn_with_overrun_counts_in_no_box_but_its_own():
    src = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole notch {
        seat = Rectangle(center=(0, 0), width=10, height=8)
        past = Rectangle(center=(0, 2), width=10, height=12, overrun=true)
    }
    AlignTop(notch, self)
    w = notch.bb.height
}
"""
    r = _compiled(src)
    vals = {v.name: v.mm for v in r.values}
    assert vals["plate.w"] == _mm(8.0)                # the seat's, not 12
    assert vals["plate.notch.bbox"][3] == _mm(20.0)   # the seat's top on the edge
    assert vals["plate.notch.past.top_right"][1] == _mm(24.0)   # drawn 4 mm past it
    part = next(p for p in r.parts if p.name == "plate")
    assert part.bbox[3] == _mm(20.0)                  # the notch opens the edge


def test_t_slot_aligned_to_an_edge_is_as_long_as_asked(tmp_path):
    src = """units mm
import "std/fasteners.aidl"
solid wall {
    body = Rectangle(center=(0, 0), width=60, height=40)
    nut = t_slot(size=3, length=12 mm, nut_depth=6 mm)
    AlignTop(nut, self)
    AlignCenterX(nut, self)
}
"""
    r = _compiled(src)
    for fmt, pts in _both(r, tmp_path):
        slot = [p for p in pts if abs(p[0]) < 2]        # the screw's slot, 3.4 mm wide
        assert 20.0 - min(p[1] for p in slot) == _mm(12.0), (fmt, slot)   # was 13

