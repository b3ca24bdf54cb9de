"""Issue 74, the render of a perforated sheet: the booleans unite holes whose boxes are apart in
one Manifold union (not levels of groups of 16), and the exact recovery turns every result
polygon that lies on one circle into that circle in array operations, and looks its edges up in
the order of their cells.  Each is checked against the way it was done before on a plate whose
holes are partly apart, partly overlapping each other and the plate's edge (one compile shared
by the tests of this module), and the DXF written holds every whole hole as an exact CIRCLE.
"""
from __future__ import annotations

import io

import ezdxf
import manifold3d as mf
import numpy as np
import pytest

from aidl_lang.output import Options, build, encode
from aidl_lang.output.part.build import booleans
from aidl_lang.pipeline import compile_source

# 12 x 10 holes apart (radii 1.5 and 2.5 mm in turn), a pair that overlaps, one across the
# plate's right edge, and a slot
PLATE = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=130, height=110)
    for i in range(12) {
        for j in range(10) {
            hole h { c = Circle(center=(-55 + i * 10, -45 + j * 10), radius=1.5 + (i + j) % 2) }
        }
    }
    hole pair { a = Circle(center=(-60, 52), radius=1.5)
                b = Circle(center=(-58, 52), radius=1.5) }
    hole edge { c = Circle(center=(65, 0), radius=2) }
    hole slot { s = Slot(start=(0, 52), end=(20, 52), width=2) }
}
"""
APART = 120


def _grouped(faces: list) -> mf.CrossSection:
    """The union as the booleans made it before: groups of 16, then the groups, ..."""
    while len(faces) > 16:
        faces = [mf.CrossSection.batch_boolean(faces[i:i + 16], mf.OpType.Add)
                 for i in range(0, len(faces), 16)]
    return mf.CrossSection.batch_boolean(faces, mf.OpType.Add)


@pytest.fixture(scope="module")
def compiled():
    unions = []
    real = booleans.mf.CrossSection.batch_boolean

    class Counting:                 # manifold3d as the booleans see it: unions recorded
        def __getattr__(self, name):
            return getattr(mf, name)

    counting = Counting()

    class CrossSection:
        def __new__(cls, *args, **kw):
            return mf.CrossSection(*args, **kw)

        @staticmethod
        def batch_boolean(faces, op):
            unions.append(len(faces))
            return real(faces, op)

    counting.CrossSection = CrossSection
    mp = pytest.MonkeyPatch()
    mp.setattr(booleans, "mf", counting)
    try:
        c = compile_source(PLATE, "plate.aidl")
    finally:
        mp.undo()
    assert c.ok, [d.message for d in c.sink.items]
    return c, unions


def test_holes_apart_are_united_in_one_union_with_the_same_result(compiled):
    c, unions = compiled
    d = c.drawing
    holes = [s for s in c.model.root.children.values() if s.kind == "hole"]
    assert len(holes) == APART + 3
    # every hole's own union (one face, or the pair's two), then ONE union of all 123 hole
    # shapes (their boxes meet: the pair's two circles are one hole); before, 123 -> 8 -> 1
    assert unions.count(len(holes)) == 1 and max(unions) == len(holes)
    assert not any(16 < n < len(holes) for n in unions)
    cut = _grouped([d.shapes[s] for s in holes])
    part = [np.asarray(p) for p in d.parts[0].shape.to_polygons()]
    body = booleans.mf.CrossSection.batch_boolean(
        [f for _, f in d.own[c.model.root]], mf.OpType.Add)
    want = [np.asarray(p) for p in (body - cut).to_polygons()]
    assert len(part) == len(want) == 1 + APART + 2     # the outline, 120 holes, pair, slot
    assert all(np.array_equal(a, b) for a, b in zip(part, want))


def test_whole_circles_are_recovered_as_one_polygon_at_a_time_was(compiled):
    c, _ = compiled
    d = c.drawing
    prov = d.exact
    shape = d.parts[0].shape
    loops = prov.loops_of([shape])[0]
    each = [prov.recover(np.asarray(P, dtype=float)) for P in shape.to_polygons()]
    each = [lp for lp in each if lp.segments]
    assert loops == each
    circles = [lp.segments[0] for lp in loops if len(lp.segments) == 1]
    assert sorted({c_.radius for c_ in circles}) == [1.5, 2.5] and len(circles) == APART
    assert all(not c_.ccw for c_ in circles)           # holes: clockwise
    # the edges looked up in any order: the same carriers
    A = np.concatenate([np.asarray(P, dtype=float) for P in shape.to_polygons()])
    B = np.concatenate([np.roll(np.asarray(P, dtype=float), -1, axis=0)
                        for P in shape.to_polygons()])
    grid = prov._chords()
    cid = grid.match(A, B, 1e-6)
    perm = np.random.default_rng(74).permutation(len(A))
    assert np.array_equal(grid.match(A[perm], B[perm], 1e-6), cid[perm])
    assert (cid >= 0).all()


def test_the_dxf_holds_every_hole_apart_as_an_exact_circle(compiled):
    c, _ = compiled
    data = encode(build(c.drawing, "plate"), ".dxf", Options())
    msp = ezdxf.read(io.StringIO(data.decode())).modelspace()
    circles = msp.query("CIRCLE")
    assert len(circles) == APART
    got = sorted((round(e.dxf.center.x, 9), round(e.dxf.center.y, 9), e.dxf.radius)
                 for e in circles)
    want = sorted((-55.0 + i * 10, -45.0 + j * 10, 1.5 + (i + j) % 2)
                  for i in range(12) for j in range(10))
    assert got == want
    # the outline with the edge hole's bite, the pair and the slot: closed polylines
    assert len(msp.query("LWPOLYLINE")) == 3


def test_the_pairs_to_match_are_bounded_per_edge_not_only_in_all(compiled, monkeypatch):
    """The exact recovery's cap on (edge, chord) pairs grows with the edges (16 each): the
    ~2,250,000 edges of 50,000 holes (~4.5 pairs each) passed the fixed 10,000,000 and were
    refused as 'curves drawn on top of each other'.  Here the fixed cap is made smaller than
    this plate's pairs (~4 per edge): the plate is still recovered whole."""
    from aidl_lang.output.part.edges import matching
    c, _ = compiled
    shape = c.drawing.parts[0].shape
    want = c.drawing.exact.loops_of([shape])[0]
    monkeypatch.setattr(matching, "MAX_CANDIDATES", shape.num_vert())
    assert c.drawing.exact.loops_of([shape])[0] == want and len(want) == 1 + APART + 2
