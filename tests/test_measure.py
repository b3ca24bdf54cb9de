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


@settings(max_examples=25, deadline=None)
@given(cx=coord, cy=coord, r=size, x=coord, y=coord, w=size, h=size)
def test_circle_and_rectangle_clearance_is_shapely_distance(cx, cy, r, x, y, w, h):
    """Apart: the clearance is the exact distance (shapely: the centre's distance to the
    rectangle less the radius, no polygon of the circle); meeting: touching or
    overlapping, never a positive clearance."""
    got = _two(f"Circle(center=({cx}, {cy}), radius={r})",
               f"Rectangle(center=({x}, {y}), width={w}, height={h})")
    rect = box(x - w / 2, y - h / 2, x + w / 2, y + h / 2)
    truth = Point(cx, cy).distance(rect) - r
    inside = rect.contains(Point(cx, cy)) and Point(cx, cy).distance(rect.exterior) >= r
    if truth > 1e-9:
        assert got["contact"] == "apart"
        assert got["clearance"] == pytest.approx(truth, abs=1e-9)
        assert got["distance"] == pytest.approx(truth, abs=1e-9)
    elif abs(truth) <= 1e-9:
        assert got["contact"] == "touching" and got["clearance"] == 0
    else:
        assert got["contact"] == "overlapping" and got["clearance"] < 0
    assert got["center_distance"] == pytest.approx(math.dist((cx, cy), (x, y)), abs=1e-9)
    if inside:                        # the circle within: its outline's gap to the sides
        assert got["distance"] == pytest.approx(Point(cx, cy).distance(rect.exterior) - r,
                                                abs=1e-9)
