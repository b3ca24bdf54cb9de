"""Operations: Mirrored, LinearPattern, CircularPattern (copies that follow their originals
through the solve), Fillet and Chamfer (corners of the final outline, after the booleans)."""
import math

import numpy as np
import pytest

from aidl_lang.output import area, render_model


def run(compile_text, body, kind="solid"):
    c = compile_text(f"{kind} s {{\n{body}\n}}\n")
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    return c


def centers(c, kind="Circle"):
    x = c.model.xs()
    out = []
    for s in c.model.structures:
        for g in s.geometry:
            if g.kind == kind:
                p = g.points["center"]
                ox, oy = s.frame_offset(None)
                from aidl_lang.geometry.core.expr import evaluate
                out.append((round(x[p.ix] + evaluate(ox, x), 6), round(x[p.iy] + evaluate(oy, x), 6)))
    return out


def test_mirrored_geometry_follows_the_original(compile_text):
    c = run(compile_text, "    axis = Line((10, -50), (10, 50), construction=true)\n    Fixed(axis)\n"
                          "    a = Circle((0, 0), 4)\n    b = Mirrored(a, about=axis)\n"
                          "    Coincident(a.center, (-5, 3))")
    assert sorted(centers(c)) == [(-5, 3), (25, 3)]
    assert area(render_model(c.model)) == pytest.approx(2 * math.pi * 16, rel=3e-3)


def test_mirrored_about_a_slanted_line_and_arc_orientation(compile_text):
    c = run(compile_text, "    axis = Line((0, 0), (10, 10), construction=true)\n    Fixed(axis)\n"
                          "    a = Arc((5, 0), (10, 0), (5, 5))\n    l = Line(a.end, a.start)\n"
                          "    b = Mirrored(a, about=axis)\n    m = Mirrored(l, about=axis)")
    x = c.model.xs()
    g = {gg.name: gg for gg in c.model.all_geometry()}
    P = lambda gg, n: (x[gg.points[n].ix], x[gg.points[n].iy])
    assert P(g["b"], "center") == pytest.approx((0, 5))
    # the copy is still counter-clockwise: start and end swap
    assert P(g["b"], "start") == pytest.approx((5, 5)) and P(g["b"], "end") == pytest.approx((0, 10))
    quarter = math.pi * 25 / 4 - 12.5
    assert area(render_model(c.model)) == pytest.approx(2 * quarter, abs=0.08)


def test_mirrored_structure_keeps_kinds_names_and_members(compile_text):
    c = run(compile_text, "    plate = Rectangle(center=(0, 0), width=40, height=20)\n"
                          "    axis = Line((0, -30), (0, 30), construction=true)\n    Fixed(axis)\n"
                          "    solid ear {\n        tab = Rectangle(center=(25, 0), width=10, height=8)\n"
                          "        hole eye {\n            e = Circle((25, 0), 2)\n        }\n    }\n"
                          "    LeftOf(plate, ear)\n    other = Mirrored(ear, about=axis)\n"
                          "    other.tab.height == 8")
    root = c.model.root
    assert set(root.children) == {"ear", "other"}
    assert root.children["other"].kind == "solid" and "eye" in root.children["other"].children
    assert root.children["other"].children["eye"].kind == "hole"
    assert sorted(centers(c)) == [(-25, 0), (25, 0)]
    want = 800 + 2 * (80 - math.pi * 4)
    assert area(render_model(c.model)) == pytest.approx(want, rel=1e-3)


def test_linear_pattern_of_a_hole(compile_text):
    c = run(compile_text, "    plate = Rectangle(center=(0, 0), width=100, height=20)\n"
                          "    hole h {\n        c = Circle((-30, 0), 3)\n    }\n"
                          "    row = LinearPattern(h, 4, (20, 0))\n    row[3].c.radius == 3\n"
                          "    Coincident(row[0].c.center, (-35, 0))")
    assert sorted(centers(c)) == [(-35, 0), (-15, 0), (5, 0), (25, 0)]
    assert area(render_model(c.model)) == pytest.approx(2000 - 4 * math.pi * 9, rel=1e-3)


@pytest.mark.parametrize("extra, want", [
    ("", [0, 60, 120, 180, 240, 300]),
    (", 100 deg", [0, 20, 40, 60, 80, 100]),
])
def test_circular_pattern(compile_text, extra, want):
    c = run(compile_text, f"    a = Circle((10, 0), 1)\n    Fixed(a)\n"
                          f"    ring = CircularPattern(a, 6, (0, 0){extra})")
    angs = sorted(round(math.degrees(math.atan2(y, x)) % 360, 6) for x, y in centers(c))
    assert angs == pytest.approx(want)
    assert all(math.hypot(x, y) == pytest.approx(10) for x, y in centers(c))


def test_pattern_statement_without_a_name_is_not_a_no_op_warning(compile_text):
    c = run(compile_text, "    a = Circle((10, 0), 1)\n    CircularPattern(a, 3, (0, 0))")
    # (three separate discs: only the shape check W0504 says so)
    assert [d.code for d in c.sink.items] == ["W0504"]
    assert len(centers(c)) == 3


def test_fillet_and_chamfer_areas(compile_text):
    sq = "    r = Rectangle(center=(0, 0), width=20, height=20)\n"
    c = run(compile_text, sq + "    Fillet(3)")
    assert area(render_model(c.model)) == pytest.approx(400 - (4 - math.pi) * 9, abs=0.08)
    c = run(compile_text, sq + "    Chamfer(3)")
    assert area(render_model(c.model)) == pytest.approx(400 - 4 * 4.5, rel=1e-9)
    # an L: five convex corners and one concave corner are all rounded
    L = ("    a = Rectangle(bottom_left=(0, 0), width=30, height=10)\n"
         "    b = Rectangle(bottom_left=(0, 0), width=10, height=30)\n    Fixed(a)\n    Fixed(b)\n")
    c = run(compile_text, L + "    Fillet(2)")
    corner = (4 - math.pi) * 4 / 4
    assert area(render_model(c.model)) == pytest.approx(500 - 4 * corner, abs=0.08)
    # thin walls survive: a 1 mm wall between hole and edge with a 3 mm fillet
    c = run(compile_text, sq + "    hole h {\n        c = Circle((0, 6), 3)\n    }\n    Fillet(3)")
    shape = render_model(c.model).parts[0].shape
    assert len(shape.to_polygons()) == 2


def test_fillet_in_a_hole_rounds_the_pocket(compile_text):
    c = run(compile_text, "    r = Rectangle(center=(0, 0), width=40, height=40)\n"
                          "    hole pocket {\n        p = Rectangle(center=(0, 0), width=10, height=10)\n"
                          "        Fillet(2)\n    }")
    assert area(render_model(c.model)) == pytest.approx(1600 - (100 - (4 - math.pi) * 4), abs=0.08)


@pytest.mark.parametrize("body, msg", [
    ("    a = Circle((0, 0), 1)\n    LinearPattern(a, 0, (5, 0))", "count must be a whole number"),
    ("    a = Circle((0, 0), 1)\n    LinearPattern(a, 2.5, (5, 0))", "count must be a whole number"),
    ("    solid c {\n        a = Circle((0, 0), 1)\n        m = Mirrored(c, about=l)\n    }\n"
     "    l = Line((0, 0), (0, 1))", None),
    ("    drawing d {\n        Fillet(2)\n    }", "outline of a solid or hole"),
    ("    solid c {\n        a = Circle((0, 0), 1)\n        LinearPattern(c, 2, (5, 0))\n    }",
     "into itself"),
    ("    a = Circle((0, 0), 1)\n    Fillet(-1)", "a size of 0 or more"),
    # issue 91: copies that would land on one another are said, not stacked in silence
    ("    a = Circle((9, 0), 1)\n    LinearPattern(a, 4, (0, 0))",
     "step is (0, 0): all 4 instances land on one spot"),
    ("    a = Circle((9, 0), 1)\n    CircularPattern(a, 6, (0, 0), angle=0 deg)",
     "every copy lands on the original"),
    ("    a = Circle((9, 0), 1)\n    CircularPattern(a, 3, (0, 0), step=360 deg)",
     "every copy lands on the original (each turns 360 deg)"),
    ("    a = Circle((9, 0), 1)\n    CircularPattern(a, 6, (0, 0), angle=720 deg)",
     "copy 5 lands on the original (5 x 144 deg = 2 whole turns)"),
    ("    a = Circle((9, 0), 1)\n    GridPattern(a, 2, 3, spacing=(0, 5))",
     "column spacing is 0: its 3 columns land on one another"),
    ("    a = Circle((9, 0), 1)\n    GridPattern(a, 2, 3, col_spacing=5, row_spacing=0)",
     "row spacing is 0: its 2 rows land on one another"),
    ("    a = Circle((9, 0), 1)\n    CornerPattern(a, at=[(9, 0), (20, 0), (9, 0)])",
     "points 0 and 2 are both (9, 0) mm"),
])
def test_operation_errors_are_diagnostics(compile_text, body, msg):
    c = compile_text(f"solid s {{\n{body}\n}}\n")
    assert not c.ok
    if msg:
        assert [d.code for d in c.sink.errors()] == ["E0108"]
        assert msg in c.sink.errors()[0].message


def test_copy_outside_the_subtree_is_E0202(compile_text):
    c = compile_text("solid s {\n    solid a {\n        c = Circle((0, 0), 1)\n    }\n"
                     "    solid b {\n        m = LinearPattern(a.c, 2, (5, 0))\n    }\n}\n")
    assert [d.code for d in c.sink.errors()] == ["E0202"]


def test_mirrored_ellipse_rotation(compile_text):
    c = run(compile_text, "    axis = Line((0, 0), (0, 10), construction=true)\n    Fixed(axis)\n"
                          "    e = Ellipse((10, 0), 6, 2, rotation=30 deg)\n    m = Mirrored(e, about=axis)")
    g = [g for g in c.model.all_geometry() if g.kind == "Ellipse"]
    assert math.degrees(g[1].data["rotation"]) == pytest.approx(180 - 30)


def test_patterns_that_only_look_alike_are_made(compile_text):
    """The zero-step refusals stop at what is exactly a stack: one row (rows=1 with a row
    spacing of 0), a full turn of 6 (60 deg apart), 5 copies over 400 deg (100 deg apart:
    past a turn, yet no copy on another; over 720 deg the last always lands on the first)."""
    for body in ("    a = Circle((9, 0), 1)\n    GridPattern(a, 1, 3, spacing=(5, 0))",
                 "    a = Circle((9, 0), 1)\n    CircularPattern(a, 6, (0, 0))",
                 "    a = Circle((9, 0), 1)\n    CircularPattern(a, 5, (0, 0), angle=400 deg)"):
        c = compile_text(f"solid s {{\n{body}\n}}\n")
        assert not c.sink.errors(), [d.message for d in c.sink.errors()]
