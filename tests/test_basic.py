import math

import pytest

from aidl_lang.output import area, render_model


def pos(model, g, name):
    p = g.points[name]
    ox = oy = 0.0
    s = p.owner
    while s is not None:
        ox += model.x[s.fx]
        oy += model.x[s.fy]
        s = s.parent
    return model.x[p.ix] + ox, model.x[p.iy] + oy


def geom(model, name):
    return next(g for g in model.all_geometry() if g.name == name)


def test_rectangle_corner_fixed_at_origin(compile_text):
    c = compile_text("""
solid s {
    r = Rectangle(center=(3, 4), width=30, height=20)
    r.bottom_left == (0, 0)
}""")
    assert c.ok, [d.message for d in c.sink.items]
    r = geom(c.model, "r")
    assert pos(c.model, r, "top_right") == pytest.approx((30, 20), abs=1e-8)
    assert pos(c.model, r, "bottom_right") == pytest.approx((30, 0), abs=1e-8)
    assert pos(c.model, r, "top_left") == pytest.approx((0, 20), abs=1e-8)


def test_area_solid_minus_hole(compile_text):
    c = compile_text("""
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole h { c = Circle(center=(3, 1), radius=5) }
    CenterInside(h, self)
}""")
    assert c.ok
    a = area(render_model(c.model))
    assert a == pytest.approx(800 - 25 * math.pi, rel=1e-3)


def test_fixed_corner_stays_and_conflict_is_reported(compile_text):
    ok = compile_text("""
solid s {
    r = Rectangle(bottom_left=(0, 0), width=30, height=20)
    Fixed(r.bottom_left)
}""")
    assert ok.ok
    r = geom(ok.model, "r")
    assert pos(ok.model, r, "top_right") == pytest.approx((30, 20), abs=1e-8)
    bad = compile_text("""
solid s {
    r = Rectangle(bottom_left=(0, 0), width=30, height=20)
    Fixed(r.bottom_left)
    r.top_right == (40, 20)
}""")
    assert not bad.ok
    assert [d.code for d in bad.sink.errors()] == ["E0401"]


def test_a_unit_name_is_one_of_that_unit():
    """`length / mm` (issue 35): a unit's name as a value is 1 of that unit (it was E0101
    "unknown name `mm`"), whatever the file's unit; a name of the program's own hides it."""
    import aidl_lang
    src = ("units in\nparam length = 2 in\nn = length / mm\nq = 90 * deg / rad\n"
           "solid s { body = Rectangle(center=(0, 0), width=n * 1 mm, height=q) }\n")
    r = aidl_lang.compile(source=src)
    assert r.ok, [d.message for d in r.errors]
    got = {v.name: v for v in r.values_matching(["s.body"])}
    assert got["s.body.width"].to_json()["value"] == pytest.approx(50.8 / 25.4, abs=1e-12)
    assert got["s.body.height"].to_json()["value"] == pytest.approx(math.pi / 2, abs=1e-12)
    shadowed = aidl_lang.compile(source="mm = 3\nsolid s { c = Circle(center=(0, 0), radius=mm) }\n")
    assert shadowed.ok and shadowed.values_matching(["s.c.radius"])[0].to_json()["value"] == 3
