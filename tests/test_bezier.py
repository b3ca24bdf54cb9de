"""Bezier: a chain of cubic Bézier segments given by its control points (issue 39: the form
`aidl import` writes a drawing's free cubics with).

Outputs are re-read by independent readers (svgelements for the SVG path, ezdxf for the DXF
SPLINE) and compared with the control points as written, to 1e-9 mm; the box and the area
are checked against the cubic's own formulas, the errors by their code, place and numbers."""
from __future__ import annotations

import math

import ezdxf
import pytest

import aidl_lang
from exact_geometry import read_svg_loops

HEART = [(0, -20), (20, -5), (25, 15), (12, 18), (5, 20), (0, 15), (0, 10),
         (0, 15), (-5, 20), (-12, 18), (-25, 15), (-20, -5), (0, -20)]


def _pts(ps) -> str:
    return "[" + ", ".join(f"({x}, {y})" for x, y in ps) + "]"


def _ok(src: str, tmp_path):
    r = aidl_lang.compile("units mm\n" + src, path=tmp_path / "b.aidl")
    assert r.ok, [str(d) for d in r.errors]
    return r


def _bez(b, t):
    u = 1 - t
    return tuple(u ** 3 * b[0][i] + 3 * u * u * t * b[1][i] + 3 * u * t * t * b[2][i]
                 + t ** 3 * b[3][i] for i in range(2))


def test_closed_chain_is_its_control_points_in_svg_and_dxf(tmp_path):
    """The heart's four segments come out as four SVG `C` commands and one DXF SPLINE whose
    control points are the points as written."""
    r = _ok(f"solid heart {{\n    b = Bezier(points={_pts(HEART)}, closed=true)\n}}\n", tmp_path)
    svg = tmp_path / "h.svg"
    svg.write_text(r.to_svg())
    (loop,) = read_svg_loops(svg)
    got = []
    for s in loop:
        assert type(s).__name__ == "B", s
        got.append(s)
    # the loop may start anywhere and run either way: match the segments as sets
    want = {tuple(HEART[i:i + 4]) for i in range(0, 12, 3)}
    want |= {tuple(reversed(b)) for b in want}
    for s in got:
        pts = [s.p0, s.p1, s.p2, s.p3]
        assert any(all(math.dist(p, q) <= 1e-9 for p, q in zip(pts, w)) for w in want), pts
    assert len(got) == 4
    dxf = tmp_path / "h.dxf"
    dxf.write_text(r.to_dxf())
    (sp,) = [e for e in ezdxf.readfile(str(dxf)).modelspace() if e.dxftype() == "SPLINE"]
    cp = [(float(p[0]), float(p[1])) for p in sp.control_points]
    assert len(cp) == 13
    # a cyclic shift of the closed chain by whole segments, in either direction
    ring = HEART[:-1]
    ok = False
    for seq in (cp, cp[::-1]):
        k = ring.index(min(ring, key=lambda p: math.dist(p, seq[0])))
        ok |= k % 3 == 0 and all(math.dist(seq[i], ring[(k + i) % 12]) <= 1e-9
                                 for i in range(13))
    assert ok, cp


def test_box_area_and_members(tmp_path):
    """bb is the curve's box (the cubic's extremes, not the control points'); a Line closes
    an open Bezier into a face of the exact area under the cubic; members as written."""
    b = [(0, 0), (10, -8), (30, -8), (40, 0)]
    r = _ok(f"solid tab {{\n    top = Bezier(points={_pts(b)})\n"
            "    bottom = Line(start=top.end, end=top.start)\n"
            "    probe = Point(top.points[2], construction=true)\n}\n", tmp_path)
    # y(t) = -24 t (1 - t): lowest -6 at t = 1/2 (the control points reach -8)
    assert r.value("tab.bbox").mm == pytest.approx((0, -6, 40, 0), abs=1e-9)
    assert r.value("tab.probe.p").mm == pytest.approx((30, -8), abs=1e-12)
    # the area between the chord and the cubic, by dense sampling (independent of the code)
    n = 20000
    pts = [_bez(b, i / n) for i in range(n + 1)]
    area = abs(sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(pts, pts[1:] + pts[:1]))) / 2
    (part,) = r.output.parts
    assert part.area == pytest.approx(area, rel=1e-7)
    # exact: x = 30 t + 30 t^2 - 20 t^3, y = -24 t (1 - t): integral of -y x' dt = 24 * 7
    assert part.area == pytest.approx(168, abs=1e-9)


def test_stroke_and_engraving_along_a_bezier(tmp_path):
    wave = [(0, 0), (5, 15), (15, -15), (20, 0), (25, 15), (35, -15), (40, 0)]
    r = _ok(f"solid band {{\n    w = Bezier(points={_pts(wave)})\n    s = Stroke(w, width=2)\n"
            f"    drawing mark {{ e = Bezier(points={_pts(wave[:4])}) }}\n}}\n", tmp_path)
    (part,) = r.output.parts
    x0, y0, x1, y1 = r.value("band.bbox").mm
    # the wave's x runs 0..40, the round caps reach 1 mm further; y within its extremes + 1
    assert (x0, x1) == pytest.approx((-1, 41), abs=1e-6)
    ymax = max(_bez(wave[:4], i / 1000)[1] for i in range(1001))
    assert y1 == pytest.approx(ymax + 1, abs=1e-3)
    assert part.area > 0


@pytest.mark.parametrize("points, closed, needle, col", [
    ([(0, 0), (10, 10), (20, 0), (30, 5), (40, 0)], False,
     "takes 3k+1 points (p0, c1, c2, p1, c3, c4, p2, ...: each cubic segment two control "
     "points and an end point), got 5: give 4 points for 1 segment", 9),
    ([(0, 0), (10, 10), (20, 0)], False, "got 3: give 4 points", 9),
    ([(0, 0), (10, 10), (20, 10), (30, 0), (20, -10), (10, -10), (1, 0)], True,
     "its last point (1, 0) is not its first (0, 0)", 9),
    ([(5, 5), (5, 5), (5, 5), (5, 5), (10, 10), (20, 10), (30, 0)], False,
     "segment 0 (points[0] to points[3]) is one point (5, 5)", 9),
])
def test_bad_chains_are_located_errors(points, closed, needle, col, tmp_path):
    src = f"units mm\nsolid a {{\n    b = Bezier(points={_pts(points)}, closed={'true' if closed else 'false'})\n}}\n"
    r = aidl_lang.compile(src, path=tmp_path / "e.aidl")
    (d,) = r.errors
    assert d.code == "E0108" and needle in d.message, d.message
    assert (d.span.line, d.span.col) == (3, col)


def test_self_crossing_closed_chain_is_refused_where_it_crosses(tmp_path):
    """A bow tie of four straight cubic segments crosses itself at (10, 10)."""
    def seg(p, q):
        return [p, (p[0] + (q[0] - p[0]) / 3, p[1] + (q[1] - p[1]) / 3),
                (p[0] + 2 * (q[0] - p[0]) / 3, p[1] + 2 * (q[1] - p[1]) / 3)]
    corners = [(0, 0), (20, 20), (20, 0), (0, 20)]
    pts = [p for i in range(4) for p in seg(corners[i], corners[(i + 1) % 4])] + [(0, 0)]
    src = (f"units mm\nsolid a {{\n    b = Bezier(points=[" +
           ", ".join(f"({x!r}, {y!r})" for x, y in pts) + "], closed=true)\n}\n")
    r = aidl_lang.compile(src, path=tmp_path / "x.aidl")
    (d,) = r.errors
    assert d.code == "E0108" and "crosses itself at (10, 10) mm" in d.message, d.message
    assert d.span.line == 3


def test_mirrored_copy_is_the_bezier_of_the_mirrored_points(tmp_path):
    """A reflection maps a Bézier to the Bézier of the reflected control points."""
    b = [(2, 1), (8, 9), (14, -3), (20, 4)]
    r = _ok(f"solid s {{\n    base = Rectangle(center=(0, -10), width=60, height=4)\n"
            f"    drawing d {{\n        c = Bezier(points={_pts(b)})\n"
            f"        axis = Line(start=(0, -5), end=(0, 5), construction=true)\n"
            f"        m = Mirrored(c, about=axis)\n    }}\n}}\n", tmp_path)
    dxf = tmp_path / "m.dxf"
    dxf.write_text(r.to_dxf())
    got = sorted(tuple((round(float(p[0]), 9), round(float(p[1]), 9)) for p in e.control_points)
                 for e in ezdxf.readfile(str(dxf)).modelspace() if e.dxftype() == "SPLINE")
    want = sorted([tuple((float(x), float(y)) for x, y in b),
                   tuple((float(-x), float(y)) for x, y in b)])
    assert [tuple(sorted(g)) for g in got] == [tuple(sorted(w)) for w in want]


def test_import_writes_svg_cubics_as_bezier_and_renders_them_back(tmp_path):
    """An SVG path of two free cubics (no interpolating spline through its ends) is written as
    one closed `Bezier` by `aidl import` and renders back to the same control points."""
    from aidl_lang.drawing.write.program import import_drawing
    svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="30mm" '
           'viewBox="0 0 40 30"><path d="M5,25 C5,5 35,5 35,25 C30,28 10,28 5,25 Z"/></svg>')
    text, notes = import_drawing(svg.encode(), "logo.svg")
    assert not notes and "Bezier(points=[" in text and "closed=true" in text, text
    r = aidl_lang.compile(text, path=tmp_path / "logo.aidl")
    assert r.ok, [str(d) for d in r.errors]
    dxf = tmp_path / "l.dxf"
    dxf.write_text(r.to_dxf())
    (sp,) = [e for e in ezdxf.readfile(str(dxf)).modelspace() if e.dxftype() == "SPLINE"]
    cp = {(round(float(p[0]), 9), round(float(p[1]), 9)) for p in sp.control_points}
    # y up: the reader flips the SVG's y (y = -y_svg)
    want = {(5.0, -25.0), (5.0, -5.0), (35.0, -5.0), (35.0, -25.0), (30.0, -28.0),
            (10.0, -28.0)}
    assert len(sp.control_points) == 7 and cp == want


def test_a_closed_bezier_cuts_a_hole_of_its_exact_area(tmp_path):
    """A closed chain as a hole: the plate loses exactly the area the cubics enclose (the
    heart's, by dense sampling of the Bernstein form: independent of the code)."""
    r = _ok("solid plate {\n    body = Rectangle(center=(0, 0), width=80, height=60)\n"
            f"    hole heart {{\n        b = Bezier(points={_pts(HEART)}, closed=true)\n    }}\n"
            "    Fixed(body)\n    Coincident(heart.b.start, (0, -20))\n}\n", tmp_path)
    n = 4000
    pts = [_bez(HEART[i:i + 4], k / n) for i in range(0, 12, 3) for k in range(n)]
    area = abs(sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(pts, pts[1:] + pts[:1]))) / 2
    (part,) = r.output.parts
    assert part.area == pytest.approx(80 * 60 - area, rel=1e-7)
    assert len(part.loops) == 2


@pytest.mark.step
def test_step_edges_lie_on_the_chain(tmp_path):
    """The STEP file, re-read by OCP: every point of the bottom face's edges lies on the
    heart's cubics (their own control points, evaluated here) to 1e-9 mm."""
    pytest.importorskip("OCP")
    from exact_geometry import step_edge_points
    from aidl_lang.geometry.shapes.spline import bezier_chain
    r = _ok(f"solid heart {{\n    b = Bezier(points={_pts(HEART)}, closed=true)\n}}\n", tmp_path)
    step = tmp_path / "h.step"
    r.write(step)
    ref = bezier_chain(HEART, True)
    pts = step_edge_points(step, 100)
    worst = max(ref.distance(q) for q in pts)
    assert len(pts) >= 101 and worst <= 1e-9, (len(pts), worst)
