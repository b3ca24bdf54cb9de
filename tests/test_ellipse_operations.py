"""Hull, Fillet, Chamfer, Offset and Shell take ellipses (issue 73): the hull and the
fillet exact (elliptic arcs, tangent lines and arcs, to 1e-9 mm), an offset or shell of an
ellipse within geometry.biarc.BIARC_TOL (1e-4 mm) of the true offset curve.  One compile and
one DXF, re-read with ezdxf; each number would fail on a wrong outline."""
from __future__ import annotations

import io
import math

import pytest

PROGRAM = """units mm
solid sole {
    e = Ellipse(center=(0, 0), rx=40, ry=20)
    o = Offset(e, 3)
}
solid ring {
    e = Ellipse(center=(0, 100), rx=40, ry=20, rotation=30 deg)
    w = Shell(e, 2)
}
solid pit {
    e = Ellipse(center=(0, 200), rx=40, ry=20)
    i = Offset(e, -12)
}
solid twin {
    a = Ellipse(center=(100, 0), rx=40, ry=20)
    b = Ellipse(center=(150, 0), rx=40, ry=20)
    h = Hull(a, b)
}
solid cam {
    e = Ellipse(center=(100, 100), rx=40, ry=20)
    c = Circle(center=(160, 110), radius=8)
    h = Hull(e, c)
}
solid kite {
    r = Rectangle(center=(200, 100), width=40, height=40)
    h = Hull(Ellipse(center=(200, 100), rx=30, ry=10, rotation=45 deg), r)
}
solid pair {
    a = Circle(center=(300, 100), radius=20)
    c = Circle(center=(320, 110), radius=10)
    Fillet(2)
}
solid umbrella {
    canopy = Ellipse(center=(100, 200), rx=40, ry=20)
    handle = Rectangle(center=(100, 170), width=6, height=30)
    Fillet(3)
}
solid bevel {
    canopy = Ellipse(center=(250, 0), rx=30, ry=15)
    hole cut { r = Rectangle(center=(250, -15), width=80, height=20) }
    Chamfer(2)
}
"""

BOUND = 1e-4        # geometry.biarc.BIARC_TOL, as docs/language.md states it


@pytest.fixture(scope="module")
def parts(tmp_path_factory):
    """{part name: [ezdxf LINE/ARC/ELLIPSE/CIRCLE entities]} of the program's DXF, and the
    parts' areas from the compile."""
    import ezdxf
    from aidl_lang.output import build, encode
    from aidl_lang.pipeline import compile_source
    p = tmp_path_factory.mktemp("ell") / "e.aidl"
    p.write_text(PROGRAM)
    c = compile_source(PROGRAM, str(p))
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    assert [d.code for d in c.sink.items if d.code.startswith(("E", "W"))] == []
    doc = ezdxf.read(io.StringIO(encode(build(c.drawing, c.model.root.name), ".dxf").decode()))
    out: dict = {}
    for en in doc.modelspace():
        name = en.dxf.layer.rsplit(".", 1)[-1]
        ents = list(en.virtual_entities()) if en.dxftype() == "LWPOLYLINE" else [en]
        out.setdefault(name, []).extend(ents)
    return out


def _points(ents, step=0.01):
    """Points along the entities (ezdxf's own flattening, 0.01 mm sagitta or finer)."""
    pts = []
    for v in ents:
        if v.dxftype() == "LINE":
            a, b = v.dxf.start, v.dxf.end
            pts += [(a.x + (b.x - a.x) * i / 20, a.y + (b.y - a.y) * i / 20) for i in range(21)]
        else:
            pts += [(q.x, q.y) for q in v.construction_tool().flattening(step)]
    return pts


def _xy(v):
    return (v.x, v.y)


def _ellipse(cx, cy, rx, ry, rot_deg=0.0):
    from aidl_lang.geometry.shapes.ellipse import ellipse
    return ellipse((cx, cy), rx, ry, math.radians(rot_deg))[0]


def _signed(e, p):
    d = e.distance(p)
    return d if e.implicit(p) > 0 else -d


def _to_arcs(ents, p):
    """Distance from ``p`` to the nearest ARC or LINE of ``ents`` (exact, not sampled)."""
    best = math.inf
    for v in ents:
        if v.dxftype() == "ARC":
            c, r = v.dxf.center, v.dxf.radius
            a = math.degrees(math.atan2(p[1] - c.y, p[0] - c.x)) % 360
            s, e = v.dxf.start_angle % 360, v.dxf.end_angle % 360
            inside = (a - s) % 360 <= (e - s) % 360
            d = abs(math.hypot(p[0] - c.x, p[1] - c.y) - r) if inside else min(
                math.dist(p, _xy(v.start_point)), math.dist(p, _xy(v.end_point)))
        else:
            a, b = v.dxf.start, v.dxf.end
            L2 = (b.x - a.x) ** 2 + (b.y - a.y) ** 2
            u = max(0.0, min(1.0, ((p[0] - a.x) * (b.x - a.x) + (p[1] - a.y) * (b.y - a.y)) / L2))
            d = math.hypot(p[0] - a.x - u * (b.x - a.x), p[1] - a.y - u * (b.y - a.y))
        best = min(best, d)
    return best


def test_offset_of_an_ellipse_is_within_its_stated_bound_both_ways(parts):
    ents = parts["sole"]
    assert {v.dxftype() for v in ents} == {"ARC"}          # biarcs, tangent-continuous
    e = _ellipse(0, 0, 40, 20)
    worst = max(abs(_signed(e, p) - 3) for p in _points(ents))
    assert 1e-7 < worst <= BOUND, worst                    # an approximation, within bound
    # the true offset curve P(t) + 3 n(t), sampled, lies within the bound of the arcs
    far = 0.0
    for k in range(120):
        t = 2 * math.pi * k / 120
        (x, y), (tx, ty) = e.at(t), e.tangent(t)
        far = max(far, _to_arcs(ents, (x + 3 * ty, y - 3 * tx)))
    assert far <= BOUND, far
    # its area is Steiner's: the ellipse's + d x perimeter + pi d^2 (to the flattening's
    # 1e-5 mm sagitta over a 210 mm outline)
    from aidl_lang.geometry.shapes.curves import EllipticArc
    pts = []
    for v in ents:
        q = [(p.x, p.y) for p in v.construction_tool().flattening(1e-5)]
        pts += q if not pts or math.dist(q[0], pts[-1]) < math.dist(q[-1], pts[-1]) else q[::-1]
    area = abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]))) / 2
    steiner = math.pi * 800 + 3 * EllipticArc(e, 0.0, 2 * math.pi).length + 9 * math.pi
    assert abs(area - steiner) <= 0.01, area - steiner
    # and the arcs join tangent: each arc's end direction is the next one's start direction
    for a, b in zip(ents, ents[1:] + ents[:1]):
        assert math.dist(_xy(a.end_point), _xy(b.start_point)) <= 1e-9
        ta = math.radians(a.dxf.end_angle) + math.pi / 2
        tb = math.radians(b.dxf.start_angle) + math.pi / 2
        assert abs((ta - tb + math.pi) % (2 * math.pi) - math.pi) <= 1e-6


def test_shell_keeps_the_ellipse_exact_and_grows_it_within_the_bound(parts):
    ents = parts["ring"]
    (inner,) = [v for v in ents if v.dxftype() == "ELLIPSE"]
    assert (inner.dxf.center.x, inner.dxf.center.y) == pytest.approx((0, 100), abs=1e-9)
    assert inner.dxf.major_axis.magnitude == pytest.approx(40, abs=1e-9)
    assert inner.dxf.ratio == pytest.approx(0.5, abs=1e-12)
    e = _ellipse(0, 100, 40, 20, 30)
    outer = [v for v in ents if v.dxftype() == "ARC"]
    worst = max(abs(_signed(e, p) - 2) for p in _points(outer))
    assert worst <= BOUND, worst


def test_an_inset_past_the_ellipse_curvature_is_within_the_bound(parts):
    # 12 mm > the ellipse's smallest radius of curvature (20^2/40 = 10 mm): the inset has
    # corners where its two sides meet; every point of it is 12 mm from the ellipse
    e = _ellipse(0, 200, 40, 20)
    pts = _points(parts["pit"])
    worst = max(abs(_signed(e, p) + 12) for p in pts)
    assert worst <= BOUND, worst
    assert max(p[0] for p in pts) == pytest.approx(40 - 12 - 0.0, abs=2.0)


def test_hull_of_two_ellipses_is_exact(parts):
    ents = parts["twin"]
    assert sorted(v.dxftype() for v in ents) == ["ELLIPSE", "ELLIPSE", "LINE", "LINE"]
    lines = sorted((v for v in ents if v.dxftype() == "LINE"), key=lambda v: v.dxf.start.y)
    for v, y in zip(lines, (-20, 20)):
        assert v.dxf.start.y == pytest.approx(y, abs=1e-9)
        assert v.dxf.end.y == pytest.approx(y, abs=1e-9)
        assert sorted((v.dxf.start.x, v.dxf.end.x)) == pytest.approx([100, 150], abs=1e-9)


def test_hull_of_an_ellipse_and_a_circle_touches_both(parts):
    ents = parts["cam"]
    e = _ellipse(100, 100, 40, 20)
    lines = [v for v in ents if v.dxftype() == "LINE"]
    assert len(lines) == 2
    for v in lines:
        p, q = (v.dxf.start.x, v.dxf.start.y), (v.dxf.end.x, v.dxf.end.y)
        ux, uy = (q[0] - p[0]) / math.dist(p, q), (q[1] - p[1]) / math.dist(p, q)
        # the circle's centre is 8 mm from the line; the ellipse touches it from one side
        assert abs(ux * (110 - p[1]) - uy * (160 - p[0])) == pytest.approx(8, abs=1e-9)
        end_on_ellipse = min(abs(e.implicit(p)), abs(e.implicit(q)))
        assert end_on_ellipse <= 1e-12
        n = (-uy, ux)
        side = [n[0] * (x - p[0]) + n[1] * (y - p[1]) for x, y in (e.at(2 * math.pi * k / 720)
                                                                   for k in range(720))]
        assert max(side) <= 1e-9 or min(side) >= -1e-9       # a tangent, not a secant
    (arc,) = [v for v in ents if v.dxftype() == "ARC"]
    assert arc.dxf.radius == pytest.approx(8, abs=1e-9)


def test_hull_of_an_ellipse_and_a_polygon_is_supported_by_both(parts):
    from shapely.geometry import MultiPoint
    ents = parts["kite"]
    e = _ellipse(200, 100, 30, 10, 45)
    corners = [(200 + sx * 20, 100 + sy * 20) for sx in (-1, 1) for sy in (-1, 1)]
    src = [e.at(2 * math.pi * k / 4000) for k in range(4000)] + corners
    lines = [v for v in ents if v.dxftype() == "LINE"]
    # the ellipse pokes past two corners (30 > 20 sqrt 2): two elliptic arcs, four lines
    assert sorted(v.dxftype() for v in ents) == ["ELLIPSE", "ELLIPSE"] + ["LINE"] * 4
    for v in lines:
        p, q = _xy(v.dxf.start), _xy(v.dxf.end)
        for end in (p, q):
            assert abs(e.implicit(end)) <= 1e-12 or min(math.dist(end, c) for c in corners) \
                <= 1e-9
        n = (p[1] - q[1], q[0] - p[0])
        side = [n[0] * (x - p[0]) + n[1] * (y - p[1]) for x, y in src]
        tol = 1e-9 * math.hypot(*n)
        assert max(side) <= tol or min(side) >= -tol          # every source on one side
    pts = _points(ents, 1e-4)                    # the DXF outline, finely flattened
    ring = MultiPoint(src).convex_hull
    assert abs(ring.area - MultiPoint(pts).convex_hull.area) <= 1e-3


def test_fillet_between_an_ellipse_and_a_line_is_a_tangent_arc(parts):
    ents = parts["umbrella"]
    e = _ellipse(100, 200, 40, 20)
    fillets = [v for v in ents if v.dxftype() == "ARC" and v.dxf.center.y > 175]
    assert len(fillets) == 2
    for v in fillets:
        c = (v.dxf.center.x, v.dxf.center.y)
        assert v.dxf.radius == pytest.approx(3, abs=1e-12)
        assert e.distance(c) == pytest.approx(3, abs=1e-9)            # tangent to the ellipse
        assert abs(abs(c[0] - 100) - 6) <= 1e-9                       # and to the handle's side
        on = [p for p in (_xy(v.start_point), _xy(v.end_point)) if abs(e.implicit(p)) <= 1e-12]
        assert len(on) == 1
    (el,) = [v for v in ents if v.dxftype() == "ELLIPSE"]
    assert el.start_point.x == pytest.approx(105.781475955, abs=1e-8)   # trimmed to the fillet
    assert el.end_point.x == pytest.approx(94.218524045, abs=1e-8)


def test_chamfer_at_an_ellipse_corner_takes_its_length_along_the_ellipse(parts):
    from aidl_lang.geometry.shapes.curves import EllipticArc
    ents = parts["bevel"]
    e = _ellipse(250, 0, 30, 15)
    (el,) = [v for v in ents if v.dxftype() == "ELLIPSE"]
    # the D's corners, where y = -5 cuts the ellipse: t = -asin(1/3) and pi + asin(1/3)
    for p in (_xy(el.start_point), _xy(el.end_point)):
        t = e.foot(p)
        t0 = -math.asin(1 / 3) if p[0] > 250 else math.pi + math.asin(1 / 3)
        d = (t - t0 + math.pi) % (2 * math.pi) - math.pi
        assert abs(EllipticArc(e, t0, d).length) == pytest.approx(2, abs=1e-9)
    lines = [v for v in ents if v.dxftype() == "LINE"]
    assert len(lines) == 3                       # the flat, two chamfers
    (flat,) = [v for v in lines if abs(v.dxf.start.y + 5) < 1e-9 and abs(v.dxf.end.y + 5) < 1e-9]
    half = 30 * math.sqrt(1 - 1 / 9) - 2
    assert sorted((flat.dxf.start.x, flat.dxf.end.x)) == pytest.approx([250 - half, 250 + half],
                                                                        abs=1e-9)


def test_fillet_beside_an_arc_over_half_a_turn_is_made(parts):
    # the small circle's arc outside the big one turns 220 deg: its corners were left sharp
    # (the tangent point's place along it was taken the short way round, past its end)
    fillets = [v for v in parts["pair"] if v.dxftype() == "ARC"
               and abs(v.dxf.radius - 2) <= 1e-9]
    assert len(fillets) == 2
    for v in fillets:
        c = (v.dxf.center.x, v.dxf.center.y)
        assert math.dist(c, (300, 100)) == pytest.approx(22, abs=1e-9)
        assert math.dist(c, (320, 110)) == pytest.approx(12, abs=1e-9)
