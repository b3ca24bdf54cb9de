"""Issue 73, parts stay, features move: when a constraint relates a structure's own geometry
(the part) to a descendant's (a hole, a child solid, a pattern's target) or a part to a hole
that ``CutInto`` cuts into it, the solve keeps the part where it is written and moves the
feature, unless the part is the only thing free (docs/solver.md, "Parts stay, features
move").

The four cases of the issue are programs in tests/programs/parts_stay/, compiled once each
through the public API; positions are read back from the solved values and the final parts
(``Result.values``, ``Result.parts``), and every constraint's residual is checked exact."""
from __future__ import annotations

import pytest

import aidl_lang
from aidl_lang.api.values import exact_bbox
from aidl_lang.solver import constraint_residuals
from conftest import ROOT

PROGRAMS = ROOT / "tests" / "programs" / "parts_stay"
EXACT = 1e-9


def _compile(source: str | None = None, name: str | None = None):
    if name is not None:
        r = aidl_lang.compile(path=str(PROGRAMS / name))
    else:
        r = aidl_lang.compile(source)
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    worst = max((v for _, v in constraint_residuals(r.compiled.model)), default=0.0)
    assert worst < EXACT, worst
    return r


def _values(r) -> dict:
    return {v.name: v.mm for v in r.values}


@pytest.fixture(scope="module")
def corner():
    return _values(_compile(name="corner_pattern.aidl"))


def test_corner_pattern_keeps_the_plate_and_moves_the_holes(corner):
    # before: plate.body.center (33.649, 13.057), the hole at (0, 0)
    assert corner["plate.body.center"] == pytest.approx((0, 0), abs=EXACT)
    got = sorted(tuple(round(c, 6) for c in corner[k]) for k in
                 ("plate.h.c.center", "plate.h_pattern[1].c.center",
                  "plate.h_pattern[2].c.center", "plate.h_pattern[3].c.center"))
    dx, dy = 60 - 26.3507, 35 - 21.9429
    assert got == sorted((round(sx * dx, 6), round(sy * dy, 6)) for sx in (-1, 1)
                         for sy in (-1, 1))
    assert corner["plate.h.c.center"] == pytest.approx((-dx, -dy), abs=EXACT)


def test_a_bolt_goes_to_its_place_on_the_plate():
    v = _values(_compile(name="bolt.aidl"))
    # before: the bolt kept (20, 20) and the plate moved to (-10, 5)
    assert v["plate.body.center"] == pytest.approx((0, 0), abs=EXACT)
    assert v["plate.bolt.c.center"] == pytest.approx((30, 15), abs=EXACT)


def test_a_knob_comes_to_the_ellipse():
    v = _values(_compile(name="knob.aidl"))
    # before: the ellipse moved up to (0, 7)
    assert v["mirror.body.center"] == pytest.approx((0, 0), abs=EXACT)
    assert v["mirror.knob.c.center"] == pytest.approx((0, 25), abs=EXACT)


@pytest.fixture(scope="module")
def lid():
    return _compile(name="lid_hole.aidl")


def test_a_hole_cut_into_a_generated_lid_goes_to_the_lid(lid):
    r = lid
    parts = {p.name: p for p in r.parts}
    # before: the whole box moved 70 mm down to meet the hole halfway (bottom at y -70)
    assert parts["kit.box.bottom"].bbox == pytest.approx((-40, -30, 40, 30), abs=EXACT)
    x0, y0, x1, y1 = parts["kit.box.lid"].bbox
    assert parts["kit.box.lid"].holes == 1
    c = _values(r)["kit.lid_hole.c.center"]
    assert c == pytest.approx(((x0 + x1) / 2, (y0 + y1) / 2), abs=EXACT)
    assert (x0, y0) == pytest.approx((-40, 80), abs=EXACT)


def test_the_part_moves_when_it_is_the_only_thing_free():
    # docs/language.md, CornerPattern: with the original `Fixed` (and the plate free) the
    # plate moves so that its bottom-left corner comes to the original
    src = (PROGRAMS / "corner_pattern.aidl").read_text().replace(
        "CornerPattern(h, body", "Fixed(h)\n    CornerPattern(h, body")
    v = _values(_compile(src))
    assert v["plate.h.c.center"] == pytest.approx((0, 0), abs=EXACT)
    assert v["plate.body.center"] == pytest.approx((60 - 26.3507, 35 - 21.9429), abs=EXACT)


def test_the_parts_own_constraints_still_place_it():
    # `body.bb.left == 0` moves the plate along x only; the bolt then goes to its corner
    src = (PROGRAMS / "bolt.aidl").read_text().replace(
        "At(", "body.bb.left == 0\n    At(")
    v = _values(_compile(src))
    assert v["plate.body.center"] == pytest.approx((40, 0), abs=EXACT)
    assert v["plate.bolt.c.center"] == pytest.approx((70, 15), abs=EXACT)


def test_a_lid_placed_on_the_rest_of_its_box_comes_down_to_it():
    # docs/language.md 6.5 (descendant exclusion): before, the box's body moved up to (0, 37.5)
    src = """
solid box {
    body = Rectangle(center=(0, 0), width=40, height=20)
    solid lid {
        top = Rectangle(center=(0, 50), width=30, height=5)
    }
    Above(lid, self)
    AlignCenterX(lid, self)
}
"""
    v = _values(_compile(src))
    assert v["box.body.center"] == pytest.approx((0, 0), abs=EXACT)
    assert v["box.lid.top.center"] == pytest.approx((0, 12.5), abs=EXACT)


def test_the_bracket_stays_on_its_written_center():
    # examples/bracket.aidl: the plate is written at (0, 0); before, it moved to (-6, 0) to
    # meet its bolt row (whose first hole is written at x = 0): the bracket was lopsided
    r = _compile((ROOT / "examples" / "bracket.aidl").read_text())
    v = _values(r)
    assert v["bracket.plate.center"] == pytest.approx((0, 0), abs=EXACT)
    assert v["bracket.bbox"] == pytest.approx((-64, -20, 64, 20), abs=EXACT)
    assert [v[f"bracket.holes[{k}].c.center"][0] for k in range(4)] == \
        pytest.approx([-30, -10, 10, 30], abs=EXACT)


def test_following_w0109s_fix_moves_no_part(lid):
    """The same hole without `CutInto` (W0109: it cuts nothing; its fix writes the
    `CutInto`): the box stays where finger_box puts it there too, so the fix moves nothing
    (before: the box went 70 mm down to meet the hole halfway, and stayed there with the
    fix only after this change)."""
    src = (PROGRAMS / "lid_hole.aidl").read_text().replace(
        "    CutInto(lid_hole, box.lid)\n", "")
    r = _compile(src)
    assert [d.code for d in r.diagnostics] == ["W0109"]
    before = {p.name: p.bbox for p in r.parts if p.name.startswith("kit.box.")}
    after = {p.name: p.bbox for p in lid.parts}
    assert len(before) == 6
    assert before["kit.box.bottom"] == pytest.approx((-40, -30, 40, 30), abs=EXACT)
    for name, box in before.items():
        assert box == pytest.approx(after[name], abs=EXACT), name
    (hole,) = [p for p in r.output.stray if p.name == "kit.lid_hole"]   # cuts nothing: no part
    x0, y0, x1, y1 = after["kit.box.lid"]
    assert exact_bbox([s for lp in hole.loops for s in lp.segments]) == pytest.approx(((x0 + x1) / 2 - 10, (y0 + y1) / 2 - 10,
                                       (x0 + x1) / 2 + 10, (y0 + y1) / 2 + 10), abs=EXACT)


def test_the_first_named_part_goes_to_the_second_and_the_hole_cut_into_one_goes_to_it():
    """In an assembly, of two parts related to each other the first-named (`b`) moves to the
    second (`a`, the reference; issue 84; before: both moved, to meet halfway at 25 / 75); a
    hole the assembly cuts into one of them moves to it (issue 73; before that: `a` went
    25 mm up to meet the hole halfway, and the parts met at 16.667 / 66.667)."""
    v = _values(_compile("""
assembly kit {
    solid a { body = Rectangle(center=(0, 0), width=40, height=20) }
    solid b { body = Rectangle(center=(100, 0), width=40, height=20) }
    hole h { c = Circle(center=(0, 50), radius=3) }
    RightOf(b, a, gap=10)
    CenterInside(h, a)
    CutInto(h, a)
}
"""))
    assert v["kit.a.body.center"] == pytest.approx((0, 0), abs=EXACT)
    assert v["kit.b.body.center"] == pytest.approx((50, 0), abs=EXACT)
    assert v["kit.h.c.center"] == pytest.approx((0, 0), abs=EXACT)


def test_a_knob_drawn_beside_the_ellipse_in_one_solid_comes_to_it():
    """The same knob drawn as a shape of the ellipse's own solid, not a child: the first
    drawn closed shape is the part and stays (before: they met halfway, the ellipse at
    (0, 3.5) and the knob at (0, 28.5)); a Fixed knob still moves the part to it."""
    src = """
solid mirror {
    body = Ellipse(center=(0, 0), rx=40, ry=25)
    knob = Circle(center=(0, 32), radius=5)
    Coincident(knob.center, body)
    AlignCenterX(knob, body)
}
"""
    v = _values(_compile(src))
    assert v["mirror.body.center"] == pytest.approx((0, 0), abs=EXACT)
    assert v["mirror.knob.center"] == pytest.approx((0, 25), abs=EXACT)
    fixed = _values(_compile(src.replace("AlignCenterX", "Fixed(knob)\n    AlignCenterX")))
    assert fixed["mirror.knob.center"] == pytest.approx((0, 32), abs=EXACT)
    assert fixed["mirror.body.center"] == pytest.approx((0, 7), abs=EXACT)


def test_the_shapes_own_constraints_place_the_part_before_the_knob_comes_to_it():
    """Within one solid, the part's own row (``body.center.y == body.center.x + 5``, which
    no pinning meets) places it first (the least move: (-2.5, 2.5)), then the knob comes to
    it (before: stage shapes failed on that row and everything moved, the body to
    (-0.75, 4.25), further than its own row asks, to meet the knob)."""
    src = """
solid mirror {
    body = Ellipse(center=(0, 0), rx=40, ry=25)
    knob = Circle(center=(0, 32), radius=5)
    body.center.y == body.center.x + 5
    Coincident(knob.center, body)
    AlignCenterX(knob, body)
}
"""
    v = _values(_compile(src))
    assert v["mirror.body.center"] == pytest.approx((-2.5, 2.5), abs=EXACT)
    assert v["mirror.knob.center"] == pytest.approx((-2.5, 27.5), abs=EXACT)
    assert v["mirror.body.rx"] == pytest.approx(40, abs=EXACT)
