"""The exact output model and its writers (docs/outputs.md): arcs recovered from the solved
model, SVG re-read by svgelements, DXF re-read by ezdxf, PNG, STL/3MF re-read by trimesh."""
import io
import math
import struct

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from conftest import EXAMPLES
from aidl_lang.geometry.shapes.tessellate import CHORD_TOL
from aidl_lang.output import Options, build, encode
from aidl_lang.output.part.part import Arc, Circle, Line

PLATE = """
units mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole bore {
        c = Circle(center=(0, 0), radius=5)
    }
    CenterInside(bore, self)
}
"""


def output_of(compile_text, src):
    c = compile_text(src)
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    return build(c.drawing, c.model.root.name), c


_compiled = {}


def example(path):
    if path not in _compiled:
        from aidl_lang.pipeline import compile_source
        c = compile_source(path.read_text(), str(path))
        assert c.ok
        _compiled[path] = (build(c.drawing, c.model.root.name), c)
    return _compiled[path]


# ------------------------------------------------------------------ the output model
def test_plate_area_and_perimeter_are_exact(compile_text):
    o, _ = output_of(compile_text, PLATE)
    (part,) = o.parts
    assert part.area == pytest.approx(800 - 25 * math.pi, rel=1e-9)
    assert part.perimeter == pytest.approx(120 + 10 * math.pi, rel=1e-9)
    outer, bore = sorted(part.loops, key=lambda lp: -lp.area)
    assert all(isinstance(s, Line) for s in outer.segments) and len(outer.segments) == 4
    (c,) = bore.segments
    assert isinstance(c, Circle) and c.radius == pytest.approx(5, abs=1e-12) and bore.is_hole


def test_arcs_cut_by_lines_end_exactly_on_both(compile_text):
    # a disc cut by a rectangle hole: a D shape; the arc ends where the line meets the circle
    o, _ = output_of(compile_text, """
solid d {
    disc = Circle(center=(0, 0), radius=10)
    hole flat { r = Rectangle(center=(0, 8), width=30, height=4) }
}""")
    (part,) = o.parts
    (loop,) = part.loops
    arcs = [s for s in loop.segments if isinstance(s, Arc)]
    lines = [s for s in loop.segments if isinstance(s, Line)]
    assert len(arcs) == 1 and len(lines) == 1
    y = 6.0
    x = math.sqrt(100 - y * y)
    ends = sorted([arcs[0].start, arcs[0].end])
    assert ends[0] == pytest.approx((-x, y), abs=1e-9) and ends[1] == pytest.approx((x, y), abs=1e-9)
    # exact area: the disc minus the circular segment above y = 6
    theta = 2 * math.acos(y / 10)
    assert part.area == pytest.approx(math.pi * 100 - 50 * (theta - math.sin(theta)), rel=1e-9)


def test_rounded_rectangle_corners_are_arcs(compile_text):
    o, _ = output_of(compile_text, "solid s { r = RoundedRectangle(center=(0, 0), width=40, "
                                   "height=20, corner_radius=4) }")
    (loop,) = o.parts[0].loops
    arcs = [s for s in loop.segments if isinstance(s, Arc)]
    assert len(arcs) == 4 and all(a.radius == pytest.approx(4, abs=1e-9) for a in arcs)
    assert all(abs(a.sweep) == pytest.approx(math.pi / 2, abs=1e-9) for a in arcs)
    assert o.area == pytest.approx(800 - (4 - math.pi) * 16, rel=1e-9)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_loops_are_closed_and_close_to_the_booleans(path):
    o, c = example(path)
    d = c.drawing
    for p, loopsrc in zip(o.parts, [q for q in d.parts if not q.shape.is_empty()]):
        for lp in p.loops:
            segs = lp.segments
            if len(segs) == 1 and isinstance(segs[0], Circle):
                continue
            for a, b in zip(segs, segs[1:] + segs[:1]):
                assert math.dist(a.end, b.start) < 1e-9
        # the exact area differs from the chords' by at most the sagitta along the outline
        assert abs(p.area - loopsrc.shape.area()) <= CHORD_TOL * p.perimeter + 1e-9
        assert p.perimeter >= loopsrc.shape.area() * 0 and p.perimeter > 0


# ------------------------------------------------------------------ DXF, re-read by ezdxf
def _dxf(o):
    import ezdxf
    return ezdxf.read(io.StringIO(encode(o, ".dxf").decode()))


def test_dxf_bore_is_a_circle_and_units_are_mm(compile_text):
    o, _ = output_of(compile_text, """
solid flange {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole bore { c = Circle(center=(0, 0), diameter=22) }
}""")
    doc = _dxf(o)
    assert doc.header["$INSUNITS"] == 4 and doc.header["$MEASUREMENT"] == 1
    msp = doc.modelspace()
    (circle,) = msp.query("CIRCLE")
    assert circle.dxf.radius == pytest.approx(11.0, abs=1e-9) and circle.dxf.layer == "CUT"
    (pl,) = msp.query("LWPOLYLINE")
    assert pl.closed and len(pl) == 4 and pl.dxf.layer == "CUT"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_dxf_matches_the_model(path):
    o, c = example(path)
    doc = _dxf(o)
    msp = doc.modelspace()
    assert doc.header["$INSUNITS"] == 4
    layers = {e.dxf.layer for e in msp}
    cut_layers = {e.dxf.layer for e in msp if e.dxf.layer != "ENGRAVE"}
    if len(o.parts) == 1:
        assert cut_layers == {"CUT"}
    else:
        assert cut_layers == {"CUT-" + p.name for p in o.parts}
    assert ("ENGRAVE" in layers) == bool(o.engrave)
    loops = [lp for p in o.parts for lp in p.loops]
    cut = [e for e in msp if e.dxf.layer != "ENGRAVE"]
    whole, contours = _cut_contours(cut)
    assert len(whole) + len(contours) == len(loops)
    radii = np.array([r for _, _, r in c.drawing.circles])
    for e in msp.query("CIRCLE"):
        assert np.min(np.abs(radii - e.dxf.radius)) < 1e-9
    # every cut entity encloses exactly the area of its loop (from the entity's own data); a
    # loop of lines and splines (a font's letter) is written piece by piece and chained here
    dxf_areas = sorted([abs(_entity_area(e)) for e in whole] + [abs(a) for a in contours])
    model_areas = sorted(abs(lp.area) for lp in loops)
    assert dxf_areas == pytest.approx(model_areas, rel=1e-9, abs=1e-9)


def test_dxf_header_extents_are_the_drawings():
    o = _hand_built()
    doc = _dxf(o)
    assert doc.header["$EXTMIN"] == pytest.approx((-20, -10, 0), abs=1e-12)
    assert doc.header["$EXTMAX"] == pytest.approx((25, 10, 0), abs=1e-12)


def _strokes_output(*strokes):
    from aidl_lang.output.part.part import Output, Stroke
    return Output(engrave=[Stroke(list(s)) for s in strokes])


def _as_model(e):
    """A LINE or ARC entity as (kind, numbers): a line's start and end x, y; an arc's start
    and end x, y (ezdxf's own geometry, counter-clockwise from start to end angle), center x,
    y and radius."""
    if e.dxftype() == "LINE":
        return "line", [*tuple(e.dxf.start)[:2], *tuple(e.dxf.end)[:2]]
    return "arc", [*tuple(e.start_point)[:2], *tuple(e.end_point)[:2], *tuple(e.dxf.center)[:2],
                   e.dxf.radius]


def test_dxf_chained_engraving_is_one_open_polyline_with_bulges():
    """An open stroke of chained lines and arcs is ONE open LWPOLYLINE (a laser runs it in one
    go); exploded by ezdxf, it gives back the same lines and arcs (a 270-degree arc as one
    bulge).  A stroke with a gap becomes two chains; lone segments stay LINE / ARC / CIRCLE."""
    big = Arc((10, 5), 5, -math.pi / 2, 1.5 * math.pi)     # 270 degrees ccw, (10, 0) -> (5, 5)
    cw = Arc((5, 8), 3, -math.pi / 2, -math.pi / 2)         # 90 degrees cw, (5, 5) -> (2, 8)
    chain = [Line((0, 0), (10, 0)), big, cw, Line((2, 8), (2, 12))]
    gapped = [Line((30, 0), (35, 0)), Line((35, 0), (35, 5)),       # a chain of two,
              Line((40, 0), (45, 0))]                               # then a lone line
    lone_arc = [Arc((0, 30), 2, 0.0, math.pi / 3)]
    lone_circle = [Circle((0, 40), 1.5)]
    doc = _dxf(_strokes_output(chain, gapped, lone_arc, lone_circle))
    msp = doc.modelspace()
    assert sorted(e.dxftype() for e in msp) == ["ARC", "CIRCLE", "LINE", "LWPOLYLINE",
                                                "LWPOLYLINE"]
    assert all(e.dxf.layer == "ENGRAVE" for e in msp)
    first, second = msp.query("LWPOLYLINE")
    assert not first.closed and not second.closed
    assert len(first) == 5           # line, the big arc, the cw arc, line, end point
    got = [_as_model(e) for e in first.virtual_entities()]
    assert [g[0] for g in got] == ["line", "arc", "arc", "line"]
    a = 1e-9
    assert got[0][1] == pytest.approx([0, 0, 10, 0], abs=a)
    # the big arc: ccw from (10, 0) through (15, 5) to (5, 5), center (10, 5)
    assert got[1][1] == pytest.approx([10, 0, 5, 5, 10, 5, 5], abs=a)
    assert got[2][1] == pytest.approx([2, 8, 5, 5, 5, 8, 3], abs=a)
    assert got[3][1] == pytest.approx([2, 8, 2, 12], abs=a)
    assert [c for p in second.get_points("xy") for c in p] == pytest.approx([30, 0, 35, 0, 35, 5])
    (line,) = msp.query("LINE")
    assert _as_model(line)[1] == pytest.approx([40, 0, 45, 0])
    (arc,) = msp.query("ARC")
    assert (arc.dxf.start_angle, arc.dxf.end_angle) == pytest.approx((0, 60))
    (circle,) = msp.query("CIRCLE")
    assert circle.dxf.radius == 1.5


def test_svg_moves_over_a_gap_in_a_stroke():
    """A stroke with a gap is drawn as two subpaths: the gap is a move, not a line."""
    import svgelements as se
    o = _strokes_output([Line((0, 0), (5, 0)), Line((5, 0), (5, 5)), Line((9, 0), (12, 0))],
                        [Circle((0, 20), 1), Line((1, 20), (3, 20))])
    svg = encode(o, ".svg", Options(style="laser")).decode()
    engrave = svg[svg.index('id="engrave"'):]
    assert engrave.count("<path") == 2
    assert "M0,0L5,0L5,-5M9,0L12,0" in engrave and "ZM1,-20L3,-20" in engrave
    doc = se.SVG.parse(io.StringIO(svg))
    (path, _) = [e for e in doc.elements() if isinstance(e, se.Path)]
    assert len(list(path.as_subpaths())) == 2


def _entity_area(e):
    """Area of a CIRCLE or a closed LWPOLYLINE with bulges, from the DXF data alone."""
    if e.dxftype() == "CIRCLE":
        return math.pi * e.dxf.radius ** 2
    if e.dxftype() == "SPLINE":          # a closed spline: its Bézier pieces (ezdxf), exactly
        from ezdxf.math import BSpline
        bs = BSpline([tuple(v)[:2] for v in e.control_points], order=e.dxf.degree + 1,
                     knots=list(e.knots))
        a = 0.0
        gx, gw = np.polynomial.legendre.leggauss(4)     # x y' - y x': degree 5, exact
        for piece in bs.bezier_decomposition():
            P = np.array([tuple(q)[:2] for q in piece], dtype=float)
            for x, w in zip(gx, gw):
                t = 0.5 * (x + 1)
                B = np.array([(1 - t) ** 3, 3 * (1 - t) ** 2 * t, 3 * (1 - t) * t * t, t ** 3])
                D = 3 * np.array([-(1 - t) ** 2, (1 - t) ** 2 - 2 * (1 - t) * t,
                                  2 * (1 - t) * t - t * t, t * t])
                (px, py), (dx, dy) = B @ P, D @ P
                a += 0.25 * w * (px * dy - py * dx)
        return a
    pts = list(e.get_points("xyb"))
    a = 0.0
    for (x0, y0, b), (x1, y1, _) in zip(pts, pts[1:] + pts[:1]):
        a += 0.5 * (x0 * y1 - x1 * y0)
        if b:
            theta = 4 * math.atan(b)
            chord = math.hypot(x1 - x0, y1 - y0)
            r = chord / (2 * math.sin(abs(theta) / 2))
            a += 0.5 * r * r * (theta - math.sin(theta))
    return a


def _cut_contours(cut):
    """``(whole, areas)``: the entities that are closed loops themselves (a CIRCLE, a closed
    LWPOLYLINE or SPLINE), and the areas of the loops written piece by piece (LINEs and open
    SPLINEs whose ends meet within 1e-6 mm), each chained from its pieces' own data and
    measured exactly (Green's theorem: a line's term and each Bézier piece's)."""
    whole, pieces = [], []
    for e in cut:
        if e.dxftype() == "CIRCLE" or (e.dxftype() == "LWPOLYLINE" and e.closed) or (
                e.dxftype() == "SPLINE" and e.closed):
            whole.append(e)
        else:
            assert e.dxftype() in ("LINE", "SPLINE"), e.dxftype()
            pieces.append(e)

    def ends(e):
        if e.dxftype() == "LINE":
            return tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]
        cp = [tuple(v)[:2] for v in e.control_points]
        return cp[0], cp[-1]

    def term(e, forward):
        if e.dxftype() == "LINE":
            (x0, y0), (x1, y1) = ends(e)
            a = 0.5 * (x0 * y1 - x1 * y0)
        else:
            a = _entity_area(e)            # the Bézier pieces' terms, open or closed alike
        return a if forward else -a
    areas, left = [], list(pieces)
    while left:
        e = left.pop(0)
        start, end = ends(e)
        total = term(e, True)
        while math.dist(end, start) > 1e-6:
            k = next(i for i, f in enumerate(left) if min(math.dist(p, end) for p in ends(f)) <= 1e-6)
            f = left.pop(k)
            a, b = ends(f)
            forward = math.dist(a, end) <= 1e-6
            total += term(f, forward)
            end = b if forward else a
        areas.append(total)
    return whole, areas


def _poly_area(P):
    x, y = P[:, 0], P[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


# ------------------------------------------------------------------ SVG, re-read by svgelements
def _svg_loops(svg_text):
    """Every closed subpath of every shape, as a polygon (arcs sampled at 512 points)."""
    import svgelements as se
    doc = se.SVG.parse(io.StringIO(svg_text), reify=True)
    out = []
    for el in doc.elements():
        if not isinstance(el, se.Shape):
            continue
        for sub in se.Path(el).as_subpaths():
            pts = []
            for seg in sub:
                if isinstance(seg, se.Line):
                    pts.append((seg.start.x, seg.start.y))
                elif isinstance(seg, (se.Arc, se.CubicBezier)):
                    pts += [tuple(q) for q in seg.npoint(np.linspace(0, 1, 513))[:-1]]
            if len(pts) >= 3:
                out.append(np.array(pts, dtype=float))
    return out


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_svg_loops_match_the_dxf(path):
    """svgelements (an independent reader) sees the same cut loops as ezdxf: same count and,
    loop by loop, the same enclosed area; in both layouts (preview and laser)."""
    o, _ = example(path)
    msp = _dxf(o).modelspace()
    whole, contours = _cut_contours([e for e in msp if e.dxf.layer != "ENGRAVE"])
    dxf_areas = sorted([abs(_entity_area(e)) for e in whole] + [abs(a) for a in contours])
    for style in ("preview", "laser"):
        svg = encode(o, ".svg", Options(style=style)).decode()
        cut_only = _cut_group(svg)
        areas = sorted(abs(_poly_area(pts)) for pts in _svg_loops(cut_only))
        assert len(areas) == len(dxf_areas)
        # the svg is scaled mm -> px by svgelements (96 dpi): compare ratios to the largest
        k = areas[-1] / dxf_areas[-1]
        assert k == pytest.approx((96 / 25.4) ** 2, rel=1e-4)
        assert [a / k for a in areas] == pytest.approx(dxf_areas, rel=1e-4, abs=1e-4)


def test_a_hole_touching_the_outline_at_a_point_is_drawn(compile_text):
    """A round hole tangent to the part's edge joins the outline at one point, so its exact
    loop holds a whole-turn arc from that point back to it: written as one SVG ``A`` it drew
    nothing (its end is its start) and the hole vanished from the SVG and PNG.  Re-read by
    svgelements, the cut encloses the board minus the notch and the whole hole."""
    o, _ = output_of(compile_text, """units mm
solid board {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole module { m = Rectangle(center=(20, 10), width=20, height=20) }
    hole bolt { c = Circle(center=(-20, 10), radius=10) }
}
""")
    svg = encode(o, ".svg", Options(style="preview")).decode()
    loops = _svg_loops(_cut_group(svg))
    k = (96 / 25.4) ** 2
    assert abs(sum(_poly_area(p) for p in loops)) / k == pytest.approx(
        60 * 40 - 20 * 20 - math.pi * 10 ** 2, rel=1e-4)


def _cut_group(svg: str) -> str:
    """The SVG with only the `cut` group kept (the others removed)."""
    import xml.etree.ElementTree as ET
    ET.register_namespace("", "http://www.w3.org/2000/svg")
    root = ET.fromstring(svg)
    for g in list(root):
        if g.get("id") not in ("cut",) and g.tag.endswith("}g"):
            root.remove(g)
    return ET.tostring(root, encoding="unicode")


def test_svg_uses_arcs_and_circles_and_no_debug_layers_by_default(compile_text):
    o, _ = output_of(compile_text, PLATE)
    svg = encode(o, ".svg").decode()
    assert 'id="cut"' in svg and 'id="engrave"' in svg
    assert 'id="holes"' not in svg and 'id="bboxes"' not in svg and "dasharray" not in svg
    assert "A5,5 0 " in svg                    # the bore as two exact half arcs
    laser = encode(o, ".svg", Options(style="laser")).decode()
    assert '<circle cx="0" cy="0" r="5"' in laser and 'fill="none"' in laser
    debug = encode(o, ".svg", Options(show=("holes", "bboxes"))).decode()
    assert 'id="holes"' in debug and 'id="bboxes"' in debug


def test_refilled_hole_is_not_drawn_as_a_hole(compile_text):
    """A hole wholly refilled by a sibling leaves no trace in the cut layer (the old `holes`
    group drew its dashed outline)."""
    o, c = output_of(compile_text, """
solid lock {
    solid body {
        b = Rectangle(center=(0, 0), width=40, height=30)
        hole key { k = Circle(center=(0, 8), radius=3) }
    }
    solid shackle { s = Rectangle(center=(0, 12), width=30, height=20) }
}""")
    (part,) = o.parts
    assert len(part.loops) == 1 and part.area == pytest.approx(40 * 30 + 30 * 7, rel=1e-9)
    assert "W0501" in [d.code for d in c.sink.items]
    assert "dasharray" not in encode(o, ".svg").decode()


def _px_per_mm() -> float:
    """svgelements' own pixels per mm (3.7795296: its constant, not 96 / 25.4 to the digit)."""
    import svgelements as se
    return float(se.Length("1mm").value(ppi=96))


def _hand_built():
    """A 40 x 20 plate whose right side is an arc through 0 degrees (x = 25 exactly, which no
    chord vertex need reach), a circular hole, and two engraving strokes: a chain of a line
    and an arc, and a single line."""
    from aidl_lang.output.part.part import Loop, Output, PartOutline, Stroke
    a = math.asin(10 / 25)                               # the arc meets y = +-10 at x = 25 cos a
    xr = 25 * math.cos(a)
    outer = Loop([Line((-20, -10), (xr, -10)), Arc((0, 0), 25, -a, 2 * a),
                  Line((xr, 10), (-20, 10)), Line((-20, 10), (-20, -10))])
    hole = Loop([Circle((0, 0), 3, ccw=False)])
    chain = Stroke([Line((-15, -5), (-10, -5)), Arc((-10, 0), 5, -math.pi / 2, math.pi)])
    single = Stroke([Line((5, 0), (10, 0))])
    return Output(parts=[PartOutline("plate", "solid", [outer, hole])],
                  engrave=[chain, single], title="plate")


def test_laser_svg_strokes_are_true_hairlines_red_cut_blue_engrave():
    """Re-read by svgelements, every laser-style element renders at most 0.025 mm wide (the
    old ``stroke-width="0.01mm"`` was 0.0378 mm on the mm page), cuts red, engraving blue."""
    import svgelements as se
    o = _hand_built()
    doc = se.SVG.parse(io.StringIO(encode(o, ".svg", Options(style="laser")).decode()))
    shapes = [e for e in doc.elements() if isinstance(e, se.Shape)]
    widths = [e.implicit_stroke_width / _px_per_mm() for e in shapes]
    assert len(shapes) == 4 and max(widths) <= 0.025 and min(widths) > 0
    colours = sorted(str(e.stroke) for e in shapes)
    assert colours == ["#0000ff"] * 2 + ["#ff0000"] * 2
    assert all(e.fill is None or e.fill.value is None for e in shapes)


def test_svg_draws_a_chained_stroke_as_one_path():
    svg = encode(_hand_built(), ".svg", Options(style="laser")).decode()
    engrave = svg[svg.index('id="engrave"'):]
    assert engrave.count("<path") == 2 and "M-15,5L-10,5A5,5 0 0 0 -5,0A5,5 0 0 0 -10,-5" in engrave  # a half turn: two quarters


def test_margin_zero_makes_the_page_the_exact_bounding_box():
    import svgelements as se
    from aidl_lang.output.part.extent import extent
    o = _hand_built()
    assert extent(o) == pytest.approx((-20, -10, 25, 10), abs=1e-12)
    assert o.bounds()[2] < 25 - 1e-6                 # the sampled extent falls short of the arc
    for style in ("preview", "laser"):
        svg = encode(o, ".svg", Options(style=style, margin=0)).decode()
        doc = se.SVG.parse(io.StringIO(svg))
        assert doc.width / _px_per_mm() == pytest.approx(45, abs=1e-6)
        assert doc.height / _px_per_mm() == pytest.approx(20, abs=1e-6)
        assert ' width="45mm"' in svg and ' height="20mm"' in svg
        assert 'viewBox="-20,-10,45,20"' in svg
    wide = se.SVG.parse(io.StringIO(encode(o, ".svg", Options(margin=2.5)).decode()))
    assert wide.width / _px_per_mm() == pytest.approx(50, abs=1e-6)
    default = se.SVG.parse(io.StringIO(encode(o, ".svg").decode()))
    assert default.width / _px_per_mm() == pytest.approx(45 + 2 * 2.25, abs=1e-6)   # 5 % of 45


@pytest.mark.parametrize("margin", [-1.0, math.inf, math.nan])
def test_a_bad_margin_is_an_output_error(margin):
    from aidl_lang.output.part.part import OutputError
    with pytest.raises(OutputError, match="margin"):
        encode(_hand_built(), ".svg", Options(margin=margin))


@settings(max_examples=300, deadline=None)
@given(st.floats(-50, 50), st.floats(-50, 50), st.floats(0.01, 100), st.floats(-20, 20),
       st.floats(-2 * math.pi, 2 * math.pi).filter(lambda v: abs(v) > 1e-6))
def test_an_arcs_extent_is_the_box_of_its_points(cx, cy, r, a0, sweep):
    """The exact extent of an arc holds all its points and is no larger than they reach
    (densely sampled: a sample misses an extreme by at most r (1 - cos(pi / 4000)))."""
    from aidl_lang.output.part.extent import extent
    from aidl_lang.output.part.part import Output, Stroke
    arc = Arc((cx, cy), r, a0, sweep)
    t = a0 + sweep * np.linspace(0, 1, 4001)
    xs, ys = cx + r * np.cos(t), cy + r * np.sin(t)
    got = extent(Output(engrave=[Stroke([arc])]))
    tol = 1e-9 * (1 + r + abs(cx) + abs(cy))
    slack = r * (1 - math.cos(math.pi / 4000)) + tol
    assert got[0] <= xs.min() + tol and got[1] <= ys.min() + tol
    assert got[2] >= xs.max() - tol and got[3] >= ys.max() - tol
    assert got[0] >= xs.min() - slack and got[1] >= ys.min() - slack
    assert got[2] <= xs.max() + slack and got[3] <= ys.max() + slack


# ------------------------------------------------------------------ PNG
def test_png_has_the_requested_width(compile_text):
    pytest.importorskip("cairosvg")
    o, _ = output_of(compile_text, PLATE)
    png = encode(o, ".png", Options(width=321))
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    w, h = struct.unpack(">II", png[16:24])
    assert w == 321 and h == round(321 * (20 + 4) / (40 + 4)) or abs(h - 321 * 24 / 44) <= 1
    big = encode(o, ".png", Options(dpi=192))
    w2, _ = struct.unpack(">II", big[16:24])
    assert w2 == pytest.approx(44 / 25.4 * 192, abs=1.5)       # 40 mm + 2 x 2 mm margin
    tight = encode(o, ".png", Options(dpi=254, margin=0))    # 10 pixels per mm, no margin
    assert struct.unpack(">II", tight[16:24]) == (400, 200)


# ------------------------------------------------------------------ STL / 3MF
def test_stl_and_3mf_are_watertight_with_the_right_volume(compile_text):
    trimesh = pytest.importorskip("trimesh")
    o, c = output_of(compile_text, PLATE)
    area = c.drawing.parts[0].shape.area()
    stl = trimesh.load(io.BytesIO(encode(o, ".stl", Options(thickness=3))), file_type="stl")
    assert stl.is_watertight and stl.volume == pytest.approx(area * 3, rel=1e-6)
    assert stl.bounds[:, 2] == pytest.approx([0, 3])
    scene = trimesh.load(io.BytesIO(encode(o, ".3mf", Options(thickness=2))), file_type="3mf")
    (mesh,) = scene.geometry.values()
    assert mesh.is_watertight and mesh.volume == pytest.approx(area * 2, rel=1e-6)


def test_3mf_has_one_body_per_assembly_part():
    trimesh = pytest.importorskip("trimesh")
    path = [p for p in EXAMPLES if p.stem == "mounting_plate"][0]
    o, c = example(path)
    scene = trimesh.load(io.BytesIO(encode(o, ".3mf")), file_type="3mf")
    assert len(scene.geometry) == len(o.parts) == 5
    areas = {p.name: p.shape.area() for p in c.drawing.parts}
    for name, mesh in scene.geometry.items():
        assert mesh.is_watertight
        assert mesh.volume == pytest.approx(areas[name] * 3.0, rel=1e-6)    # default 3 mm


# ------------------------------------------------------------------ thickness
THICK = """param thickness = 24 mm
thickness 4 mm
assembly kit {
    solid a {
        thickness 6 mm
        r = Rectangle(center=(0, 0), width=10, height=10)
    }
    solid b {
        r = Rectangle(center=(30, 0), width=thickness, height=10)
    }
}
"""


def test_thickness_file_default_and_per_structure_override(compile_text):
    trimesh = pytest.importorskip("trimesh")
    o, c = output_of(compile_text, THICK)
    assert {p.name: p.thickness for p in o.parts} == {"kit.a": 6.0, "kit.b": 4.0}
    scene = trimesh.load(io.BytesIO(encode(o, ".3mf")), file_type="3mf")
    vols = {n: g.volume for n, g in scene.geometry.items()}
    # `param thickness` is still an ordinary name: b is 24 mm wide
    assert vols == pytest.approx({"kit.a": 100 * 6.0, "kit.b": 240 * 4.0}, rel=1e-9)
    # --thickness overrides the program's
    stl = trimesh.load(io.BytesIO(encode(o, ".stl", Options(thickness=2))), file_type="stl")
    assert stl.volume == pytest.approx((100 + 240) * 2, rel=1e-9)


def test_thickness_statement_and_assignment_coexist(compile_text):
    o, c = output_of(compile_text, """solid s {
    thickness = 3
    thickness 2 in
    r = Rectangle(center=(0, 0), width=thickness, height=1)
}""")
    assert o.parts[0].thickness == pytest.approx(50.8) and o.area == pytest.approx(3.0)


@pytest.mark.parametrize("src,msg", [
    ("thickness -2 mm\nsolid s { r = Rectangle(center=(0, 0), width=1, height=1) }",
     "positive length"),
    ("thickness 30 deg\nsolid s { r = Rectangle(center=(0, 0), width=1, height=1) }",
     "expects a length"),
])
def test_bad_thickness_is_a_located_error(compile_text, src, msg):
    c = compile_text(src)
    (d,) = c.sink.errors()
    assert d.code == "E0109" and msg in d.message and d.span.line == 1 and d.span.col == 11


def test_thickness_formats_and_round_trips():
    from aidl_lang.editor.fmt import format_source
    src = "thickness   3mm\nsolid s { thickness 2 mm; r = Rectangle(center=(0,0), width=4, height=4) }\n"
    out = format_source(src)
    assert out.startswith("thickness 3 mm\nsolid s {\n    thickness 2 mm\n")
    assert format_source(out) == out


# ------------------------------------------------------------------ STEP (the `step` extra)
@pytest.mark.step
def test_step_keeps_circles_as_cylinders_and_the_exact_volume(compile_text, tmp_path):
    pytest.importorskip("OCP")
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.BRepGProp import BRepGProp
    from OCP.GeomAbs import GeomAbs_Cylinder, GeomAbs_Plane
    from OCP.GProp import GProp_GProps
    from OCP.STEPControl import STEPControl_Reader
    from OCP.TopAbs import TopAbs_FACE, TopAbs_SOLID
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    o, _ = output_of(compile_text, """thickness 3 mm
assembly kit {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=40, height=20, corner_radius=3)
        hole bore { c = Circle(center=(0, 0), radius=5) }
    }
    solid washer {
        thickness 1.5 mm
        d = Circle(center=(40, 0), radius=6)
        hole h { c = Circle(center=(40, 0), radius=2.5) }
    }
}""")
    path = tmp_path / "kit.step"
    path.write_bytes(encode(o, ".step"))
    r = STEPControl_Reader()
    assert r.ReadFile(str(path)) == 1
    r.TransferRoots()
    shape = r.OneShape()
    g = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, g)
    exact = (800 - (4 - math.pi) * 9 - 25 * math.pi) * 3 + (36 - 6.25) * math.pi * 1.5
    assert g.Mass() == pytest.approx(exact, rel=1e-6)
    kinds = []
    e = TopExp_Explorer(shape, TopAbs_FACE)
    while e.More():
        kinds.append(BRepAdaptor_Surface(TopoDS.Face(e.Current())).GetType())
        e.Next()
    # 4 rounded corners + the bore + the washer's outside and inside
    assert kinds.count(GeomAbs_Cylinder) == 7
    assert kinds.count(GeomAbs_Plane) == 4 + 2 + 2
    e, n = TopExp_Explorer(shape, TopAbs_SOLID), 0
    while e.More():
        n += 1
        e.Next()
    assert n == 2


def test_a_laser_png_shows_its_cuts_one_pixel_wide():
    """`--svg-style laser -o x.png` was all white (a 0.01 mm hairline is a hundredth of a
    pixel); a raster draws the cut at least one pixel wide: the rectangle's outline and the
    bore are red pixels all round."""
    import io

    import numpy as np
    from PIL import Image

    import aidl_lang
    r = aidl_lang.compile(source="solid plate {\n body = Rectangle(center=(0, 0), width=40, "
                                 "height=20)\n hole bore { c = Circle(center=(10, 0), radius=4) }\n}\n")
    for kw in ({}, {"width": 800}):
        a = np.asarray(Image.open(io.BytesIO(r.to_png(style="laser", **kw))).convert("RGB"))
        red = (a[:, :, 0] > 200) & (a[:, :, 1] < 100) & (a[:, :, 2] < 100)
        px = a.shape[1] / 44.0                   # pixels per mm (a 2 mm margin each side)
        # the rectangle's perimeter (120 mm) and the bore's (25 mm); a one-pixel line off
        # the pixel grid is half red on two pixels, so not every pixel counts
        assert red.sum() >= 0.4 * 145 * px, (kw, int(red.sum()), px)
    assert 'stroke-width="0.01"' in r.to_svg(style="laser")      # the SVG keeps its hairline


@pytest.mark.step
@pytest.mark.parametrize("suffix", sorted(__import__("aidl_lang.output", fromlist=["FORMATS"]).FORMATS))
def test_a_program_that_draws_nothing_is_a_clear_error_for_machines_and_3d(tmp_path, suffix):
    """A program with no shape: SVG, DXF, PDF and PNG are a blank page; every machine and 3D
    format refuses with one message saying what is missing (GLB and 3MF were an internal
    error, trimesh's "Can't export empty scenes!"; G-code an empty job)."""
    import subprocess
    import sys
    from aidl_lang.output import FORMATS
    if suffix in (".step", ".stp"):
        pytest.importorskip("OCP")
    prog = tmp_path / "empty.aidl"
    prog.write_text("units mm\nparam width = 40 mm\n")
    out = tmp_path / f"empty{suffix}"
    r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "render", str(prog), "-o", str(out)],
                       capture_output=True, text=True)
    if FORMATS[suffix].empty:
        assert r.returncode == 0 and out.exists(), r.stderr
    else:
        assert r.returncode == 1 and not out.exists()
        assert f"error: nothing to write to {suffix[1:].upper()}: the drawing has no" in r.stderr
        assert "internal error" not in r.stderr and "Traceback" not in r.stderr
