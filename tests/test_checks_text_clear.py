"""W0516 for letters that meet the cut edge (issue 111): an engraved text whose strokes come
within 0.2 mm of a hole's edge or the outline, where the laser engraves into its cut (other
marks keep their 0.5 mm rule; letters set tight beside a hole on purpose, 0.2 mm and more,
are not warned).  Real programs through the compiler: the stroke font's letters and a font's
outlines."""
from __future__ import annotations

import pytest

import aidl_lang

PLATE = """solid tag {
    plate = RoundedRectangle(center=(0, 0), width=70, height=35, corner_radius=4)
    hole hang { c = Circle(center=(0, -8.5), diameter=10) }
    drawing label { word = Text("TEE", (0, BASE), size=5FONT) }
}
"""


def _w(src: str) -> list:
    r = aidl_lang.compile(source=src)
    assert r.ok, [d.message for d in r.errors]
    return [d for d in r.diagnostics if d.code == "W0516"]


def test_letters_a_tenth_from_a_hole_are_warned_with_the_gap_and_the_move():
    # the hole's top at y = -3.5; the letters' baseline 0.1 mm above it ("E" sits on it)
    (w,) = _w(PLATE.replace("BASE", "-3.4").replace("FONT", ""))
    assert w.message.startswith('engraving `tag.label.word` (text "TEE") comes 0.10 mm from '
                                "the cut edge of `tag` (the hole `tag.hang`) at ")
    assert "text needs 0.2 mm clear of the edge" in w.message
    assert w.hint.startswith("keep `tag.label.word` 0.10 mm or more further from the edge")
    assert w.span.line == 4
    # the hint followed: 0.1 mm higher, nothing
    assert _w(PLATE.replace("BASE", "-3.3").replace("FONT", "")) == []


@pytest.mark.parametrize("base", ["-3.3", "-3.0", "2"])
def test_letters_set_tight_but_clear_are_not_warned(base):
    assert _w(PLATE.replace("BASE", base).replace("FONT", "")) == []


def test_outline_letters_touching_a_hole_are_warned():
    # a font's letters (filled outlines, issue 112) on the hole's edge: their bottom at -3.48
    ws = _w(PLATE.replace("BASE", "-3.48").replace("FONT", ', font="sans"'))
    assert len(ws) == 1 and "touches the cut edge of `tag` (the hole `tag.hang`)" in ws[0].message


def test_letters_near_the_outline_name_the_outline():
    src = PLATE.replace("BASE", "-17.4").replace("FONT", "").replace(
        'Text("TEE", (0, -17.4)', 'Text("TEE", (20, -17.4)')
    (w,) = _w(src)
    assert "(the outline)" in w.message and "comes 0.10 mm from" in w.message


def test_an_assert_on_a_texts_center_says_how_far_it_lies_off_its_position():
    """Issue 111 (run j): an assert on a Text's `.center` failed by a few hundredths; E0405
    now says the centre is the letters' box's, how far from `position` and which way."""
    src = """solid p {
    body = Rectangle(center=(0, 0), width=200, height=80)
    drawing d {
        a = Text("Quigley", (0, 10), size=10, valign="middle", font="sans")
        b = Text("Quigley", (0, -20), size=10, valign="middle")
    }
    assert d.a.center.y == 10 mm, "a"
    assert abs(d.b.center.y + 20 mm) < 0.01 mm, "b"
    assert d.b.position.y == -20 mm, "by position: holds"
}
"""
    r = aidl_lang.compile(source=src)
    ws = [d for d in r.diagnostics if d.code == "E0405"]
    assert [w.span.line for w in ws] == [7, 8]
    assert ws[0].message.endswith("; `p.d.a.center` is its letters' box centre, 1.36 mm below "
                                  "its `position` (descenders, round letters' overshoot): a "
                                  "text is placed, and best asserted, by its `position`")
    assert "`p.d.b.center` is its letters' box centre, 1.43 mm below its `position`" \
        in ws[1].message


CARD = """solid card {
    body = Rectangle(center=(0, 0), width=90, height=50)
    hole slot { s = Rectangle(center=(-30, -22), width=3, height=6) }
    drawing border { r = RoundedRectangle(center=(0, 0), width=82, height=H, corner_radius=2) }
}
"""


def test_a_border_through_an_edge_slot_is_said_to_run_across_it():
    """Issue 111 (run r's place card): an engraved border 4 mm inside the edge crossed a
    foot slot cut 6 mm up from the bottom; W0516 said "touches ... keep it 0.50 mm further
    from the edge", which would not clear it.  It now says the border runs across the
    outline, part of it off the material; a border that stops short of the slot is clean."""
    r = aidl_lang.compile(source=CARD.replace("H", "42"))
    (w,) = [d for d in r.diagnostics if d.code == "W0516"]
    assert "engraving `card.border.r` runs across the cut edge of `card` (the outline) at " \
        "(-31.50, -21.00)" in w.message
    assert w.hint.startswith("it crosses the outline there, so part of it lies off the "
                             "material: shrink or move `card.border.r` to stay on it, 0.5 mm "
                             "clear of the edge")
    clear = aidl_lang.compile(source=CARD.replace("H", "36"))   # its bottom at -18, 1 mm clear
    assert [d.code for d in clear.diagnostics if d.severity == "warning"] == []


SAIL = """solid sail {
    body = Polygon([(-35, 0), (35, 0), (0, 100)])
    hole foot { gap = Rectangle(center=(GX, 2), width=40, height=4) }
}
assert sail.body.bb.width == 70 mm, "sail 70 wide"
"""


def test_an_assert_on_a_shapes_box_that_its_holes_cut_is_w0405():
    """Issue 111 (run s's toy sailboat): a joint's gaps cut the sail's foot back and the
    model's `assert sail.body.bb.width == 70 mm` held on the polygon as drawn.  W0405 says
    the assert reads the shape before its holes and would fail on the final outline; a hole
    that leaves the foot's corners (the outline still 70 wide) is not warned."""
    r = aidl_lang.compile(source=SAIL.replace("GX", "20"))
    (w,) = [d for d in r.diagnostics if d.code == "W0405"]
    # (the gap runs out through the side it cuts back, material beside it: the polygon's
    # size as drawn is taken as meant, a note (issue 111, run ha's fork))
    assert w.severity == "note"
    assert w.message == ("`assert sail.body.bb.width == 70 mm` reads the box of `sail.body`, "
                         "the outline of `sail`, before its holes: it holds there (the shape "
                         "as drawn, a hole run out through that side cutting it back) and would "
                         "fail on the final outline (its right 1.400 mm in)")
    assert "move the holes that cut that side" in w.hint
    r = aidl_lang.compile(source=SAIL.replace("GX", "0"))
    assert [d.code for d in r.diagnostics if d.severity == "warning"] == []
