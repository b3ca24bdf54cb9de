"""Issue 36 section 2, "Exact, to the last digit, in every format": SVG coordinates to 1e-9 mm
(half circles as two quarter arcs), DXF extents when the drawing's corner is the origin, one
DXF bulge for every arc short of a whole turn, and the ellipse's exact carrier.

Real programs through the real pipeline and writers; the files are re-read by independent
readers (ezdxf, svgelements) and compared with the design's numbers.
"""
from __future__ import annotations

import io
import math
import re

import pytest
from hypothesis import assume, given, settings, strategies as st

from conftest import EXAMPLES

SVG_TOL = 1e-9         # the SVG writer prints 9 decimals of a mm: rounding is <= 5e-10
DXF_TOL = 1e-9


def output(compile_text, src):
    from aidl_lang.output import build
    c = compile_text(src)
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    return build(c.drawing, c.model.root.name)


def svg_of(o, **kw) -> str:
    from aidl_lang.output.writers.svg import to_svg
    return to_svg(o, **kw)


def dxf_doc(o):
    """The DXF of ``o`` as written to a file and read back (ezdxf fills the header only when
    it writes)."""
    import ezdxf
    from aidl_lang.output import encode
    return ezdxf.read(io.StringIO(encode(o, ".dxf").decode()))


def svg_segments(svg: str):
    """svgelements' segments of every path of the ``cut`` layer, in model coordinates
    (viewBox corner put back, y flipped back)."""
    import svgelements as se
    vb = re.search(r'viewBox="([^"]+)"', svg).group(1).replace(",", " ").split()
    vx, vy = float(vb[0]), float(vb[1])
    # width and height in user units: the view transform is the identity (svgelements' own
    # mm -> px factor is rounded)
    svg = re.sub(r'height="[^"]+"', f'height="{vb[3]}"', svg, count=1)
    svg = re.sub(r' width="[^"]+"', f' width="{vb[2]}"', svg, count=1)
    doc = se.SVG.parse(io.StringIO(svg), reify=True)
    out = []
    for el in doc.elements():
        if isinstance(el, se.Path):
            for s in el:
                if not isinstance(s, se.Move):
                    out.append(s)
    return out, (lambda p: (p.x + vx, -(p.y + vy)))


# ------------------------------------------------------------------ SVG to 1e-9 mm
def test_svg_numbers_have_nine_decimals_and_no_trailing_zeros(compile_text):
    o = output(compile_text, """
solid p {
    body = Rectangle(center=(0, 0), width=40 / 3, height=10)
    hole h { c = Circle(center=(1 / 7, 0), radius=5 / 3) }
}
""")
    svg = svg_of(o, margin=0)
    d = re.search(r'id="part-p"><path d="([^"]+)"', svg).group(1)
    nums = re.findall(r"-?\d+(?:\.\d+)?", d)
    assert nums
    for n in nums:
        assert not (("." in n) and n.endswith("0")), n          # no trailing zeros
        assert len(n.partition(".")[2]) <= 9, n
    assert "6.666666667," in d                                  # 20/3 to 9 decimals
    segs, model = svg_segments(svg)
    import svgelements as se
    arcs = [s for s in segs if isinstance(s, se.Arc)]
    assert len(arcs) == 4                                       # a circle: four quarter arcs
    for a in arcs:
        cx, cy = model(a.center)
        assert abs(cx - 1 / 7) <= 3 * SVG_TOL and abs(cy) <= 3 * SVG_TOL
        assert abs(a.rx - 5 / 3) <= SVG_TOL and abs(a.ry - 5 / 3) <= SVG_TOL
        assert abs(abs(a.sweep) - math.pi / 2) <= 4e-9 / (5 / 3)
    xs = [model(s.end)[0] for s in segs if isinstance(s, se.Line)]
    assert min(xs) == pytest.approx(-20 / 3, abs=SVG_TOL)
    assert max(xs) == pytest.approx(20 / 3, abs=SVG_TOL)


def test_svg_half_circles_are_two_quarter_arcs(compile_text):
    """A slot's ends are half circles: each written as two quarter arcs, whose centres and
    radii re-read by svgelements are the design's to 1e-9 mm."""
    o = output(compile_text, """
solid p {
    s = Slot(center=(0.1, 0.2), length=30, width=20 / 3, rotation=30 deg)
}
""")
    svg = svg_of(o)
    import svgelements as se
    segs, model = svg_segments(svg)
    arcs = [s for s in segs if isinstance(s, se.Arc)]
    assert len(arcs) == 4
    r = 10 / 3
    h = (30 - 20 / 3) / 2
    ends = [(0.1 + h * math.cos(math.pi / 6) * k, 0.2 + h * math.sin(math.pi / 6) * k)
            for k in (1, -1)]
    for a in arcs:
        assert abs(abs(a.sweep) - math.pi / 2) <= 4e-9 / r
        assert abs(a.rx - r) <= SVG_TOL and abs(a.ry - r) <= SVG_TOL
        c = model(a.center)
        assert min(math.dist(c, e) for e in ends) <= 3 * SVG_TOL


@given(sweep=st.floats(1e-3, 2 * math.pi - 1e-3), a0=st.floats(-math.pi, math.pi),
       r=st.floats(0.5, 500))
@settings(max_examples=40, deadline=None)
def test_svg_arcs_are_pieces_of_at_most_a_quarter(sweep, a0, r):
    import svgelements as se
    from aidl_lang.output.part.part import Arc, Output, Stroke
    arc = Arc((3.0, -2.0), r, a0, sweep)
    svg = svg_of(Output(engrave=[Stroke([arc])]))
    segs, model = svg_segments(svg)
    arcs = [s for s in segs if isinstance(s, se.Arc)]
    assert len(arcs) == math.ceil(sweep / (math.pi / 2) - 1e-9)
    # each end is rounded to 5e-10 mm: a piece's angle is the design's within ~1e-9 / r
    ang = 4e-9 / r
    assert sum(abs(a.sweep) for a in arcs) == pytest.approx(sweep, abs=len(arcs) * ang)
    for a in arcs:
        assert abs(a.sweep) <= math.pi / 2 + ang
        # the curve a reader draws is the design's circle to ~1e-9 mm (the centre of a short
        # piece is ill-conditioned, the points of it are not)
        for t in (0.0, 0.25, 0.5, 0.75, 1.0):
            assert abs(math.dist(model(a.point(t)), (3.0, -2.0)) - r) <= 3 * SVG_TOL
    assert math.dist(model(arcs[-1].end), arc.end) <= SVG_TOL


# ------------------------------------------------------------------ DXF extents
def test_dxf_extents_of_the_ruler_whose_corner_is_the_origin(tmp_path):
    from aidl_lang.cli.main import main
    import ezdxf
    ruler = next(p for p in EXAMPLES if p.name == "ruler.aidl")
    out = tmp_path / "ruler.dxf"
    assert main(["render", str(ruler), "-o", str(out)]) == 0
    doc = ezdxf.readfile(out)
    # the bar: margin 8 + 150 mm scale + tail 22 = 180 mm long, 36 mm wide, corner at 0, 0
    assert tuple(doc.header["$EXTMIN"]) == pytest.approx((0, 0, 0), abs=DXF_TOL)
    assert tuple(doc.header["$EXTMAX"]) == pytest.approx((180, 36, 0), abs=DXF_TOL)


def test_dxf_extents_of_a_layout_sheet_are_the_sheet(tmp_path):
    pytest.importorskip("spyrrow")
    from aidl_lang.cli.main import main
    import ezdxf
    prog = tmp_path / "kit.aidl"
    prog.write_text("""
assembly kit {
    solid a { body = Rectangle(center=(0, 0), width=40, height=30) }
    solid b { body = Circle(center=(100, 0), radius=12) }
}
""")
    out = tmp_path / "cut.dxf"
    assert main(["render", str(prog), "--layout", "sheet", "--sheet", "300x200mm",
                 "-o", str(out)]) == 0
    doc = ezdxf.readfile(out)
    assert tuple(doc.header["$EXTMIN"]) == pytest.approx((0, 0, 0), abs=DXF_TOL)
    assert tuple(doc.header["$EXTMAX"]) == pytest.approx((300, 200, 0), abs=DXF_TOL)


# ------------------------------------------------------------------ DXF: one bulge per arc
def _bulge_arcs(e):
    """(center, radius, sweep) of each bulged vertex of an LWPOLYLINE, by ezdxf's own
    bulge_to_arc."""
    from ezdxf.math import bulge_to_arc
    pts = list(e.get_points("xyb"))
    n = len(pts)
    out = []
    for i, (x, y, b) in enumerate(pts):
        if b == 0 or (i == n - 1 and not e.closed):
            continue
        q = pts[(i + 1) % n]
        c, a0, a1, r = bulge_to_arc((x, y), q[:2], b)
        out.append(((c.x, c.y), r, 4 * math.atan(b)))
    return out


def test_dxf_slot_half_circles_are_one_bulge_each(compile_text):
    o = output(compile_text, """
solid p {
    s = Slot(center=(0, 0), length=30, width=10)
}
""")
    doc = dxf_doc(o)
    (e,) = doc.modelspace().query("LWPOLYLINE")
    assert len(e) == 4                                   # two lines, two half circles
    arcs = _bulge_arcs(e)
    assert len(arcs) == 2
    for c, r, sw in arcs:
        assert abs(abs(sw) - math.pi) <= 1e-12 and abs(r - 5) <= DXF_TOL
        assert min(math.dist(c, (10, 0)), math.dist(c, (-10, 0))) <= DXF_TOL


@given(sweep=st.floats(math.pi - 1e-9, 2 * math.pi - 1.001e-3), a0=st.floats(-math.pi, math.pi),
       r=st.floats(0.5, 500))
@settings(max_examples=50, deadline=None)
def test_dxf_an_arc_short_of_a_whole_turn_is_one_bulge(sweep, a0, r):
    """A closed chain of an arc and the chord back: two vertices, one bulge; the arc re-read
    has the design's centre and radius."""
    from aidl_lang.output.part.part import Arc, Line, Output, Stroke
    arc = Arc((7.0, -3.0), r, a0, sweep)
    o = Output(engrave=[Stroke([arc, Line(arc.end, arc.start)], closed=True)])
    (e,) = dxf_doc(o).modelspace().query("LWPOLYLINE")
    assert len(e) == 2
    ((c, rr, sw),) = _bulge_arcs(e)
    tol = DXF_TOL * max(1.0, r / 10)
    assert math.dist(c, (7.0, -3.0)) <= tol and abs(rr - r) <= tol
    assert abs(sw - sweep) <= 1e-9


# ------------------------------------------------------------------ the exact ellipse
def _ellipses(doc):
    """(center, major axis vector, ratio, start, end) of every ELLIPSE entity."""
    return [(tuple(e.dxf.center)[:2], tuple(e.dxf.major_axis)[:2], e.dxf.ratio,
             e.dxf.start_param, e.dxf.end_param) for e in doc.modelspace().query("ELLIPSE")]


def _design(cx, cy, rx, ry, rot):
    """The design's ellipse in DXF's canonical terms: major axis vector and ratio."""
    if rx < ry:
        rx, ry, rot = ry, rx, rot + math.pi / 2
    return (cx, cy), (rx * math.cos(rot), rx * math.sin(rot)), ry / rx


def _same_axis(a, b, tol):
    """Major axis vectors equal up to sign (an ellipse's axis points either way)."""
    return math.dist(a, b) <= tol or math.dist(a, (-b[0], -b[1])) <= tol


def _on_ellipse(p, c, rx, ry, rot) -> float:
    """The distance-like error of ``p`` from the ellipse: |implicit| * min semi-axis / 2."""
    x, y = p[0] - c[0], p[1] - c[1]
    u = x * math.cos(rot) + y * math.sin(rot)
    v = -x * math.sin(rot) + y * math.cos(rot)
    return abs((u / rx) ** 2 + (v / ry) ** 2 - 1) * min(rx, ry) / 2


@given(cx=st.floats(-50, 50), cy=st.floats(-50, 50), rx=st.floats(1, 30), ry=st.floats(1, 30),
       rot=st.floats(-180, 180))
@settings(max_examples=15, deadline=None)
def test_an_elliptical_hole_is_one_dxf_ellipse_and_svg_elliptical_arcs(cx, cy, rx, ry, rot):
    """A plate with an elliptical hole: the DXF holds one ELLIPSE whose centre, major axis,
    ratio and parameters are the design's to 1e-9; the SVG's elliptical arcs, re-read by
    svgelements, lie on the design's ellipse to 3e-9 mm; the area is exact."""
    from aidl_lang.output import build
    from aidl_lang.pipeline import compile_source
    if abs(rx - ry) < 1e-6:
        ry = rx + 0.5
    src = f"""
solid p {{
    body = Rectangle(center=({cx!r}, {cy!r}), width={2 * max(rx, ry) + 10!r}, height={2 * max(rx, ry) + 10!r})
    hole h {{ e = Ellipse(center=({cx!r}, {cy!r}), rx={rx!r}, ry={ry!r}, rotation={rot!r} deg) }}
}}
"""
    c = compile_source(src, "t.aidl")
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    o = build(c.drawing, "p")
    side = 2 * max(rx, ry) + 10
    assert o.area == pytest.approx(side * side - math.pi * rx * ry, abs=1e-9 * side * side)
    (el,) = _ellipses(dxf_doc(o))
    center, axis, ratio = _design(cx, cy, rx, ry, math.radians(rot))
    assert math.dist(el[0], center) <= DXF_TOL
    assert _same_axis(el[1], axis, DXF_TOL * max(rx, ry))
    assert abs(el[2] - ratio) <= 1e-12
    assert (el[3], el[4]) == pytest.approx((0, 2 * math.pi), abs=1e-12)
    import svgelements as se
    segs, model = svg_segments(svg_of(o))
    arcs = [s for s in segs if isinstance(s, se.Arc) and abs(s.rx - s.ry) > 1e-6]
    assert len(arcs) == 4
    for a in arcs:
        assert sorted((a.rx, a.ry)) == pytest.approx(sorted((rx, ry)), abs=SVG_TOL)
        for t in (0.0, 0.3, 0.5, 0.9, 1.0):
            assert _on_ellipse(model(a.point(t)), (cx, cy), rx, ry, math.radians(rot)) <= 3 * SVG_TOL


def test_a_union_and_a_cut_keep_exact_elliptical_arcs(compile_text):
    """A rectangle with an elliptical lobe added on its right edge and an ellipse cut out of
    its left edge: each is one ELLIPSE piece between the exact crossings (x = +-20, y = +-5
    where the ellipses meet the edges), the lines end there."""
    o = output(compile_text, """
solid p {
    body = Rectangle(center=(0, 0), width=40, height=30)
    lobe = Ellipse(center=(20, 0), rx=8, ry=5)
    hole bite { e = Ellipse(center=(-20, 0), rx=5, ry=10, rotation=90 deg) }
}
""")
    doc = dxf_doc(o)
    els = sorted(_ellipses(doc))
    assert len(els) == 2
    bite, lobe = els
    # the lobe: x = 20 + 8 cos t, y = 5 sin t, from t = -pi/2 to pi/2 (ccw)
    assert math.dist(lobe[0], (20, 0)) <= DXF_TOL and _same_axis(lobe[1], (8, 0), DXF_TOL)
    assert lobe[2] == pytest.approx(5 / 8, abs=1e-15)
    assert (lobe[3] % (2 * math.pi), lobe[4] % (2 * math.pi)) == \
        pytest.approx((1.5 * math.pi, 0.5 * math.pi), abs=1e-9)
    # the bite: rx 5 along 90 deg = major axis 10 along x, ratio 0.5; half of it inside
    assert math.dist(bite[0], (-20, 0)) <= DXF_TOL and _same_axis(bite[1], (10, 0), DXF_TOL)
    assert bite[2] == pytest.approx(0.5, abs=1e-15)
    assert abs((bite[4] - bite[3]) - math.pi) <= 1e-9
    ends = set()
    for e in doc.modelspace().query("ELLIPSE"):
        for p in (e.start_point, e.end_point):
            ends.add((round(p.x, 9), round(p.y, 9)))
    assert ends == {(20.0, 5.0), (20.0, -5.0), (-20.0, 5.0), (-20.0, -5.0)}
    assert o.area == pytest.approx(1200 + math.pi * 8 * 5 / 2 - math.pi * 10 * 5 / 2, abs=1e-9)


def test_an_ellipse_crossing_a_circle_meets_it_on_both_curves(compile_text):
    o = output(compile_text, """
solid p {
    e = Ellipse(center=(0, 0), rx=20, ry=8, rotation=25 deg)
    c = Circle(center=(15, 9), radius=6)
}
""")
    (part,) = o.parts
    (lp,) = part.loops
    from aidl_lang.output.part.part import Arc, EllipticArc
    kinds = sorted(type(s).__name__ for s in lp.segments)
    assert kinds == ["Arc", "EllipticArc"]
    for s in lp.segments:
        for p in (s.start, s.end):
            assert _on_ellipse(p, (0, 0), 20, 8, math.radians(25)) <= 1e-12
            assert abs(math.dist(p, (15, 9)) - 6) <= 1e-9
    assert isinstance(lp.segments[0], (Arc, EllipticArc))


def test_fillet_where_two_ellipses_meet_is_a_located_refusal(compile_text):
    # Offset, Shell, Hull and a Fillet beside a line or arc take ellipses
    # (tests/test_ellipse_operations.py); two ellipses' corner has no fillet here yet
    c = compile_text("units mm\nsolid p {\n    e = Ellipse(center=(0, 0), rx=20, ry=10)\n"
                     "    f = Ellipse(center=(20, 0), rx=10, ry=6)\n    Fillet(2)\n}\n")
    errs = [d for d in c.sink.items if d.severity == "error"]
    assert [d.code for d in errs] == ["E0407"], [(d.code, d.message) for d in c.sink.items]
    assert "where an Ellipse meets" in errs[0].message
    assert errs[0].span.line == 3                # at the Ellipse


@pytest.mark.step
def test_an_ellipse_is_an_ellipse_in_step(compile_text, tmp_path):
    pytest.importorskip("OCP")
    from OCP.BRepAdaptor import BRepAdaptor_Curve
    from OCP.BRepGProp import BRepGProp
    from OCP.GeomAbs import GeomAbs_Ellipse
    from OCP.GProp import GProp_GProps
    from OCP.STEPControl import STEPControl_Reader
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    from aidl_lang.output import Options, encode
    o = output(compile_text, """
solid p {
    body = Rectangle(center=(0, 0), width=40, height=30)
    lobe = Ellipse(center=(20, 0), rx=8, ry=5)
    hole h { e = Ellipse(center=(-5, 0), rx=6, ry=3, rotation=30 deg) }
}
""")
    f = tmp_path / "p.step"
    f.write_bytes(encode(o, ".step", Options(thickness=2.0)))
    r = STEPControl_Reader()
    r.ReadFile(str(f))
    r.TransferRoots()
    shape = r.OneShape()
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, props)
    area = 1200 + math.pi * 8 * 5 / 2 - math.pi * 6 * 3
    assert props.Mass() == pytest.approx(2 * area, rel=1e-9)
    ex = TopExp_Explorer(shape, TopAbs_EDGE)
    radii = set()
    while ex.More():
        c = BRepAdaptor_Curve(TopoDS.Edge(ex.Current()))
        if c.GetType() == GeomAbs_Ellipse:
            el = c.Ellipse()
            radii.add((round(el.MajorRadius(), 9), round(el.MinorRadius(), 9)))
        ex.Next()
    assert radii == {(8.0, 5.0), (6.0, 3.0)}


def test_a_mirrored_ellipse_is_the_reflected_curve(compile_text):
    o = output(compile_text, """
solid p {
    axis = Line((0, -30), (0, 30), construction=true)
    Fixed(axis)
    e = Ellipse(center=(15, 5), rx=10, ry=4, rotation=30 deg)
    m = Mirrored(e, about=axis)
}
""")
    els = sorted(_ellipses(dxf_doc(o)))
    assert len(els) == 2
    left, right = els
    assert math.dist(left[0], (-15, 5)) <= DXF_TOL and math.dist(right[0], (15, 5)) <= DXF_TOL
    a = math.radians(30)
    assert _same_axis(right[1], (10 * math.cos(a), 10 * math.sin(a)), DXF_TOL)
    assert _same_axis(left[1], (-10 * math.cos(a), 10 * math.sin(a)), DXF_TOL)


@given(ex=st.floats(-15, 15), ey=st.floats(-10, 10), rx=st.floats(3, 25), ry=st.floats(3, 25),
       rot=st.floats(0, 180), cut=st.booleans())
@settings(max_examples=25, deadline=None)
def test_a_rectangle_and_an_ellipse_come_out_on_their_curves(ex, ey, rx, ry, rot, cut):
    """Law: a 40 x 30 rectangle united with (or cut by) a random ellipse: every output piece
    lies on its curve (ellipse pieces' ends on the design's ellipse to 1e-9, line ends on the
    rectangle's sides or the ellipse) and the exact area equals shapely's area of the finely
    sampled design within the chords' error."""
    import shapely
    from aidl_lang.output import build
    from aidl_lang.output.part.part import EllipticArc, Line
    from aidl_lang.pipeline import compile_source
    if abs(rx - ry) < 1e-3:
        ry = rx + 0.5
    # an ellipse within 0.01 mm of a side (beyond it or short of it) meets the side inside the
    # union's chord tolerance: a sliver of 1.4 um past the side (ex=10, rx=10, ry=10.5,
    # rot=3) is lost (noted in issue 85's closing note), so the law holds clear of it
    a = math.radians(rot)
    X = math.hypot(rx * math.cos(a), ry * math.sin(a))
    Y = math.hypot(rx * math.sin(a), ry * math.cos(a))
    assume(all(abs(g) > 0.01 for g in (ex + X - 20, ex - X + 20, ey + Y - 15, ey - Y + 15)))
    ell = f"Ellipse(center=({ex!r}, {ey!r}), rx={rx!r}, ry={ry!r}, rotation={rot!r} deg)"
    src = ("solid p {\n    body = Rectangle(center=(0, 0), width=40, height=30)\n" +
           (f"    hole h {{ e = {ell} }}\n" if cut else f"    e = {ell}\n") + "}\n")
    c = compile_source(src, "t.aidl")
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    o = build(c.drawing, "p")
    a = math.radians(rot)
    E = _ellipse_poly(ex, ey, rx, ry, rot)
    R = shapely.box(-20, -15, 20, 15)
    want = (R.difference(E) if cut else R.union(E)).area
    # the 20000-gon is short of the ellipse by ~ area * 1.6e-8; chords of 0.005 mm would be
    # off by ~ perimeter * 0.003 mm^2
    assert o.area == pytest.approx(want, abs=1e-4)
    for p in o.parts:
        for lp in p.loops:
            for s in lp.segments:
                for q in (s.start, s.end):
                    on_e = _on_ellipse(q, (ex, ey), rx, ry, a) <= 1e-9
                    if isinstance(s, EllipticArc):
                        assert on_e, (s, q)
                    else:
                        assert isinstance(s, Line)
                        on_r = min(abs(abs(q[0]) - 20) if abs(q[1]) <= 15 + 1e-9 else 1,
                                   abs(abs(q[1]) - 15) if abs(q[0]) <= 20 + 1e-9 else 1) <= 1e-9
                        assert on_r or on_e, (s, q)


def _ellipse_poly(cx, cy, rx, ry, rot, n=20000):
    """The ellipse sampled at ``n`` evenly spaced parameters, a shapely polygon (the reference
    of the laws below; built with NumPy: in Python lists it was 7 of their 10 s of CPU)."""
    import numpy as np
    import shapely
    a = math.radians(rot)
    s = 2 * math.pi * np.arange(n) / n
    return shapely.Polygon(np.column_stack(
        (cx + rx * np.cos(s) * math.cos(a) - ry * np.sin(s) * math.sin(a),
         cy + rx * np.cos(s) * math.sin(a) + ry * np.sin(s) * math.cos(a))))


@given(d=st.tuples(st.floats(-20, 20), st.floats(-20, 20)), r1=st.tuples(st.floats(4, 20), st.floats(4, 20)),
       r2=st.tuples(st.floats(2, 20), st.floats(2, 20)), rots=st.tuples(st.floats(0, 180), st.floats(0, 180)),
       circle=st.booleans())
@settings(max_examples=20, deadline=None)
def test_an_ellipse_with_an_ellipse_or_a_circle_has_its_exact_area(d, r1, r2, rots, circle):
    """Law: the union of an ellipse with a second ellipse (or a circle) has the area of the
    finely sampled design (shapely) and every piece's ends on both of its neighbours'
    curves."""
    from aidl_lang.output import build
    from aidl_lang.pipeline import compile_source
    (rx, ry), (sx, sy) = r1, r2
    if abs(rx - ry) < 1e-3:
        ry = rx + 0.5
    if abs(sx - sy) < 1e-3:
        sy = sx + 0.5
    other = f"Circle(center=({d[0]!r}, {d[1]!r}), radius={sx!r})" if circle else \
        f"Ellipse(center=({d[0]!r}, {d[1]!r}), rx={sx!r}, ry={sy!r}, rotation={rots[1]!r} deg)"
    src = (f"solid p {{\n    a = Ellipse(center=(0, 0), rx={rx!r}, ry={ry!r}, rotation={rots[0]!r} deg)\n"
           f"    b = {other}\n}}\n")
    c = compile_source(src, "t.aidl")
    assert c.ok, [(x.code, x.message) for x in c.sink.items]
    o = build(c.drawing, "p")
    A = _ellipse_poly(0, 0, rx, ry, rots[0])
    B = _ellipse_poly(d[0], d[1], sx, sx if circle else sy, 0 if circle else rots[1])
    assert o.area == pytest.approx(A.union(B).area, abs=1e-4)
    from aidl_lang.geometry.shapes.curves import carrier, distance_to
    for p in o.parts:
        for lp in p.loops:
            segs = lp.segments
            for k, s in enumerate(segs):
                nxt = segs[(k + 1) % len(segs)]
                if s is nxt:
                    continue
                assert distance_to(carrier(s), s.end) <= 1e-9
                assert distance_to(carrier(nxt), s.end) <= 1e-9
