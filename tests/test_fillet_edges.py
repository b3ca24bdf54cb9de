"""Issue 91, "no operation dropped in silence": `Fillet([edge1, edge2], r)` and
`Chamfer([edge1, edge2], d)` on generated pairs of edges (meeting at their ends, crossing
mid-span, one ending on the other, apart, parallel) either make the corner or say why, located
at the call (E0408 naming both edges; W0406 with the size a short piece left).

The law: every pair that meets gives an arc tangent to both edges' lines (a chamfer: a line
with its ends on both lines, equally far from where they meet), re-read from the SVG by
svgelements and from the DXF by ezdxf, to 1e-6 mm, of the asked size or of the smaller size
its W0406 names; every pair that does not meet gives one E0408 naming both edges and nothing
is rounded.  Real programs through the real parser, solver, booleans and writers.
Cost: 2 x 16 generated programs, about 0.1 s each (about 4 s in all)."""
from __future__ import annotations

import math
import re

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from test_exact_formats import _bulge_arcs, dxf_doc, svg_segments

TOL = 1e-6              # mm: the brief's bound on the re-read geometry
MEETS = ("ends", "convex", "crossing", "one ends")


def _pt(p) -> str:
    return f"({p[0]!r}, {p[1]!r})"


def _r(turn: float, *pts):
    """The points turned by ``turn`` (radians) about the origin, as the program writes them
    (6 decimals), so the edges are what it reads."""
    c, s = math.cos(turn), math.sin(turn)
    return [(round(x * c - y * s, 6), round(x * s + y * c, 6)) for x, y in pts]


@st.composite
def pairs(draw):
    """(case, program body, edge 1's ends, edge 2's ends, names): edge 1 runs up the line
    x = 0 (the right side of the solid `stem`), edge 2 leaves the point M = (0, m) at angle
    phi (the bottom side of the solid `arm`, a parallelogram of height w above it); the
    whole drawing then turned by a generated angle."""
    case = draw(st.sampled_from(MEETS + ("apart", "past the end", "parallel")))
    turn = math.radians(draw(st.sampled_from([0.0, 90.0]) | st.floats(0, 360)))
    a, b = draw(st.floats(10, 40)), draw(st.floats(10, 40))        # edge 1: y from -a to b
    m = draw(st.floats(-a + 4, b - 4))
    phi = math.radians(draw(st.floats(-55, 55)))
    d = (math.cos(phi), math.sin(phi))
    L, w = draw(st.floats(12, 40)), draw(st.floats(3, 8))
    M = (0.0, m)
    if case in ("ends", "convex"):
        # one polygon: (-12, -a), (0, -a), M, M + L d, then back up-left; its edges 1 and 2
        # meet at M (an inside corner), its edges 0 and 1 at (0, -a) (an outside one)
        P3 = (L * d[0], m + L * d[1])
        P4 = (-12.0, max(P3[1], m) + w)
        pts = _r(turn, (-12.0, -a), (0.0, -a), M, P3, P4)
        M = pts[2]
        body = f"    solid stem {{\n        p = Polygon(points=[{', '.join(map(_pt, pts))}])\n    }}\n"
        if case == "ends":
            return case, body, (pts[1], M), (M, pts[3]), ("stem.p.edges[1]", "stem.p.edges[2]")
        return case, body, (pts[0], pts[1]), (pts[1], M), ("stem.p.edges[0]", "stem.p.edges[1]")
    stem = _r(turn, (-12.0, -a), (0.0, -a), (0.0, b), (-12.0, b))
    if case == "parallel":
        g = draw(st.sampled_from([0.0, 0.5, 3.0]))
        A, B = (g, m - 2), (g, m + L)              # along x = g, up
        arm = _r(turn, A, B, (g + w, m + L), (g + w, m - 2))
    else:
        s = {"crossing": draw(st.floats(2, 8)), "one ends": 0.0,
             "apart": -draw(st.floats(0.5, 5)), "past the end": 2.0}[case]
        if case == "past the end":                  # edge 2 crosses x = 0 above edge 1's top
            M = (0.0, b + draw(st.floats(1, 6)))
        A = (M[0] - s * d[0], M[1] - s * d[1])
        B = (M[0] + L * d[0], M[1] + L * d[1])
        arm = _r(turn, A, B, (B[0], B[1] + w), (A[0], A[1] + w))
    body = (f"    solid stem {{\n        p = Polygon(points=[{', '.join(map(_pt, stem))}])\n    }}\n"
            f"    solid arm {{\n        q = Polygon(points=[{', '.join(map(_pt, arm))}])\n    }}\n")
    return case, body, (stem[1], stem[2]), (arm[0], arm[1]), ("stem.p.edges[1]", "arm.q.edges[0]")


def _line_gap(p, e) -> float:
    """Distance from point ``p`` to the line through edge ``e``."""
    (x0, y0), (x1, y1) = e
    L = math.hypot(x1 - x0, y1 - y0)
    return abs((x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0)) / L


def _meet(e1, e2):
    (ax, ay), (bx, by) = e1
    (cx, cy), (dx, dy) = e2
    ux, uy, vx, vy = bx - ax, by - ay, dx - cx, dy - cy
    t = ((cx - ax) * vy - (cy - ay) * vx) / (ux * vy - uy * vx)
    return ax + t * ux, ay + t * uy


def _compile(src):
    from aidl_lang import api
    res = api.compile(src)
    return res, [d for d in res.diagnostics if d.code in ("E0408", "W0406")]


def _size_said(said, asked: float) -> float:
    """The size the corner got: the asked one, or the one its W0406 names."""
    if not said:
        return asked
    (d,) = said
    assert d.code == "W0406", d.message
    got = re.search(r"with only ([0-9.e+-]+) mm", d.message)
    return float(got.group(1)) if got else 0.0


def _check_said(case, said, names, span_line):
    """A pair that does not meet: one E0408 at the call naming both edges."""
    assert case not in MEETS, [d.message for d in said]
    (d,) = said
    assert d.code == "E0408" and d.severity == "error"
    assert f"`{names[0]}`" in d.message and f"`{names[1]}`" in d.message, d.message
    assert d.span.line == span_line


def _run(op: str, pair, size: float):
    """Compile ``op([edge1, edge2], size)`` on the generated pair: None when it says E0408
    (checked: a pair that does not meet, both edges named, at the call), else (case, source,
    edge 1, edge 2, the result, its W0406 if any, the size the corner got)."""
    case, body, e1, e2, names = pair
    src = f"solid hook {{\n{body}    {op}([{names[0]}, {names[1]}], {size})\n}}\n"
    line = src[:src.index(op + "(")].count("\n") + 1
    res, said = _compile(src)
    if any(d.code == "E0408" for d in said):
        _check_said(case, said, names, line)
        return None
    assert case in MEETS, (case, src)
    got = _size_said(said, size)
    if said:
        assert got < size and said[0].span.line == line
    return case, src, e1, e2, res, said, got


SETTINGS = settings(max_examples=16, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])


@given(pair=pairs(), r=st.sampled_from([0.5, 2.0, 5.0, 60.0]))
@SETTINGS
def test_a_fillet_of_two_edges_is_an_arc_tangent_to_both_or_a_message(pair, r):
    ran = _run("Fillet", pair, r)
    if ran is None:
        return
    case, src, e1, e2, res, said, rho = ran
    o = res.output
    # the SVG, by svgelements: one arc of radius rho tangent to both lines (its centre rho
    # from each, its ends on them)
    import svgelements as se
    segs, back = svg_segments(res.to_svg())
    arcs = [(back(s.center), s.rx, back(s.start), back(s.end)) for s in segs
            if isinstance(s, se.Arc)]
    # (the writer gives an arc in pieces of at most a quarter turn: one centre, one radius)
    tangent = {(round(a[0][0], 5), round(a[0][1], 5), round(a[1], 5)): a for a in arcs
               if abs(_line_gap(a[0], e1) - a[1]) <= TOL and abs(_line_gap(a[0], e2) - a[1]) <= TOL}
    if rho == 0:
        assert not tangent
        return
    assert len(tangent) == 1, (case, src, arcs)
    (c, got, _, _), = tangent.values()
    ends = [q for a in arcs if math.dist(a[0], c) <= TOL for q in a[2:]]
    assert any(_line_gap(q, e1) <= TOL for q in ends) and any(_line_gap(q, e2) <= TOL
                                                               for q in ends)
    # the asked radius to 1e-6 mm, or the one the W0406 names (printed to 6 digits)
    assert abs(got - rho) <= (TOL if not said else 1e-5 * rho), (got, rho)
    # ... and the DXF, by ezdxf: one bulge of that radius, its centre that far from both lines
    bulges = [a for e in dxf_doc(o).modelspace().query("LWPOLYLINE") for a in _bulge_arcs(e)]
    assert sum(1 for c, rr, _ in bulges if abs(rr - got) <= TOL
               and abs(_line_gap(c, e1) - got) <= TOL
               and abs(_line_gap(c, e2) - got) <= TOL) == 1, (src, bulges)


@given(pair=pairs(), dist=st.sampled_from([0.5, 2.0, 5.0, 60.0]))
@SETTINGS
def test_a_chamfer_of_two_edges_is_a_line_across_the_corner_or_a_message(pair, dist):
    ran = _run("Chamfer", pair, dist)
    if ran is None:
        return
    case, src, e1, e2, res, said, leg = ran
    tol = TOL if not said else 1e-5 * leg          # a W0406's size: printed to 6 digits
    M = _meet(e1, e2)
    import svgelements as se
    segs, back = svg_segments(res.to_svg())
    cuts = []
    for s in segs:
        if isinstance(s, (se.Line, se.Close)):
            p, q = back(s.start), back(s.end)
            for u, v in ((p, q), (q, p)):
                if (_line_gap(u, e1) <= TOL and _line_gap(v, e2) <= TOL
                        and abs(math.dist(u, M) - leg) <= tol
                        and abs(math.dist(u, M) - math.dist(v, M)) <= TOL):
                    cuts.append((u, v))
    assert len(cuts) == 1, (case, src, leg)


def test_the_crossing_fillet_of_the_l_hook_is_made():
    """The defect as filed: two rectangles' edges crossing mid-span (the inside corner of an
    L) were rounded by nothing and nothing was said; now the 6 mm arc is there, centred 6 mm
    from both edges, and the output has the L's area plus the fillet's (36 - 9 pi mm^2)."""
    src = ("solid hook {\n    solid stem {\n        body = Rectangle(center=(0, 0), width=10, "
           "height=60)\n    }\n    solid arm {\n        body = Rectangle(center=(20, -25), "
           "width=50, height=10)\n    }\n    Fillet([stem.body.right, arm.body.top], 6)\n}\n")
    res, said = _compile(src)
    assert res.ok and said == []
    import svgelements as se
    segs, back = svg_segments(res.to_svg())
    (arc,) = [s for s in segs if isinstance(s, se.Arc)]
    assert math.dist(back(arc.center), (11, -14)) <= TOL and abs(arc.rx - 6) <= TOL
    (part,) = res.parts
    assert part.area == pytest.approx(600 + 400 + 36 - 9 * math.pi, abs=1e-6)
