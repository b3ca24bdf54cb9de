"""Constructor variants: Triangle by base and height, Trapezoid, Arc through three points,
Ellipse (held semi-axes and rotation, drawn as a polyline loop, bounding box exact)."""
import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

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


# ---------------------------------------------------------------- ArcSlot and Star (issue 23)
def _exact(src):
    from aidl_lang.output.part.part import build
    from aidl_lang.pipeline import compile_source
    c = compile_source(src, "t.aidl")
    assert c.ok and not [d for d in c.sink.items if d.severity == "warning"], \
        [d.message for d in c.sink.items]
    return c, build(c.drawing)


def test_arc_slot_is_four_tangent_arcs_of_the_asked_radii():
    import math
    from aidl_lang.geometry.shapes.curves import Arc, turn_between
    c, o = _exact("solid s { a = ArcSlot(center=(3, -2), radius=15, start_angle=20 deg, "
                  "end_angle=160 deg, width=5) }")
    (loop,) = o.parts[0].loops
    segs = loop.segments
    assert all(isinstance(g, Arc) for g in segs) and len(segs) == 4
    assert sorted(g.radius for g in segs) == pytest.approx([2.5, 2.5, 12.5, 17.5], abs=1e-12)
    for g in segs:
        if g.radius > 3:
            assert g.center == pytest.approx((3, -2), abs=1e-12)
            assert abs(g.sweep) == pytest.approx(math.radians(140), abs=1e-12)
        else:
            assert abs(g.sweep) == pytest.approx(math.pi, abs=1e-12)
    for i, g in enumerate(segs):
        assert abs(turn_between(segs[i - 1], g)) < 1e-12
        assert math.dist(segs[i - 1].end, g.start) < 1e-12
    # area: the annular sector plus two half discs (= one disc of width/2)
    area = 0.5 * math.radians(140) * (17.5 ** 2 - 12.5 ** 2) + math.pi * 2.5 ** 2
    assert loop.area == pytest.approx(area, rel=1e-12)


def test_arc_slot_members_and_bounding_box(compile_text):
    import math
    c = compile_text("solid s {\n a = ArcSlot(center=(0, 0), radius=10, start_angle=0 deg, "
                     "end_angle=90 deg, width=2)\n"
                     " p = Point(at=a.end)\n q = Point(at=a.midpoint)\n}\n")
    assert c.ok
    x = c.model.xs()
    g = {g.name: g for g in c.model.root.geometry}
    pe, pm = g["p"].points["p"], g["q"].points["p"]
    assert (x[pe.ix], x[pe.iy]) == pytest.approx((0, 10), abs=1e-9)
    h = 10 / math.sqrt(2)
    assert (x[pm.ix], x[pm.iy]) == pytest.approx((h, h), abs=1e-9)
    from aidl_lang.geometry.relations.bbox import numeric_box
    # caps around (10, 0) and (0, 10) of radius 1, the outer arc's extremes at x = 11, y = 11
    assert numeric_box(g["a"], c.model.root, x) == pytest.approx((-1, 11, -1, 11), abs=1e-9)


def test_star_tips_and_notches_at_their_radii():
    import math
    c, o = _exact("solid s { st = Star(center=(5, 5), points=5, outer_radius=12, "
                  "inner_radius=5, rotation=10 deg) }")
    (loop,) = o.parts[0].loops
    pts = [g.start for g in loop.segments]
    assert len(pts) == 10
    radii = sorted(round(math.dist(p, (5, 5)), 9) for p in pts)
    assert radii == [5.0] * 5 + [12.0] * 5
    tip = max(pts, key=lambda p: p[1])
    assert math.degrees(math.atan2(tip[1] - 5, tip[0] - 5)) == pytest.approx(100, abs=1e-9)
    # the area of a star polygon: 2n triangles between a tip and a notch
    area = 10 * 0.5 * 12 * 5 * math.sin(math.pi / 5)
    assert loop.area == pytest.approx(area, rel=1e-12)


@pytest.mark.parametrize("src, msg", [
    ("Star(center=(0, 0), points=5, outer_radius=3, inner_radius=4)", "smaller than"),
    ("Star(center=(0, 0), points=2.5, outer_radius=3, inner_radius=1)", "whole number"),
    ("ArcSlot(center=(0, 0), radius=2, start_angle=0, end_angle=90 deg, width=5)", "twice"),
    ("ArcSlot(center=(0, 0), radius=9, start_angle=0 deg, end_angle=360 deg, width=1)",
     "whole turn"),
])
def test_star_and_arc_slot_errors_are_located(compile_text, src, msg):
    c = compile_text("solid s {\n    g = " + src + "\n}\n")
    (d,) = [d for d in c.sink.items if d.severity == "error"]
    assert msg in d.message and d.span.line == 2


def test_fillet_and_chamfer_take_two_edges_as_their_corner():
    """`Fillet(edge1, edge2, radius=r)` (what models write) rounds the corner where the two
    edges meet, as `Fillet([edge1, edge2], r)` does; it was "`radius` given twice"."""
    from aidl_lang.geometry.shapes.curves import Arc, Line
    c, o = _exact("solid p {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
                  "    Fillet(body.top, body.right, radius=5)\n"
                  "    Chamfer(body.bottom, body.left, 3)\n}\n")
    segs = o.parts[0].loops[0].segments
    (arc,) = [g for g in segs if isinstance(g, Arc)]
    assert arc.radius == pytest.approx(5, abs=1e-12)
    assert arc.center == pytest.approx((15, 5), abs=1e-12)
    ends = sorted((round(g.start[0], 9), round(g.start[1], 9)) for g in segs if isinstance(g, Line))
    assert (-20.0, -7.0) in ends and (-17.0, -10.0) in ends


def test_text_center_is_the_middle_of_its_strokes(compile_text):
    from aidl_lang.geometry.shapes.text import text_extent
    c = compile_text("drawing d {\n    t = Text(\"HELLO\", (10, 30), size=5)\n"
                     "    p = Point(at=t.center)\n}\n")
    assert c.ok
    x = c.model.xs()
    g = {g.name: g for g in c.model.root.geometry}
    x0, x1, y0, y1 = text_extent("HELLO", 5.0, "middle", "baseline", 0.0)
    pt = g["p"].points["p"]
    assert (x[pt.ix], x[pt.iy]) == pytest.approx((10 + (x0 + x1) / 2, 30 + (y0 + y1) / 2),
                                                abs=1e-9)


def test_an_arc_with_arguments_no_form_takes_together_names_them(compile_text):
    """`Arc(radius=, start=, end=)` was "`Arc` has no argument `radius`" (issue 83): `radius` is
    an argument of Arc, only not with `start` and `end`; the hint lists the three forms."""
    c = compile_text("solid s {\n    a = Arc(radius=5, start=(0, 0), end=(10, 0))\n}\n")
    [d] = [d for d in c.sink.items if d.is_error]
    assert (d.code, d.message) == ("E0104", "`Arc` has no form taking `radius` with `start` "
                                            "and `end`")
    assert (d.span.line, d.span.col) == (2, 9)
    assert d.hint.count("Arc(") == 3 and "radius: length, start_angle: angle" in d.hint


def _forms_law_entries():
    from aidl_lang.registry import ENTRIES, arg_synonyms
    out = []
    for e in ENTRIES.values():
        if len(e.variants) > 1:
            syn = arg_synonyms(e.name)       # a name that is also another's synonym (Slot's
            names = sorted({a.name for v in e.variants for a in v} - set(syn))  # `angle`): out
            out.append((e, names))
    return out


FORMS_LAW = _forms_law_entries()


@settings(max_examples=300, deadline=None)
@given(data=st.data())
def test_a_call_that_fits_no_form_names_the_right_culprits(data):
    """For every constructor of several forms and any set S of its argument names (keywords)
    that binds no form, the reason never says a given argument is missing or unknown; it is
    either the missing argument that completes a form taking all of S, or it names the
    culprits C and the fitting F (C + F = S) where no form takes all of S and, when a form
    is complete with S, C is exactly what lies outside such a form (its own arguments are
    never called wrong), else F fits one form."""
    from aidl_lang.registry import choose_variant
    entry, names = data.draw(st.sampled_from(FORMS_LAW))
    given_ = data.draw(st.lists(st.sampled_from(names), unique=True, min_size=1,
                                max_size=len(names)))
    S = set(given_)
    forms = [({a.name for a in v}, {a.name for a in v if a.required}) for v in entry.variants]
    variant, reason = choose_variant(entry, 0, given_)
    fits = [f for f, req in forms if S <= f and req <= S]
    if variant is not None:
        assert fits
        return
    assert not fits, (entry.name, given_, reason)
    assert "has no argument" not in reason and "given twice" not in reason
    m = re.fullmatch(r"missing argument `(\w+)`", reason)
    if m:
        assert m.group(1) not in S
        assert any(S <= f and m.group(1) in req for f, req in forms), (entry.name, given_)
        return
    m = re.fullmatch(r"has no form taking (.+?)(?: with (.+)| together)", reason)
    assert m, (entry.name, given_, reason)
    culprits = set(re.findall(r"`(\w+)`", m.group(1)))
    fitting = set(re.findall(r"`(\w+)`", m.group(2) or ""))
    assert culprits and culprits | fitting == S and not culprits & fitting
    assert not any(S <= f for f, _req in forms)
    complete = [f for f, req in forms if req <= S]
    if complete:
        assert any(culprits == S - f for f in complete), (entry.name, given_, reason)
    else:
        assert any(fitting <= f for f, _req in forms), (entry.name, given_, reason)
