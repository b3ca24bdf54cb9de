"""The fast kernels of the shape checks and writers (output/checks.py, output/part.py) against their
reference versions: same booleans, same sample points, bit for bit (hypothesis)."""
import numpy as np
from hypothesis import given, settings, strategies as st

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
    from aidl_lang.geometry.tessellate import segments_for
    from aidl_lang.output.part import Arc, Line
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
    from aidl_lang.output.part import Arc, Circle, Line
    p = st.tuples(st.floats(-50, 50), st.floats(-50, 50))
    r = st.floats(0.001, 40)
    return st.one_of(st.builds(Line, p, p),
                     st.builds(Arc, p, r, st.floats(-7, 7), st.floats(-6.3, 6.3)),
                     st.builds(Circle, p, r, st.booleans()))


@settings(max_examples=150, deadline=None)
@given(st.lists(st.lists(_segment(), min_size=1, max_size=5), min_size=0, max_size=4),
       st.lists(st.lists(_segment(), min_size=1, max_size=3), min_size=0, max_size=3))
def test_points_and_bounds_equal_the_reference(loops, strokes):
    from aidl_lang.output.part import Circle, Loop, Output, PartOutline, Stroke
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


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(-1e6, 1e6), min_size=1, max_size=30))
def test_median_equals_numpy(xs):
    from aidl_lang.output.part import _median
    a = np.array(xs).reshape(-1, 1)
    assert _median(a) == float(np.median(a))


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
