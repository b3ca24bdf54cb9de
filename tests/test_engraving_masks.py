"""Engraving minus engraving (issue 95): a `hole` in a `drawing` hides that drawing's lines
where it covers them (a compass rose's points behind each other).  Through the real pipeline
(the hole's shapes united by Manifold), the SVG read back with svgelements and measured against
shapely's own difference of the same shapes.  The law, over generated rectangles: the visible
length of the back outline is exactly what shapely leaves of it.  (~3 s CPU.)"""
import math
import xml.etree.ElementTree as ET

import pytest
import svgelements
from hypothesis import given, settings, strategies as st
from shapely.geometry import LineString, Point, Polygon
from shapely.ops import polygonize, unary_union

import aidl_lang
from aidl_lang.cli.main import main

SVG_NS = "{http://www.w3.org/2000/svg}"

ROSE = """def point(a, tip, side, spread) -> drawing {
    p = Polygon(points=[(0, 0), (side * cos(a - spread), side * sin(a - spread)),
                        (tip * cos(a), tip * sin(a)), (side * cos(a + spread), side * sin(a + spread))])
}
solid plate {
    disc = Circle(center=(0, 0), radius=50)
    drawing rose {
        drawing back {
            for i in range(4) { p = point(45 deg + i * 90 deg, 30, 7, 25 deg) }
            hole covered {
                for i in range(4) { hole q = point(i * 90 deg, 42, 8, 30 deg) }
            }
        }
        drawing front {
            for i in range(4) { q = point(i * 90 deg, 42, 8, 30 deg) }
        }
    }
}
"""


def _kite(a, tip, side, spread):
    return Polygon([(0, 0), (side * math.cos(a - spread), side * math.sin(a - spread)),
                    (tip * math.cos(a), tip * math.sin(a)),
                    (side * math.cos(a + spread), side * math.sin(a + spread))])


def _engraved(path):
    """The segments of the SVG's engraved paths (the `engrave` group), as the page has them
    (y down)."""
    root = ET.parse(str(path)).getroot()
    [grp] = [g for g in root.iter(SVG_NS + "g") if g.get("id") == "engrave"]
    return [seg for p in grp.iter(SVG_NS + "path") for seg in svgelements.Path(p.get("d"))
            if not isinstance(seg, (svgelements.Move, svgelements.Close))]


def _render(tmp_path, src, name="x"):
    p = tmp_path / f"{name}.aidl"
    p.write_text(src)
    assert main(["render", str(p), "-o", str(tmp_path / f"{name}.svg")]) == 0
    return _engraved(tmp_path / f"{name}.svg")


def test_compass_rose_back_points_hidden_behind_the_front(tmp_path):
    """The faces the engraved lines bound (shapely's polygonize of the SVG's segments) are
    exactly the four front points and what shapely leaves of the back points outside them:
    no back line inside a front point, every area to 1e-9 mm^2."""
    r = aidl_lang.compile(source=ROSE)
    assert r.ok and not [d for d in r.diagnostics if d.severity != "note"], \
        [(d.code, d.message) for d in r.diagnostics]
    segs = _engraved_lines(_render(tmp_path, ROSE))
    faces = sorted(f.area for f in polygonize(_noded(segs)))
    fronts = [_kite(i * math.pi / 2, 42, 8, math.radians(30)) for i in range(4)]
    backs = [_kite(math.pi / 4 + i * math.pi / 2, 30, 7, math.radians(25)) for i in range(4)]
    front = unary_union(fronts)
    seen = unary_union(backs).difference(front)
    want = sorted([f.area for f in fronts] + [g.area for g in getattr(seen, "geoms", [seen])])
    assert len(faces) == len(want) == 8
    assert faces == pytest.approx(want, abs=5e-8)     # (the SVG's numbers: 1e-9 mm)
    exact = [LineString([sg.start, sg.end])
             for st in r.output.engrave for sg in st.segments]
    assert sorted(f.area for f in polygonize(_noded(exact))) == pytest.approx(want, abs=1e-9)
    visible = sum(b.boundary.difference(front).length for b in backs)
    drawn = sum(sg.length for st in r.output.engrave if ".back." in st.source
                for sg in st.segments)
    assert drawn == pytest.approx(visible, abs=1e-9)
    assert sum(s.length for s in segs) == pytest.approx(visible + sum(f.length for f in fronts),
                                                        abs=1e-7)
    assert visible < 0.75 * sum(b.length for b in backs)         # (a quarter and more hidden)


def _noded(lines):
    """The lines split at every end of another that lies on them (within 1e-9 mm), that end
    taken exactly, so that polygonize sees the T-joints the masking made."""
    ends = {c for ln in lines for c in ln.coords}
    out = []
    for ln in lines:
        a = ln.coords[0]
        cut = sorted((ln.project(Point(e)), e) for e in ends
                     if e not in ln.coords and ln.distance(Point(e)) < 1e-9)
        pts = [a] + [e for _, e in cut] + [ln.coords[1]]
        out += [LineString([p, q]) for p, q in zip(pts, pts[1:])]
    return out


def _engraved_lines(segs):
    out = []
    for s in segs:
        assert isinstance(s, svgelements.Line), s
        out.append(LineString([(s.start.x, -s.start.y), (s.end.x, -s.end.y)]))
    return out


def test_circle_and_text_cut_by_a_hole_and_a_sibling_left_whole(tmp_path):
    """A circle half under the hole keeps exactly its other half (an arc of 10 pi mm, its ends
    on the hole's edge); the sibling drawing beside it is not the hole's to hide."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=60, height=60)
    drawing back {
        c = Circle(center=(0, 0), radius=10)
        hole front { r = Rectangle(center=(10, 0), width=20, height=40) }
    }
    drawing other { c = Circle(center=(0, 0), radius=12) }
}
"""
    segs = _render(tmp_path, src)
    arcs = [s for s in segs if isinstance(s, svgelements.Arc)]
    assert sum(s.length(error=1e-12) for s in arcs) == pytest.approx(10 * math.pi, abs=1e-7)
    r = aidl_lang.compile(source=src)
    [other] = [s for s in r.output.engrave if s.source == "plate.other.c"]
    assert [type(g).__name__ for g in other.segments] == ["Circle"]
    ends = {(round(a.start.x, 9), round(a.start.y, 9)) for a in arcs} | \
        {(round(a.end.x, 9), round(a.end.y, 9)) for a in arcs}
    assert {(0.0, -10.0), (0.0, 10.0)} <= ends


@settings(max_examples=8, deadline=None)
@given(x=st.integers(-25, 25), y=st.integers(-25, 25), w=st.integers(4, 40),
       h=st.integers(4, 40), turn=st.integers(0, 80))
def test_law_the_visible_back_is_shapelys_difference(x, y, w, h, turn):
    """A 30 x 20 outline behind a turned rectangle: the back's drawn length is exactly the
    length shapely leaves of its outline outside the front (1e-9 mm), the front drawn whole."""
    src = f"""drawing rose {{
    drawing back {{
        b = Rectangle(center=(0, 0), width=30, height=20)
        hole front {{ f = Rectangle(center=({x}, {y}), width={w}, height={h}, rotation={turn} deg) }}
    }}
    drawing top {{ f = Rectangle(center=({x}, {y}), width={w}, height={h}, rotation={turn} deg) }}
}}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok
    drawn = sum(sg.length for s in r.output.engrave if s.source.startswith("rose.back.")
                for sg in s.segments)
    back = Polygon([(-15, -10), (15, -10), (15, 10), (-15, 10)])
    t = math.radians(turn)
    c, s_ = math.cos(t), math.sin(t)
    front = Polygon([(x + c * u - s_ * v, y + s_ * u + c * v)
                     for u, v in ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2),
                                  (-w / 2, h / 2))])
    assert drawn == pytest.approx(back.boundary.difference(front).length, abs=1e-9)


def test_a_hole_that_hides_nothing_is_said_at_its_shape():
    src = """drawing back {
    p = Polygon(points=[(0, 0), (20, 5), (30, 30), (5, 20)])
    hole front { q = Circle(center=(60, 0), radius=5) }
}
"""
    r = aidl_lang.compile(source=src)
    [d] = [d for d in r.diagnostics if d.code == "W0526"]
    assert d.span.line == 3 and "covers none of drawing `back`'s lines" in d.message
    assert "delete it" in d.hint
