"""Drawing to design, round five (issue 93): what an edit means, from the spec in
docs/import.md ("What an edit means"), on drawings made here with ezdxf and the compiled
DXF read back with ezdxf.  Corner slots of a motor plate about its bore keep their inset
from the corners (they were a 58 mm grid about the bore: a wider plate left them 21 mm in);
a rounded comb's notches are one pattern with a count and a pitch (they were seven literal
notches); a row of pots off the centre line changes pitch about its centre (it kept its
first pot); a board's holes move as one with their nearest corner, with place params; a
bolt circle's first-hole angle is a param.  Cost: 5 imports, about 12 compiles (6 s CPU)."""
from __future__ import annotations

import io
import math

import ezdxf
import ezdxf.bbox
import pytest

import aidl_lang
from aidl_lang.drawing.infer import import_drawing


def _doc(w: float, h: float, bulge: float = 0.0):
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (w, 0), (w, h), (0, h)], close=True)
    return doc, m


def _text(doc) -> str:
    s = io.StringIO()
    doc.write(s)
    text, _ = import_drawing(s.getvalue().encode(), "p.dxf", infer=True)
    return text


def _out(text: str, tmp_path, **edit):
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl", overrides=edit)
    assert res.ok, ([str(d) for d in res.errors], text)
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    return doc.modelspace()


def _circles(ms, r: float | None = None) -> list:
    return sorted((round(e.dxf.center.x, 9), round(e.dxf.center.y, 9)) for e in ms
                  if e.dxftype() == "CIRCLE" and (r is None or abs(e.dxf.radius - r) < 1e-9))


def _slot(m, c, L, w):
    x, y = c
    r = w / 2
    m.add_line((x - L / 2 + r, y - r), (x + L / 2 - r, y - r))
    m.add_arc((x + L / 2 - r, y), r, -90, 90)
    m.add_line((x + L / 2 - r, y + r), (x - L / 2 + r, y + r))
    m.add_arc((x - L / 2 + r, y), r, 90, 270)


def test_a_motor_plates_corner_slots_keep_their_inset(tmp_path):
    doc, m = _doc(70, 70)
    m.add_circle((35, 35), 11)
    for sx in (-1, 1):
        for sy in (-1, 1):
            m.add_circle((35 + sx * 15.5, 35 + sy * 15.5), 1.6)
            _slot(m, (35 + sx * 29, 35 + sy * 29), 8, 3.4)
    text = _text(doc)
    assert "param corner_inset = 6 mm" in text and "at the corners: read as" in text, text
    ms = _out(text, tmp_path, width=100)
    # each slot (a closed polyline 8 x 3.4 mm) centred 6 mm in from its corner
    boxes = []
    for e in ms:
        if e.dxftype() == "LWPOLYLINE":
            b = ezdxf.bbox.extents([e])
            if abs(b.size.x - 8) < 1e-6 and abs(b.size.y - 3.4) < 1e-6:
                boxes.append((round(b.center.x, 9), round(b.center.y, 9)))
    assert sorted(boxes) == [(6, 6), (6, 64), (94, 6), (94, 64)], (boxes, text)
    # the motor's holes stay about the bore, on the plate's centre
    assert _circles(ms, 1.6) == [(34.5, 19.5), (34.5, 50.5), (65.5, 19.5), (65.5, 50.5)]


def _comb(n: int, p: float, x0: float):
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    W, H, w, dep = 120, 40, 4, 15
    k = math.tan(math.pi / 8)       # a quarter circle's bulge
    pts = [(3, 0, 0), (W - 3, 0, k), (W, 3, 0), (W, H - 3, k), (W - 3, H, 0)]
    for i in reversed(range(n)):
        c = x0 + i * p
        pts += [(c + w / 2, H, 0), (c + w / 2, H - dep, 0), (c - w / 2, H - dep, 0), (c - w / 2, H, 0)]
    pts += [(3, H, k), (0, H - 3, 0), (0, 3, k)]
    m.add_lwpolyline(pts, format="xyb", close=True)
    return doc


@pytest.mark.parametrize("x0, anchor", [(24.0, "centre"), (8.0, "left end")])
def test_a_combs_notches_are_one_pattern_of_its_side(tmp_path, x0, anchor):
    text = _text(_comb(7, 12, x0))
    assert "param notches_n = 7" in text and "param notches_pitch = 12 mm" in text, text
    ms = _out(text, tmp_path, notches_n=5, notches_pitch=14)
    pts = [p for e in ms if e.dxftype() == "LWPOLYLINE" for p in e.get_points("xy")]
    bottoms = sorted({round(x, 6) for x, y in pts if abs(y - 25) < 1e-6})
    mids = [(a + b) / 2 for a, b in zip(bottoms[::2], bottoms[1::2])]
    # about the comb's centre (60), or from its first notch 8 mm from the left edge
    want = [60 + (i - 2) * 14 for i in range(5)] if anchor == "centre" else \
        [8 + i * 14 for i in range(5)]
    assert len(mids) == 5 and max(abs(a - b) for a, b in zip(mids, want)) < 1e-6, (mids, text)


def test_a_row_off_the_centre_line_changes_pitch_about_its_centre(tmp_path):
    doc, m = _doc(160, 60)
    for x in (30, 50, 70):                  # three pots about x = 50, 30 mm in: no set end
        m.add_circle((x, 30), 3.5)
    text = _text(doc)
    ms = _out(text, tmp_path, holes_pitch=25, width=200)
    assert _circles(ms) == [(25.0, 30.0), (50.0, 30.0), (75.0, 30.0)], text


def test_a_boards_holes_move_as_one_with_their_nearest_corner(tmp_path):
    doc, m = _doc(150, 160)
    uno = [(14.0, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5)]
    for x, y in uno:
        m.add_circle((80 + x, 10 + y), 1.6)
    text = _text(doc)
    assert "param holes_x = 3.9 mm" in text and "param holes_y = 17.6 mm" in text, text
    ms = _out(text, tmp_path, width=180, height=190)
    want = sorted((round(110 + x, 9), round(10 + y, 9)) for x, y in uno)
    assert max(math.dist(a, b) for a, b in zip(_circles(ms), want)) < 1e-9, text
    ms = _out(text, tmp_path, holes_x=10)           # the set's place, one param
    assert max(math.dist(a, (b[0] - 6.1, b[1])) for a, b in
               zip(_circles(ms), sorted((80 + x, 10 + y) for x, y in uno))) < 1e-9


def test_a_bolt_circles_first_hole_angle_is_a_param(tmp_path):
    doc, m = _doc(100, 100)
    for k in range(5):
        a = math.radians(20 + 72 * k)
        m.add_circle((50 + 30 * math.cos(a), 50 + 30 * math.sin(a)), 2.0)
    text = _text(doc)
    assert "param bolt_circle_angle = 20 deg" in text, text
    ms = _out(text, tmp_path, bolt_circle_angle="35 deg", bolt_circle_n=6)
    want = sorted((round(50 + 30 * math.cos(math.radians(35 + 60 * k)), 9),
                   round(50 + 30 * math.sin(math.radians(35 + 60 * k)), 9)) for k in range(6))
    assert max(math.dist(a, b) for a, b in zip(_circles(ms), want)) < 1e-9, text


def _corner_pattern(doc, m, W: float, H: float, inset: float, r: float) -> str:
    """Four holes of radius ``r`` ``inset`` in from the corners of a W x H plate added,
    the drawing inferred: its program, which holds them as one corner pattern."""
    for x in (inset, W - inset):
        for y in (inset, H - inset):
            m.add_circle((x, y), r)
    text = _text(doc)
    assert "CornerPattern(corner_holes, body, inset=corner_inset)" in text, text
    return text


def test_a_panels_mounting_holes_round_its_window_keep_their_corners(tmp_path):
    """Four holes 5 mm in from a panel's corners, about its centred display window: nearer
    their corners than the window's edge, so they are at the corners (the language's
    `CornerPattern`, the inset one param), not a grid about the window; a motor's holes
    that hug their bore stay about it (test_a_motor_plates_corner_slots_keep_their_inset)."""
    doc, m = _doc(120, 80)
    m.add_lwpolyline([(40, 25), (80, 25), (80, 55), (40, 55)], close=True)
    text = _corner_pattern(doc, m, 120, 80, 5, 1.6)
    ms = _out(text, tmp_path, width=150, corner_inset=6)
    assert _circles(ms) == [(6, 6), (6, 74), (144, 6), (144, 74)], text


def test_a_grilles_mounting_holes_the_size_of_its_holes_are_at_the_corners(tmp_path):
    """A hex grille of 5 mm holes and four 5 mm mounting holes 6 mm in from the corners: the
    grille one pattern, the four a corner pattern (they were four holes each on its own,
    each with its own size param: the inset no param)."""
    doc, m = _doc(100, 100)
    for j in range(-2, 3):
        for i in range(-3, 4):
            x, y = (i + (j % 2) / 2) * 8, j * 8 * math.sqrt(3) / 2
            if math.hypot(x, y) + 2.5 <= 20:
                m.add_circle((50 + x, 50 + y), 2.5)
    text = _corner_pattern(doc, m, 100, 100, 6, 2.5)
    ms = _out(text, tmp_path, corner_inset=8, width=120)
    assert [p for p in _circles(ms) if p[0] < 15 or p[0] > 105] == \
        [(8, 8), (8, 92), (112, 8), (112, 92)], text


def test_a_bolt_circle_beside_a_board_of_its_hole_size_is_its_own(tmp_path):
    """Five 4 mm holes evenly round a centre nothing marks, beside an Arduino's four 4 mm
    holes: a bolt circle (its count and angle params) and the board's set, not one listed
    set of nine (the count and the circle were no param)."""
    doc, m = _doc(160, 100)
    for k in range(5):
        a = math.radians(15 + 72 * k)
        m.add_circle((40 + 12 * math.cos(a), 50 + 12 * math.sin(a)), 2.0)
    for x, y in [(14.0, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5)]:
        m.add_circle((80 + x, 20 + y), 2.0)
    text = _text(doc)
    assert "param bolt_circle_n = 5" in text and "param bolt_circle_angle = 15 deg" in text, text
    ms = _out(text, tmp_path, bolt_circle_n=6)
    assert len(_circles(ms)) == 10, text
