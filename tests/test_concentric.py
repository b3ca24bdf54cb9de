"""``Concentric`` takes every shape that has a center (issue 36): each is solved onto a
free circle's center; a structure (a spur gear instance) is refused with a located hint
that names the member to use."""
from __future__ import annotations

import pytest

import aidl_lang

CENTERED = {
    "Circle": "Circle(center=(7, -3), radius=2)",
    "Arc": "Arc(center=(7, -3), radius=4, start_angle=10 deg, end_angle=80 deg)",
    "ArcSlot": "ArcSlot(center=(7, -3), radius=8, start_angle=-30 deg, end_angle=100 deg, width=3)",
    "Star": "Star(center=(7, -3), points=5, outer_radius=6, inner_radius=2.5)",
    "RegularPolygon": "RegularPolygon(center=(7, -3), radius=5, sides=6)",
    "Ellipse": "Ellipse(center=(7, -3), rx=6, ry=3, rotation=20 deg)",
    "Slot": "Slot(center=(7, -3), length=12, width=4, rotation=30 deg)",
    "Rectangle": "Rectangle(center=(7, -3), width=9, height=4)",
    "Trapezoid": "Trapezoid(center=(7, -3), bottom_width=10, top_width=4, height=5)",
}


@pytest.mark.parametrize("kind", sorted(CENTERED))
@pytest.mark.parametrize("order", ["shape first", "circle first"])
def test_concentric_takes_every_centered_shape(kind, order):
    args = "s, c" if order == "shape first" else "c, s"
    src = (f"units mm\nsolid a {{\n    s = {CENTERED[kind]}\n"
           f"    c = Circle(center=(-20, 15), radius=1)\n    Concentric({args})\n}}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]
    cx, cy = r.value("a.c.center").mm
    sx, sy = r.value("a.s.center").mm
    assert abs(cx - sx) < 1e-9 and abs(cy - sy) < 1e-9
    # the shape is held and free to move; the pair meets between the two starting guesses
    assert abs(cx - 7) > 1e-6 or abs(cy + 3) > 1e-6 or abs(cx + 20) > 1e-6


def test_concentric_with_a_point():
    src = ("units mm\nsolid a {\n"
           "    c = Circle(center=(0, 0), radius=1)\n    Concentric(c, (4, 2))\n}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]
    assert r.value("a.c.center").mm == pytest.approx((4, 2), abs=1e-9)


GEAR = ('units mm\nimport "std/gears.aidl" as gears\nsolid a {{\n'
        '    g = gears.spur_gear(teeth=12, module=2 mm, cx=30 mm, cy=-4 mm)\n'
        '    c = Circle(center=(0, 0), radius=2)\n    Concentric(c, {})\n}}\n')


def test_concentric_with_a_gear_names_the_member():
    r = aidl_lang.compile(source=GEAR.format("g"))
    (d,) = r.errors
    assert d.code == "E0108" and "shape with a center" in d.message
    assert (d.span.line, d.span.col, d.span.end_col) == (6, 19, 20)
    assert "`g.hub`" in d.hint and "`g.hub.center`" in d.hint


def test_concentric_with_the_named_gear_member():
    r = aidl_lang.compile(source=GEAR.format("g.hub"))
    assert r.ok, [(d.code, d.message) for d in r.errors]
    # the circle is `a`'s own geometry, the gear a child solid: the part stays where it is
    # written and the gear comes to it (issue 73; before, the circle went to (30, -4))
    assert r.value("a.c.center").mm == pytest.approx((0, 0), abs=1e-9)
    assert r.value("a.g.hub.center").mm == pytest.approx((0, 0), abs=1e-9)


def test_concentric_with_a_shape_without_center():
    src = ("units mm\nsolid a {\n    s = Spline(points=[(0, 0), (5, 3), (9, 0)], closed=true)\n"
           "    c = Circle(center=(0, 0), radius=1)\n    Concentric(c, s)\n}\n")
    (d,) = aidl_lang.compile(source=src).errors
    assert d.code == "E0108" and d.span.line == 5 and "Spline has no center" in d.hint


@pytest.mark.parametrize("call, col, name, kind", [
    ("Coincident(s, (3, 4))", 5, "s", "an ArcSlot"),
    ("Distance(c, t, 20)", 5, "t", "a Star"),
    ("Symmetric(t, s, about=axis)", 5, "t", "a Star"),
    ("At(s, (1, 2))", 8, "s", "an ArcSlot"),
])
def test_point_constraints_name_the_center_member(call, col, name, kind):
    """The other point constraints take points: given a shape with a center, the located
    error's hint names the member to use."""
    src = ("units mm\nsolid a {\n"
           "    s = ArcSlot(center=(5, 5), radius=8, start_angle=0, end_angle=90, width=2)\n"
           "    t = Star(center=(30, 5), points=5, outer_radius=6, inner_radius=2.5)\n"
           "    c = Circle(center=(-10, 0), radius=2)\n"
           "    axis = Line(start=(15, -20), end=(15, 20), construction=true)\n"
           f"    {call}\n}}\n")
    (d,) = aidl_lang.compile(source=src).errors
    assert d.code == "E0108" and (d.span.line, d.span.col) == (7, col)
    assert f"`{name}` is {kind}: name its point, `{name}.center`" in d.hint


def test_named_center_member_is_then_accepted():
    src = ("units mm\nsolid a {\n"
           "    s = ArcSlot(center=(5, 5), radius=8, start_angle=0, end_angle=90, width=2)\n"
           "    Coincident(s.center, (3, 4))\n}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok and r.value("a.s.center").mm == pytest.approx((3, 4), abs=1e-9)
