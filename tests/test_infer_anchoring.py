"""Issue 85, anchoring as the drawing means it: `aidl import --infer` writes a plate's body
so that its width and height params grow it from the point its drawing is drawn from (a
corner at the origin: that corner; the centre at the origin: the centre), and places every
feature (a round hole, a cut-out no primitive makes, a bore with a key) from the body's
centre line when it is on it, else from the nearer edge, so that a new width or height keeps
each feature where the drawing ties it; a label with the hole it names.

The law: a generated plate with generated features, drawn with ezdxf; its inferred program
compiled with a new width and height (``overrides``, as ``--set``) and written to DXF is the
drawing of the same design at the new size, exactly (1e-6 mm, no translation allowed), for
every feature kind and both origins."""
from __future__ import annotations

import io
import math
import re
import sys

import ezdxf
import pytest
from hypothesis import HealthCheck, given, reject, settings
from hypothesis import strategies as st

import aidl_lang
from aidl_lang.drawing.infer import import_drawing
from conftest import ROOT

sys.path.insert(0, str(ROOT / "tests"))
import dxf_compare  # noqa: E402


def _ref(v: float, size: float) -> tuple[int, float]:
    """The reference a coordinate is tied to: (-1 the low edge, 0 the centre, 1 the high
    edge, the offset from it); the centre line when on it, else the nearer edge (ties: the
    low one)."""
    side = 0 if abs(v - size / 2) <= 1e-6 else -1 if v <= size / 2 else 1
    return side, v - (size / 2 + side * size / 2)


def _moved(v: float, size: float, new: float) -> float:
    side, d = _ref(v, size)
    return new / 2 + side * new / 2 + d


ROW = (3, 9.0)          # a row of 3 holes 9 mm apart along x, its x the first hole's


def _moved_row(x: float, size: float, new: float) -> float:
    """A row's first x at the new size: centred when its middle is on the centre line, else
    kept by its end member nearer an edge (issue 85: "a row symmetric about the centre:
    centred"; never by its first member)."""
    n, pitch = ROW
    lo, hi = x, x + (n - 1) * pitch
    if abs((lo + hi) / 2 - size / 2) <= 1e-6:
        return _moved((lo + hi) / 2, size, new) - (hi - lo) / 2
    return lo if lo <= size - hi else new - (size - hi) - (hi - lo)


def draw(path, W: float, H: float, centred: bool, features: list) -> None:
    """A W x H plate (its lower-left corner at the origin, or its centre there) with
    ``features`` ``(kind, x, y)`` placed from its lower-left corner."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    ox, oy = (-W / 2, -H / 2) if centred else (0.0, 0.0)
    m.add_lwpolyline([(ox, oy), (ox + W, oy), (ox + W, oy + H), (ox, oy + H)], close=True)
    for kind, x, y in features:
        cx, cy = ox + x, oy + y
        if kind == "circle":
            m.add_circle((cx, cy), 2.5)
        elif kind == "row":
            for k in range(ROW[0]):
                m.add_circle((cx + k * ROW[1], cy), 1.5)
        elif kind == "dhole":           # a circle of radius 4 with a flat 3 mm right of centre
            a = math.degrees(math.acos(3 / 4))
            s = 4 * math.sin(math.radians(a))
            m.add_arc((cx, cy), 4, a, 360 - a)
            m.add_line((cx + 3, cy - s), (cx + 3, cy + s))
        elif kind == "keyhole":         # a bore of radius 4 with a 3 mm key down to -9 mm
            a = math.asin(1.5 / 4)
            c = 4 * math.cos(a)
            m.add_arc((cx, cy), 4, math.degrees(-math.pi / 2 + a), math.degrees(-math.pi / 2 - a) + 360)
            m.add_lwpolyline([(cx + 1.5, cy - c), (cx + 1.5, cy - 9), (cx - 1.5, cy - 9),
                              (cx - 1.5, cy - c)])
    doc.saveas(path)


def _meet(a, b) -> bool:
    """Whether features ``a`` and ``b`` ((kind, x, y)) may meet: a row reaches 18 mm along x,
    a keyhole's key 9 mm below its bore (a D-hole 16.5 mm under a keyhole overlapped it)."""
    reach = 12 + 18 * ("row" in (a[0], b[0])) + 6 * ("keyhole" in (a[0], b[0]))
    return math.hypot(a[1] - b[1], a[2] - b[2]) < reach


FEATURE = st.tuples(st.sampled_from(["circle", "dhole", "keyhole", "row"]),
                    st.floats(0.1, 0.9), st.floats(0.15, 0.85))


def _spread(features: list, W: float, H: float) -> list:
    """Features at those fractions of a third of the plate's width each (the k-th feature
    in the k-th third), kept 12 mm from the edges: none touches another or the edge."""
    third = W / 4
    return [(kind, round(k * third + 12 + fx * (third - 24), 1) if third > 26 else
             round(12 + fx * (W - 24 - (18 if kind == "row" else 0)), 1),
             round(12 + fy * (H - 24), 1))
            for k, (kind, fx, fy) in enumerate(features)]


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(W=st.integers(60, 160), H=st.integers(50, 120), dW=st.integers(-20, 40),
       dH=st.integers(-15, 30), centred=st.booleans(),
       features=st.lists(FEATURE, min_size=1, max_size=3, unique_by=lambda f: f[0]))
def test_law_a_new_plate_size_keeps_every_feature_where_the_drawing_ties_it(
        tmp_path, W, H, dW, dH, centred, features):
    placed = _spread(features, W, H)     # one of each kind (alike ones are a pattern)
    if any(_meet(a, b) for a in placed for b in placed if a is not b):
        reject()
    src = tmp_path / "p.dxf"
    draw(src, W, H, centred, placed)
    text, _ = import_drawing(src.read_bytes(), "p.dxf", infer=True)
    W2, H2 = W + dW, H + dH
    moved = [(k, (_moved_row if k == "row" else _moved)(x, W, W2), _moved(y, H, H2))
             for k, x, y in placed]
    if any(_meet(a, b) for a in moved for b in moved if a is not b) or \
            any(not 10 <= x <= W2 - 10 - 18 * (k == "row") or not 10 <= y <= H2 - 10
                for k, x, y in moved):
        reject()                         # features that meet, or leave the plate, at the new size
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl",
                            overrides={"width": f"{W2} mm", "height": f"{H2} mm"})
    assert res.ok, (text, [str(d) for d in res.errors])
    got = tmp_path / "got.dxf"
    got.write_text(res.to_dxf())
    want = tmp_path / "want.dxf"
    # the truth: each feature as far from its reference as drawn, the plate grown from its
    # origin (a corner at (0, 0), or its centre)
    draw(want, W2, H2, centred, moved)
    dxf_compare.TOL = 1e-6
    left, extra = dxf_compare.unmatched(dxf_compare.curves(want), dxf_compare.curves(got))
    assert not left and not extra, (text, left[:3], extra[:3])


def test_a_plate_drawn_from_its_corner_grows_from_it(tmp_path):
    """The body of a plate whose lower-left corner is at the origin is written from it
    (``center=(width / 2, height / 2)``); a keyhole 20 mm from the right edge stays 20 mm
    from it at 150 mm (it stayed at x = 100 before: 50 mm from the edge)."""
    src = tmp_path / "k.dxf"
    draw(src, 120, 60, False, [("keyhole", 100, 40), ("dhole", 15, 15)])
    text, _ = import_drawing(src.read_bytes(), "k.dxf", infer=True)
    assert "body = Rectangle(center=(width / 2, height / 2), width=width, height=height)" \
        in text, text
    # the bore with its key is a keyway (tests/test_infer_bores.py), its centre by the
    # nearer (right, top) edges
    assert "c = (width - 20, height - 20)" in text and "param keyway_w = 3 mm" in text, text
    res = aidl_lang.compile(text, path=tmp_path / "k.aidl", overrides={"width": "150 mm"})
    assert res.ok and res.freedom()["dof"] == 0
    (part,) = res.parts
    assert part.bbox == pytest.approx((0, 0, 150, 60), abs=1e-9)



def test_a_row_by_the_right_edge_keeps_its_right_hole_when_its_pitch_changes(tmp_path):
    """Three holes 9 mm apart, the last 10 mm from the right edge of a 120 mm plate: the row
    is written from that hole (``width - holes_x + (i - (holes_n - 1)) * holes_pitch``, its
    10 mm from the edge a param since issue 114), so a
    pitch of 12 keeps it 10 mm from the edge and moves the others (before: from the first
    hole, the last one ended 16 mm from the edge)."""
    src = tmp_path / "r.dxf"
    draw(src, 120, 60, False, [("row", 92, 30)])
    text, _ = import_drawing(src.read_bytes(), "r.dxf", infer=True)
    assert "width - holes_x + (i - (holes_n - 1)) * holes_pitch" in text, text
    assert "param holes_x = 10 mm  # its end member, from the right edge" in text, text
    res = aidl_lang.compile(text, path=tmp_path / "r.aidl", overrides={"holes_pitch": "12 mm",
                                                                       "width": "140 mm"})
    assert res.ok
    got = tmp_path / "got.dxf"
    got.write_text(res.to_dxf())
    circles = sorted(c[1][0][0] for c in dxf_compare.curves(got) if c[0] == "C")
    assert circles == pytest.approx([106, 118, 130], abs=1e-9)


def test_labels_on_their_own_layer_move_with_the_hole_they_name(tmp_path):
    """A plate on OUTLINE, a hole 15 mm from its right edge and its label "PWR" 8 mm above it
    on LABELS (a drawing of its own beside the part): at 150 mm wide the label is still
    8 mm above the hole (it stayed at x = 105 before)."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (120, 0), (120, 60), (0, 60)], close=True,
                     dxfattribs={"layer": "OUTLINE"})
    m.add_circle((105, 20), 3, dxfattribs={"layer": "OUTLINE"})
    m.add_text("PWR", height=3, dxfattribs={"layer": "LABELS", "insert": (105, 28)})
    doc.saveas(tmp_path / "l.dxf")
    text, _ = import_drawing((tmp_path / "l.dxf").read_bytes(), "l.dxf", infer=True)
    assert 'Text("PWR", position=(width - 15, 28)' in text, text
    res = aidl_lang.compile(text, path=tmp_path / "l.aidl", overrides={"width": "150 mm"})
    assert res.ok


def _plate(path, W: float, H: float, circles=(), texts=(), dholes=(), rects=()) -> None:
    """A W x H plate from (0, 0) with ``circles`` ``(x, y, d)``, centred TEXT ``texts``
    ``(word, x, y, height)``, D-holes ``(x, y)`` (radius 5, a flat 3.5 right of centre) and
    rectangular cut-outs ``rects`` ``(x0, y0, x1, y1)``."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (W, 0), (W, H), (0, H)], close=True)
    for x0, y0, x1, y1 in rects:
        m.add_lwpolyline([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], close=True)
    for x, y, d in circles:
        m.add_circle((x, y), d / 2)
    for x, y in dholes:
        a = math.degrees(math.acos(3.5 / 5))
        s = 5 * math.sin(math.radians(a))
        m.add_arc((x, y), 5, a, 360 - a)
        m.add_line((x + 3.5, y - s), (x + 3.5, y + s))
    for word, x, y, h in texts:
        m.add_text(word, height=h).set_placement(
            (x, y), align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER)
    doc.saveas(path)


def _edited(tmp_path, src, overrides: dict):
    """``(program, circle centres, arc centres, how far the engraved text moved (dx, dy))``
    of ``src`` inferred and compiled with ``overrides``, read back by ezdxf; the text's
    move is its strokes' box against the program compiled as drawn."""
    text, _ = import_drawing(src.read_bytes(), src.name, infer=True)

    def out(ov):
        res = aidl_lang.compile(text, path=tmp_path / "e.aidl", overrides=ov)
        assert res.ok, (text, [str(d) for d in res.errors])
        return ezdxf.read(io.StringIO(res.to_dxf())).modelspace()

    def points(e) -> list:
        if e.dxftype() == "LWPOLYLINE":
            return list(e.get_points("xy"))
        if e.dxftype() == "LINE":
            return [(e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y)]
        return []

    def box(msp):
        pts = [v for e in msp if e.dxf.layer == "ENGRAVE" for v in points(e)]
        return min(p[0] for p in pts), min(p[1] for p in pts)
    msp = out(overrides)
    cut = [e for e in msp if e.dxf.layer != "ENGRAVE"]
    circles = sorted((round(e.dxf.center.x, 6), round(e.dxf.center.y, 6))
                     for e in cut if e.dxftype() == "CIRCLE")
    arcs = sorted({(round(e.dxf.center.x, 6), round(e.dxf.center.y, 6))
                   for e in cut if e.dxftype() == "ARC"})
    moved = None
    if any(e.dxf.layer == "ENGRAVE" for e in msp):
        (x1, y1), (x0, y0) = box(msp), box(out({}))
        moved = (x1 - x0, y1 - y0)
    return text, circles, arcs, moved


def test_a_hole_off_the_centre_line_stays_by_its_nearer_edge(tmp_path):
    """A hole 40 mm from the left edge of a 100 mm plate (10 mm left of the centre line) is
    dimensioned from that edge, only a hole on the centre line from the centre: at 140 mm
    wide the first stays 40 mm from the left edge (before: 10 mm left of the new centre,
    at 60) and the second follows the centre to 70."""
    src = tmp_path / "c.dxf"
    _plate(src, 100, 60, circles=[(40, 15, 5), (50, 45, 4)])
    text, circles, _, _ = _edited(tmp_path, src, {"width": "140 mm"})
    assert circles == [(40, 15), (70, 45)], text


LABELS = {
    # "PWR" 22.5 mm under a hole (more than five of its 3 mm heights, nearer the bottom edge
    # than the hole's centre) is in line with it: it names it, and at 120 mm high both move
    # up together (before: the text stayed 17.5 mm from the bottom edge)
    "right under its hole": ((100, 80), {"circles": [(15, 40, 8)], "texts": [("PWR", 15, 17.5, 3)]},
                             {"height": "120 mm"}, [(15, 60)], (0, 20)),
    # a D-hole's bore on the centre line (its box's middle is not: the flat cuts it) and its
    # label 15 mm under it: at 200 mm wide both stay on the centre line (the label moves 20)
    "under a D-hole's bore": ((160, 80), {"dholes": [(80, 40)], "texts": [("12V", 80, 25, 5)]},
                              {"width": "200 mm"}, [], (20, 0)),
    # a title centred on the plate with a hole 8 mm right of it: the hole is by the right
    # edge, the title stays on the centre line at 80 mm wide (moves 10, not 20)
    "a title on the centre line": ((60, 100), {"circles": [(38, 56, 5)],
                                               "texts": [("M3", 30, 50, 4)]},
                                   {"width": "80 mm"}, [(58, 56)], (10, 0)),
    # "IN" 10 mm from the left edge and 12 mm from a centred hole, in line with none: the
    # plate's label, it stays 10 mm from the left edge at 50 mm wide (before: it moved 5
    # with the hole)
    "off the lines of a hole": ((40, 50), {"circles": [(20, 8, 8)],
                                           "texts": [("IN", 10, 15, 3)]},
                                {"width": "50 mm"}, [(25, 8)], (0, 0)),
    # "FAN" 35 mm under a hole 20 mm from the top (33 mm from its edge, past 25 mm) but 45 mm
    # from the bottom edge behind it: nearer the hole than that edge, it names the hole and
    # moves up 20 with it at 120 mm high (before: it stayed 45 mm from the bottom edge)
    "nearer its hole than the edge behind it": (
        (100, 100), {"circles": [(80, 80, 4)], "texts": [("FAN", 80, 45, 3)]},
        {"height": "120 mm"}, [(80, 100)], (0, 20)),
    # "IN" 20 mm from the top, in line with a hole 40 mm under it (38 mm from its edge, more
    # than 25 mm and than the 20 mm to the top edge): the plate's label, it stays 20 mm from
    # the top (moves 20 at 120 mm high) while the hole, 40 mm from the bottom, stays
    "nearer the edge behind it than its hole": (
        (100, 100), {"circles": [(30, 40, 4)], "texts": [("IN", 30, 80, 3)]},
        {"height": "120 mm"}, [(30, 40)], (0, 20)),
}


@pytest.mark.parametrize("case", LABELS, ids=list(LABELS))
def test_a_label_moves_with_the_hole_it_is_in_line_with(tmp_path, case):
    """A text in line with a hole (above, below or beside it, within 25 mm of its edge)
    names it and moves with it when the plate grows; one on the plate's centre line stays
    on it; one in line with no hole is placed from the plate's centre line or nearer edge."""
    (W, H), drawn, overrides, want, move = LABELS[case]
    src = tmp_path / "l.dxf"
    _plate(src, W, H, **drawn)
    text, circles, _, moved = _edited(tmp_path, src, overrides)
    assert circles == want, text
    assert moved == pytest.approx(move, abs=1e-9), text


def test_a_label_on_the_line_through_an_arc_slots_centre_but_off_the_slot_names_nothing(
        tmp_path):
    """An arc slot 4 mm wide about (50, 10) at radius 30, from 45 to 135 deg, on a 100 x 60
    plate: "IN" at (20, 10) is on the horizontal line through its centre, but that line
    misses the slot (it runs from y = 29 up): the text names nothing and stays 20 mm from
    the left edge at 140 mm wide while the slot follows the centre line (before: the text
    followed the slot's centre, moving 20)."""
    src = tmp_path / "a.dxf"
    _plate(src, 100, 60, texts=[("IN", 20, 10, 3)])
    doc = ezdxf.readfile(src)
    m = doc.modelspace()
    c, R, w = (50, 10), 30, 4
    m.add_arc(c, R + w / 2, 45, 135)
    m.add_arc(c, R - w / 2, 45, 135)
    for a, (s0, s1) in ((45, (225, 45)), (135, (135, 315))):
        end = (c[0] + R * math.cos(math.radians(a)), c[1] + R * math.sin(math.radians(a)))
        m.add_arc(end, w / 2, s0, s1)
    doc.saveas(src)
    text, _, arcs, moved = _edited(tmp_path, src, {"width": "140 mm"})
    assert "ArcSlot(center=(width / 2, 10)" in text, text
    assert moved == pytest.approx((0, 0), abs=1e-9), text


def test_a_label_under_a_cut_out_moves_with_its_centre_when_its_width_changes(tmp_path):
    """A 22 x 10 mm cut-out 6 mm from the right edge of a 100 x 60 plate, "PWR" centred 15 mm
    under it: at window_width 30 the cut-out grows away from the edge it is dimensioned
    from (its centre moves 4 mm left) and its label moves with it (before: it stayed)."""
    src = tmp_path / "w.dxf"
    _plate(src, 100, 60, rects=[(72, 30, 94, 40)], texts=[("PWR", 83, 20, 3)])
    text, _, _, moved = _edited(tmp_path, src, {"window_width": "30 mm"})
    assert "window_width" in text, text
    assert moved == pytest.approx((-4, 0), abs=1e-9), text


def test_a_label_names_the_hole_of_its_own_size_before_a_pattern_member_in_line(tmp_path):
    """A centred cut-out's label 18 mm under it, in line with a column of a grid of holes
    nearer it: the label names the hole of its own (the grid's members are a pattern), so
    at 100 mm high it stays 18 mm under the cut-out, y = 32."""
    src = tmp_path / "g.dxf"
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (60, 0), (60, 80), (0, 80)], close=True)
    m.add_lwpolyline([(19, 35), (41, 35), (41, 45), (19, 45)], close=True)
    for i in range(4):
        for j in range(3):
            m.add_circle((20 + 10 * i, 8 + 10 * j), 1.25)
    m.add_text("IN", height=3).set_placement(
        (30, 22), align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER)
    doc.saveas(src)
    text, _, _, moved = _edited(tmp_path, src, {"height": "100 mm"})
    assert moved == pytest.approx((0, 10), abs=1e-9), text


def test_a_boards_holes_listed_together_move_as_one(tmp_path):
    """An Arduino's four holes (one size, no pattern) on a 100 mm plate, their middle 5.7 mm
    right of the centre line: placed together by the reference nearest that middle, the
    centre, so at 120 mm wide all four move 10 mm, the board's shape kept."""
    holes = [(29.68, 10.87), (30.95, 59.13), (81.75, 15.95), (81.75, 43.89)]
    src = tmp_path / "a.dxf"
    _plate(src, 100, 70, circles=[(x, y, 3.2) for x, y in holes])
    text, circles, _, _ = _edited(tmp_path, src, {"width": "120 mm"})
    assert circles == sorted((round(x + 10, 6), y) for x, y in holes), text


def test_two_equal_holes_on_a_slant_are_each_placed_from_their_own_reference(tmp_path):
    """Two 10 mm holes of a 120 x 70 plate, one on its centre, one 8 mm from its left and top
    edges: on a slant, they are no row (no one dimensions a pitch along the diagonal of
    two): each is placed from its own reference, one size param for both (a bracket's
    screws), so at 140 mm wide the first follows the centre to x = 70 and the second stays
    8 mm from the left edge (before: a row of two from the corner hole, the centre one left
    at x = 60)."""
    src = tmp_path / "p.dxf"
    _plate(src, 120, 70, circles=[(60, 35, 10), (8, 62, 10)])
    text, circles, _, _ = _edited(tmp_path, src, {"width": "140 mm"})
    assert circles == [(8, 62), (70, 35)], text
    _, circles, _, _ = _edited(tmp_path, src, {"height": "90 mm"})
    assert circles == [(8, 82), (60, 45)], text
    assert re.findall(r"^param (\w+) = 10 mm", text, re.M) == ["holes_d"], text


def test_two_holes_left_beside_a_row_of_their_size_stay_by_their_corners(tmp_path):
    """A row of three 5 mm holes 10 mm apart by the upper right corner of a 150 x 100 plate
    and two more 5 mm holes 8 mm into its lower left and upper right corners (one group:
    the upper right one is as near the row as its pitch): the row is a row, the two left
    over are each placed from their own corner, so at 200 mm wide the lower left one stays
    at x = 8 and the upper right one moves 50 with its edge (before: listed together,
    placed by the centre nearest their middle, both moved 25)."""
    src = tmp_path / "r.dxf"
    row = [(125 + 10 * i, 80, 5) for i in range(3)]
    _plate(src, 150, 100, circles=row + [(8, 8, 5), (140, 92, 5)])
    text, circles, _, _ = _edited(tmp_path, src, {"width": "200 mm"})
    assert (8, 8) in circles and (190, 92) in circles, text


def test_a_hole_beside_a_row_of_its_size_has_its_own_size(tmp_path):
    """A column of five 6 mm holes 10 mm apart 20 mm from the left edge of a 50 x 120 plate
    and one more 6 mm hole 12 mm from that edge on the centre line (one group: it is as
    near the column as its pitch): the column is a row, the hole beside it a feature of its
    own, so its new diameter (4 mm) leaves the column's five (before: one `hole_d` for
    all six)."""
    src = tmp_path / "c.dxf"
    _plate(src, 50, 120, circles=[(20, 40 + 10 * i, 6) for i in range(5)] + [(12, 60, 6)])
    text, _ = import_drawing(src.read_bytes(), src.name, infer=True)
    own = re.findall(r"^param (hole\d+_d) = 6 mm", text, re.M)
    assert len(own) == 1, text
    res = aidl_lang.compile(text, path=tmp_path / "e.aidl", overrides={own[0]: "4 mm"})
    assert res.ok, [str(d) for d in res.errors]
    circles = sorted((round(e.dxf.center.x, 6), round(e.dxf.center.y, 6), round(e.dxf.radius, 6))
                     for e in ezdxf.read(io.StringIO(res.to_dxf())).modelspace()
                     if e.dxftype() == "CIRCLE")
    assert circles == [(12, 60, 2)] + [(20, 40 + 10 * i, 3) for i in range(5)], text


def test_a_slanted_pair_beside_a_grid_has_a_size_param_named_for_its_diameter(tmp_path):
    """A 2 x 2 grid of 4 mm holes and a slanted pair of 3 mm holes: the pair's size param is
    `holes_2_d` (`holes` is the grid's), a name ending in `_d` as every diameter's (before:
    `holes_d_2`), and setting it changes the pair's two holes only."""
    src = tmp_path / "s.dxf"
    grid = [(10 + 10 * i, 10 + 10 * j, 4) for i in range(2) for j in range(2)]
    _plate(src, 100, 60, circles=grid + [(60, 10, 3), (90, 50, 3)])
    text, _ = import_drawing(src.read_bytes(), src.name, infer=True)
    assert re.findall(r"^param (\w+) = 3 mm", text, re.M) == ["holes_2_d"], text
    res = aidl_lang.compile(text, path=tmp_path / "e.aidl", overrides={"holes_2_d": "5 mm"})
    assert res.ok, [str(d) for d in res.errors]
    radii = sorted(round(e.dxf.radius, 6) for e in ezdxf.read(io.StringIO(res.to_dxf()))
                   .modelspace() if e.dxftype() == "CIRCLE")
    assert radii == [2] * 4 + [2.5] * 2, text
