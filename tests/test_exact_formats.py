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
from hypothesis import given, settings, strategies as st

from conftest import EXAMPLES

SVG_TOL = 1e-9         # the SVG writer prints 9 decimals of a mm: rounding is <= 5e-10
DXF_TOL = 1e-9


def output(compile_text, src):
    from aidl_lang.output import build
    c = compile_text(src)
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    return build(c.drawing, c.model.root.name)


def svg_of(o, **kw) -> str:
    from aidl_lang.output.svg import to_svg
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
    from aidl_lang.output.part import Arc, Output, Stroke
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
    from aidl_lang.output.part import Arc, Line, Output, Stroke
    arc = Arc((7.0, -3.0), r, a0, sweep)
    o = Output(engrave=[Stroke([arc, Line(arc.end, arc.start)], closed=True)])
    (e,) = dxf_doc(o).modelspace().query("LWPOLYLINE")
    assert len(e) == 2
    ((c, rr, sw),) = _bulge_arcs(e)
    tol = DXF_TOL * max(1.0, r / 10)
    assert math.dist(c, (7.0, -3.0)) <= tol and abs(rr - r) <= tol
    assert abs(sw - sweep) <= 1e-9
