"""The fast kernels of the shape checks and writers (output/checks/, output/part/part.py) against their
reference versions: same booleans, same sample points, bit for bit (hypothesis)."""
import numpy as np
from hypothesis import example, given, settings, strategies as st

from aidl_lang.output.checks import _inside, _inside_loops, _sample, _samples

# small integer grids make points fall on vertices, on edges and on horizontal edges: the ties
# where a different floating-point expression would give a different answer
coord = st.one_of(st.integers(-6, 6).map(float),
                  st.floats(-10, 10, allow_nan=False, allow_infinity=False))
point = st.tuples(coord, coord)
loop = st.lists(point, min_size=1, max_size=12)


@settings(max_examples=300, deadline=None)
@given(st.lists(loop, min_size=0, max_size=4), st.lists(point, min_size=0, max_size=40))
def test_inside_equals_the_per_loop_reference(loops, pts):
    P = np.array(pts, dtype=float).reshape(-1, 2)
    got = _inside(P, loops)
    assert got.dtype == bool and got.shape == (len(P),)
    if loops:
        assert np.array_equal(got, _inside_loops(P, loops))
    else:
        assert not got.any()


def test_inside_square_with_a_hole_and_a_second_island():
    outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
    hole = [(3, 3), (3, 7), (7, 7), (7, 3)]               # clockwise: a hole
    island = [(20, 0), (24, 0), (22, 4)]
    pts = np.array([(1, 1), (5, 5), (9, 5), (11, 5), (22, 1), (22, 5), (-1, 5), (2, 9.99)])
    assert _inside(pts, [outer, hole, island]).tolist() == [
        True, False, True, False, True, False, False, True]


line = st.tuples(st.just("line"), point, point)
circle = st.tuples(st.just("circle"), point, st.floats(0.1, 5))
arc = st.tuples(st.just("arc"), point, st.floats(0.1, 5), st.floats(-7, 7), st.floats(-7, 7))
poly = st.tuples(st.just("poly"), st.lists(point, min_size=2, max_size=6))


@settings(max_examples=100, deadline=None)
@given(st.lists(st.one_of(line, line, circle, arc, poly), min_size=1, max_size=12))
def test_samples_equal_the_per_item_samples(items):
    ref = np.vstack([_sample(it) for it in items])
    got = _samples(items)
    assert got.shape == ref.shape and np.array_equal(got, ref)


# ---------------------------------------------------------------- Output.bounds / Loop.points
def _points_reference(segments):
    """Loop.points as it was written before (one tuple per vertex, through Arc.at)."""
    import math
    from aidl_lang.geometry.shapes.tessellate import segments_for
    from aidl_lang.output.part.part import Arc, Line
    out = []
    for s in segments:
        if isinstance(s, Line):
            out.append(s.start)
        elif isinstance(s, Arc):
            n = max(1, segments_for(s.radius, abs(s.sweep)))
            out += [s.at(s.start_angle + s.sweep * i / n) for i in range(n)]
        else:
            n = segments_for(s.radius)
            sg = 1 if s.ccw else -1
            out += [(s.center[0] + s.radius * math.cos(sg * 2 * math.pi * i / n),
                     s.center[1] + s.radius * math.sin(sg * 2 * math.pi * i / n))
                    for i in range(n)]
    return np.asarray(out, dtype=float)


def _segment():
    from aidl_lang.output.part.part import Arc, Circle, Line
    p = st.tuples(st.floats(-50, 50), st.floats(-50, 50))
    r = st.floats(0.001, 40)
    return st.one_of(st.builds(Line, p, p),
                     st.builds(Arc, p, r, st.floats(-7, 7), st.floats(-6.3, 6.3)),
                     st.builds(Circle, p, r, st.booleans()))


@settings(max_examples=150, deadline=None)
@given(st.lists(st.lists(_segment(), min_size=1, max_size=5), min_size=0, max_size=4),
       st.lists(st.lists(_segment(), min_size=1, max_size=3), min_size=0, max_size=3))
def test_points_and_bounds_equal_the_reference(loops, strokes):
    from aidl_lang.output.part.part import Circle, Loop, Output, PartOutline, Stroke
    for segs in loops:
        got, ref = Loop(segs).points(), _points_reference(segs)
        assert got.shape == ref.shape and np.array_equal(got, ref)
    out = Output(parts=[PartOutline("p", "solid", [Loop(s) for s in loops])],
                 engrave=[Stroke(s) for s in strokes])
    xs, ys = [], []
    for k, segs in enumerate(loops + strokes):
        P = _points_reference(segs)
        E = np.array([s.end for s in segs if not isinstance(s, Circle)]).reshape(-1, 2) \
            if k >= len(loops) else np.zeros((0, 2))
        for q in (P, E):
            if len(q):
                xs += [q[:, 0].min(), q[:, 0].max()]
                ys += [q[:, 1].min(), q[:, 1].max()]
    ref = (min(xs), min(ys), max(xs), max(ys)) if xs else (0.0, 0.0, 1.0, 1.0)
    assert out.bounds() == ref


def test_check_imports_no_lark_scipy_writers_or_masked_arrays(tmp_path):
    """A cold `aidl check` imports neither Lark (the parser runs its cached table), SciPy, the
    writers (svgwrite and its network stack), the Hershey package nor numpy.ma; a cold
    `aidl render` to SVG imports svgwrite but not numpy.ma (np.median, np.unique)."""
    import subprocess
    import sys
    from conftest import ROOT
    src = ROOT / "examples" / "telephone.aidl"
    heavy = ("lark", "scipy", "svgwrite", "urllib.request", "HersheyFonts", "numpy.ma")

    def loaded(argv):
        probe = ("import sys\nfrom aidl_lang.cli.main import main\n"
                 f"main({argv!r})\n"
                 f"print('LOADED:' + ' '.join(m for m in {heavy!r} if m in sys.modules))")
        r = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        return r.stdout.strip().splitlines()[-1].split(":", 1)[1].split()
    subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(src)],
                   capture_output=True)         # the parse table and glyphs are cached now
    assert loaded(["check", str(src)]) == []
    assert loaded(["render", str(src), "-o", str(tmp_path / "t.svg")]) == ["svgwrite",
                                                                           "urllib.request"]
    assert (tmp_path / "t.svg").read_text().startswith("<?xml") or \
        "<svg" in (tmp_path / "t.svg").read_text()[:200]


@settings(max_examples=100, deadline=None)
@given(st.lists(loop, min_size=1, max_size=3), st.lists(point, min_size=0, max_size=30),
       st.lists(point, min_size=0, max_size=30))
def test_inside_of_points_taken_together_is_per_point(loops, a, b):
    """W0505 tests the points of all the geometries of one part in one call: a point's verdict
    does not depend on the other points."""
    A = np.array(a, dtype=float).reshape(-1, 2)
    B = np.array(b, dtype=float).reshape(-1, 2)
    both = _inside(np.vstack([A, B]), loops)
    assert np.array_equal(both, np.concatenate([_inside(A, loops), _inside(B, loops)]))


@settings(max_examples=100, deadline=None)
@given(st.one_of(line, circle, arc, poly))
def test_sample_counts(item):
    from aidl_lang.output.checks import _n_samples
    assert _n_samples(item) == len(_sample(item))


@settings(max_examples=100, deadline=None)
@given(st.lists(st.one_of(circle, circle, line), min_size=1, max_size=12))
def test_runs_of_circles_equal_the_per_item_samples(items):
    assert np.array_equal(_samples(items), np.vstack([_sample(it) for it in items]))


# ------------------------------------------------ W0505: on the material without growing it
_shape_spec = st.lists(st.tuples(st.sampled_from(["square", "circle"]), st.floats(-5, 5),
                                 st.floats(-5, 5), st.floats(0.5, 6), st.booleans()),
                       min_size=1, max_size=4)


def _cross_section(spec):
    import manifold3d as mf
    acc = mf.CrossSection()
    for kind, x, y, size, cut in spec:
        s = (mf.CrossSection.square((size, size * 0.7), center=True) if kind == "square"
             else mf.CrossSection.circle(size / 2, 40)).translate((x, y))
        acc = acc - s if cut else acc + s
    return acc


@settings(max_examples=150, deadline=None)
@given(_shape_spec, st.integers(0, 2**32 - 1))
# a circle added, cut by a larger one and cut again leaves a sliver of 3e-9 mm^2 that the
# grown outline drops (found by this test in CI: points near the sliver's edges were "surely")
@example([("circle", 2.375, -1.75, 1.5, False), ("circle", 0.0, -0.5, 4.0, True),
          ("square", 0.0, 0.0, 1.0, False), ("circle", 2.375, -1.75, 1.5, True)], 0)
def test_points_surely_on_the_material_are_inside_the_grown_part(spec, seed):
    """What `_all_on_material` accepts per point (inside the outline, or within
    `_SURELY_GROWN` of an edge) is inside Manifold's outline grown by ENGRAVE_TOL: points at
    0 to 1.5 ENGRAVE_TOL from the vertices and edges of random unions and differences."""
    import manifold3d as mf
    from aidl_lang.output.checks import ENGRAVE_TOL, _edges, _inside
    from aidl_lang.output.checks.marks.sampling import _loop_area, _surely_on_material
    shape = _cross_section(spec)
    loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    if not loops:
        return
    rng = np.random.default_rng(seed)
    P = np.concatenate(loops)
    Q = np.concatenate([np.concatenate([p[1:], p[:1]]) for p in loops])
    k = rng.integers(0, len(P), 300)
    base = P[k] + rng.uniform(0, 1, (300, 1)) * (Q[k] - P[k])      # on the edges
    ang = rng.uniform(0, 2 * np.pi, 300)
    r = rng.uniform(0, 1.5 * ENGRAVE_TOL, 300)
    pts = base + np.column_stack([r * np.cos(ang), r * np.sin(ang)])
    surely = _surely_on_material(pts, loops)
    grown = shape.offset(ENGRAVE_TOL, mf.JoinType.Round, 2.0, 16)
    inside = _inside(pts, _edges([np.asarray(p, dtype=float) for p in grown.to_polygons()]))
    assert not (surely & ~inside).any()
    # the test decides most points near loops of some area (those under ENGRAVE_TOL^2 it
    # leaves to the grown outline)
    big = np.concatenate([np.full(len(p), abs(_loop_area(p)) >= ENGRAVE_TOL ** 2) for p in loops])
    near_big = big[k]
    assert near_big.sum() < 30 or surely[near_big].sum() > near_big.sum() / 3


# The brute-force reference squares distances and rounds its projection, so at a distance
# of 0, or with coordinates whose squares underflow, it calls points 1e-87 or 4e-230 away
# "within" (_within is right): coordinates below 1e-100 are 0 here and the distance is at
# least 1e-3 (W0505 uses ~0.1 mm), integers included for exact ties
_wcoord = coord.map(lambda v: 0.0 if abs(v) < 1e-100 else v)
_wdist = st.one_of(st.integers(1, 3).map(float), st.floats(1e-3, 3))


@settings(max_examples=100, deadline=None)
@example([(0.0, 1.0, 0.0, 2.0)], [(0.0, -1.05e-82)], 1.0)   # 1 + 1e-82 rounds to 1: within
@given(st.lists(st.tuples(_wcoord, _wcoord, _wcoord, _wcoord), min_size=1, max_size=8),
       st.lists(st.tuples(_wcoord, _wcoord), min_size=1, max_size=30), _wdist)
def test_within_equals_the_brute_force_distance(segs, pts, dist):
    from aidl_lang.output.checks import _within
    S = np.array(segs, dtype=float)
    P = np.array(pts, dtype=float)
    got = _within(P, (S[:, 0], S[:, 1], S[:, 2], S[:, 3]), dist)
    a, b = S[None, :, :2], S[None, :, 2:]
    d = b - a
    L2 = (d * d).sum(-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, ((P[:, None] - a) * d).sum(-1) / L2, 0), 0, 1)
    e = P[:, None] - a - t[..., None] * d
    want = ((e * e).sum(-1) <= dist * dist).any(axis=1)
    assert np.array_equal(got, want)


@settings(max_examples=200, deadline=None)
@given(_shape_spec)
def test_pieces_are_the_counter_clockwise_loops(spec):
    """W0504 skips the split when at most one loop runs counter-clockwise: a non-empty
    Manifold cross-section has exactly one piece per such loop."""
    from aidl_lang.output.checks import _signed
    shape = _cross_section(spec)
    if shape.is_empty():
        return
    outer = sum(_signed(np.asarray(p, dtype=float)) > 0 for p in shape.to_polygons())
    assert outer == len(shape.decompose())
