"""Drawing to design, round six (issue 103): drawings that are not perfectly regular, as
makers' files are, keep the spec's relations (docs/import.md, "What an edit means").  The
drawings are made here with ezdxf (not from the inference's rules); each edit is compiled
through the real compiler and its DXF read back with ezdxf, the hole centres compared with
the edited part's, numerically.  A corner plate with one odd hole (4.4 among 4 mm) keeps its
holes at the corners (they were three "board" holes from the centre and one from its
corner); a 4 x 3 grid with one hole missing keeps its 30 mm pitch about the centre (it was
a grid, a row and a 4-hole set); a row whose holes CAD rounded up to 0.05 mm off the pitch
stays one row, exact.  Cost: a few imports and about ten compiles (seconds)."""
from __future__ import annotations

import dataclasses
import io
import math

import ezdxf
from ezdxf import bbox
import pytest

import aidl_lang
from test_infer_round5 import _doc, _text  # a plate drawn with ezdxf; its import (--infer)
from aidl_lang.drawing.infer import import_drawing


def _holes(text: str, tmp_path, **edit) -> list:
    """``(x, y, diameter)`` of every circle of the compiled program, read back by ezdxf."""
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl", overrides=edit)
    assert res.ok, ([str(d) for d in res.errors], text)
    ms = ezdxf.read(io.StringIO(res.to_dxf())).modelspace()
    return sorted((round(e.dxf.center.x, 9) + 0.0, round(e.dxf.center.y, 9) + 0.0,
                   round(2 * e.dxf.radius, 9)) for e in ms if e.dxftype() == "CIRCLE")


def _corner_plate(odd):
    doc, m = _doc(160, 100)
    for x in (10, 150):
        for y in (10, 90):
            m.add_circle((x, y), 2.2 if (x, y) == odd else 2.0)
    return doc


@pytest.mark.parametrize("odd", [(150, 90), (10, 10)])
def test_a_corner_plate_with_one_odd_hole_keeps_its_corners(tmp_path, odd):
    text = _text(_corner_plate(odd))
    assert "in no pattern" not in text and "corner_inset = 10 mm" in text, text
    got = _holes(text, tmp_path, width=200)
    want = sorted((x if x == 10 else 190, y, 4.4 if (x, y) == odd else 4.0)
                  for x in (10, 150) for y in (10, 90))
    assert got == want, (got, text)
    # the inset moves all four, the odd one keeps its own size; its size is one param
    got = _holes(text, tmp_path, corner_inset=15, corner_holes_odd_d=5)
    moved = (15 if odd[0] == 10 else 145, 15 if odd[1] == 10 else 85)
    want = sorted((x, y, 5.0 if (x, y) == moved else 4.0) for x in (15, 145) for y in (15, 85))
    assert got == want, (got, text)


def _gapped_grid(missing):
    doc, m = _doc(160, 100)
    for i, x in enumerate((35, 65, 95, 125)):
        for j, y in enumerate((20, 50, 80)):
            if (i, j) not in missing:
                m.add_circle((x, y), 2.5)
    return doc


@pytest.mark.parametrize("missing", [[(2, 1)], [(0, 0)], [(1, 2), (3, 0)]])
def test_a_grid_with_holes_missing_keeps_its_columns(tmp_path, missing):
    text = _text(_gapped_grid(missing))
    assert "param holes_pitch = 30 mm" in text and "left out, as drawn" in text, text
    got = _holes(text, tmp_path, width=200)
    want = sorted((x, y, 5.0) for i, x in enumerate((55, 85, 115, 145))
                  for j, y in enumerate((20, 50, 80)) if (i, j) not in missing)
    assert got == want, (got, text)
    # a new pitch spreads it about the plate's centre, the gaps where they were
    got = _holes(text, tmp_path, holes_pitch=25)
    want = sorted((80 + (i - 1.5) * 25, 50 + (j - 1) * 25, 5.0) for i in range(4)
                  for j in range(3) if (i, j) not in missing)
    assert got == want, (got, text)


def test_a_row_missing_a_hole_is_one_row_with_a_gap(tmp_path):
    doc, m = _doc(120, 40)
    for x in (10, 20, 30, 50, 60):          # 10 mm in on a 10 mm pitch, 40 left out
        m.add_circle((x, 20), 1.5)
    text = _text(doc)
    assert "param holes_n = 6" in text and "if not (i == 3)" in text, text
    # its end member 10 mm in from the left edge stays (nearer it than 1.5 pitches)
    got = _holes(text, tmp_path, holes_pitch=12, width=150)
    assert [g[0] for g in got] == [10, 22, 34, 58, 70], (got, text)


def test_a_row_cad_rounded_off_its_pitch_stays_one_row_exactly(tmp_path):
    doc, m = _doc(120, 40)
    pitch = 25.4 / 3                        # six pots a third of an inch apart,
    xs = [round(30 + k * pitch, 1) for k in range(6)]   # written to 0.1 mm by the CAD
    for x in xs:
        m.add_circle((x, 20), 3.5)
    text = _text(doc)
    assert "param holes_n = 6" in text and "(CAD rounding)" in text, text
    # as drawn, to 1e-9 mm: each hole's offset off the pitch kept
    assert _holes(text, tmp_path) == [(x, 20.0, 7.0) for x in xs], text
    # a new pitch spreads the row about its middle, placed from the left edge (30 mm in:
    # more than one and a half pitches); each hole within CAD rounding of the edited part's
    got = _holes(text, tmp_path, holes_pitch=10, width=150)
    mid = 30 + 2.5 * pitch
    want = [mid + (k - 2.5) * 10 for k in range(6)]
    assert max(abs(g[0] - w) for g, w in zip(got, want)) <= 0.05, (got, text)
    assert [g[1] for g in got] == [20.0] * 6, got


def test_an_odd_corner_hole_beside_a_grid_of_the_corner_holes_size(tmp_path):
    """Three corner holes of 3 mm, the fourth 3.3 mm, and a 3 x 2 grid of 3 mm holes: the
    corner holes are one corner pattern (its odd member its own size), the grid its own."""
    doc, m = _doc(150, 60)
    for x in (5, 145):
        for y in (5, 55):
            m.add_circle((x, y), 1.65 if (x, y) == (5, 5) else 1.5)
    for x in (63, 75, 87):
        for y in (24, 36):
            m.add_circle((x, y), 1.5)
    text = _text(doc)
    assert "corner_inset = 5 mm" in text and "holes_cols = 3" in text, text
    got = _holes(text, tmp_path, width=170, corner_inset=6)
    want = sorted([(6.0, 6.0, 3.3), (6.0, 54.0, 3.0), (164.0, 6.0, 3.0), (164.0, 54.0, 3.0)] +
                  [(x + 10.0, y, 3.0) for x in (63, 75, 87) for y in (24, 36)])
    assert got == want, (got, text)


def _fan(p: float, d: float, field: float, c=(40.0, 40.0)) -> list:
    """The holes of a square-set grille clipped to a round field (mm), as the edited part's
    drawing has them: every node ``p`` apart about ``c`` whose hole lies whole in it."""
    k = int(field / p) + 2
    return sorted((round(c[0] + i * p, 9) + 0.0, round(c[1] + j * p, 9) + 0.0, d)
                  for i in range(-k, k + 1) for j in range(-k, k + 1)
                  if math.hypot(i * p, j * p) + d / 2 <= field / 2 + 1e-9)


def test_a_fan_grilles_square_set_holes_in_a_round_field_have_a_field_param(tmp_path):
    doc, m = _doc(80, 80)
    for x, y, _ in _fan(6, 4, 60):
        m.add_circle((x, y), 2)
    text = _text(doc)
    assert "param holes_field_d = 60 mm" in text and "if not" not in text, text
    assert _holes(text, tmp_path) == _fan(6, 4, 60), text
    # a smaller field, a new pitch, on a wider plate: refilled about the plate's centre
    assert _holes(text, tmp_path, holes_field_d=48) == _fan(6, 4, 48), text
    assert _holes(text, tmp_path, holes_pitch=7, width=100) == _fan(7, 4, 60, (50, 40)), text


def test_two_parts_side_by_side_keep_their_gap(tmp_path):
    """Two plates drawn side by side in one file, 10 mm apart: the second is placed from
    the first's right edge by a gap param and grows from its edge nearer the first, so a
    wider first plate moves it along, a wider second one grows away, a new gap moves it."""
    doc, m = _doc(60, 40)
    m.add_lwpolyline([(70, 0), (120, 0), (120, 40), (70, 40)], close=True)
    for x in (5, 55):
        for y in (5, 35):
            m.add_circle((x, y), 1.6)
    m.add_circle((95, 20), 4)
    text = _text(doc)
    assert "param l_02_gap = 10 mm" in text, text
    for edit, bore in (({}, 95.0), ({"l_01_width": 80}, 115.0), ({"l_02_width": 70}, 105.0),
                       ({"l_02_gap": 5}, 90.0)):
        got = _holes(text, tmp_path, **edit)
        corners = [(5.0, 5.0), (5.0, 35.0)] + [(5.0 + edit.get("l_01_width", 60) - 10, y)
                                               for y in (5.0, 35.0)]
        assert [g[:2] for g in got] == sorted(corners + [(bore, 20.0)]), (edit, got, text)


def test_an_inch_row_cad_rounded_keeps_its_pitch_in_inches(tmp_path):
    """An inch drawing ($INSUNITS 1) of a row on a 0.4 in pitch, its holes written to the
    thousandth a little off it: one row, its pitch 0.4 in (the 0.05 mm tolerance taken in
    inches, not 0.05 in), drawn exactly; a new pitch keeps each hole's offset."""
    doc = ezdxf.new("R2010")
    doc.units = 1
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (3, 0), (3, 1), (0, 1)], close=True)
    off = [0.001, -0.001, 0.0, 0.0015]
    for k, o in enumerate(off):
        m.add_circle((0.9 + k * 0.4 + o, 0.5), 0.1)
    text = _text(doc)
    assert "units in" in text and "param holes_pitch = 0.4 in" in text, text
    got = _holes(text, tmp_path)
    want = [round((0.9 + k * 0.4 + o) * 25.4, 9) for k, o in enumerate(off)]
    assert [g[0] for g in got] == want, (got, text)
    got = _holes(text, tmp_path, holes_pitch="0.5 in")
    mid = 0.9 + 1.5 * 0.4                   # about its middle (0.9 in: past 1.5 pitches)
    want = [(mid + (k - 1.5) * 0.5 + o) * 25.4 for k, o in enumerate(off)]
    assert max(abs(g[0] - w) for g, w in zip(got, want)) < 1e-6, (got, text)


def _motor_text() -> str:
    from maker_drawings import motor_plate     # the outline a polyline with rounded corners
    text, _ = import_drawing(motor_plate(), "m.dxf", infer=True)
    return text


def _motor_holes(w, h, spacing=31.0, edge_in=12.0) -> list:
    """The motor plate's circles as the maker dimensioned them: from the right and top."""
    c = (w - 40.0, h - 40.0)
    out = [(c[0], c[1], 22.0)] + [(c[0] + sx * spacing / 2, c[1] + sy * spacing / 2, 3.4)
                                  for sx in (-1, 1) for sy in (-1, 1)]
    out += [(w - 10.0, y, 3.4) for y in (edge_in, h - edge_in)]
    return sorted((round(x, 9) + 0.0, round(y, 9) + 0.0, d) for x, y, d in out)


def test_a_motor_plate_keeps_its_features_at_the_far_edges(tmp_path):
    """A motor mount drawn from its lower left corner whose motor and holes are dimensioned
    from the right and top edges, two holes of the motor holes' size by the right edge, two
    slots (lines and arcs) 20 mm from the top and bottom: a wider or taller plate keeps each
    at its distance from its own edge (the slots were spread about the centre line; the two
    holes were single holes and the motor's four a grid off its bore)."""
    text = _motor_text()
    assert "far right and top edges" in text and "slots_inset = 20 mm" in text, text
    assert "holes_inset = 12 mm" in text and "bore_c = (width - bore_x, height - bore_y)" \
        in text and "param bore_x = 40 mm" in text, text      # (its distances params: issue 114)
    assert _holes(text, tmp_path) == _motor_holes(160, 100), text
    assert _holes(text, tmp_path, width=190, height=120) == _motor_holes(190, 120), text
    got = _holes(text, tmp_path, motor_holes_pitch=26, holes_inset=15)
    assert got == _motor_holes(160, 100, 26, 15), (got, text)
    res = aidl_lang.compile(text, path=tmp_path / "m.aidl", overrides={"height": 120})
    ms = ezdxf.read(io.StringIO(res.to_dxf())).modelspace()
    boxes = [bbox.extents([e]) for e in ms if e.dxftype() != "CIRCLE"]
    ys = sorted((round(b.extmin.y, 9), round(b.extmax.y, 9)) for b in boxes
                if abs(b.extmin.x - 9.25) < 1e-6 and abs(b.extmax.x - 14.75) < 1e-6)
    # each slot (14 long, 5.5 wide, 12 mm from the left) 20 mm from the bottom and the top
    assert ys == [(13.0, 27.0), (93.0, 107.0)], (ys, text)


def _fill(w, h, p, d, margin) -> list:
    """A perforated plate's holes as a maker fills its field (the plate less ``margin``): as
    many each way as lie whole in it, centred."""
    nx = math.floor((w - 2 * margin - d) / p + 1e-9) + 1
    ny = math.floor((h - 2 * margin - d) / p + 1e-9) + 1
    return sorted((round(w / 2 + (i - (nx - 1) / 2) * p, 9) + 0.0,
                   round(h / 2 + (j - (ny - 1) / 2) * p, 9) + 0.0, d)
                  for i in range(nx) for j in range(ny))


def test_a_perforated_plates_pitch_refills_the_plate_less_its_margin(tmp_path):
    """A square-set field of 5 mm holes over a 200 x 150 plate but for a 15 mm margin (17 x
    12 on a 10 mm pitch): a new pitch, plate size or margin refills the field with as many
    holes as fit, centred (it was a 17 x 12 grid: 15 mm spread it past the plate's edge)."""
    doc, m = _doc(200, 150)
    for x, y, d in _fill(200, 150, 10, 5, 15):
        m.add_circle((x, y), d / 2)
    text = _text(doc)
    assert "param holes_margin = 15 mm" in text and "perforated" in text, text
    assert _holes(text, tmp_path) == _fill(200, 150, 10, 5, 15), text
    for edit, want in (({"holes_pitch": 15}, _fill(200, 150, 15, 5, 15)),     # 12 x 8
                       ({"holes_pitch": 8}, _fill(200, 150, 8, 5, 15)),
                       ({"width": 230, "holes_margin": 20}, _fill(230, 150, 10, 5, 20)),
                       ({"holes_d": 4}, _fill(200, 150, 10, 4, 15))):
        got = _holes(text, tmp_path, **edit)
        assert got == want, (edit, len(got), len(want), text)
    assert len(_fill(200, 150, 15, 5, 15)) == 12 * 8


def test_a_perforated_plates_hex_field_follows_the_plate(tmp_path):
    """A staggered field over the plate but for its margin: the field is the plate less the
    margin (it was a field of its own size: a taller plate kept it, a new margin had no
    param); a new pitch refills it about the plate's centre."""
    from maker_drawings import perforated_hex
    text, _ = import_drawing(perforated_hex(), "p.dxf", infer=True)
    assert "param holes_margin = 15 mm" in text, text
    for edit, kw in (({}, {}), ({"height": 170}, {"height": 170.0}),
                     ({"holes_margin": 12, "holes_pitch": 15}, {"margin": 12.0, "pitch": 15.0})):
        doc = ezdxf.read(io.StringIO(perforated_hex(**kw).decode()))
        want = sorted((round(e.dxf.center.x, 9) + 0.0, round(e.dxf.center.y, 9) + 0.0,
                       round(2 * e.dxf.radius, 9)) for e in doc.modelspace()
                      if e.dxftype() == "CIRCLE")
        assert _holes(text, tmp_path, **edit) == want, (edit, text)


@pytest.mark.parametrize("left_off, right_gap", [(0.03, True), (0.0, True), (0.03, False)])
def test_two_irregular_groups_of_one_size_stay_two_patterns(tmp_path, left_off, right_gap):
    """Two 2 x 2 groups of 4 mm holes 20 mm in from each end of a 200 x 100 plate, the left
    one with a hole CAD rounded 0.03 mm off its node, the right one with a hole left out:
    two patterns (a grid, a grid with a gap list), each kept from its own edge (they were
    "7 holes fit no pattern", one set placed from the centre: at width 240 every hole moved
    20 mm)."""
    doc, m = _doc(200, 100)
    holes = []
    for i in range(2):
        for j in range(2):
            holes.append((20 + i * 30 + (left_off if (i, j) == (1, 0) else 0.0), 35 + j * 30))
            if not (right_gap and (i, j) == (1, 1)):
                holes.append((150 + i * 30, 35 + j * 30))
    for x, y in holes:
        m.add_circle((x, y), 2)
    text = _text(doc)
    assert "fit no pattern" not in text and "set `" not in text, text
    assert ("grid with a gap list" in text) == right_gap and \
        ("(CAD rounding)" in text) == bool(left_off), text
    assert _holes(text, tmp_path) == sorted((x, y, 4.0) for x, y in holes), text
    got = _holes(text, tmp_path, width=240, height=120)
    want = sorted((round(x + (40 if x > 100 else 0), 9) + 0.0, y + 10, 4.0) for x, y in holes)
    assert got == want, (got, text)


@pytest.mark.parametrize("kind", ["edgepair", "perforated", "twogroups"])
def test_generated_round6_kinds_keep_their_edges(tmp_path, kind):
    """The generated kinds of this round (tests/gen_drawings.py, truths from the spec: two
    holes or slots by their own edges, a perforated plate, two 2 x 2 groups one CAD rounded
    and one with a hole left out), their labels left off: each drawing's program is the
    drawing, and a new width and height (15 % more) give the edited design's drawing."""
    import random

    import gen_drawings as gen
    from benchmarks.imports import infer_edits as bench
    for seed in range(4):
        d = gen.random_design(random.Random(seed), [kind], pool=(kind,))
        d.features = [f for f in d.features if f["kind"] != "label"]
        suffix, data = gen.export(d)
        text, _ = import_drawing(data, "d" + suffix, infer=True)
        assert bench.compare(d, bench.output_of(text, tmp_path / "d.aidl"), tmp_path) == [], \
            (d.describe(), text)
        for e in d.edits():
            if e.kind != "body":
                continue
            new = round(d.value(e) * 1.15, 2)
            d2 = d.edited(e, new)
            if not d2.valid():
                continue
            name, ov = bench.find_param(text, d, dataclasses.replace(e, new=new))
            got = bench.output_of(text, tmp_path / "e.aidl", {name: ov})
            assert bench.compare(d2, got, tmp_path) == [], (d.describe(), e.label, text)
