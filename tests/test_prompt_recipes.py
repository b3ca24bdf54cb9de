"""The prompt's recipes for what issue 111's models reached for, each through the real
compiler: Lines and Arcs meeting end to end in a solid close into one outline (an arched top;
runs i and q drew a big circle hole instead), written to DXF and re-read by ezdxf (one closed
polyline, the arc exact: its bulge, 2 x sagitta / chord); a point partway along a line (run
p); a hexagram of two RegularPolygons (run r's menorah: two Triangles by `center` share their
boxes' centres, a bow-tie)."""
from __future__ import annotations

import pytest

import aidl_lang

SRC = """solid gauge {
    a = Line((-40, 0), (40, 0))
    b = Line((40, 0), (40, 30))
    top = Arc(start=(40, 30), through=(0, THROUGH), end=(-40, 30))
    d = Line((-40, 30), (-40, 0))
}
"""


@pytest.mark.parametrize("through, bulge", [("25", -0.125), ("35", 0.125)])
def test_an_arched_top_between_lines_is_one_outline_with_an_exact_arc(tmp_path, through, bulge):
    import ezdxf
    r = aidl_lang.compile(source=SRC.replace("THROUGH", through))
    assert r.ok and not [d for d in r.diagnostics if d.severity == "warning"]
    out = tmp_path / "gauge.dxf"
    r.write(out)
    (pl,) = [e for e in ezdxf.readfile(out).modelspace() if e.dxf.layer.upper() == "CUT"]
    assert pl.dxftype() == "LWPOLYLINE" and pl.closed
    pts = list(pl.get_points("xyb"))
    assert len(pts) == 4
    # the arc from (40, 30) to (-40, 30) through (0, 25) (concave) or (0, 35) (arched): the
    # bulge is 2 x 5 / 80, its sign the side (clockwise into the part, counter-clockwise out)
    (k,) = [i for i, p in enumerate(pts) if abs(p[2]) > 0]
    assert pts[k][2] == pytest.approx(bulge, abs=1e-12)
    assert (pts[k][0], pts[k][1]) == pytest.approx((40, 30), abs=1e-9)


def test_a_point_a_quarter_along_a_line_places_a_hole():
    """The prompt's `l.start + (l.end - l.start) * 0.25` (issue 111, run p reached for a
    point partway along a line): exact, through the solver."""
    r = aidl_lang.compile(source="""solid p {
    body = Rectangle(center=(0, 0), width=60, height=40)
    edge = Line((-20, -10), (20, 10), construction=true)
    hole h { c = Circle(center=(0, 0), radius=2) }
    Coincident(h.c.center, edge.start + (edge.end - edge.start) * 0.25)
}
""")
    assert r.ok
    assert {v.name: v.mm for v in r.values}["p.h.c.center"] == pytest.approx((-10, -5), abs=1e-9)


def test_a_hexagram_of_two_regular_triangles_shares_one_centre():
    r = aidl_lang.compile(source="""solid p {
    body = Rectangle(center=(0, 0), width=80, height=80)
    drawing star {
        up = RegularPolygon(center=(0, 0), radius=30, sides=3, rotation=90 deg)
        down = RegularPolygon(center=(0, 0), radius=30, sides=3, rotation=270 deg)
    }
}
""")
    assert r.ok and not [d for d in r.diagnostics if d.severity == "warning"]
    import math
    vals = {v.name: v.mm for v in r.values}
    # each vertex 30 mm from the one centre (0, 0): up's first at 90 deg, down's at 270
    for n, a0 in (("up", 90), ("down", 270)):
        assert vals[f"p.star.{n}.center"] == pytest.approx((0, 0), abs=1e-9)
        for k in range(3):
            a = math.radians(a0 + 120 * k)
            assert vals[f"p.star.{n}.p{k}"] == pytest.approx((30 * math.cos(a), 30 * math.sin(a)),
                                                             abs=1e-9)


def test_the_prompts_heart_is_one_symmetric_piece_of_two_lines_and_two_arcs(tmp_path):
    """A heart was reached for in runs j, p and t (t's two circles over a triangle left spurs):
    the prompt's two Hulls of a circle and a point make one piece, mirror-symmetric, whose
    DXF outline (ezdxf) is 2 lines and 2 arcs of radius 9 mm."""
    import ezdxf
    r = aidl_lang.compile(source="""solid tag {
    left = Hull(Circle(center=(-8, 5), radius=9), Point(0, -16))
    right = Hull(Circle(center=(8, 5), radius=9), Point(0, -16))
}
""")
    assert r.ok and not [d for d in r.diagnostics if d.severity == "warning"]
    (p,) = r.parts
    assert p.bbox == pytest.approx((-17, -16, 17, 14), abs=1e-9)
    out = tmp_path / "heart.dxf"
    r.write(out)
    (pl,) = [e for e in ezdxf.readfile(out).modelspace() if e.dxf.layer.upper() == "CUT"]
    pts = list(pl.get_points("xyb"))
    assert len(pts) == 4 and sum(abs(b) > 1e-9 for *_, b in pts) == 2     # 2 arcs, 2 lines
    assert sorted(round(x, 9) for x, *_ in pts) == sorted(round(-x, 9) for x, *_ in pts)
