"""Countersink marks on some of a pattern's holes follow those holes (issue 91, "countersink
marks stay behind").  `aidl import --infer` of a plate whose CSK layer marked three of its
four corner holes wrote the three marks as fixed circles in the layer's `drawing`: `--set
width=200` moved the holes and left the marks on bare material (with all four marked they
followed).  Now a mark is written with its hole whatever subset is marked: in the pattern's
loop, under an `if` naming the marked turns (`if not (sx == 1 and sy == 1)`), its centre the
hole's.  The law: plates of a corner pattern, a row, a grid, a bolt circle, a mirrored
pair or a board's hole set, any non-empty subset of the n holes marked; after each edit of the plate's size and
the pattern's own params every mark (read back by ezdxf from the compiled DXF) sits on a
hole centre to 1e-9 mm, the marked holes are as many as drawn, and as drawn they are the
drawn ones.  Cost: 18 generated plates, 3 compiles each (about 12 s of CPU)."""
from __future__ import annotations

import io
import math
import re

import ezdxf
import pytest
from hypothesis import given, settings, HealthCheck, strategies as st

import aidl_lang
from aidl_lang.drawing.infer import import_drawing

W, H = 120.0, 80.0


def _holes(kind: str, n: int) -> list:
    """The centres of a pattern of ``kind`` on a 120 x 80 mm plate (``n``: its count where
    the kind has one)."""
    if kind == "corner":
        return [(x, y) for x in (7.0, W - 7.0) for y in (7.0, H - 7.0)]
    if kind == "row":
        return [(W / 2 + (i - (n - 1) / 2) * 12.5, 20.0) for i in range(n)]
    if kind == "grid":
        return [(30.0 + 15 * i, 25.0 + 15 * j) for i in range(3) for j in range(2)]
    if kind == "bolt":
        return [(W / 2 + 25 * math.cos(2 * math.pi * k / n), H / 2 + 25 * math.sin(2 * math.pi * k / n))
                for k in range(n)]
    if kind == "board":             # an Arduino Uno's holes, by the plate's right bottom corner
        return [(40 + x, 8 + y) for x, y in [(14.0, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5)]]
    return [(W / 2 - 35.0, 30.0), (W / 2 + 35.0, 30.0)]        # a mirrored pair


def _dxf(centres: list, marked: set = frozenset(), layer: str = "CSK", label=None) -> bytes:
    """The plate with holes at ``centres`` on HOLES: the ``marked`` ones with a countersink
    mark on ``layer``, or a text "M3" at ``label`` on it."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    for ly in ("OUTLINE", "HOLES", layer):
        doc.layers.add(ly)
    m.add_lwpolyline([(0, 0), (W, 0), (W, H), (0, H)], close=True, dxfattribs={"layer": "OUTLINE"})
    for k, c in enumerate(centres):
        m.add_circle(c, 1.6, dxfattribs={"layer": "HOLES"})
        if k in marked:
            m.add_circle(c, 3.2, dxfattribs={"layer": layer})
    if label is not None:
        m.add_text("M3", height=3, dxfattribs={"layer": layer, "insert": label})
    s = io.StringIO()
    doc.write(s)
    return s.getvalue().encode()


def _circles(res, layer: str) -> list:
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    return [(e.dxf.center.x, e.dxf.center.y) for e in doc.modelspace()
            if e.dxf.layer == layer and e.dxftype() == "CIRCLE"]


@st.composite
def plates(draw):
    kind = draw(st.sampled_from(["corner", "row", "grid", "bolt", "pair", "board"]))
    n = draw(st.integers(3, 6))
    centres = _holes(kind, n)
    marked = draw(st.sets(st.integers(0, len(centres) - 1), min_size=1))
    return kind, centres, marked


@settings(max_examples=18, deadline=None, suppress_health_check=list(HealthCheck))
@given(plates())
def test_marks_follow_their_holes_whatever_subset_is_marked(tmp_path_factory, case):
    kind, centres, marked = case
    text, _ = import_drawing(_dxf(centres, marked), "csk.dxf", infer=True)
    assert "drawing csk" not in text, text          # every mark written with its hole
    assert ("holes, as drawn" in text) == (len(marked) < len(centres)), text
    own = [nm for nm in re.findall(r"^param (\w+) = ([\d.]+) mm", text, re.M)
           if re.search(r"_(pitch|inset|pcd|spacing|x)$", nm[0])]
    edits = [{}, {"width": 170, "height": 95}] + [{nm: float(v) * 1.25} for nm, v in own[:1]]
    path = tmp_path_factory.mktemp("csk") / "p.aidl"
    for edit in edits:
        res = aidl_lang.compile(text, path=path, overrides=edit)
        assert res.ok, ([str(d) for d in res.errors], text)
        # each mark is its hole's `Countersink` (issue 102): on the COUNTERSINK layer
        assert text.count("Countersink(") >= 1 and not _circles(res, "ENGRAVE"), text
        holes, marks = _circles(res, "CUT"), _circles(res, "COUNTERSINK")
        assert len(holes) == len(centres) and len(marks) == len(marked), (edit, text)
        for mx, my in marks:
            assert min(math.hypot(mx - x, my - y) for x, y in holes) <= 1e-9, (edit, text)
        if not edit:
            want = sorted((round(centres[k][0], 6), round(centres[k][1], 6)) for k in marked)
            assert sorted((round(x, 6), round(y, 6)) for x, y in marks) == want


def _label_box(res) -> tuple:
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    pts = [p[:2] for e in doc.modelspace() if e.dxf.layer == "ENGRAVE" and e.dxftype() == "LWPOLYLINE"
           for p in e.get_points()]
    return min(p[0] for p in pts), min(p[1] for p in pts)


@pytest.mark.parametrize("kind, member, off, edit", [
    ("corner", 1, (0, 6), {"corner_inset": 11, "width": 150}),
    ("row", 4, (0, -7), {"holes_pitch": 15}),
    ("bolt", 0, (5, 0), {"bolt_circle_pcd": 64}),
])
def test_a_label_beside_a_member_of_a_pattern_follows_it(tmp_path, kind, member, off, edit):
    """A label beside one hole of a pattern ("M3" 6 mm above a corner hole) was placed from
    the body's edge: a new inset moved the hole and not its label.  Now it is placed at its
    member's turn of the loop (the loop's variables replaced by that turn's values), so it
    moves by exactly the hole's move (ezdxf: the label's outlines and the hole's circle)."""
    centres = _holes(kind, 5)
    c = centres[member]
    text, _ = import_drawing(_dxf(centres, layer="LABELS", label=(c[0] + off[0], c[1] + off[1])),
                             "l.dxf", infer=True)
    assert all(k in text for k in edit), text
    path = tmp_path / "l.aidl"
    before = aidl_lang.compile(text, path=path)
    after = aidl_lang.compile(text, path=path, overrides=edit)
    assert before.ok and after.ok, text
    (bx, by), (ax, ay) = _label_box(before), _label_box(after)
    hole_after = min(_circles(after, "CUT"), key=lambda h: math.hypot(h[0] - ax, h[1] - ay))
    moved = (hole_after[0] - c[0], hole_after[1] - c[1])
    assert abs(moved[0]) + abs(moved[1]) > 1.0, (moved, text)        # the edit moved it
    assert abs(ax - bx - moved[0]) <= 1e-9 and abs(ay - by - moved[1]) <= 1e-9, text
