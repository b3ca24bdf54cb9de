"""`Result.measure` (issue 86): distances, centre distances, angles and clearances between
named entities of a compiled program, exact (1e-9 mm), against known truth: circles of a
known gap, a gear pair meshing at module x (z1 + z2) / 2, and a hypothesis law over random
circle/rectangle pairs against shapely's distance."""
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import aidl_lang

shapely = pytest.importorskip("shapely")
from shapely.geometry import Point, box  # noqa: E402


def _two(a: str, b: str):
    r = aidl_lang.compile(source=f"units mm\nsolid s {{\n    a = {a}\n    b = {b}\n}}\n")
    assert r.ok, [d.message for d in r.diagnostics]
    return r.measure("s.a", "s.b")


def test_two_circles_of_known_gap():
    got = _two("Circle(center=(0, 0), radius=3)", "Circle(center=(3, 4), radius=1.5)")
    assert got["center_distance"] == pytest.approx(5, abs=1e-12)
    assert got["clearance"] == pytest.approx(0.5, abs=1e-12) and got["contact"] == "apart"
    assert got["points"][0] == pytest.approx([1.8, 2.4], abs=1e-12)
    got = _two("Circle(center=(0, 0), radius=3)", "Circle(center=(4, 0), radius=1)")
    assert got["contact"] == "touching" and got["clearance"] == 0
    got = _two("Circle(center=(0, 0), radius=3)", "Circle(center=(3, 0), radius=1)")
    assert got["contact"] == "overlapping"
    assert got["clearance"] == pytest.approx(-1, abs=1e-9)     # 3 + 1 - 3 deep
    # concentric: the outlines 2 apart, the small one 2 deep inside; the same circle twice
    got = _two("Circle(center=(1, 1), radius=3)", "Circle(center=(1, 1), radius=1)")
    assert got["distance"] == pytest.approx(2, abs=1e-12) and got["contact"] == "overlapping"
    assert got["clearance"] == pytest.approx(-2, abs=1e-9) and got["center_distance"] == 0
    got = _two("Circle(center=(1, 1), radius=3)", "Circle(center=(1, 1), radius=3)")
    assert got["distance"] == 0 and got["contact"] == "overlapping"
    # an open arc (a quarter from 0 to 90 degrees) and a point: its nearest end
    got = _two("Arc(center=(0, 0), radius=10, start_angle=0 deg, end_angle=90 deg)",
               "Point(-30, 10)")
    assert got["a"]["kind"] == "arc" and got["distance"] == pytest.approx(30, abs=1e-9)
    assert got["points"][0] == pytest.approx([0, 10], abs=1e-12)


def test_a_gear_pair_at_its_centre_distance_and_lines_at_an_angle():
    r = aidl_lang.compile(source="""units mm
import "std/gears.aidl"
assembly kit {
    pair = gear_pair(teeth1=12, teeth2=36, module=2 mm, backlash=0.1 mm, angle=30 deg)
    solid bar {
        l1 = Line((0, 100), (10, 100))
        l2 = Line((0, 110), (-10, 110 + 10 * sqrt(3)))
    }
}
""")
    assert r.ok
    got = r.measure("pair.gear1", "pair.gear2")
    assert got["center_distance"] == pytest.approx(48, abs=1e-9)       # 2 (12 + 36) / 2
    assert got["contact"] == "apart" and 0 < got["clearance"] < 0.2       # the backlash
    got = r.measure("bar.l1", "bar.l2")
    assert got["angle"] == pytest.approx(120, abs=1e-9)
    assert got["distance"] == pytest.approx(10, abs=1e-9)
    with pytest.raises(KeyError) as e:
        r.measure("pair.gear3", "bar.l1")
    assert e.value.args[1] == "a" and "pair.gear1" in e.value.args[0]


coord = st.integers(-400, 400).map(lambda v: v / 8)
size = st.integers(4, 160).map(lambda v: v / 8)
shape = st.one_of(st.tuples(st.just("circle"), coord, coord, size),
                  st.tuples(st.just("rect"), coord, coord, size, size))


def _aidl(s) -> str:
    if s[0] == "circle":
        return f"Circle(center=({s[1]}, {s[2]}), radius={s[3]})"
    return f"Rectangle(center=({s[1]}, {s[2]}), width={s[3]}, height={s[4]})"


def _truth(a, b) -> float:
    """The signed gap of two shapes from shapely: polygons for rectangles (exact), a
    circle as its centre less its radius (no polygon of the circle)."""
    def geom(s):
        if s[0] == "circle":
            return Point(s[1], s[2]), s[3]
        return box(s[1] - s[3] / 2, s[2] - s[4] / 2, s[1] + s[3] / 2, s[2] + s[4] / 2), 0.0
    (ga, ra), (gb, rb) = geom(a), geom(b)
    return ga.distance(gb) - ra - rb


@settings(max_examples=40, deadline=None)
@given(a=shape, b=shape)
def test_clearance_of_circles_and_rectangles_is_shapely_distance(a, b):
    """Apart: the clearance and the distance are shapely's distance, exact (1e-9 mm);
    meeting: touching (0) or overlapping (0 or less), never a positive clearance; the centre
    distance is the centres'."""
    got = _two(_aidl(a), _aidl(b))
    truth = _truth(a, b)
    if truth > 1e-9:
        assert got["contact"] == "apart"
        assert got["clearance"] == pytest.approx(truth, abs=1e-9)
        assert got["distance"] == pytest.approx(truth, abs=1e-9)
    elif truth >= -1e-9 and not (a[0] == b[0] == "circle" and truth < 0):
        assert got["contact"] in ("touching", "overlapping") and got["clearance"] <= 0
    else:
        assert got["contact"] == "overlapping" and got["clearance"] <= 0
    assert got["center_distance"] == pytest.approx(math.dist(a[1:3], b[1:3]), abs=1e-9)
    if a[0] == b[0] == "circle" and truth < -1e-9 and math.dist(a[1:3], b[1:3]) >= max(
            a[3], b[3]):                   # crossing circles, neither centre inside the
        # other: the nearest point of each to the other's centre is r1 + r2 - d deep
        assert got["clearance"] == pytest.approx(truth, abs=1e-9)


def _lens(r1: float, r2: float, d: float) -> float:
    """The area two circles share, in closed form."""
    if d >= r1 + r2:
        return 0.0
    if d <= abs(r1 - r2):
        return math.pi * min(r1, r2) ** 2
    a1 = r1 * r1 * math.acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1))
    a2 = r2 * r2 * math.acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2))
    return a1 + a2 - 0.5 * math.sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2)
                                     * (d + r1 + r2))


def _fine(s):
    """A shape for shapely: a rectangle exact, a circle of 8,192 chords (area within
    2e-6 mm² per mm of radius)."""
    if s[0] == "circle":
        return Point(s[1], s[2]).buffer(s[3], quad_segs=2048)
    return box(s[1] - s[3] / 2, s[2] - s[4] / 2, s[1] + s[3] / 2, s[2] + s[4] / 2)


@settings(max_examples=30, deadline=None)
@given(a=shape, b=shape)
def test_overlap_area_is_exact_for_circles_and_rectangles(a, b):
    """Issue 91: `overlap_area` of two overlapping shapes of lines and arcs is exact, not a
    polygon estimate (263.7704 for an exact 263.8938): two circles' lens and two rectangles'
    box to 1e-9 relative, a circle and a rectangle to shapely's area over a circle of 8,192
    chords (its own error under 1e-6 relative); no `overlap_area_within` (no estimate)."""
    got = _two(_aidl(a), _aidl(b))
    if got["contact"] != "overlapping":
        return
    area = got["overlap_area"]
    assert "overlap_area_within" not in got
    if a[0] == b[0] == "circle":
        truth = _lens(a[3], b[3], math.dist(a[1:3], b[1:3]))
        assert area == pytest.approx(truth, rel=1e-9, abs=1e-9)
    elif a[0] == b[0] == "rect":
        assert area == pytest.approx(_fine(a).intersection(_fine(b)).area, rel=1e-9, abs=1e-9)
    else:
        assert area == pytest.approx(_fine(a).intersection(_fine(b)).area, rel=1e-6, abs=1e-6)


def test_the_root_assembly_is_measured_as_its_parts_together():
    """Issue 91: `measure` with the root assembly as `a` was `ValueError: an outline with no
    curves`; an assembly is now its parts together (an estimate of the area with its bound),
    and a structure with no outline and no parts is a clear KeyError."""
    r = aidl_lang.compile(source="""units mm
assembly kit {
    solid a { c = Circle(center=(0, 0), radius=10) }
    solid b { c = Circle(center=(30, 0), radius=10) }
}
""")
    assert r.ok
    got = r.measure("kit", "a")
    assert got["a"] == {"name": "kit", "kind": "assembly"} and got["contact"] == "overlapping"
    within = got["overlap_area_within"]
    assert 0 < within <= 1 and abs(got["overlap_area"] - math.pi * 100) <= within
    got = r.measure("b", "kit")             # b is in kit: b's own outline, 0 apart
    assert got["distance"] == 0 and got["contact"] == "overlapping"
    # kit's outline is both circles: b's outline is 10 mm from a's
    assert r.measure("kit", "kit")["distance"] == 0
    empty = aidl_lang.compile(source="units mm\nassembly kit {\n    p = Point(0, 0)\n}\n")
    assert empty.ok
    with pytest.raises(KeyError) as e:
        empty.measure("kit", "p")
    assert e.value.args[1] == "a" and "no outline of its own and no parts" in e.value.args[0]
