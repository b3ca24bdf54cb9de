"""Drawing to design, round seven: the misses of the blind maker run (issue 114,
data/maker_runs/issue114/REPORT.md; docs/import.md, "What an edit means").  The drawings are
made here with ezdxf or svgwrite (the makers' numbers, not the inference's rules), imported
through the real importer (``--infer``), each edit compiled by the real compiler and its DXF
read back with ezdxf; hole centres and sizes are compared numerically.

* a set's or a feature's distance from an edge is a param: a Pi's 2 x 2 holes 20 / 15 mm in
  (`holes_x`, `holes_y`), two holes each by its own edge (`hole1_x`, `hole2_x`), a motor's
  bore 35 mm from the right edge that its screw holes follow (`bore_x`);
* a hole of another size on a row's lattice only past missing members (a terminal strip's
  mounting hole) is a hole of its own by its nearer edge, not the row's odd member with gaps;
* a perforated margin the drawing only bounds (a 12 mm margin's holes are kept by any margin
  over 7.5 and up to 12.5 mm) is read as the roundest, and the head and the param say the
  range: the maker's 12 gives the drawing back.
Cost: a few imports and about twenty compiles (seconds)."""
from __future__ import annotations

import re

import pytest

from aidl_lang.drawing.infer import import_drawing

from test_infer_round5 import _doc, _text  # a plate drawn with ezdxf; its import (--infer)
from test_infer_round6 import _holes       # the compiled program's circles, read by ezdxf


def _param(text: str, name: str) -> float:
    m = re.search(rf"^param {name} = (-?[\d.]+)", text, re.M)
    assert m, (name, text)
    return float(m.group(1))


def test_a_boards_grid_by_its_corner_has_its_distances_as_params(tmp_path):
    """A Raspberry Pi's four 2.7 mm holes (58 x 49 mm) 20 mm from the left edge and 15 from
    the bottom of a 150 x 100 plate, 3.4 mm holes in its corners (the maker run's #2)."""
    doc, m = _doc(150, 100)
    for x in (5, 145):
        for y in (5, 95):
            m.add_circle((x, y), 1.7)
    for x in (20, 78):
        for y in (15, 64):
            m.add_circle((x, y), 1.35)
    text = _text(doc)
    assert _param(text, "holes_x") == 20 and _param(text, "holes_y") == 15, text
    assert "holes_x + i * holes_pitch_x" in text, text
    pi = [g for g in _holes(text, tmp_path, holes_x=30) if g[2] == 2.7]
    assert pi == [(30, 15, 2.7), (30, 64, 2.7), (88, 15, 2.7), (88, 64, 2.7)], (pi, text)
    # a new width keeps the board by the left edge, the corner holes by theirs
    got = _holes(text, tmp_path, width=180)
    assert [g[:2] for g in got if g[2] == 2.7] == [(20, 15), (20, 64), (78, 15), (78, 64)]
    assert [g[:2] for g in got if g[2] == 3.4] == [(5, 5), (5, 95), (175, 5), (175, 95)]


def test_two_holes_by_their_own_edges_have_their_distances_as_params(tmp_path):
    """An SVG strip 140 x 40 mm with 6 mm holes 25 mm from the left edge and 25.03 from the
    right (the maker run's #20): each hole's distance from its edge is one number."""
    import svgwrite
    d = svgwrite.Drawing(size=("140mm", "40mm"), viewBox="0 0 140 40")
    d.add(d.rect((0, 0), (140, 40), fill="none", stroke="black"))
    for x in (25, 140 - 25.03):
        d.add(d.circle((x, 20), 3, fill="none", stroke="black"))
    text, _ = import_drawing(d.tostring().encode(), "strip.svg", infer=True)
    assert "each kept from its own nearer edge" in text, text
    assert _param(text, "hole1_x") == 25 and _param(text, "hole2_x") == 25.03, text
    xs = [g[0] for g in _holes(text, tmp_path, hole1_x=30)]
    assert xs == [30, pytest.approx(114.97, abs=1e-9)], (xs, text)
    xs = [g[0] for g in _holes(text, tmp_path, width=180, hole2_x=40)]
    assert xs == [25, 140], (xs, text)


def test_a_bore_by_the_far_edge_has_its_distance_as_a_param(tmp_path):
    """A 110 x 70 plate with a 22 mm bore 35 mm from its right edge, four 3.4 mm holes 31 mm
    apart round it (the maker run's #56): `bore_x` moves the bore and its holes."""
    doc, m = _doc(110, 70)
    m.add_circle((75, 35), 11)
    for dx in (-15.5, 15.5):
        for dy in (-15.5, 15.5):
            m.add_circle((75 + dx, 35 + dy), 1.7)
    text = _text(doc)
    assert _param(text, "bore_x") == 35 and "width - bore_x" in text, text
    got = _holes(text, tmp_path, bore_x=40)
    assert [g[0] for g in got if g[2] == 22] == [70], (got, text)
    assert sorted({g[0] for g in got if g[2] == 3.4}) == [54.5, 85.5], (got, text)
    got = _holes(text, tmp_path, width=130)         # the motor keeps the right edge
    assert [g[0] for g in got if g[2] == 22] == [95], (got, text)


def _terminal_strip(mount_x: float = 118.0):
    """Ten 3.5 mm terminals on a 9 mm pitch from x = 10 on the centre line of a 130 x 25 mm
    strip, a 5 mm mounting hole at ``mount_x`` (118 = 10 + 12 x 9: 12 mm from the right
    edge, on the row's lattice two nodes past its last terminal by chance)."""
    doc, m = _doc(130, 25)
    for i in range(10):
        m.add_circle((10 + 9 * i, 12.5), 1.75)
    m.add_circle((mount_x, 12.5), 2.5)
    return doc


def test_a_hole_of_another_size_past_missing_members_is_its_own(tmp_path):
    """The maker run's #49-51: the mounting hole is no 13th terminal with two gaps."""
    text = _text(_terminal_strip())
    assert "completes a" not in text and "_odd_d" not in text and "if not" not in text, text
    assert _param(text, "holes_n") == 10 and _param(text, "hole1_x") == 12, text
    got = _holes(text, tmp_path, holes_pitch=10)     # the first terminal stays 10 mm in
    assert [g[0] for g in got if g[2] == 3.5] == [10 + 10 * i for i in range(10)], (got, text)
    assert [g[0] for g in got if g[2] == 5] == [118], (got, text)
    got = _holes(text, tmp_path, holes_n=8)
    assert [g[0] for g in got if g[2] == 3.5] == [10 + 9 * i for i in range(8)], (got, text)
    assert [g[0] for g in got if g[2] == 5] == [118], (got, text)
    got = _holes(text, tmp_path, width=150)          # the mounting hole follows the right edge
    assert [g[0] for g in got if g[2] == 5] == [138], (got, text)
    assert [g[0] for g in got if g[2] == 3.5] == [10 + 9 * i for i in range(10)], (got, text)


def test_a_hole_of_another_size_next_to_its_row_stays_its_member(tmp_path):
    """What was right stays: the 5 mm hole one pitch past the last terminal (x = 100) ends
    the row as its odd member, its own size on its turn."""
    text = _text(_terminal_strip(mount_x=100.0))
    assert "completes a pattern" in text and _param(text, "holes_n") == 11, text
    got = _holes(text, tmp_path, holes_pitch=10)
    assert [g[0] for g in got if g[2] == 5] == [110], (got, text)


def _perforated(margin: float):
    """A 200 x 150 plate, 5 mm holes on a 10 mm pitch filling it less ``margin`` (as many as
    lie whole in it, centred): the maker run's #11 (12 mm)."""
    doc, m = _doc(200, 150)
    nx, ny = (int((s - 2 * margin - 5) // 10) + 1 for s in (200, 150))
    for i in range(nx):
        for j in range(ny):
            m.add_circle((100 + (i - (nx - 1) / 2) * 10, 75 + (j - (ny - 1) / 2) * 10), 2.5)
    return doc, (nx, ny)


@pytest.mark.parametrize("margin, reading, lo, hi", [(12, 10, 7.5, 12.5), (15, 15, 12.5, 17.5)])
def test_a_perforated_margin_the_drawing_only_bounds_is_said(tmp_path, margin, reading, lo, hi):
    """No margin is drawn, only holes: every margin over 7.5 and up to 12.5 mm keeps the 18 x
    13 holes of a 12 mm one (the roundest, 10, is read).  The param's comment and the head
    say the range, so the maker who dimensioned 12 sets 12 and gets the drawing back."""
    doc, (nx, ny) = _perforated(margin)
    text = _text(doc)
    assert _param(text, "holes_margin") == reading, text
    said = f"every margin over {lo:g} and up to {hi:g} mm keeps these holes"
    assert said in text and f"over {lo:g} and up to {hi:g} mm, each keeps" in text, text
    drawn = _holes(text, tmp_path, holes_margin=margin)
    assert len(drawn) == nx * ny and drawn == _holes(text, tmp_path), text
    got = _holes(text, tmp_path, holes_margin=20)       # refilled: 16 x 11 holes, centred
    assert len(got) == 16 * 11 and got[0][:2] == (25, 25), (got[0], text)
