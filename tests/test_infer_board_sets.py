"""A board's set of holes (holes of one size in no pattern) keeps its place as two params and
the edges its maker drew it from (issue 114, the blind maker run's misses #1 and #2,
data/maker_runs/issue114b/REPORT.md; docs/import.md, "What an edit means").  The drawings are
made here with ezdxf (the makers' numbers: an Arduino Mega 2560's datasheet holes), imported
through the real importer (``--infer``), each edit compiled by the real compiler and its DXF
read back with ezdxf; hole centres and sizes are compared numerically.

* an Arduino Mega's six holes 20 / 12 mm (its corner) from the left and bottom edges of a
  200 x 90 plate, their middle nearer the centre lines: placed from the lower left corner
  (``holes_x``, ``holes_y``), so a wider plate keeps the board and "8 mm up" is one number;
* a set read from the centre (an Uno centred on its plate by its board) has its offsets from
  the centre lines as params too, never numbers in the text;
* a set of no known board whose nearest hole is a dimensioned distance (20 mm) from the
  edges is placed from them; 0.37 mm off it, from the centre as before.
Cost: four imports and about ten compiles (seconds)."""
from __future__ import annotations

import re

import pytest

from test_infer_round5 import _doc, _text  # a plate drawn with ezdxf; its import (--infer)
from test_infer_round6 import _holes       # the compiled program's circles, read by ezdxf

MEGA = [(13.97, 2.54), (15.24, 50.8), (66.04, 7.62), (66.04, 35.56), (90.17, 50.8), (96.52, 2.54)]
UNO = MEGA[:4]


def _param(text: str, name: str) -> tuple[float, str]:
    m = re.search(rf"^param {name} = (-?[\d.]+) mm(?:  # (.*))?$", text, re.M)
    assert m, (name, text)
    return float(m.group(1)), m.group(2) or ""


def _mega_plate():
    doc, m = _doc(200, 90)
    doc.layers.add("HOLES")
    for x, y in MEGA:
        m.add_circle((20 + x, 12 + y), 1.6, dxfattribs={"layer": "HOLES"})
    for x in (6, 194):
        for y in (6, 84):
            m.add_circle((x, y), 2, dxfattribs={"layer": "HOLES"})
    return _text(doc)


def test_a_mega_by_its_corner_stays_by_the_left_edge_and_moves_by_one_param(tmp_path):
    text = _mega_plate()
    assert "one set `holes`, placed from the bottom left corner" in text, text
    assert _param(text, "holes_x") == (33.97, "the set's hole nearest the corner, from the "
                                              "left edge"), text
    assert _param(text, "holes_y")[0] == 14.54, text
    board = sorted((round(20 + x, 9), round(12 + y, 9), 3.2) for x, y in MEGA)
    assert [g for g in _holes(text, tmp_path) if g[2] == 3.2] == board, text
    # miss #1: 240 mm wide, the Mega stays 20 mm from the left edge (it moved 20 mm right)
    got = _holes(text, tmp_path, width=240)
    assert [g for g in got if g[2] == 3.2] == board, text
    assert [g[:2] for g in got if g[2] == 4.0] == [(6, 6), (6, 84), (234, 6), (234, 84)]
    # miss #2: "the Mega 12 -> 20 mm from the bottom" is one param, every hole 8 mm up
    got = _holes(text, tmp_path, holes_y=14.54 + 8)
    assert [g for g in got if g[2] == 3.2] == [(x, round(y + 8, 9), d) for x, y, d in board]


def test_a_set_read_from_the_centre_has_its_place_as_two_params(tmp_path):
    """An Uno centred on a 100 x 70 plate by its board (68.58 x 53.34 mm, its corner at
    (15.71, 8.33)): read from the centre, its offsets are ``holes_x``/``holes_y`` (they were
    `width / 2 - 19.05` in the text, no param)."""
    doc, m = _doc(100, 70)
    holes = [(15.71 + x, 8.33 + y) for x, y in UNO]
    for x, y in holes:
        m.add_circle((x, y), 1.6)
    text = _text(doc)
    assert "placed from the centre" in text, text
    hx, said = _param(text, "holes_x")
    hy, _ = _param(text, "holes_y")
    assert (hx, hy) == (-19.05, 24.13) and "from the vertical centre line" in said, text
    assert "center=(width / 2 + holes_x + c.x, height / 2 + holes_y + c.y)" in text, text
    drawn = sorted((round(x, 9), round(y, 9), 3.2) for x, y in holes)
    assert _holes(text, tmp_path) == drawn
    assert _holes(text, tmp_path, width=120) == [(round(x + 10, 9), y, d) for x, y, d in drawn]
    assert _holes(text, tmp_path, holes_y=hy + 8) == [(x, round(y + 8, 9), d)
                                                      for x, y, d in drawn]


@pytest.mark.parametrize("off, edges", [(0.0, True), (0.37, False)])
def test_a_set_a_dimensioned_distance_from_the_edges_is_placed_from_them(tmp_path, off, edges):
    """Three 3 mm holes of a sensor (no known board) on an 80 x 50 plate, their middle nearer
    the centre lines than the edges: the nearest hole 20 / 12 mm from the left and bottom
    edges is placed from them (a new width keeps it); 20.37 / 12.37 mm, from the centre (a
    new width moves it half the change)."""
    doc, m = _doc(80, 50)
    holes = [(20 + off + x, 12 + off + y) for x, y in [(0, 0), (21.3, 3.8), (5.1, 17.8)]]
    for x, y in holes:
        m.add_circle((x, y), 1.5)
    text = _text(doc)
    assert ("from the bottom left corner" in text) == edges, text
    assert ("placed from the centre" in text) != edges, text
    got = _holes(text, tmp_path, width=100, height=60)
    shift = (0, 0) if edges else (10, 5)
    assert got == sorted((round(x + shift[0], 9), round(y + shift[1], 9), 3.0)
                         for x, y in holes), text
