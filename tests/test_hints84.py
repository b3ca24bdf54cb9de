"""Issue 84, "every hint safe", for the warnings whose hints had no law over generated cases:
each law generates small real programs that raise the warning with a known truth, applies the
hint as written (the edit a model would make from its text) and compiles again through the
real parser, solver and Manifold: the warning goes, no new warning appears, and the part's
outline is the one the edit draws (its symmetric difference with shapely's union of the
shapes as moved, under 1e-3 mm^2) - or the hint names no number because none is safe.

Also the flood of issue 84: a part of thousands of circles that falls apart found one W0519
per pair of neighbours (860 lines); a per-part check says its first few and "and N more like
it" (:func:`aidl_lang.output.checks.common._say_few`)."""
from __future__ import annotations

import re

import pytest
from hypothesis import given, settings, strategies as st
from shapely.geometry import Point, Polygon, box
from shapely.affinity import rotate
from shapely.ops import unary_union

import aidl_lang
from aidl_lang.output.checks.common import SHOWN


def _compile(src: str, min_wall=None):
    """The program compiled through the real pipeline: (its diagnostics' warnings, part name
    -> its final region as shapely sees it)."""
    from aidl_lang.pipeline import compile_source
    c = compile_source(src, "/tmp/h14.aidl", **({} if min_wall is None else {"min_wall": min_wall}))
    errs = [f"{d.code} {d.message}" for d in c.sink.items if d.severity == "error"]
    assert not errs, errs
    return c


def _warnings(c, code=None) -> list:
    return [d for d in c.sink.items if d.severity == "warning" and code in (None, d.code)]


def _codes(c) -> set:
    return {d.code for d in _warnings(c)}


def _region(c, name):
    """Part ``name``'s final region (a CrossSection) as a shapely region, mm: its
    counter-clockwise loops less its clockwise ones (the openings)."""
    (shape,) = [p.shape for p in c.drawing.parts if p.name == name]
    rings = [Polygon(P) for P in shape.to_polygons() if len(P) >= 3]
    outer = unary_union([g for g in rings if g.exterior.is_ccw])
    return outer.difference(unary_union([g for g in rings if not g.exterior.is_ccw]))


def _same_region(a, b, tol=1e-3) -> bool:
    return a.symmetric_difference(b).area < tol


# ------------------------------------------------------------------ the flood (W0519, W0515)
GRID = """solid s {{
    for i in range({n}) {{ for j in range({n}) {{ c = Circle(center=(i * {sp}, j * {sp}), radius=1) }} }}
}}
"""


@pytest.mark.parametrize("n", [4, 8])
def test_a_part_that_falls_apart_says_its_first_slits_and_how_many_more(n):
    """``n`` x ``n`` discs 0.05 mm apart: a slit between each pair of neighbours, 2 n (n - 1)
    of them (112 for n = 8; before, 112 W0519 lines).  Said: the first few, the last of them
    with the count of the rest, in this part."""
    r = _compile(GRID.format(n=n, sp=2.05))
    ws = _warnings(r, "W0519")
    total = 2 * n * (n - 1)
    assert len(ws) == min(SHOWN, total)
    more = [w for w in ws if "more like it" in w.message]
    if total > SHOWN:
        (last,) = more
        assert last is ws[-1]
        assert f"(and {total - SHOWN} more like it in `s`)" in last.message
    else:
        assert more == []
    assert "W0504" in _codes(r)           # the part falls apart, said once


def test_tiny_voids_are_said_a_few_and_counted():
    """8 x 8 discs 1.98 mm apart (radius 1): they overlap, and leave a void between each four,
    49 of them (before: 49 W0515 lines)."""
    r = _compile(GRID.format(n=8, sp=1.98))
    ws = _warnings(r, "W0515")
    assert len(ws) == SHOWN
    assert f"(and {49 - SHOWN} more like it in `s`)" in ws[-1].message


# ------------------------------------------------------------------ W0519, a plain slit
TAG = """solid tag {{
    bar = Rectangle(center=(0, 0), width=30, height=12)
    top = Circle(center=(15, {ty}), radius={r})
    bottom = Circle(center=(15, {by}), radius={r})
}}
"""


def _tag(g, r, shift=0.0):
    """A dog-bone tag's end: two lobes of radius ``r`` beyond the bar, ``g`` mm apart (the
    bottom one moved ``shift`` mm up): the program and the region it draws (shapely)."""
    ty, by = round(r + g / 2, 6), round(-(r + g / 2) + shift, 6)
    truth = unary_union([box(-15, -6, 15, 6), Point(15, ty).buffer(r, 256),
                         Point(15, by).buffer(r, 256)])
    return TAG.format(ty=ty, by=by, r=r), truth


def _moves(hint: str) -> tuple:
    """The two moves W0519's plain hint names: (mm towards, mm away)."""
    m = re.search(r"overlap by at least 0.5 mm \(move one ([0-9.]+) mm towards the other\) "
                  r"or open the gap to at least 0.5 mm \(move one ([0-9.]+) mm away\)", hint)
    assert m, hint
    return float(m.group(1)), float(m.group(2))


@settings(max_examples=15, deadline=None)
@given(g=st.floats(0.02, 0.4), r=st.integers(5, 6))
def test_law_a_plain_slits_moves_remove_it_and_move_only_that_lobe(g, r):
    """A tag's two end lobes ``g`` mm apart beyond the bar (narrower than 0.5 mm): W0519
    names the slit with two moves, each rounded up to 0.01 mm.  Each, made as written (the
    bottom lobe moved ``D`` mm down, or up into the top one), leaves no warning at all and
    the outline the moved lobe draws (shapely's union of the bar and the two discs so placed, within the
    chords' 0.6 mm^2; a lobe 0.1 mm off is 2 mm^2).  Before, the gap 0.375 mm read "move one 0.12 mm away" (0.125 rounded to even):
    done, 0.495 mm was warned again; and "more than 0.25 mm towards the other", made with
    0.01 mm to spare, left the two discs meeting in a V-notch narrower than 0.5 mm over
    more than 0.5 mm (a nick, warned again)."""
    g = round(g, 4)
    src, truth = _tag(g, r)
    c = _compile(src)
    ws = _warnings(c, "W0519")
    if not ws:
        return                    # the chords' gap reached 0.5 mm: nothing to fix
    (w,) = ws
    assert _codes(c) == {"W0519"}
    assert _same_region(_region(c, "tag"), truth, 0.6)
    towards, away = _moves(w.hint)
    width = float(re.search(r"is ([0-9.]+) mm wide", w.message).group(1))
    assert g - 0.006 <= width                     # the chords' gap is a little wider
    assert width + 0.5 - 0.005 <= towards <= width + 0.511
    assert 0.5 - width - 0.011 <= away <= 0.5 - g + 0.01
    for shift in (-away, towards):
        moved, truth = _tag(g, r, shift)
        after = _compile(moved)
        assert _codes(after) == set(), (g, shift, [x.message for x in _warnings(after)])
        assert _same_region(_region(after, "tag"), truth, 0.6)


def test_the_gap_of_0375_mm_is_opened_by_013_mm():
    """The case the law found: 0.5 - 0.375 = 0.125 printed "0.12" (to even), too little."""
    (w,) = _warnings(_compile(_tag(0.375, 6)[0]), "W0519")
    assert _moves(w.hint) == (0.88, 0.13)


def test_two_discs_overlapped_as_told_leave_no_nick():
    """The overlap the hint asks for, on two round lobes 0.25 mm apart: before, "move one more
    than 0.25 mm towards the other", made 0.26 mm, left a V-notch at the discs' junction
    (W0519 again); now "overlap by at least 0.5 mm (move one 0.76 mm towards the other)"."""
    src, _ = _tag(0.25, 5)
    (w,) = _warnings(_compile(src), "W0519")
    towards, _ = _moves(w.hint)
    assert "W0519" in _codes(_compile(_tag(0.25, 5, 0.26)[0]))     # the old hint, made
    assert _codes(_compile(_tag(0.25, 5, towards)[0])) == set()


# ------------------------------------------------------------------ W0520, a ledge
STACK = """solid p {{
    base = Rectangle(center=({bx}, {by}), width={bw}, height={bh})
    top = Rectangle(center=({tx}, {ty}), width={tw}, height={th})
}}
"""


def _stack(s, side, out, w, turned, moves=None):
    """A block stood on a base 20 x 10 mm, one of its sides ``s`` mm past the base's (``out``)
    or short of it, on the ``side`` (+1 right, -1 left); ``turned``: the whole laid on its
    side (x and y swapped).  ``moves``: shape -> (dx, dy) mm made.  The program and its
    region (shapely)."""
    edge = side * (10 + (s if out else -s))                 # the block's side, x
    tx, ty = round(edge - side * w / 2, 6), 7.5
    shapes = {"base": [0.0, 0.0, 20.0, 10.0], "top": [tx, ty, float(w), 5.0]}
    if turned:
        shapes = {k: [y, x, h, w_] for k, (x, y, w_, h) in shapes.items()}
    for k, (dx, dy) in (moves or {}).items():
        shapes[k][0] = round(shapes[k][0] + dx, 6)
        shapes[k][1] = round(shapes[k][1] + dy, 6)
    truth = unary_union([box(x - a / 2, y - b / 2, x + a / 2, y + b / 2)
                         for x, y, a, b in shapes.values()])
    (bx, by, bw, bh), (tx, ty, tw, th) = shapes["base"], shapes["top"]
    return STACK.format(bx=bx, by=by, bw=bw, bh=bh, tx=tx, ty=ty, tw=tw, th=th), truth


@settings(max_examples=20, deadline=None)
@given(s=st.floats(0.03, 0.45), side=st.sampled_from([1, -1]), out=st.booleans(),
       w=st.integers(4, 12), turned=st.booleans())
def test_law_a_ledges_move_aligns_the_edges_and_changes_nothing_else(s, side, out, w, turned):
    """A block on a base with its side ``s`` mm off the base's (past it or short of it, right
    or left, upright or laid on its side): W0520 names the shape that pokes and the move that
    aligns it.  Made as written, no warning is left and the outline is the union of the two
    rectangles so moved (within 0.01 mm^2: the move is given to 0.001 mm).  Before, the hint
    said "move or resize `p.top` by 0.20 mm": no direction (two ways to move, one doubles the
    ledge), and a resize about the centre moves the edge half as far."""
    s = round(s, 3)
    src, truth = _stack(s, side, out, w, turned)
    c = _compile(src)
    assert _same_region(_region(c, "p"), truth)
    # (under 0.1 mm a note: it hardly shows once cut, run fc; its hint is the same law)
    (x,) = [d for d in c.sink.items if d.code == "W0520"]
    assert x.severity == ("warning" if s >= 0.1 else "note")
    assert _codes(c) <= {"W0520"}
    m = re.search(r"move `p\.(\w+)` by \((-?[0-9.]+), (-?[0-9.]+)\) mm", x.hint)
    assert m, x.hint
    shape, dx, dy = m.group(1), float(m.group(2)), float(m.group(3))
    assert abs(abs(dx) + abs(dy) - s) < 0.002                 # the ledge's depth, one way
    moved, truth = _stack(s, side, out, w, turned, {shape: (dx, dy)})
    after = _compile(moved)
    assert _codes(after) == set(), (x.hint, [y.message for y in _warnings(after)])
    assert not [d for d in after.sink.items if d.code == "W0520"]
    assert _same_region(_region(after, "p"), truth, 0.01)


# ------------------------------------------------------------------ W0516, a mark meets the cut
MARK = """solid p {{
    body = Rectangle(center=(0, 0), width=20, height=10)
    hole h {{ c = Circle(center=(-6, 0), radius=2) }}
    drawing d {{
        mark = Line(({x0}, {y0}), ({x1}, {y1}))
    }}
}}
"""


@settings(max_examples=20, deadline=None)
@given(gap=st.floats(0.0, 0.45), to_hole=st.booleans(), turn=st.floats(-60, 60),
       y0=st.floats(-3, 3), y1=st.floats(-3.5, 3.5))
def test_law_a_marks_new_end_clears_the_edge_and_keeps_the_line(gap, to_hole, turn, y0, y1):
    """A straight mark from inside a plate 20 x 10 mm to ``gap`` mm from its right side, or
    from the hole's edge (radius 2 mm at (-6, 0), at ``turn`` degrees): W0516 gives the point
    to end it at.  Written there, no warning is left, the mark keeps its start and its line
    (the new end within 0.01 mm of the old segment, nearer its start), and it ends at least
    0.5 mm from the edge (shapely: the plate's boundary and the hole's 32-gon or circle)."""
    import math
    from shapely.geometry import LineString
    if to_hole:
        a = math.radians(turn)
        start = (2.0, round(y0, 3))
        end = (round(-6 + (2 + gap) * math.cos(a), 3), round((2 + gap) * math.sin(a), 3))
    else:
        start, end = (2.0, round(y0, 3)), (round(10 - gap, 3), round(y1, 3))
    c = _compile(MARK.format(x0=start[0], y0=start[1], x1=end[0], y1=end[1]))
    ws = _warnings(c, "W0516")
    if not ws:
        return                 # the hole's chords are farther than the true circle: clear
    (w,) = ws
    assert _codes(c) == {"W0516"}
    m = re.search(r"at \((-?[0-9.]+), (-?[0-9.]+)\) \(shorten it by", w.hint)
    assert m, w.hint
    new = (float(m.group(1)), float(m.group(2)))
    after = _compile(MARK.format(x0=start[0], y0=start[1], x1=new[0], y1=new[1]))
    assert _codes(after) == set(), (w.hint, [x.message for x in _warnings(after)])
    assert LineString([start, end]).distance(Point(new)) < 0.01
    assert math.dist(start, new) < math.dist(start, end)
    edge = box(-10, -10 / 2, 10, 10 / 2).exterior.union(Point(-6, 0).buffer(2, 256).exterior)
    assert edge.distance(Point(new)) >= 0.5 - 0.01


# ------------------------------------------------------------------ W0513, text over text
TEXTS = """solid p {{
    body = Rectangle(center=(0, 0), width=160, height=80)
    drawing d {{
        a = Text("{ta}", (-10, 0), size={sa})
        b = Text("{tb}", ({bx}, {by}), size={sb})
    }}
}}
"""


def _engraved(c) -> tuple:
    """The engraved strokes: how many, and their total length (mm)."""
    import numpy as np
    return len(c.drawing.lines), round(sum(float(np.hypot(*np.diff(pl, axis=0).T).sum())
                                           for _, pl in c.drawing.lines), 6)


@settings(max_examples=20, deadline=None)
@given(ta=st.sampled_from(["AB", "12", "OK", "Hi", "LID"]),
       tb=st.sampled_from(["CD", "34", "NO", "XYZ", "7"]),
       sa=st.integers(3, 8), sb=st.integers(3, 8),
       fx=st.floats(-0.8, 0.8), fy=st.floats(-0.6, 0.6))
def test_law_text_drawn_over_text_moves_clear_and_apart(ta, tb, sa, sb, fx, fy):
    """Text ``b`` placed over text ``a`` (offset by a share of ``a``'s size): W0513 gives the
    move of ``b`` that clears it.  Made as written, no warning is left (neither "drawn over"
    nor "runs into": before, the hint's "at least 4.45 mm away", made, left the two boxes
    touching, warned again as one string), the plate's outline is the same and the
    engraving the same strokes (count and length)."""
    bx, by = round(-10 + fx * sa * len(ta) * 0.8, 3), round(fy * sa, 3)
    src = TEXTS.format(ta=ta, tb=tb, sa=sa, sb=sb, bx=bx, by=by)
    c = _compile(src)
    ws = [w for w in _warnings(c, "W0513") if "is drawn over" in w.message]
    if not ws:
        return
    (w,) = ws
    m = re.search(r"by \((-?[0-9.]+), (-?[0-9.]+)\) mm", w.hint)
    assert m, w.hint
    dx, dy = float(m.group(1)), float(m.group(2))
    moved = TEXTS.format(ta=ta, tb=tb, sa=sa, sb=sb, bx=round(bx + dx, 3), by=round(by + dy, 3))
    after = _compile(moved)
    assert _codes(after) == set(), (w.hint, [x.message for x in _warnings(after)])
    assert _same_region(_region(after, "p"), _region(c, "p"))
    assert _engraved(after) == pytest.approx(_engraved(c))


def test_the_overlap_move_of_before_left_the_labels_touching():
    """The case the law stands on: "CD" 4 mm right of "AB" (size 5) is drawn over it by
    4.46 mm; moved that far only, the boxes touch (W0513, one string); the hint moves it
    6.96 mm, the overlap and half the size."""
    src = TEXTS.format(ta="AB", tb="CD", sa=5, sb=5, bx=-6, by=0)
    (w,) = _warnings(_compile(src), "W0513")
    assert "move `p.d.b` 6.96 mm right, by (6.96, 0.00) mm" in w.hint
    touching = _compile(src.replace("(-6, 0)", "(-1.54, 0)"))
    assert [x for x in _warnings(touching, "W0513") if "runs into" in x.message]


# ------------------------------------------------------------------ W0505, off the material
OFF = """solid p {{
    body = Rectangle(center=(0, 0), width={W}, height={H})
    drawing d {{
        mark = {mark}
    }}
{fix}}}
"""


@settings(max_examples=16, deadline=None)
@given(W=st.integers(20, 40), H=st.integers(10, 20), kind=st.sampled_from("CLTA"),
       fx=st.floats(0.3, 0.8), fy=st.floats(-0.5, 0.5))
def test_law_a_mark_off_the_material_constrained_as_told_lies_on_it(W, H, kind, fx, fy):
    """A mark (circle, line, text, arc) placed across the plate's right side (``fx`` of the
    half-width out): W0505's hint names the constraint, `Inside(d.mark, body, margin=0.5
    mm)`.  Written in `p`, no warning is left (neither W0505 nor W0516: before, the hint's
    `Inside(label, body)`, made, set the mark on the cut edge), the plate's outline is the
    same and the mark is the same strokes (count and length), moved."""
    x, y = round(W / 2 * (0.6 + fx), 3), round(H / 2 * fy, 3)
    mark = {"C": f"Circle(center=({x}, {y}), radius=3)",
            "L": f"Line(({x - 6}, {y}), ({x + 2}, {y + 1}))",
            "T": f'Text("OK", ({x - 3}, {y}), size=4)',
            "A": f"Arc(center=({x}, {y}), radius=4, start_angle=30 deg, end_angle=150 deg)"}[kind]
    c = _compile(OFF.format(W=W, H=H, mark=mark, fix=""))
    ws = _warnings(c, "W0505")
    if not ws:
        return
    (w,) = ws
    m = re.search(r"`(Inside\([^`]*\))` in `p`", w.hint)
    assert m, w.hint
    after = _compile(OFF.format(W=W, H=H, mark=mark, fix=f"    {m.group(1)}\n"))
    assert _codes(after) == set(), (w.hint, [x.message for x in _warnings(after)])
    assert _same_region(_region(after, "p"), _region(c, "p"))
    assert _engraved(after) == pytest.approx(_engraved(c), abs=1e-6)


def test_a_mark_larger_than_the_body_is_told_to_shrink():
    """No constraint can hold a 30 mm circle on a 20 x 10 mm plate: the hint says to shrink
    it (an `Inside` there is E0401)."""
    c = _compile(OFF.format(W=20, H=10, mark="Circle(center=(0, 0), radius=15)", fix=""))
    (w,) = _warnings(c, "W0505")
    assert "Inside" not in w.hint and w.hint.startswith("shrink the drawing to fit on `body`")


# ------------------------------------------------------------------ W0506, cut away by a hole
CUT = """solid p {{
    body = Rectangle(center=(0, 0), width=30, height=20)
    solid boss {{ c = Circle(center=({cx}, {cy}), radius={r}) }}
    hole h {{ r = Rectangle(center=({cx}, {cy}), width={hw}, height={hh}) }}
}}
"""
KEPT = """solid p {{
    solid plate {{
        body = Rectangle(center=(0, 0), width=30, height=20)
        hole h {{ r = Rectangle(center=({cx}, {cy}), width={hw}, height={hh}) }}
    }}
    solid boss {{ c = Circle(center=({cx}, {cy}), radius={r}) }}
}}
"""


@settings(max_examples=16, deadline=None)
@given(cx=st.integers(-6, 6), cy=st.integers(-3, 3), r=st.floats(2, 6), hw=st.integers(6, 12),
       hh=st.integers(6, 10))
def test_law_a_solid_cut_away_by_its_parts_hole_is_kept_or_deleted_as_told(cx, cy, r, hw, hh):
    """A boss (a disc) in a plate whose own hole cuts it away: W0506.  When the disc reaches
    the plate around the hole, the hint puts the plate's shapes and hole in a solid of their
    own beside it (before: "declare it beside `p`", the part itself: made, the boss became
    a separate part); done, no warning is left and the outline is the plate less the hole
    plus the disc (shapely).  When it lies within the opening, keeping it would be an island
    (W0504): the hint says to delete it, and deleted, nothing changes; when it covers the
    whole opening, keeping it would leave a hole that cuts nothing (W0501) and deleting the
    hole leaves it covered (W0506): the hint says to delete it, and deleted, nothing
    changes."""
    args = dict(cx=cx, cy=cy, r=round(r, 3), hw=hw, hh=hh)
    c = _compile(CUT.format(**args))
    ws = _warnings(c, "W0506")
    if not ws:
        return
    (w,) = ws
    assert "beside `p`" not in w.hint
    plate = box(-15, -10, 15, 10).difference(box(cx - hw / 2, cy - hh / 2, cx + hw / 2, cy + hh / 2))
    assert _same_region(_region(c, "p"), plate)
    if "island" in w.hint or "covers the whole opening" in w.hint:
        after = _compile(CUT.format(**args).replace(
            f"    solid boss {{ c = Circle(center=({cx}, {cy}), radius={args['r']}) }}\n", ""))
        truth = plate
    else:
        assert "put the rest of `p` (its shapes and hole `h`) in a `solid`" in w.hint
        after = _compile(KEPT.format(**args))
        truth = plate.union(Point(cx, cy).buffer(args["r"], 256))
    assert _codes(after) == set(), (w.hint, [x.message for x in _warnings(after)])
    assert [p.name for p in after.drawing.parts] == ["p"]
    assert _same_region(_region(after, "p"), truth, 0.2)


SIGN = """solid sign {{
{ring}
    solid letter {{ p = Circle(center=(0, 0), radius=30) }}
    solid bar {{ b = Rectangle(center=(0, 0), width=180, height=20, rotation=-45 deg) }}
}}
"""
RING = """    disc = Circle(center=(0, 0), diameter=200)
    hole inside { c = Circle(center=(0, 0), diameter=160) }"""


def test_a_solid_in_the_opening_joined_by_another_is_kept_as_the_hint_says():
    """Issue 111 (run s's no-parking sign): a letter inside a ring's opening, crossed by a bar
    that reaches the ring, both declared in the ring's solid with its hole.  W0506 on each;
    the letter's hint said "delete it" (an island), which drops the design; now both say to
    put the ring and its hole in a solid of their own, and done, nothing is cut away: one
    part, the ring, the bar and the disc (shapely)."""
    c = _compile(SIGN.format(ring=RING))
    ws = _warnings(c, "W0506")
    assert len(ws) == 2
    assert all("put the rest of `sign` (its shapes and hole `inside`) in a `solid` of their "
               "own inside `sign`" in w.hint for w in ws)
    kept = _compile(SIGN.format(ring="    solid ring {\n" + RING + "\n    }"))
    assert _codes(kept) == set()
    truth = Point(0, 0).buffer(100, 256).difference(Point(0, 0).buffer(80, 256)).union(
        Point(0, 0).buffer(30, 256)).union(rotate(box(-90, -10, 90, 10), -45, origin=(0, 0)))
    assert [p.name for p in kept.drawing.parts] == ["sign"]
    assert _same_region(_region(kept, "sign"), truth, 1e-3 * truth.area)     # (chords)


# ------------------------------------------------------------------ W0504, two pieces
APART = """solid p {{
    body = Rectangle(center=(0, 0), width=30, height=16)
    foot = {foot}
{fix}}}
"""


@settings(max_examples=16, deadline=None)
@given(side=st.sampled_from(["below", "above", "left", "right"]), gap=st.floats(0.2, 3),
       round_=st.booleans(), size=st.integers(2, 8), along=st.floats(-0.5, 0.5))
def test_law_two_pieces_joined_by_the_hints_constraint(side, gap, round_, size, along):
    """A foot (a rectangle or a disc, ``size`` mm) drawn ``gap`` mm off one side of a body:
    W0504 writes the relation that holds as drawn, foot first (`Below(foot, body, gap=-1
    mm)`).  Added to `p`, no warning is left, the body stays where written and the foot
    moves straight towards it until they overlap by the figure given: the outline is the
    union of the body and the foot so moved (shapely).  Before, the hint's example
    `Above(a, b, gap=-1 mm)`, made with the pieces in the order named, put a foot drawn
    under the body on top of it."""
    gap, along = round(gap, 3), round(along * 10, 3)
    half = size / 2
    at = {"below": (along, -8 - gap - half), "above": (along, 8 + gap + half),
          "left": (-15 - gap - half, along / 2), "right": (15 + gap + half, along / 2)}[side]
    toward = {"below": (0, 1), "above": (0, -1), "left": (1, 0), "right": (-1, 0)}[side]

    def foot(x, y):
        x, y = round(x, 6), round(y, 6)
        return (f"Circle(center=({x}, {y}), radius={half})" if round_ else
                f"Rectangle(center=({x}, {y}), width={size}, height={size})"), \
            (Point(x, y).buffer(half, 256) if round_ else box(x - half, y - half, x + half, y + half))

    src, _ = foot(*at)
    c = _compile(APART.format(foot=src, fix=""))
    (w,) = _warnings(c, "W0504")
    m = re.search(r"`((Below|Above|LeftOf|RightOf)\(foot, body, gap=-([0-9.]+) mm\))` in `p`",
                  w.hint)
    assert m, w.hint
    assert m.group(2) == {"below": "Below", "above": "Above", "left": "LeftOf",
                          "right": "RightOf"}[side]
    over = float(m.group(3))
    after = _compile(APART.format(foot=src, fix=f"    {m.group(1)}\n"))
    assert _codes(after) == set(), (w.hint, [x.message for x in _warnings(after)])
    shift = gap + over
    _, moved = foot(at[0] + toward[0] * shift, at[1] + toward[1] * shift)
    truth = unary_union([box(-15, -8, 15, 8), moved])
    assert _same_region(_region(after, "p"), truth, 0.2)


def test_a_disc_set_half_a_millimetre_clear_by_inside_is_clear():
    """The case W0505's law found: a disc constrained `Inside(d.mark, body, margin=0.5 mm)`
    ends 0.4999999 mm from the plate's side after solving, and W0516 said it "comes 0.50 mm
    from the cut edge" (the hint's own fix, warned again): clear to within 1e-6 mm is clear."""
    mark = "Circle(center=(18.225, 0.0), radius=3)"
    c = _compile(OFF.format(W=27, H=10, mark=mark, fix="    Inside(d.mark, body, margin=0.5 mm)\n"))
    assert _codes(c) == set()


def test_ledges_of_one_part_are_said_a_few_and_counted():
    """A comb of 12 teeth on a spine, each with a collar flush with its left side and 0.2 mm
    past its right side: 12 ledges (before, 12 W0520 lines), said 5 and "(and 7 more like
    it in `p`)"."""
    src = ("solid p {\n    spine = Rectangle(center=(33, 0), width=72, height=4)\n"
           + "".join(f"    t{k} = Rectangle(center=({k * 6}, 6), width=3, height=8)\n"
                     f"    s{k} = Rectangle(center=({k * 6 + 0.1}, 3), width=3.2, height=2)\n"
                     for k in range(12)) + "}\n")
    ws = _warnings(_compile(src), "W0520")
    assert len(ws) == SHOWN and all("pokes 0.20 mm past" in w.message for w in ws)
    assert ws[-1].message.endswith(f"(and {12 - SHOWN} more like it in `p`)")
