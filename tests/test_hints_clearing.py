"""Issue 91: W0508's machine fix was `AllowOverlap(pens, phone)`, which silenced a pen hole
running into a phone slot (a repair loop applying it hides the defect).  Now two different
holes that overlap get a fix that moves one of them clear: the shortest move that leaves the
minimum wall to the other hole, to every other hole and to the outline, written in the
shape's own call (its expressions kept: `-40 + 20 * i` becomes `-40 + 20 * i - 3.52`).
Only copies of one pattern overlapping by more than a wall (a row of vents run into a slot
by design) get `AllowOverlap`.

The law: generated pairs of overlapping holes (circles, rectangles, triangles; positions
written as numbers or as param expressions; one hole drawn alone or as a loop's two copies,
which the fix moves together; a third hole standing by), each fix applied to
the file and the file checked again with `aidl check`'s compile: the overlap is gone, no
warning is left or added, the plate has one opening per hole, and for two circles (two
rectangles) the move is the shortest one, to 0.03 mm.  Cost: 14 generated cases, two small
compiles each, about 2.5 s (3 s with the other tests here)."""
from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings, strategies as st

from aidl_lang.pipeline import compile_source

WALL = 0.5


def _compile(tmp, src: str, name: str = "pair.aidl"):
    p = tmp / name
    p.write_text(src)
    c = compile_source(src, str(p))
    assert c.ok, [(d.code, d.message) for d in c.sink.items if d.severity == "error"]
    return c


def _apply(src: str, fix) -> str:
    sp = fix.span
    return src[:sp.start] + fix.replacement + src[sp.end:]


def _fixed_clean(tmp, src: str, replacement: str):
    """The one W0508 of ``src``: its fix is ``replacement``, and the file with it applied
    checks with no warning at all.  Returns the warning and the fixed compile."""
    c = _compile(tmp, src)
    (w,) = [d for d in c.sink.items if d.code == "W0508"]
    assert w.fix.replacement == replacement, (w.fix.replacement, w.hint)
    fixed = _compile(tmp, _apply(src, w.fix), "fixed.aidl")
    assert not [d for d in fixed.sink.items if d.severity == "warning"]
    return w, fixed


def _shape(kind: str, x: str, y: str, size: float) -> str:
    if kind == "circle":
        return f"Circle(center=({x}, {y}), radius={size})"
    if kind == "rect":
        return f"Rectangle(center=({x}, {y}), width={2 * size}, height={1.2 * size})"
    return (f"Polygon([({x} - {size}, {y} - {size}), ({x} + {size}, {y} - {size}), "
            f"({x}, {y} + {size})])")


PROGRAM = """param shift = {shift}
solid plate {{
    body = Rectangle(center=(0, 0), width=140, height=100)
    hole a {{ s = {a} }}
    hole b {{ s = {b} }}
    hole c {{ s = Circle(center=({cx}, {cy}), radius=3) }}
}}
"""


def _bbox_gap(c) -> list:
    return [d for d in c.sink.items if d.severity == "warning"]


@settings(max_examples=14, deadline=None)
@given(ka=st.sampled_from(["circle", "rect", "tri"]), kb=st.sampled_from(["circle", "rect", "tri"]),
       sa=st.floats(3, 9), sb=st.floats(3, 9), angle=st.floats(0, 2 * math.pi),
       depth=st.floats(0.3, 0.8), param=st.booleans(), c_at=st.floats(0, 2 * math.pi),
       row=st.booleans())
def test_law_each_W0508_fix_clears_the_overlap_and_nothing_gets_worse(
        tmp_path_factory, ka, kb, sa, sb, angle, depth, param, c_at, row):
    tmp = tmp_path_factory.mktemp("pair")
    sa, sb = round(sa, 3), round(sb, 3)
    reach = (sa + sb) * (1 - depth)               # centres closer than the sizes: overlap
    bx, by = round(reach * math.cos(angle), 3), round(reach * math.sin(angle), 3)
    cx, cy = round(bx / 2 + 20 * math.cos(c_at), 3), round(by / 2 + 20 * math.sin(c_at), 3)
    x = f"shift + {bx - 7}" if param else f"{bx}"
    b = _shape(kb, x, f"{by}", sb)
    if row:                 # b one of a loop's copies: the fix moves the statement, all of them
        b = _shape(kb, f"{x} + {round(2.5 * sb + 2, 3)} * k", f"{by}", sb)
        b = f"[{b} for k in range(2)]"
    src = PROGRAM.format(shift=7, a=_shape(ka, "0", "0", sa), b=b, cx=cx, cy=cy)
    c = _compile(tmp, src)
    ws = [d for d in c.sink.items if d.code == "W0508"]
    assume(len(ws) == 1 and not [d for d in _bbox_gap(c) if d.code != "W0508"])
    (w,) = ws
    assume("wholly inside" not in w.message)          # one inside the other: no move meant
    # two that cross are a note, one cross-shaped opening (every crossing the model runs met
    # was meant, issue 111 round eleven): its hint gives the move, it proposes no fix
    assume(w.severity == "warning")
    assert w.fix is not None and "AllowOverlap" not in w.fix.replacement, w.hint
    if param and "plate.b" in w.hint.split("further")[0]:
        assert "shift +" in w.fix.replacement          # the param expression is kept
    fixed = _compile(tmp, _apply(src, w.fix), "fixed.aidl")
    left = [(d.code, d.message) for d in _bbox_gap(fixed)]
    assert left == [], (w.hint, w.fix.replacement, left)
    (part,) = fixed.drawing.parts
    assert part.shape.num_contour() == 4 + row         # the outline and one per hole shape
    # the shortest move, where it is known in closed form: never shorter; no longer unless
    # the third hole stands in its way
    v = [float(t) for t in w.hint.split("by (")[1].split(")")[0].split(", ")]
    moved = math.hypot(*v)
    need = None
    if ka == kb == "circle" and not row:
        need = sa + sb - reach + WALL
    if ka == kb == "rect" and not row:
        need = min(sa + sb - abs(bx), 0.6 * (sa + sb) - abs(by)) + WALL
    if need is not None:
        assert need <= moved + 0.01, (need, moved)
        clear = min(math.hypot(cx, cy), math.hypot(cx - bx, cy - by)) - 3 - 2 * max(sa, sb)
        if clear > need + 1:
            assert moved <= need + 0.03, (need, moved, w.hint)


def test_the_pen_and_the_phone_slot(tmp_path):
    """The issue's case: a row of pen holes, one running into the phone slot.  The fix moves
    the row's statement by the shortest move (3.5 mm and the margin, along x), written
    against the loop's own expression; applied, the design checks clean with 5 openings."""
    src = """param width = 160
param pen_d = 12
solid organizer {
    base = Rectangle(center=(0, 0), width=width, height=80)
    hole phone {
        slot = Rectangle(center=(30, 0), width=14, height=70)
    }
    hole pens {
        holes = [Circle(center=(-40 + 20 * i, 20), radius=pen_d / 2) for i in range(4)]
    }
}
"""
    w, fixed = _fixed_clean(tmp_path, src,
                            "Circle(center=(-40 + 20 * i - 3.52, 20), radius=pen_d / 2)")
    assert "by (-3.52, 0.00) mm" in w.hint and "4 copies" in w.hint
    assert fixed.drawing.parts[0].shape.num_contour() == 6


def test_a_hole_placed_by_a_constraint_is_not_the_one_moved_and_never_AllowOverlap(tmp_path):
    """The screw's place is a constraint's, so editing its call would move nothing: the
    fix moves the opening instead (its place is its call's); with both placed by
    constraints there is no fix, only the hint.  A window more than four times the screw's
    area is never the one moved (run dd: a 201 mm window moved 10.5 mm off its engraved
    index for a thumb notch on its edge): no fix, the hint names the screw."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole opening { r = Rectangle(center=(0, 0), width=10, height=8) }
    hole screw { c = Circle(center=(0, 0), radius=3) }
    screw.c.center == (6, 0)
}
"""
    w, fixed = _fixed_clean(tmp_path, src, "Rectangle(center=(-2.51, 0), width=10, height=8)")
    window = src.replace("width=10, height=8", "width=30, height=20").replace("(6, 0)", "(15, 0)")
    c = _compile(tmp_path, window, "window.aidl")
    (w,) = [d for d in c.sink.items if d.code == "W0508"]
    assert w.fix is None and "move hole `plate.screw`" in w.hint
    both = src.replace("    screw.c.center", "    opening.r.center == (0, 0)\n    screw.c.center")
    c = _compile(tmp_path, both, "both.aidl")
    (w,) = [d for d in c.sink.items if d.code == "W0508"]
    assert w.fix is None and "move hole `plate.screw`" in w.hint


def test_copies_of_one_pattern_overlapping_by_design_keep_AllowOverlap(tmp_path):
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole vent { c = Circle(center=(-20, 0), radius=4) }
    vents = LinearPattern(vent, 4, (7, 0))
}
"""
    c = _compile(tmp_path, src)
    ws = [d for d in c.sink.items if d.code == "W0508"]
    assert ws and all(d.fix is not None and d.fix.replacement.strip() in (
        "AllowOverlap(vents)", "AllowOverlap(vent, vents)")
                      for d in ws)
    grazing = src.replace("(7, 0)", "(7.8, 0)")              # 0.2 mm deep: a slip, no fix
    c = _compile(tmp_path, grazing, "grazing.aidl")
    ws = [d for d in c.sink.items if d.code == "W0508"]
    assert ws and all(d.fix is None for d in ws)


def test_the_hint_offers_the_radius_that_clears_and_it_does(tmp_path):
    """A screw hole 1 mm over a window's edge: the fix moves it 1.51 mm out; the hint also
    gives the radius that would clear instead (its centre 5 mm from the edge: 4.49 mm),
    which written in leaves the wall."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole window { r = Rectangle(center=(0, 0), width=30, height=20) }
    hole screw { c = Circle(center=(20, 0), radius=6) }
}
"""
    c = _compile(tmp_path, src)
    (w,) = [d for d in c.sink.items if d.code == "W0508"]
    assert w.fix.replacement == "Circle(center=(21.51, 0), radius=6)"
    assert "or make its radius 4.49 mm so that it clears" in w.hint
    smaller = _compile(tmp_path, src.replace("radius=6", "radius=4.49"), "smaller.aidl")
    assert not [d for d in smaller.sink.items if d.severity == "warning"]


def test_the_move_is_written_in_the_files_units(tmp_path):
    """`units inch`: the screw's centre moved by 3.69 mm is written 0.75 + 0.1453 in (the
    move rounded up to 1e-4 in), and the file so fixed checks clean."""
    src = """units inch
solid plate {
    body = Rectangle(center=(0, 0), width=4, height=3)
    hole opening { r = Rectangle(center=(0, 0), width=1.5, height=1) }
    hole screw { c = Circle(center=(0.75, 0), radius=0.125) }
}
"""
    w, fixed = _fixed_clean(tmp_path, src, "Circle(center=(0.8953, 0), radius=0.125)")


def test_a_circular_patterns_copy_is_not_moved_by_its_original_the_other_hole_is(tmp_path):
    """Moving a CircularPattern's original turns each copy's move: the edit of its call is
    no fix.  The slot overlapping a copy is moved instead, and the file so fixed is clean."""
    src = """solid plate {
    body = Circle(center=(0, 0), radius=50)
    hole ring {
        c = Circle(center=(20, 0), radius=4)
        cs = CircularPattern(c, 6, (0, 0))
    }
    hole slot { s = Rectangle(center=(5, 20), width=10, height=6) }
}
"""
    w, fixed = _fixed_clean(tmp_path, src, "Rectangle(center=(0.49, 20), width=10, height=6)")
    placed = src.replace("\n}\n", "\n    slot.s.center == (5, 20)\n}\n")
    c = _compile(tmp_path, placed, "placed.aidl")
    (w,) = [d for d in c.sink.items if d.code == "W0508"]
    assert w.fix is None                # neither can be moved by its call: the hint alone


HANGER = """solid hanger {
    board = RoundedRectangle(center=(0, 0), width=90, height=220, corner_radius=8)
    hole knob { c = Circle(center=(0, 60), diameter=55) }
    hole slit { s = Rectangle(center=(30, 60), width=45, height=4) }
    AlignCenterX(knob, board)
    VerticalDistance(knob.c.center, board.top.midpoint, 45 mm)
    AlignCenterY(slit, knob)
    slit.s.left.midpoint.x == knob.c.center.x
    slit.bb.right == board.bb.right
    ALLOW
}
"""


def test_a_slit_placed_from_a_holes_centre_reads_as_one_opening(tmp_path):
    """105e #01: a door hanger's slit, placed by relations from the knob hole's centre to the
    edge (61 % of it inside the hole): W0508's hint led with moving the slit 28 mm away,
    which cuts it off its hole.  Now it leads with the one opening (`AllowOverlap`), the
    move second, and no machine fix; followed, the program checks clean.  A hole only half
    inside another (a screw centred on a window's edge, a common slip) still leads with the
    move."""
    c = _compile(tmp_path, HANGER.replace("ALLOW", ""))
    (w,) = [d for d in c.sink.items if d.code == "W0508"]
    assert w.fix is None
    assert w.hint.startswith("one opening looks meant (61% of hole `hanger.slit` lies inside "
                             "hole `hanger.knob`): write `AllowOverlap(knob, slit)` in `hanger`")
    assert "; if two are meant, move hole `hanger.slit` 28.01 mm further" in w.hint
    ok = _compile(tmp_path, HANGER.replace("ALLOW", "AllowOverlap(knob, slit)"), "ok.aidl")
    assert not [d for d in ok.sink.items if d.severity == "warning"]
    (part,) = ok.drawing.parts
    assert part.shape.num_contour() == 1      # the slit runs out at the edge: one outline
    edge = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole opening { r = Rectangle(center=(0, 0), width=30, height=20) }
    hole screw { c = Circle(center=(0, 0), radius=3) }
    opening.r.center == (0, 0)
    screw.c.center == (15, 0)
}
"""
    (w,) = [d for d in _compile(tmp_path, edge, "edge.aidl").sink.items if d.code == "W0508"]
    assert w.hint.startswith("move hole `plate.screw`"), w.hint
