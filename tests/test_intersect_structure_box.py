"""Issue 111: a structure's `.bb` is its drawn result's, not an `Intersect`'s inputs'.

A model's knob had a D-shaft hole written `hole d { c = Circle(...); r = Rectangle(...);
shape = Intersect(c, r) }`; the round's report said its box was 1.5 mm off, counting the
Rectangle, which the Intersect consumes (construction: solved, not drawn).  Here the hole's box
as a relation reads it (placed by `CenterInside`, `AlignTop`, its circle's centre; the
Rectangle straight or turned, written as names, a list or inline) equals the opening the part is
cut with, read back from the SVG by svgelements, and law 3, *members are the geometry*
(benchmarks/laws/law_members.py), holds.
"""
from __future__ import annotations

import pytest

import aidl_lang
from benchmarks.laws import law_members

SHAPES = {
    "names": "c = Circle(center=(0, 0), radius=3)\n        "
             "r = Rectangle(center=(0, -1.5), width=8, height=6{turn})\n        "
             "shape = Intersect(c, r)",
    "list": "c = Circle(center=(0, 0), radius=3)\n        "
            "r = Rectangle(center=(0, -1.5), width=8, height=6{turn})\n        "
            "shape = Intersect([c, r])",
    "inline": "shape = Intersect(Circle(center=(0, 0), radius=3), "
              "Rectangle(center=(0, -1.5), width=8, height=6{turn}))",
}
KNOB = """units mm
solid knob {{
    body = Rectangle(center=(0, 0), width=40, height=40)
    hole d {{
        {shape}
    }}
    {relation}
}}
"""


def _opening(r, tmp_path) -> tuple:
    """The box (left, bottom, right, top) of the part's inner loop, from the SVG."""
    from exact_geometry import loop_box, read_svg_loops
    path = tmp_path / "knob.svg"
    path.write_text(r.to_svg(), encoding="utf-8")
    boxes = [loop_box(loop) for loop in read_svg_loops(path)]
    inner = [b for b in boxes if b[2] - b[0] < 30]
    assert len(inner) == 1, boxes
    return inner[0]


@pytest.mark.parametrize("form", list(SHAPES))
@pytest.mark.parametrize("turn", ["", ", rotation=30 deg"])
@pytest.mark.parametrize("relation", ["CenterInside(d, self)",
                                      "d.bb.top == body.bb.top - 5",
                                      "knob.d.bb.left == body.bb.left + 4"])
def test_the_d_holes_box_is_the_opening(form, turn, relation, tmp_path):
    src = KNOB.format(shape=SHAPES[form].format(turn=turn), relation=relation)
    r = aidl_lang.compile(src)
    assert r.ok, [d.message for d in r.errors]
    box = {v.name: v.mm for v in r.values}["knob.d.bbox"]
    assert box == pytest.approx(_opening(r, tmp_path), abs=1e-6)
    # the flat: 1.5 mm above the circle's centre (1.5 mm of the Rectangle past the circle's
    # bottom is not in the box), or turned with the Rectangle
    assert box[3] - box[1] < 6.0 - 0.25
    assert law_members.violations(r) == []
