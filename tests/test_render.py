"""Rendering: areas against formulas (Manifold booleans), tessellation accuracy, part structure
(unions, holes, assemblies, drawings) and the SVG page."""
import math
import re

import numpy as np
import pytest

from aidl_lang.output import area, render_model, to_svg


def rendered(compile_text, src):
    c = compile_text(src)
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    return render_model(c.model)


def polys(part):
    return [np.asarray(p) for p in part.shape.to_polygons()]


def test_solid_minus_hole(compile_text):
    d = rendered(compile_text, """solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole h { c = Circle(center=(3, 1), radius=5) }
    CenterInside(h, self)
}""")
    assert area(d) == pytest.approx(800 - 25 * math.pi, rel=1e-3)
    (part,) = d.parts
    assert part.kind == "solid" and len(polys(part)) == 2       # outline + the hole's boundary
    assert len(d.hole_outlines) == 1
    hole = d.hole_outlines[0]
    outline = max(polys(part), key=lambda p: np.ptp(p[:, 0]))
    body_center = (outline.min(axis=0) + outline.max(axis=0)) / 2
    # centered by CenterInside (the plate's own sketch moved: the paper's local-first solve)
    assert hole.mean(axis=0) == pytest.approx(body_center, abs=0.05)


def test_circle_tessellation_within_0_01_mm(compile_text):
    d = rendered(compile_text, "solid s { c = Circle(center=(10, -20), diameter=100) }")
    (part,) = d.parts
    (pts,) = polys(part)
    r = np.hypot(pts[:, 0] - 10, pts[:, 1] + 20)
    assert np.all(np.abs(r - 50) <= 0.01)
    # the chords, too: each edge's midpoint is within 0.01 mm of the circle
    mid = (pts + np.roll(pts, -1, axis=0)) / 2
    rm = np.hypot(mid[:, 0] - 10, mid[:, 1] + 20)
    assert np.all(np.abs(rm - 50) <= 0.01)
    # and the polygon goes all the way round (no gap bigger than a chord allows)
    ang = np.sort(np.arctan2(pts[:, 1] + 20, pts[:, 0] - 10))
    gaps = np.diff(np.concatenate([ang, ang[:1] + 2 * math.pi]))
    assert gaps.max() < 2 * math.acos(1 - 0.01 / 50)
    assert area(d) == pytest.approx(math.pi * 50 ** 2, abs=math.pi * 100 * 0.01)


def test_small_and_large_circles_keep_the_tolerance(compile_text):
    for r in (0.5, 3, 400):
        d = rendered(compile_text, f"solid s {{ c = Circle(center=(0, 0), radius={r}) }}")
        (pts,) = polys(d.parts[0])
        mid = (pts + np.roll(pts, -1, axis=0)) / 2
        assert np.all(r - np.hypot(mid[:, 0], mid[:, 1]) <= 0.01), r
        assert np.all(np.abs(np.hypot(pts[:, 0], pts[:, 1]) - r) <= 1e-6 * max(1, r)), r


def test_rectangle_area_and_rotation(compile_text):
    d = rendered(compile_text,
                 "solid s { r = Rectangle(center=(5, 5), width=30, height=12, rotation=37 deg) }")
    assert area(d) == pytest.approx(360, rel=1e-9)
    (pts,) = polys(d.parts[0])
    assert len(pts) == 4
    c, s = math.cos(math.radians(37)), math.sin(math.radians(37))
    want = {(round(5 + dx * c - dy * s, 6), round(5 + dx * s + dy * c, 6))
            for dx in (-15, 15) for dy in (-6, 6)}
    assert {(round(x, 6), round(y, 6)) for x, y in pts} == want


def test_solid_child_is_unioned(compile_text):
    d = rendered(compile_text, """solid s {
    body = Rectangle(bottom_left=(0, 0), width=40, height=20)
    Fixed(body)
    solid tab { r = Rectangle(bottom_left=(30, 10), width=20, height=20) }
    Fixed(tab.r)
}""")
    (part,) = d.parts
    # 40x20 + 20x20 - overlap 10x10
    assert area(d) == pytest.approx(800 + 400 - 100, rel=1e-9)
    assert len(polys(part)) == 1                                 # one merged outline
    assert part.shape.bounds() == pytest.approx((0, 0, 50, 30))


def test_overlapping_own_faces_union_not_add(compile_text):
    d = rendered(compile_text, """solid s {
    a = Circle(center=(0, 0), radius=10)
    b = Circle(center=(0, 0), radius=10)
    r = Rectangle(center=(0, 0), width=4, height=4)
}""")
    assert area(d) == pytest.approx(math.pi * 100, rel=1e-3)


def test_hole_of_a_child_solid_cuts_only_that_child(compile_text):
    src = """solid s {
    body = Rectangle(center=(0, 0), width=100, height=50)
    Fixed(body)
    solid boss {
        c = Circle(center=(%s, 0), radius=10)
        hole bore { b = Circle(center=(%s, 0), radius=4) }
        Fixed(c)
        Concentric(bore.b, c)
    }
    hole slot { r = Rectangle(center=(30, 0), width=10, height=20) }
    Fixed(slot.r)
}"""
    # a boss outside the body: its bore shows; the slot cuts the body
    d = rendered(compile_text, src % (100, 95))
    assert area(d) == pytest.approx(5000 - 200 + math.pi * (100 - 16), rel=1e-3)
    # a boss inside the body: the boss (a ring) is unioned with the body, which covers the bore
    d = rendered(compile_text, src % (-20, -22))
    assert area(d) == pytest.approx(5000 - 200, rel=1e-9)


def test_hole_at_top_level_of_assembly_is_a_hole_part(compile_text):
    d = rendered(compile_text, """assembly kit {
    solid plate { r = Rectangle(center=(0, 0), width=20, height=20) }
    hole cut { c = Circle(center=(50, 0), radius=3) }
}""")
    kinds = sorted(p.kind for p in d.parts)
    assert kinds == ["hole", "solid"]
    assert area(d) == pytest.approx(400, rel=1e-9)     # a hole part has no area of its own


def test_assembly_children_stay_separate(compile_text):
    d = rendered(compile_text, """assembly kit {
    solid a { r = Rectangle(center=(0, 0), width=20, height=10) }
    solid b { r = Rectangle(center=(5, 0), width=20, height=10) }
    Fixed(a.r)
    Fixed(b.r)
}""")
    names = sorted(p.name for p in d.parts)
    assert names == ["kit.a", "kit.b"]
    areas = sorted(p.shape.area() for p in d.parts)
    assert areas == pytest.approx([200, 200])
    # overlapping parts are not merged: total is the sum, not the union (300)
    assert area(d) == pytest.approx(400)


def test_implicit_root_of_several_structures_is_an_assembly(compile_text):
    d = rendered(compile_text, """solid a { c = Circle((0, 0), 10) }
solid b { r = Rectangle(center=(100, 0), width=10, height=10) }
""")
    assert sorted(p.name for p in d.parts) == ["model.a", "model.b"]


def test_loose_top_level_geometry_is_one_solid(compile_text):
    d = rendered(compile_text, """c = Rectangle(center=(0, 0), width=10, height=10)
r = Rectangle(center=(5, 0), width=10, height=10)
""")
    (part,) = d.parts
    assert part.name == "model" and part.kind == "solid"
    assert area(d) == pytest.approx(150)


def test_drawing_contributes_lines_not_area(compile_text):
    base = """solid s {
    body = Rectangle(center=(0, 0), width=40, height=20)
    Fixed(body)
%s}"""
    plain = rendered(compile_text, base % "")
    drawn = rendered(compile_text, base % """    drawing marks {
        l = Line((-10, -5), (10, -5))
        box = Rectangle(center=(0, 0), width=4, height=4)
        c = Circle(center=(15, 0), radius=2)
        t = Text("AB", (0, 5), size=4)
    }
""")
    assert area(drawn) == pytest.approx(area(plain)) == pytest.approx(800)
    assert plain.lines == []
    styles = {s for s, _ in drawn.lines}
    assert styles == {"drawing"}
    seg = [pl for _, pl in drawn.lines if len(pl) == 2]
    assert any(np.allclose(pl, [[-10, -5], [10, -5]]) for pl in seg)
    # the rectangle is drawn as a closed polyline through its corners
    closed = [pl for _, pl in drawn.lines if len(pl) == 5 and np.allclose(pl[0], pl[-1])]
    assert any(np.allclose(np.abs(pl[:4]), 2) for pl in closed)


def test_construction_geometry_is_not_drawn(compile_text):
    d = rendered(compile_text, """solid s {
    body = Rectangle(center=(0, 0), width=40, height=20)
    guide = Circle(center=(0, 0), radius=30, construction=true)
}""")
    assert area(d) == pytest.approx(800)
    assert d.parts[0].shape.bounds() == pytest.approx((-20, -10, 20, 10))


def test_closed_chain_of_lines_and_arc_is_a_face(compile_text):
    d = rendered(compile_text, """solid s {
    base = Line((-10, 0), (10, 0))
    a = Arc(center=(0, 0), start=base.end, end=base.start)
}""")
    # a half disc of radius 10
    assert area(d) == pytest.approx(math.pi * 50, rel=1e-3)
    assert d.open_curves == []


@pytest.mark.parametrize("dx,dy", [(4e-7, 3e-7), (-4e-7, 3e-7), (4e-7, -6e-7), (-6e-7, -4e-7)])
def test_line_ends_a_hair_apart_across_a_grid_cell_chain_into_a_face(compile_text, dx, dy):
    """Two ends within the chaining tolerance (1e-6 mm) on either side of a line of the ends'
    grid (cells of END_CELL = 0.25 mm: every corner here is on one) are one corner: the
    square closes, whichever cell each end falls in."""
    d = rendered(compile_text, f"""solid s {{
    a = Line((0, 0), (0.25, 0))
    b = Line(({0.25 + dx!r}, {dy!r}), (0.25, 0.25))
    c = Line((0.25, 0.25), ({dx!r}, {0.25 + dy!r}))
    e = Line((0, 0.25), (0, 0))
}}""")
    assert d.open_curves == []
    assert area(d) == pytest.approx(0.0625, rel=1e-4)


def test_open_curves_are_reported_not_filled(compile_text):
    d = rendered(compile_text, """solid s {
    a = Line((0, 0), (10, 0))
    b = Line((10, 0), (10, 10))
}""")
    assert area(d) == 0
    assert sorted(g.name for g in d.open_curves) == ["a", "b"]
    assert [s for s, _ in d.lines] == ["open", "open"]


def test_rounded_rectangle_area(compile_text):
    d = rendered(compile_text,
                 "solid s { r = RoundedRectangle(center=(0, 0), width=40, height=20, corner_radius=5) }")
    assert area(d) == pytest.approx(800 - (4 - math.pi) * 25, rel=1e-3)
    assert d.parts[0].shape.bounds() == pytest.approx((-20, -10, 20, 10), abs=1e-6)


def test_slot_and_regular_polygon_area(compile_text):
    d = rendered(compile_text, "solid s { a = Slot(center=(0, 0), length=20, width=6) }")
    # length is overall: a 14 long spine plus two half discs of radius 3
    assert area(d) == pytest.approx(14 * 6 + math.pi * 9, rel=1e-3)
    assert d.parts[0].shape.bounds() == pytest.approx((-10, -3, 10, 3), abs=0.01)
    d = rendered(compile_text, "solid s { a = Slot((0, 0), (0, 10), 2) }")
    assert area(d) == pytest.approx(10 * 4 + math.pi * 4, abs=(20 + 4 * math.pi) * 0.01)
    d = rendered(compile_text, "solid s { p = RegularPolygon(center=(0, 0), radius=10, sides=6) }")
    assert area(d) == pytest.approx(1.5 * math.sqrt(3) * 100, rel=1e-9)


def test_units_inch_area(compile_text):
    d = rendered(compile_text, "units inch\nsolid s { r = Rectangle(center=(0, 0), width=2, height=1) }")
    assert area(d) == pytest.approx(2 * 25.4 * 25.4, rel=1e-9)


# ------------------------------------------------------------------ SVG
def _svg_attrs(svg):
    head = svg[svg.index("<svg"):svg.index(">", svg.index("<svg"))]
    return dict(re.findall(r'(\w+)="([^"]*)"', head))


def test_svg_has_viewbox_and_size_in_mm(compile_text):
    d = rendered(compile_text, "solid s { r = Rectangle(center=(10, 5), width=40, height=20) }")
    svg = to_svg(d, title="s")
    a = _svg_attrs(svg)
    assert a["width"].endswith("mm") and a["height"].endswith("mm")
    w, h = float(a["width"][:-2]), float(a["height"][:-2])
    vx, vy, vw, vh = map(float, a["viewBox"].replace(",", " ").split())
    # one user unit is one millimetre
    assert (w, h) == pytest.approx((vw, vh), abs=1e-3)
    # the view covers the part (y flipped: model y up, page y down) with a margin
    assert vx < -10 and vx + vw > 30
    assert vy < -15 and vy + vh > 5
    assert vw > 40 and vh > 20
    assert "<path" in svg


def test_svg_width_follows_the_model(compile_text):
    narrow = to_svg(rendered(compile_text, "solid s { r = Rectangle(center=(0, 0), width=40, height=20) }"))
    wide = to_svg(rendered(compile_text, "solid s { r = Rectangle(center=(0, 0), width=100, height=20) }"))
    wn = float(_svg_attrs(narrow)["width"][:-2])
    ww = float(_svg_attrs(wide)["width"][:-2])
    assert ww - wn == pytest.approx(60 * 1.1, rel=0.05)     # the margin scales with the size


def test_svg_paths_flip_y(compile_text):
    d = rendered(compile_text, "solid s { r = Rectangle(bottom_left=(0, 10), width=5, height=5) }")
    svg = to_svg(d)
    path = re.search(r'<path d="M([^"]*)Z"', svg).group(1)
    ys = sorted({round(float(p.split(",")[1]), 4) for p in re.split(r"[ML]", path)})
    assert ys == [-15.0, -10.0]


# ------------------------------------------------------------------ boxes agree with drawings
@pytest.mark.parametrize("shape", [
    "Circle(center=(3, -2), radius=7)",
    "Rectangle(center=(0, 0), width=20, height=8, rotation=30 deg)",
    "RoundedRectangle(center=(1, 2), width=20, height=10, corner_radius=3)",
    # issue 109: boxed by its corner arcs (±10.83), no longer its sharp corners (±14.14)
    pytest.param("RoundedRectangle(center=(0, 0), width=20, height=20, corner_radius=8, "
                 "rotation=45 deg)", id="rotated-rounded-rectangle"),
    "RegularPolygon(center=(0, 0), radius=10, sides=5, rotation=10 deg)",
    "Slot(center=(0, 0), length=30, width=6, rotation=60 deg)",
    "Triangle((0, 0), (10, 2), (3, 9))",
    "Polygon([(0, 0), (10, 0), (12, 5), (4, 9), (-3, 4)])",
])
def test_bounding_box_matches_the_drawn_shape(compile_text, shape):
    from aidl_lang.geometry.relations.bbox import numeric_box
    c = compile_text(f"solid s {{ g = {shape} }}")
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    l, r, b, t = numeric_box(c.model.root, None, c.model.xs())
    x0, y0, x1, y1 = render_model(c.model).parts[0].shape.bounds()
    assert (l, r, b, t) == pytest.approx((x0, x1, y0, y1), abs=0.011)


@pytest.mark.parametrize("anchor, x0", [("start", 10.0), ("middle", None), ("end", None)])
def test_text_size_is_cap_height_and_anchor_places_it(compile_text, anchor, x0):
    from aidl_lang.geometry.relations.bbox import numeric_box
    c = compile_text(f'drawing d {{ t = Text("AIDL", (10, 20), size=8, anchor="{anchor}") }}')
    assert c.ok
    d = render_model(c.model)
    pts = np.vstack([pl for _, pl in d.lines])
    left, right = pts[:, 0].min(), pts[:, 0].max()
    assert (pts[:, 1].min(), pts[:, 1].max()) == pytest.approx((20, 28), abs=1e-6)
    assert right - left > 8
    if anchor == "start":
        assert left == pytest.approx(10)
    elif anchor == "middle":
        assert (left + right) / 2 == pytest.approx(10)
    else:
        assert right == pytest.approx(10)
    (g,) = list(c.model.all_geometry())
    assert numeric_box(g, None, c.model.xs()) == pytest.approx((left, right, 20, 28), abs=1e-6)
