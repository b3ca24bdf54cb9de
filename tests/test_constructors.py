"""Constructor variants: Triangle by base and height, Trapezoid, Arc through three points,
Ellipse (held semi-axes and rotation, drawn as a polyline loop, bounding box exact)."""
import math

import numpy as np
import pytest

from aidl_lang.output import area, render_model


def solved(compile_text, body):
    c = compile_text("solid s {\n" + body + "\n}\n")
    assert c.ok, [d.message for d in c.sink.items]
    x = c.model.xs()
    geo = {g.name: g for g in c.model.all_geometry()}
    P = lambda g, n: np.array([x[geo[g].points[n].ix], x[geo[g].points[n].iy]])
    return c, P


def test_triangle_by_base_and_height(compile_text):
    c, P = solved(compile_text, "t = Triangle(center=(5, 5), base=40, height=30, rotation=90 deg)\n"
                                "    Fixed(t.a)")
    a, b, apex = P("t", "a"), P("t", "b"), P("t", "c")
    assert np.linalg.norm(a - b) == pytest.approx(40)
    mid = (a + b) / 2
    assert np.linalg.norm(apex - mid) == pytest.approx(30)
    assert apex[0] < mid[0] and apex[1] == pytest.approx(mid[1])      # turned 90 deg: apex left
    assert area(render_model(c.model)) == pytest.approx(600, rel=1e-9)


def test_trapezoid_members_and_area(compile_text):
    c, P = solved(compile_text, "z = Trapezoid(center=(0, 0), bottom_width=30, top_width=10, height=20)\n"
                                "    r = Rectangle(center=(0, 40), width=10, height=5)\n"
                                "    Coincident(r.bottom_left, z.top_left)\n"
                                "    z.bottom_width + z.top_width == 40")
    assert P("z", "top_left") == pytest.approx(P("r", "bottom_left"))
    assert P("z", "top_right")[0] - P("z", "top_left")[0] == pytest.approx(10)
    assert area(render_model(c.model)) == pytest.approx((30 + 10) / 2 * 20 + 50)


@pytest.mark.parametrize("through, below", [((0, -25), True), ((0, 15), False)])
def test_arc_through_three_points(compile_text, through, below):
    c, P = solved(compile_text, f"a = Arc(start=(-20, -5), through={through}, end=(20, -5))\n"
                                "    l = Line(a.end, a.start)")
    s, e, t, ctr = (P("a", n) for n in ("start", "end", "through", "center"))
    r = np.linalg.norm(s - ctr)
    assert np.linalg.norm(e - ctr) == pytest.approx(r) and np.linalg.norm(t - ctr) == pytest.approx(r)
    # the closed face (arc + chord) lies on the side of the through point
    d = render_model(c.model)
    b = d.parts[0].shape.bounds()
    assert (b[1] < -20) == below and (b[3] > 10) == (not below)


def test_arc_through_collinear_points_is_a_diagnostic(compile_text):
    c = compile_text("solid s {\n    a = Arc(start=(0, 0), through=(1, 0), end=(2, 0))\n}\n")
    assert [d.code for d in c.sink.items] == ["E0108"]
    assert "not on one line" in c.sink.items[0].message


def test_ellipse_area_rotation_and_bounding_box(compile_text):
    c, P = solved(compile_text, "e = Ellipse(center=(0, 0), rx=20, ry=10, rotation=30 deg)\n"
                                "    Fixed(e.center)\n"
                                "    r = Rectangle(center=(50, 0), width=10, height=10)\n"
                                "    LeftOf(e, r, gap=5)\n    AlignTop(r, e)")
    d = render_model(c.model)
    assert area(d) == pytest.approx(math.pi * 20 * 10 + 100, rel=5e-4)
    ex = math.sqrt((20 * math.cos(math.pi / 6)) ** 2 + (10 * math.sin(math.pi / 6)) ** 2)
    ey = math.sqrt((20 * math.sin(math.pi / 6)) ** 2 + (10 * math.cos(math.pi / 6)) ** 2)
    assert P("r", "bottom_left")[0] == pytest.approx(ex + 5)
    assert P("r", "top_left")[1] == pytest.approx(ey)


def test_ellipse_needs_positive_axes(compile_text):
    c = compile_text("solid s {\n    e = Ellipse((0, 0), 0, 3)\n}\n")
    assert [d.code for d in c.sink.items] == ["E0108"]
