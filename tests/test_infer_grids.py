"""Issue 85, "a grid is one grid however it is clipped; rows and grids placed by their centre or
their edge-anchored end": a hex grid clipped to a round field comes back from `aidl import
--infer` as one grid (its pitch, hole and field params), a staggered grid is placed by its
centre, a chamfered plate with a notch by a corner keeps its size params; each param, edited, gives the drawing of the design with that number (drawn again here
with ezdxf, compared curve by curve to 1e-6 mm)."""
from __future__ import annotations

import math
import re
import sys

import ezdxf
import pytest
from hypothesis import given, settings, strategies as st

import aidl_lang
from aidl_lang.drawing.infer import import_drawing
from conftest import ROOT

sys.path.insert(0, str(ROOT / "tests"))
import dxf_compare  # noqa: E402


def _doc(W: float, H: float):
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (W, 0), (W, H), (0, H)], close=True)
    return doc, m


def hex_in_circle(path, p: float, d: float, field: float, c=(40.0, 45.0), W=80.0, H=90.0) -> int:
    """A plate with the holes (diameter ``d``) of a hex lattice of pitch ``p`` about ``c``
    that lie whole in a round field of diameter ``field`` (a fan grille in a round cut-out:
    its rows are of many counts); returns the number of holes."""
    doc, m = _doc(W, H)
    dy, n = p * math.sqrt(3) / 2, 0
    for j in range(-20, 21):
        for i in range(-20, 21):
            x, y = (i + (j % 2) / 2) * p, j * dy
            if math.hypot(x, y) + d / 2 <= field / 2 + 1e-9:
                m.add_circle((c[0] + x, c[1] + y), d / 2)
                n += 1
    doc.saveas(path)
    return n


def hex_in_rect(path, p: float, d: float, fw: float, fh: float, c=(40.0, 45.0),
                shift: int = 0, W: float = 80.0, H: float = 90.0) -> int:
    """A plate with the holes (diameter ``d``) of a hex lattice of pitch ``p`` about ``c``
    (its middle row shifted half a pitch when ``shift``) that lie whole in a rectangular
    field ``fw`` x ``fh`` (a vent field); returns the number of holes."""
    doc, m = _doc(W, H)
    dy, n = p * math.sqrt(3) / 2, 0
    for j in range(-20, 21):
        for i in range(-20, 21):
            x, y = (i + (j + shift) % 2 / 2) * p, j * dy
            if abs(x) + d / 2 <= fw / 2 + 1e-9 and abs(y) + d / 2 <= fh / 2 + 1e-9:
                m.add_circle((c[0] + x, c[1] + y), d / 2)
                n += 1
    doc.saveas(path)
    return n


def stagger(path, p: float) -> None:
    """A plate 80 x 100 with a staggered grid about (40, 25) (its centre 25 mm up, not on the
    plate's centre line): at pitch 8, rows of 5, 4 and 5 holes 3 mm, the rows ``p sqrt(3) /
    2`` apart, the lattice's nodes in a field 40 x 24 (five pitches by three)."""
    hex_in_rect(path, p, 3.0, 40.0, 24.0, c=(40.0, 25.0), shift=1, H=100.0)


def _same(a, b) -> tuple:
    dxf_compare.TOL = 1e-6
    return dxf_compare.unmatched(dxf_compare.curves(a), dxf_compare.curves(b))


def _infer(tmp_path, src) -> str:
    text, _ = import_drawing(src.read_bytes(), src.name, infer=True)
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl")
    warned = [d for d in res.diagnostics if d.severity == "warning"]
    assert res.ok and not warned, (text, [str(d) for d in res.diagnostics])
    back = tmp_path / "back.dxf"
    back.write_text(res.to_dxf())
    assert _same(src, back) == ([], []), text
    return text


def _edited_is(tmp_path, text: str, param: str, value: str, want) -> None:
    res = aidl_lang.compile(text, path=tmp_path / "e.aidl", overrides={param: value})
    assert res.ok, [str(d) for d in res.errors]
    got = tmp_path / "got.dxf"
    got.write_text(res.to_dxf())
    left, extra = _same(want, got)
    assert not left and not extra, (text, len(left), len(extra), left[:2], extra[:2])


def test_a_hex_grid_in_a_round_field_is_one_grid(tmp_path):
    """31 holes of a hex lattice (pitch 8, holes 4 mm) inside a round field of 48 mm (rows
    of many counts): one grid with `holes_pitch`, `holes_d` and `holes_field_d` (six
    pitches across), not rows each of its own; a new pitch refills the same field (7 mm: 37
    holes), a new field likewise (60 mm: 43), a new hole size keeps the holes."""
    src = tmp_path / "hex.dxf"
    assert hex_in_circle(src, 8.0, 4.0, 48.0) == 31
    text = _infer(tmp_path, src)
    assert "param holes_pitch = 8 mm" in text and "param holes_field_d = 48 mm" in text, text
    assert len(re.findall(r"^param ", text, re.M)) == 5, text     # width, height, d, pitch, field
    for param, value, kw in (("holes_pitch", 7.0, {"p": 7.0}), ("holes_field_d", 60.0,
                             {"field": 60.0}), ("holes_d", 5.0, {"d": 5.0})):
        args = {"p": 8.0, "d": 4.0, "field": 48.0, **kw}
        want = tmp_path / f"want_{param}.dxf"
        n = hex_in_circle(want, **args)
        assert n != 31 or param == "holes_d"
        _edited_is(tmp_path, text, param, f"{value} mm", want)


@settings(max_examples=6, deadline=None)
@given(p=st.sampled_from([5.0, 6.0, 7.5, 8.0]), k=st.integers(4, 6),
       dp=st.sampled_from([-0.5, 0.5, 1.0]), cx=st.sampled_from([30.0, 40.0, 47.5]))
def test_a_round_hex_field_law(tmp_path_factory, p, k, dp, cx):
    """Law: any hex lattice of pitch ``p`` clipped to a round field ``k`` pitches across
    (holes 0.4 p) is inferred as one grid whose field is that diameter, and its pitch edited
    by ``dp`` gives the same field filled at the new pitch."""
    tmp = tmp_path_factory.mktemp("law")
    src = tmp / "h.dxf"
    hex_in_circle(src, p, 0.4 * p, k * p, c=(cx, 45.0))
    text = _infer(tmp, src)
    m = re.search(r"^param holes_field_d = ([\d.]+) mm", text, re.M)
    assert m and abs(float(m.group(1)) - k * p) < 1e-9, text
    want = tmp / "want.dxf"
    hex_in_circle(want, p + dp, 0.4 * p, k * p, c=(cx, 45.0))
    _edited_is(tmp, text, "holes_pitch", f"{p + dp} mm", want)


def chamfered_notched(path, W: float = 80.0, p: float = 12.0) -> None:
    """A plate W x 60 with 5 mm chamfers, a square notch 10 mm wide 6 mm up its right side
    (nearer the corner than two chamfer legs) and a row of three holes centred on it."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(5, 0), (W - 5, 0), (W, 5), (W, 6), (W - 10, 6), (W - 10, 16), (W, 16),
                      (W, 55), (W - 5, 60), (5, 60), (0, 55), (0, 5)], close=True)
    for i in range(3):
        m.add_circle((W / 2 + (i - 1) * p, 30), 2.0)
    doc.saveas(path)


def test_a_chamfered_plate_with_a_notch_by_a_corner_keeps_its_params(tmp_path):
    """The notch too near a corner for `Chamfer` (it cuts at most half a side): the plate is
    written corner by corner from `width`, `height` and `chamfer` (it was a chain of fixed
    lines, so its row had no body to be centred on), so a new width keeps the notch by the
    right edge and the row centred, and a new pitch keeps the row centred."""
    src = tmp_path / "c.dxf"
    chamfered_notched(src)
    text = _infer(tmp_path, src)
    assert "param width = 80 mm" in text and "param chamfer = 5 mm" in text, text
    want = tmp_path / "w.dxf"
    chamfered_notched(want, W=100.0)
    _edited_is(tmp_path, text, "width", "100 mm", want)
    chamfered_notched(want, p=15.0)
    _edited_is(tmp_path, text, "holes_pitch", "15 mm", want)


def grid_by_top(path, p: float, rows: int = 2) -> None:
    """A plate 90 x 50 with a 2-column grid (25 mm apart) centred across it whose top row is
    12 mm below the top edge (its middle 3 mm above the centre line, nearer it than its
    bottom row is to the bottom edge)."""
    doc, m = _doc(90.0, 50.0)
    for i in range(2):
        for j in range(rows):
            m.add_circle((45 + (i - 0.5) * 25, 38 - j * p), 2.25)
    doc.saveas(path)


@pytest.mark.parametrize("draw,param,old,new", [(stagger, "holes_pitch", 8.0, 10.0),
                                                  (grid_by_top, "holes_pitch_y", 20.0, 15.0)],
                         ids=["stagger", "grid-by-top"])
def test_a_grid_keeps_its_centre_or_its_end_by_the_edge(tmp_path, draw, param, old, new):
    """A staggered grid centred 25 mm up a 100 mm plate (rows of 5, 4, 5) keeps its centre
    when its pitch changes and refills its field (it was placed from its first row: its
    middle moved 0.87 mm per mm of pitch; then it kept its counts); a grid whose top row is 12 mm below the top edge, its middle 3 mm off the
    centre line (not symmetric about it, so not centred), keeps its top row (it was placed
    from its bottom, first, row)."""
    src = tmp_path / "g.dxf"
    draw(src, old)
    text = _infer(tmp_path, src)
    want = tmp_path / "want.dxf"
    draw(want, new)
    _edited_is(tmp_path, text, param, f"{new} mm", want)


def obround(path, length: float, width: float, angle: float = 30.0) -> None:
    """A plate 80 x 60 with an obround slot at (40, 30) turned ``angle`` degrees, each end cap
    drawn as two quarter arcs (as SVG writers split an arc of half a turn)."""
    doc, m = _doc(80.0, 60.0)
    a, r = math.radians(angle), width / 2
    u, v = (math.cos(a), math.sin(a)), (-math.sin(a), math.cos(a))
    half = length / 2 - r

    def at(s, t):
        return (40 + s * u[0] + t * v[0], 30 + s * u[1] + t * v[1])
    m.add_line(at(-half, -r), at(half, -r))
    m.add_line(at(half, r), at(-half, r))
    for s, start in ((half, -90.0), (-half, 90.0)):
        for k in range(2):
            a0 = angle + start + 90 * k
            m.add_arc(at(s, 0), r, a0, a0 + 90)
    doc.saveas(path)


def test_an_obround_at_any_angle_is_a_slot(tmp_path):
    """An obround turned 30 degrees, its caps drawn as quarter arcs: a `Slot` with
    `slot_length` and `slot_width` (it was a RoundedRectangle whose corner radius, half its
    width, had to be edited with the width to keep it a slot)."""
    src = tmp_path / "o.dxf"
    obround(src, 20.0, 4.0)
    text = _infer(tmp_path, src)
    assert "Slot(" in text and "param slot_width = 4 mm" in text, text
    want = tmp_path / "want.dxf"
    obround(want, 20.0, 6.0)
    _edited_is(tmp_path, text, "slot_width", "6 mm", want)
    obround(want, 24.0, 4.0)
    _edited_is(tmp_path, text, "slot_length", "24 mm", want)


def notch_at_chamfer(path, w: float = 15.0) -> None:
    """A plate 80 x 60 with 5 mm chamfers and a square notch ``w`` wide, 10 deep, in its top
    side from where the top-left chamfer ends (x = 5)."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(5, 0), (75, 0), (80, 5), (80, 55), (75, 60), (5 + w, 60), (5 + w, 50),
                      (5, 50), (5, 60), (0, 55), (0, 5)], close=True)
    doc.saveas(path)


def grille_and_grid(path, px: float = 10.0) -> None:
    """A plate 100 x 50 with a staggered grille (rows of 4, 3, 4, pitch 8, about (0, 10) from
    the plate's centre) and a 5 x 2 grid of pitches ``px`` and 8 near its bottom, about
    x = 65 (its right end 15 mm from the edge at ``px`` 10: one and a half pitches, no set
    end, so a new pitch keeps its middle: docs/import.md, "What an edit means"), all holes
    4.5 mm."""
    doc, m = _doc(100.0, 50.0)
    dy = 8 * math.sqrt(3) / 2
    for j in range(3):
        n = 4 - j % 2
        for i in range(n):
            m.add_circle((50 + (i - (n - 1) / 2) * 8, 35 + (j - 1) * dy), 2.25)
    for i in range(5):
        for j in range(2):
            m.add_circle((65 + (i - 2) * px, 5 + j * 8), 2.25)
    doc.saveas(path)


@pytest.mark.parametrize("draw,held,param,old,new", [
    (notch_at_chamfer, ("param notch_width = 15 mm", "param chamfer = 5 mm"), "notch_width",
     15.0, 18.0),
    (grille_and_grid, ("param holes_2_pitch_x = 10 mm", "param holes_pitch = 8 mm"),
     "holes_2_pitch_x", 10.0, 12.0)], ids=["notch-at-chamfer", "grille-and-grid"])
def test_a_feature_once_missed_comes_back_with_its_params(tmp_path, draw, held, param, old,
                                                           new):
    """A notch whose side starts where a chamfer ends (it was a chain of fixed lines, no
    param): the plate's eight corners from `width`, `height` and `chamfer`, the notch a hole
    with `notch_width`, which edited keeps its side by the chamfer.  A grille and a grid of
    one hole size (no one pattern for all 21; they were rows of each): each its own pattern,
    so the grid's pitch edited moves the grid only."""
    src = tmp_path / "f.dxf"
    draw(src, old)
    text = _infer(tmp_path, src)
    assert all(h in text for h in held), text
    want = tmp_path / "want.dxf"
    draw(want, new)
    _edited_is(tmp_path, text, param, f"{new} mm", want)


def test_a_hex_grid_in_a_rectangular_field_is_one_grid(tmp_path):
    """A vent field 40 x 32 cut with a hex lattice of pitch 10 (holes 2.5: rows of 4, 3 and
    4): one grid with `holes_pitch`, `holes_d`, `holes_field_width` and
    `holes_field_height` (it was a staggered grid of fixed counts: a new pitch kept 4-3-4
    holes and overran or left empty the field, and the field had no param); a new pitch
    refills the same field (9 mm: 5-4-5), a new field width likewise (50 mm: 5-6-5), a new
    hole size keeps the holes."""
    src = tmp_path / "vent.dxf"
    assert hex_in_rect(src, 10.0, 2.5, 40.0, 32.0) == 11
    text = _infer(tmp_path, src)
    assert "param holes_field_width = 40 mm" in text, text
    assert "param holes_pitch = 10 mm" in text and "holes_cols" not in text, text
    for param, value, kw in (("holes_pitch", 9.0, {"p": 9.0}), ("holes_field_width", 50.0,
                             {"fw": 50.0}), ("holes_d", 3.0, {"d": 3.0})):
        args = {"p": 10.0, "d": 2.5, "fw": 40.0, "fh": 20.0, **kw}
        want = tmp_path / f"want_{param}.dxf"
        n = hex_in_rect(want, **args)
        assert n != 11 or param == "holes_d"
        _edited_is(tmp_path, text, param, f"{value} mm", want)


def test_the_rosette_of_seven_is_a_round_field(tmp_path):
    """Seven holes, one and the six round it (rows of 2, 3, 2: a staggered grid too): a hex
    grid in a round field (a whole number of pitches, 24 mm at pitch 8), so that a new
    pitch refills the circle (5 mm: 19 holes) and `holes_field_d` has a param."""
    src = tmp_path / "r.dxf"
    assert hex_in_circle(src, 8.0, 4.0, 24.0) == 7
    text = _infer(tmp_path, src)
    assert "param holes_field_d = 24 mm" in text, text
    want = tmp_path / "want.dxf"
    assert hex_in_circle(want, 5.0, 4.0, 24.0) == 19
    _edited_is(tmp_path, text, "holes_pitch", "5 mm", want)


@settings(max_examples=6, deadline=None)
@given(p=st.sampled_from([6.0, 8.0, 10.0]), kw=st.integers(3, 6), kh=st.integers(2, 5),
       shift=st.integers(0, 1), dp=st.sampled_from([-1.0, -0.5, 1.0]))
def test_a_rectangular_hex_field_law(tmp_path_factory, p, kw, kh, shift, dp):
    """Law: a hex lattice of pitch ``p`` (holes 0.3 p) clipped to a field ``kw`` by ``kh``
    pitches (its middle row on the centre or shifted half a pitch; the fewest whole pitches
    that hold those holes) is inferred as one grid whose field is that size, and its pitch
    edited by ``dp`` gives the same field filled at the new pitch."""
    tmp = tmp_path_factory.mktemp("rlaw")
    src = tmp / "h.dxf"
    n = hex_in_rect(src, p, 0.3 * p, kw * p, kh * p, shift=shift, W=120.0, H=120.0,
                    c=(60.0, 60.0))
    if n <= 7:          # a row, or the rosette of seven (a round field: the test above)
        return
    # the field the drawing says: the fewest whole pitches each way that hold those holes
    # (a field a pitch narrower holding the same holes is not told apart by the drawing)
    for fw, fh in (((kw - 1) * p, kh * p), (kw * p, (kh - 1) * p)):
        if hex_in_rect(tmp / "x.dxf", p, 0.3 * p, fw, fh, shift=shift, W=120.0, H=120.0,
                       c=(60.0, 60.0)) == n:
            return
    text = _infer(tmp, src)
    if "holes_field_d" in text:     # holes a round field holds too (taken as round first)
        return
    got = {k: float(v) for k, v in
           re.findall(r"^param holes_field_(width|height) = ([\d.]+) mm", text, re.M)}
    assert got == {"width": kw * p, "height": kh * p}, text
    want = tmp / "want.dxf"
    hex_in_rect(want, p + dp, 0.3 * p, kw * p, kh * p, shift=shift, W=120.0, H=120.0,
                c=(60.0, 60.0))
    _edited_is(tmp, text, "holes_pitch", f"{p + dp} mm", want)


def row_and_pair(path, p: float = 15.0, n: int = 4) -> None:
    """A plate 100 x 60 with a row of ``n`` holes 4 mm, ``p`` apart along y = 45, its right
    end 15 mm from the right edge, and two more such holes side by side near the bottom-left
    corner (so the six are no one pattern and no two features: the rows among them)."""
    doc, m = _doc(100.0, 60.0)
    for i in range(n):
        m.add_circle((85 - i * p, 45.0), 2.0)
    for x in (10.0, 18.0):
        m.add_circle((x, 10.0), 2.0)
    doc.saveas(path)


@pytest.mark.parametrize("param,value,kw", [("holes_pitch", "12 mm", {"p": 12.0}),
                                            ("holes_n", "5", {"n": 5})], ids=["pitch", "count"])
def test_a_row_among_other_holes_keeps_its_end_by_the_edge(tmp_path, param, value, kw):
    """A row found among equal holes of no one pattern is placed by its end nearer an edge
    (its right end, 15 mm from the right), not by its first member (its left end, which a new
    pitch or count kept, so that the row's right end moved: 85 -> 76 mm at pitch 12)."""
    src = tmp_path / "r.dxf"
    row_and_pair(src)
    text = _infer(tmp_path, src)
    assert "param holes_pitch = 15 mm" in text and "param holes_n = 4" in text, text
    want = tmp_path / "want.dxf"
    row_and_pair(want, **kw)
    _edited_is(tmp_path, text, param, value, want)
