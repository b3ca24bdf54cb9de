"""A Polygon that encloses no area says why (issue 70): a self-crossing "bowtie" whose two
halves cancel was reported as "points all on one line", which they are not.  Now E0108 names
the two edges that cross and where, and gives the points' order around their centre as the
fix, which compiles to the square meant (docs/language.md, Polygon)."""
import pytest

from aidl_lang.api import compile as aidl_compile


def _error(src):
    c = aidl_compile(src, path="p.aidl")
    assert not c.ok
    (d,) = [d for d in c.sink.items if d.severity == "error"]
    return d


def test_a_bowtie_polygon_names_the_crossing_edges_and_the_order_that_fixes_it():
    d = _error("solid plate {\n    p = Polygon([(0,0),(10,10),(10,0),(0,10)])\n}\n")
    assert d.code == "E0108"
    assert "one line" not in d.message
    assert "edge 0 (points[0] to points[1]) crosses edge 2 (points[2] to points[3]) at (5, 5)" \
        in d.message, d.message
    assert "self-intersecting" in d.message
    assert (d.span.line, d.span.col) == (2, 9)
    assert "points[0], points[2], points[1], points[3]" in d.hint, d.hint
    assert "(0, 0), (10, 0), (10, 10), (0, 10)" in d.hint, d.hint
    # the order the hint gives is the 10 x 10 square
    fixed = aidl_compile("solid plate {\n    p = Polygon([(0,0),(10,0),(10,10),(0,10)])\n}\n")
    assert fixed.ok and not [x for x in fixed.sink.items if x.severity == "error"]
    assert abs(fixed.output.parts[0].area - 100.0) < 1e-9


def test_a_double_bowtie_names_its_first_crossing():
    d = _error("solid plate {\n    p = Polygon([(0,0),(10,10),(20,0),(20,10),(10,0),(0,10)])\n}\n")
    assert "edge 0 (points[0] to points[1]) crosses edge 4 (points[4] to points[5]) at (5, 5)" \
        in d.message, d.message


@pytest.mark.parametrize("points, words", [
    ("[(0,0),(10,0),(20,0)]", "all on one line"),
    ("[(0,0),(10,0),(10,10),(10,0)]", "goes out and comes back along itself")])
def test_other_polygons_without_area_keep_their_own_words(points, words):
    d = _error(f"solid plate {{\n    p = Polygon({points})\n}}\n")
    assert d.code == "E0108" and words in d.message and "cross" not in d.message, d.message
