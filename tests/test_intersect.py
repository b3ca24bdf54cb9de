"""``Intersect``: the area closed shapes have in common, and open lines clipped to it (issue 73:
a racket's strings trimmed to its head).  Exact: the DXF re-read with ezdxf, ends on the
curves to 1e-9 mm, areas by closed forms."""
from __future__ import annotations

import io
import math

import pytest

PROGRAM = """units mm
solid lens {
    a = Circle(center=(200, 0), radius=30)
    b = Circle(center=(230, 0), radius=30)
    k = Intersect(a, b)
}
solid band {
    e = Ellipse(center=(0, 200), rx=40, ry=20)
    r = Rectangle(center=(0, 200), width=100, height=20)
    k = Intersect([e, r])
}
solid racket {
    head = Ellipse(center=(0, 0), rx=60, ry=45)
    hole face { inner = Ellipse(center=(0, 0), rx=55, ry=40) }
}
drawing strings {
    frame = Ellipse(center=(0, 0), rx=55, ry=40, construction=true)
    mains = [Line((x, -50), (x, 50)) for x in range(-50, 51, 10)]
    s = Intersect(mains, frame)
}
solid badge {
    disc = Circle(center=(0, -200), radius=40)
    rim = Ellipse(center=(0, -200), rx=30, ry=20, construction=true)
    bow = Arc(center=(0, -290), radius=100, start_angle=45 deg, end_angle=135 deg)
    s = Intersect(bow, rim)
}
drawing ticks {
    c = Circle(center=(400, 0), radius=20, construction=true)
    q = Rectangle(center=(410, 0), width=20, height=60, construction=true)
    zig = Polyline([(380, -30), (430, 10), (380, 10)])
    t = Intersect(zig, c, q)
}
"""


@pytest.fixture(scope="module")
def done(tmp_path_factory):
    import ezdxf
    from aidl_lang.output import build, encode
    from aidl_lang.pipeline import compile_source
    p = tmp_path_factory.mktemp("int") / "i.aidl"
    p.write_text(PROGRAM)
    c = compile_source(PROGRAM, str(p))
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    assert [d.code for d in c.sink.items if d.code.startswith(("E", "W"))] == []
    o = build(c.drawing, c.model.root.name)
    doc = ezdxf.read(io.StringIO(encode(o, ".dxf").decode()))
    ents: dict = {}
    for en in doc.modelspace():
        for v in (en.virtual_entities() if en.dxftype() == "LWPOLYLINE" else [en]):
            ents.setdefault(en.dxf.layer, []).append(v)
    return o, ents


def _xy(v):
    return (v.x, v.y)


def _layer(ents, word):
    return [v for k, vs in ents.items() if word in k for v in vs]


def test_two_circles_give_their_lens(done):
    o, ents = done
    arcs = _layer(ents, "lens")
    assert sorted(v.dxftype() for v in arcs) == ["ARC", "ARC"]
    for v in arcs:
        assert v.dxf.radius == pytest.approx(30, abs=1e-12)
        for p in (_xy(v.start_point), _xy(v.end_point)):
            assert p[0] == pytest.approx(215, abs=1e-9)
            assert abs(p[1]) == pytest.approx(15 * math.sqrt(3), abs=1e-9)
    (part,) = [p for p in o.parts if p.name.endswith("lens")]
    r, d = 30, 30
    lens = 2 * r * r * math.acos(d / (2 * r)) - d / 2 * math.sqrt(4 * r * r - d * d)
    assert part.area == pytest.approx(lens, abs=1e-9)


def test_an_ellipse_cut_to_a_band_keeps_its_elliptic_arcs(done):
    o, ents = done
    kinds = sorted(v.dxftype() for v in _layer(ents, "band"))
    assert kinds == ["ELLIPSE", "ELLIPSE", "LINE", "LINE"]
    (part,) = [p for p in o.parts if p.name.endswith("band")]
    u = 0.5                          # the band's half height over ry
    assert part.area == pytest.approx(2 * 40 * 20 * (u * math.sqrt(1 - u * u) + math.asin(u)),
                                      abs=1e-9)


def test_strings_clipped_to_the_head_end_exactly_on_its_ellipse(done):
    from aidl_lang.geometry.shapes.ellipse import ellipse
    _, ents = done
    lines = [v for v in _layer(ents, "ENGRAVE") if v.dxftype() == "LINE"
             and abs(v.dxf.start.x) < 60 and abs(v.dxf.start.y) < 60]
    # x = -50 .. 50 step 10: the frame is 55 wide, so all 11 strings cross it
    assert sorted(round(v.dxf.start.x) for v in lines) == list(range(-50, 51, 10))
    e = ellipse((0, 0), 55, 40, 0.0)[0]
    for v in lines:
        for p in (_xy(v.dxf.start), _xy(v.dxf.end)):
            assert abs(e.implicit(p)) <= 1e-12
        x = v.dxf.start.x
        assert abs(v.dxf.end.y - v.dxf.start.y) == pytest.approx(
            2 * 40 * math.sqrt(1 - (x / 55) ** 2), abs=1e-9)


def test_a_polyline_clipped_to_two_shapes_common_area(done):
    _, ents = done
    pieces = [v for v in _layer(ents, "ENGRAVE") if v.dxftype() == "LINE"
              and v.dxf.start.x > 300]
    # the common area: the circle r 20 about (400, 0) right of x = 400; the zigzag's first
    # leg enters at x = 400 and leaves through the circle, its second runs along y = 10
    assert len(pieces) == 2
    ends = sorted((_xy(v.dxf.start), _xy(v.dxf.end)) for v in pieces)
    for a, b in ends:
        for p in (a, b):
            on_circle = abs(math.dist(p, (400, 0)) - 20) <= 1e-9
            on_side = abs(p[0] - 400) <= 1e-9
            assert on_circle or on_side, p
    flat = [v for v in pieces if abs(v.dxf.start.y - 10) < 1e-9 and abs(v.dxf.end.y - 10) < 1e-9]
    (f,) = flat
    assert sorted((f.dxf.start.x, f.dxf.end.x)) == pytest.approx([400, 400 + math.sqrt(300)],
                                                                  abs=1e-9)


@pytest.mark.parametrize("body, code, words", [
    ("a = Circle(center=(0, 0), radius=5)\n    k = Intersect(a, Circle(center=(50, 0), "
     "radius=5))", "E0406", "no area in common"),
    ("a = Circle(center=(0, 0), radius=5)\n    k = Intersect(a)", "E0108", "two closed shapes"),
    ("l = Line((0, 0), (10, 0))\n    k = Intersect(l, 3)", "E0108", "got number"),
    ("l = Line((0, 0), (10, 0))\n    k = Intersect(l, Line((0, 1), (10, 1)))", "E0108",
     "at least one closed shape"),
])
def test_wrong_use_is_located_at_the_call(tmp_path, body, code, words):
    from aidl_lang.pipeline import compile_source
    src = f"units mm\nsolid p {{\n    {body}\n}}\n"
    p = tmp_path / "w.aidl"
    p.write_text(src)
    c = compile_source(src, str(p))
    errs = [d for d in c.sink.items if d.severity == "error"]
    assert [d.code for d in errs] == [code], [(d.code, d.message) for d in c.sink.items]
    assert words in errs[0].message
    assert (errs[0].span.line, errs[0].span.col) == (4, 9)


def test_an_arc_clipped_in_a_solid_is_engraved_between_its_crossings(done):
    from aidl_lang.geometry.shapes.ellipse import ellipse
    _, ents = done
    (arc,) = [v for v in _layer(ents, "ENGRAVE") if v.dxftype() == "ARC"
              and v.dxf.center.y < -250]
    assert arc.dxf.radius == pytest.approx(100, abs=1e-12)
    e = ellipse((0, -200), 30, 20, 0.0)[0]
    for p in (_xy(arc.start_point), _xy(arc.end_point)):
        assert abs(e.implicit(p)) <= 1e-12              # ends exactly on the ellipse
        assert abs(math.dist(p, (0, -290)) - 100) <= 1e-9
    assert arc.start_point.x == pytest.approx(-arc.end_point.x, abs=1e-9)
