"""Issue 74: a perforated sheet costs each stage work in proportion to its holes, end to end.

A panel of N round holes goes through the real pipeline (``compile_source``: reading, the
interpreter, the solver, the booleans, the final-part checks; ``build``; the DXF writer) under
cProfile, at N and at 4 N holes, read from a DXF by ``Drawing2D`` and written as an AIDL loop.
The Python calls of each stage (grouped by the module that runs them; ezdxf's reading and
writing as a stage of its own) must grow about 4 times (linear; constant work makes it less),
never the 16 times of a pass over every pair of holes; the whole run the same.  On main before
issue 74 (500 -> 2,000 holes) every stage grew 3.5-4.0 times, the whole 3.1 (DXF) and 3.8
(loop).  Array work (NumPy, Manifold) is not a Python call: a stage made array-shaped counts
few calls, and its time is in the benchmark.  The result is checked too: the DXF
written holds the outline and every hole as an exact CIRCLE (re-read by ezdxf).

The array work is counted too, where a stage's Python calls cannot show it: the vertices the
booleans hand to Manifold's unions (``batch_boolean``; ``manifold`` below) and the elements of
the arrays the cut order (``toolpath.plan``, the G-code, HP-GL and LightBurn writers' order;
``toolpath`` below) passes to NumPy.  Before the cut order looked its entries up in a grid,
each step of its nearest-neighbour tour measured every entry left and each loop's depth
tested every other loop's box: 16 times the work at 4 times the holes.

Per-hole objects kept are counted too: the arrays the exact recovery keeps per circle before
its chords are indexed, the hole outlines made before anything reads them, and the cyclic
collector's passes over the model (each walks its tens of thousands of objects).

Counts, not time: the figures do not depend on the machine's load.  Times are in
``benchmarks/checks/perforated.py``.
"""
from __future__ import annotations

import cProfile
import gc
import io
import pstats
from collections import Counter

import ezdxf
import pytest
from hypothesis import given, settings, strategies as st

import manifold3d as mf
import numpy as np

from aidl_lang.base.limits import DEFAULT_BUDGET
from aidl_lang.output import Options, build, checks, encode
from aidl_lang.output.fabrication import toolpath
from aidl_lang.output.part.build import booleans
from aidl_lang.output.part.measure import nearby
from aidl_lang.pipeline import compile_source, run_deep
from benchmarks.checks.perforated import grid, panel_aidl, reader, write_dxf

# (folder in aidl_lang/, stage); the first that matches names a function's stage
STAGES = [("aidl_lang/drawing/", "reading"), ("aidl_lang/interp", "interpreter"),
          ("aidl_lang/solver/", "solver"), ("aidl_lang/geometry/", "geometry"),
          ("aidl_lang/output/part/", "booleans"), ("aidl_lang/output/checks/", "checks"),
          ("aidl_lang/output/writers/", "writers"), ("aidl_lang/", "other"),
          ("/ezdxf/", "ezdxf")]
# linear work grows 4 times from N to 4 N holes (less with the fixed work of a compile); a
# pass over pairs grows 16 times, and N log N Python (a sort with a key, a tree) ~4.9 times
GROWTH = 4.6
FEW = 200                   # calls at N below which a stage counts as FEW
SMALL = (25, 20)            # 500 holes; 4 times: (50, 40), 2,000 holes


def _stage(filename: str) -> str | None:
    f = filename.replace("\\", "/")
    for part, name in STAGES:
        if part in f:
            return name
    return None


class _Counted:
    """A NumPy function that adds the elements of its array arguments to ``work[key]``."""

    def __init__(self, real, work: Counter, key: str):
        self.real, self.work, self.key = real, work, key

    def __call__(self, *args, **kw):
        self.work[self.key] += sum(a.size for a in args if isinstance(a, np.ndarray))
        return self.real(*args, **kw)

    def __getattr__(self, name):            # np.subtract.at and the like: as they are
        return getattr(self.real, name)


class _NumPy:
    """``numpy`` as a module sees it, each function call's array elements counted."""

    def __init__(self, work: Counter, key: str):
        self._work, self._key = work, key

    def __getattr__(self, name):
        real = getattr(np, name)
        if isinstance(real, type) or not callable(real):
            return real
        return _Counted(real, self._work, self._key)


class _Manifold:
    """``manifold3d`` as the booleans see it, the vertices handed to each union counted."""

    def __init__(self, work: Counter):
        work_ = work

        class CrossSection:
            def __new__(cls, *args, **kw):
                return mf.CrossSection(*args, **kw)

            @staticmethod
            def batch_boolean(faces, op):
                work_["manifold"] += sum(f.num_vert() for f in faces)
                return mf.CrossSection.batch_boolean(faces, op)

            def __class_getitem__(cls, item):
                return mf.CrossSection

        for name in dir(mf.CrossSection):
            if not name.startswith("_") and name != "batch_boolean":
                setattr(CrossSection, name, getattr(mf.CrossSection, name))
        self.CrossSection = CrossSection

    def __getattr__(self, name):
        return getattr(mf, name)


def _run(tmp_path, nx: int, ny: int, how: str) -> tuple[Counter, int, bytes]:
    """Calls by stage of compiling and writing the panel to DXF (and, written as a loop,
    ordering its cuts), with the array work of the booleans' unions and of the cut order, and
    the cyclic collector's passes (``collections``: each walks the objects of its
    generations, the model's tens of thousands of structures among them); the number of
    holes; the DXF."""
    W, H, centres = grid(nx, ny)
    folder = tmp_path / f"{how}{nx}x{ny}"
    folder.mkdir()
    if how == "dxf":
        write_dxf(folder / "panel.dxf",
                  [(-W / 2, -H / 2), (W / 2, -H / 2), (W / 2, H / 2), (-W / 2, H / 2)],
                  [(x, y, 2.0) for x, y in centres])
        src = reader("panel.dxf")
    else:
        src = panel_aidl(nx, ny)
    path = folder / "panel.aidl"
    path.write_text(src)
    pr = cProfile.Profile()
    work: Counter = Counter()
    mp = pytest.MonkeyPatch()
    mp.setattr(booleans, "mf", _Manifold(work))
    mp.setattr(toolpath, "np", _NumPy(work, "toolpath"))
    from aidl_lang.output.part.edges import exact as exact_mod
    real_cells, real_match = exact_mod._Grid._cells, exact_mod._Grid.match

    def cells(grid, M):                 # edges looked up in the exact recovery's grid
        work["cell lookups"] += len(M)
        return real_cells(grid, M)

    def match(grid, P, Q, tol):         # edges matched
        work["edges matched"] += len(P)
        return real_match(grid, P, Q, tol)
    real_init = exact_mod._Grid.__init__

    def indexed(grid, A, B, C):         # chords put in the exact recovery's grid
        work["chords indexed"] += len(A)
        real_init(grid, A, B, C)
    mp.setattr(exact_mod._Grid, "_cells", cells)
    mp.setattr(exact_mod._Grid, "match", match)
    mp.setattr(exact_mod._Grid, "__init__", indexed)
    from aidl_lang.output.checks.holes import openings
    real_local = openings._Near.local

    def local(near, part, region):      # a hole's neighbourhood to intersect (W0501)
        work["hole intersections"] += 1
        return real_local(near, part, region)
    mp.setattr(openings._Near, "local", local)

    counting = [True]

    def counted(phase, info):
        if phase == "stop" and counting[0]:
            work["collections"] += 1

    def work_():
        # on the compile's own thread (run_deep: cProfile sees one thread), where the
        # compile then runs as it is, without a thread of its own
        pr.enable()
        try:
            # the wall-time budget scaled: a loaded machine under cProfile may take long
            res = compile_source(src, str(path), budget=DEFAULT_BUDGET.scaled(20))
            assert res.ok, [d.message for d in res.sink.items]
            exact = res.drawing.exact
            work["arrays kept"] = sum(isinstance(x, np.ndarray) for x in exact._b + exact._c)
            holes = res.drawing.hole_outlines           # (main before: a list of arrays)
            work["hole outlines made"] = sum(isinstance(x, np.ndarray)
                                             for x in getattr(holes, "_items", holes))
            out = build(res.drawing, res.model.root.name, deadline=res.deadline)
            if how == "loop":           # (the same cut order from either)
                counting[0] = False     # (the writers that order cuts do it paused)
                cuts = toolpath.plan(out)
                counting[0] = True
                assert sum(c.operation == "cut_inner" for c in cuts) == len(centres)
            data = encode(out, ".dxf", Options())
            pr.disable()
            # read (the SVG's `--show holes`): each hole's outline, the circle's 45 chords
            # (a DXF's holes are its Drawing2D's own, no hole structures)
            assert [len(P) for P in holes] == [45] * len(centres) * (how == "loop")
            return data
        finally:
            pr.disable()
    gc.callbacks.append(counted)
    try:
        data = run_deep(work_)
    finally:
        gc.callbacks.remove(counted)
        mp.undo()
    calls: Counter = Counter(work)
    for (filename, _, _), (_, nc, _, _, _) in pstats.Stats(pr, stream=io.StringIO()).stats.items():
        stage = _stage(filename)
        calls["all"] += nc
        if stage is not None:
            calls[stage] += nc
    return calls, len(centres), data


def _holes(data: bytes) -> tuple[int, list[float], int]:
    """Circles, their radii, and closed outlines of the DXF (re-read by ezdxf)."""
    doc = ezdxf.read(io.StringIO(data.decode()))
    msp = doc.modelspace()
    circles = list(msp.query("CIRCLE"))
    outlines = len(msp.query("LWPOLYLINE")) + len(msp.query("LINE")) // 4
    return len(circles), sorted({round(c.dxf.radius, 9) for c in circles}), outlines


@pytest.mark.parametrize("how", ["dxf", "loop"])
def test_each_stage_grows_linearly_with_the_holes(tmp_path, how):
    """500 -> 2,000 holes: every stage's Python calls grow at most GROWTH times (linear)."""
    small, n1, d1 = _run(tmp_path, *SMALL, how)
    large, n4, d4 = _run(tmp_path, SMALL[0] * 2, SMALL[1] * 2, how)
    assert (n1, n4) == (500, 2000)
    for data, n in ((d1, n1), (d4, n4)):
        circles, radii, outlines = _holes(data)
        assert circles == n and radii == [2.0] and outlines >= 1
    # a stage of fewer than FEW calls (array work, or none) may grow to GROWTH x FEW
    grew = {s: round(large[s] / max(small[s], FEW), 2) for s in large}
    worst = {s: g for s, g in grew.items() if g > GROWTH}
    assert not worst, (f"stages past {GROWTH}x from {n1} to {n4} holes: {worst}; calls: "
                       + str({s: (small[s], large[s]) for s in large}))
    # the grouping names the stages (a rename of the folders would leave them out)
    assert {"all", "geometry", "booleans"} <= set(large), large
    # (a drawing's circles are one face: no union; a loop's holes are united once)
    assert how == "dxf" or {"toolpath", "manifold"} <= set(large), large
    # the exact recovery's chords of a circle are its polygon alone until they are indexed
    # (exact._pieces), not two more arrays per hole kept from the booleans to the writer
    # (main before: 4,002 arrays at 2,000 holes, 1,002 at 500; the outline's carriers: one)
    assert small["arrays kept"] <= 1 and large["arrays kept"] <= 1, large["arrays kept"]
    # the part of each hole that cuts (`--show holes` only) is made when read, not the
    # solid's shape intersected with its holes and an array per hole in every compile
    assert small["hole outlines made"] == 0 == large["hole outlines made"], large
    # the collector is paused through the booleans, the checks, the exact outlines and the
    # writer (as through the parser, the interpreter and the solver): a pass when each ends
    # (4-5 here), not one every 700 objects made (main before: 500 -> 2,000 holes 12 -> 39
    # passes from a DXF, 10 -> 50 as a loop; 861 passes, 0.68 s CPU at 20,000 holes)
    assert small["collections"] <= 8 and large["collections"] <= 8, \
        (small["collections"], large["collections"])
    # the exact recovery takes a hole no boolean touched (its polygon the circle's own
    # vertices) as that circle without the chord grid: only the outline's edges are matched,
    # against a grid of the outline's chords (main before: every hole's 45 chords indexed
    # and matched, 90,004 at 2,000 holes), each edge's cells looked up once
    for w in (small, large):
        assert 4 <= w["edges matched"] <= 8 and w["chords indexed"] <= 8, w
        assert w["cell lookups"] == w["edges matched"], (w["cell lookups"], w["edges matched"])
    # the panel's own holes are not intersected with its shape for W0501 (no structure
    # between them and the panel could refill them; main before: one per hole, 500 / 2,000)
    assert small["hole intersections"] == 0 == large["hole intersections"], large


def test_the_slit_search_measures_no_neighbours_along_the_holes(tmp_path, monkeypatch):
    """W0519's search (slits._check_slits) of a DXF panel of 100 round holes (4,504 chord
    vertices: the large path): it measured each vertex against the chords beside it on its
    own circle (21,608 candidate pairs, 4.8 per vertex; 3.2 million at 20,000 holes, past the
    pair limit at 50,000: the slits went unchecked, W0521), every one then dropped as not
    facing.  Now only vertices whose tangent runs against the segment are searched: 2 here
    (the outline's corners), none per hole.  Counts of pairs measured, not time."""
    seen = {"pairs": 0, "vertices": 0, "on": False}
    measure, slits = nearby._measure, checks._check_slits

    def counted_measure(V, A, B, vfeat, sfeat, v, s, dist):
        if seen["on"]:
            seen["pairs"] += len(v)
        return measure(V, A, B, vfeat, sfeat, v, s, dist)

    def counted_slits(d, s, loops, *args, **kw):
        seen["on"], seen["vertices"] = True, seen["vertices"] + sum(len(P) for P in loops)
        try:
            return slits(d, s, loops, *args, **kw)
        finally:
            seen["on"] = False
    monkeypatch.setattr(nearby, "_measure", counted_measure)
    monkeypatch.setattr(checks, "_check_slits", counted_slits)
    W, H, centres = grid(10, 10)
    write_dxf(tmp_path / "panel.dxf",
              [(-W / 2, -H / 2), (W / 2, -H / 2), (W / 2, H / 2), (-W / 2, H / 2)],
              [(x, y, 2.0) for x, y in centres])
    res = compile_source(reader("panel.dxf"), str(tmp_path / "panel.aidl"))
    assert res.ok and not res.sink.items, [d.message for d in res.sink.items]
    assert seen["vertices"] > nearby.SMALL_VERTS, seen          # the large path
    assert seen["pairs"] <= 10, seen                            # was 21,608


def _circle_loop(cx, cy, r, n, turn=0.0, cw=True):
    t = turn + 2 * np.pi * np.arange(n) / n
    P = np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])
    return P[::-1] if cw else P


@settings(max_examples=12, deadline=None)
@given(st.lists(st.tuples(st.floats(0.2, 3.0), st.floats(-0.3, 0.8), st.integers(8, 60),
                          st.floats(0, 6.3)), min_size=60, max_size=60),
       st.floats(0.1, 2.0))
def test_the_slit_search_leaves_out_only_circles_that_pair_with_nothing(rows, t):
    """slits._lone_circles (a law): a loop it leaves out of W0519's search holds no vertex
    and no edge of a pair the search measures and keeps on all the loops (close_pairs_facing,
    then not adjacent, apart, facing: slits._check_slits's own filters), so the warnings are
    the same; circles of a grid (some -0.3 to 0.8 mm from their neighbour or the outline, radii
    0.2-3 mm, 8-60 chords, any phase, either way round), in a square outline."""
    from aidl_lang.output.checks.material import slits, walls
    loops = [np.array([[-40.0, -40.0], [40.0, -40.0], [40.0, 40.0], [-40.0, 40.0]])]
    for k, (r, gap, n, turn) in enumerate(rows):
        cy = -36 + 8 * (k // 10)
        if k % 10 == 0:         # against the outline, `gap` from it
            cx = -40 + r + gap
        elif k % 10 == 1:       # against the one before
            cx = prev[0] + prev[1] + r + gap
        else:
            cx = -36 + 8 * (k % 10)
        prev = (cx, r)
        loops.append(_circle_loop(cx, cy, r, n, turn, cw=k % 7 != 0))
    V, nxt, prv = walls._ring(loops)
    if len(V) <= nearby.SMALL_VERTS:
        loops += [_circle_loop(0, 50, 4, nearby.SMALL_VERTS)]   # past the small path
        V, nxt, prv = walls._ring(loops)
    of = np.repeat(np.arange(len(loops)), [len(P) for P in loops])
    v, sg, dist, _ = nearby.close_pairs_facing(V, nxt, prv, t, slits.FACING)
    ok = (v != nxt[sg]) & (dist > 1e-6) & walls._facing(V, nxt, prv, v, sg, slits.FACING)
    paired = set(of[v[ok]].tolist()) | set(of[sg[ok]].tolist())
    out = set(np.flatnonzero(slits._lone_circles(loops, t)).tolist())
    assert not out & paired, sorted(out & paired)
    assert out, "no circle left out"


# ------------------------------------------------ 5,000 circles in a row (benchmarks' collinear)
ROW = 600          # circles 1 mm apart: past the booleans' turn (scanwork.plan, ~430 circles)


@pytest.fixture(scope="module")
def long_row():
    """The collinear plate of ``benchmarks/checks/perforated.py`` at ROW holes of r 0.6 mm (they
    overlap: one long opening), compiled once; the holes' union as the booleans hand it to
    the part's last booleans (``Renderer.union(..., frame=True)``: (shape, turned))."""
    from benchmarks.checks.perforated import collinear_aidl
    framed = []
    real = booleans.Renderer.union

    def union(self, faces, s=None, frame=False):
        got = real(self, faces, s, frame=frame)
        if frame:
            framed.append(got)
        return got
    measured = {"inside": 0, "pairs": 0, "refills": 0}
    real_measure, analyse = nearby._measure, checks._analyse

    def counted_measure(V, A, B, vfeat, sfeat, v, s, dist):
        measured["pairs"] += len(v) if measured["inside"] else 0
        return real_measure(V, A, B, vfeat, sfeat, v, s, dist)

    def counted_analyse(*args, **kw):
        measured["inside"] += 1
        try:
            return analyse(*args, **kw)
        finally:
            measured["inside"] -= 1
    mp = pytest.MonkeyPatch()
    mp.setattr(booleans.Renderer, "union", union)
    mp.setattr(nearby, "_measure", counted_measure)
    mp.setattr(checks, "_analyse", counted_analyse)
    from aidl_lang.output.checks.holes import openings
    real_refill = openings._Near._near_refill

    def refill(near, part, regions):    # the row's opening within the holes (one boolean)
        measured["refills"] += 1
        return real_refill(near, part, regions)
    mp.setattr(openings._Near, "_near_refill", refill)
    try:
        res = compile_source(collinear_aidl(ROW, 0.6), "row.aidl", min_wall=0)
    finally:
        mp.undo()
    return res, framed, measured


def test_holes_found_overlapping_are_not_measured_or_intersected_again(long_row):
    """W0508/W0507's search (``openings._analyse``): the holes of the row overlap (found by
    intersecting them first: ROW - 1 merges); their boundaries' close pairs were then
    measured too and dropped as merged (1,198 vertex-segment pairs here; 107,221 with the
    default minimum wall thickness, 0.34 s of the 5,000-hole check).  They are skipped
    before they are measured (``close_pairs(skip=...)``): none here, nothing else is near."""
    res, _, measured = long_row
    merges = [d for d in res.sink.items if d.code == "W0508"]
    assert len(merges) == ROW - 1 == len([d for d in res.sink.items if d.code != "W0534"])
    assert measured["pairs"] == 0, measured
    # nor is the plate's shape within its own holes made for W0501 (no structure between
    # the plate and its holes could refill them; main before: one union of the row, 0.07 s
    # at 5,000 holes)
    assert measured["refills"] == 0, measured


def test_a_long_row_of_holes_is_cut_and_opened_scanned_along_it(long_row, monkeypatch):
    """A plate minus ROW overlapping circles in a row.  Clipper2 scans along y: a row along x
    puts every circle's edges on each scan line, and its booleans and offsets then cost far
    more than along the row (at 5,000 holes the plate minus the row took 1.05 s scanned
    across it, 0.03 s along it; the whole row's opening 15 s and 0.18 s).  What is handed
    to Clipper is checked here by its extent along the scan line, not timed.

    The booleans cut the holes in the frame they were united in (turned a quarter turn: the
    row lies along y there), where the union was turned back first before.  W0507's opening
    (``walls._thin``) opens its tiles of the row turned (each opened shape at most
    ``TURN_ASPECT`` times wider than tall; the tiles were 20 times wider), and clips the
    tiles in arrays (``_clip_ring``: the region of Clipper's intersection with each tile's
    box), with the same pieces as the whole opening."""
    from aidl_lang.output.checks.material import walls
    from aidl_lang.output.part.build.scanwork import turned, turned_back
    res, framed, _ = long_row
    assert res.ok
    (part,) = res.drawing.parts
    # the booleans: one union of the holes, returned as scanned (turned), cut as it is
    ((cut, turn),) = framed
    x0, y0, x1, y1 = cut.bounds()
    assert turn and y1 - y0 > 100 * (x1 - x0)                # the row along y: scanned along
    plate = (ROW + 3) * 6.0
    assert part.shape.area() == pytest.approx(plate - cut.area(), abs=1e-6)
    assert part.shape.num_contour() == 2                 # the plate and its one long opening
    # W0507's opening: tiles opened turned, clipped in arrays
    t = 0.5
    opened, clips = [], []
    real_open, real_clip = walls._open, walls._clip_loops

    def counted_open(shape, t):
        a, b, c, e = shape.bounds()
        opened.append((c - a) / (e - b))
        return real_open(shape, t)

    def checked_clip(loops, boxes, a, b, c, e):
        got = real_clip(loops, boxes, a, b, c, e)
        if len(clips) < 4:              # the region: Clipper's intersection with the box
            box = mf.CrossSection.square((c - a, e - b)).translate((a, b))
            want = mf.CrossSection([p.tolist() for p in loops], mf.FillRule.Positive) ^ box
            mine = mf.CrossSection([p.tolist() for p in got[0]], mf.FillRule.Positive)
            clips.append(((mine ^ want).area(), want.area(), mine.area()))
        return got
    monkeypatch.setattr(walls, "_open", counted_open)
    monkeypatch.setattr(walls, "_clip_loops", checked_clip)
    shape = part.shape ^ mf.CrossSection.square((150.0, 6.0)).translate((-2.0, -3.0))
    assert shape.num_vert() > walls.TILE_VERTS                # the first 150 mm, in tiles
    pieces = walls._thin(shape, t, least=2 * t * t, whole_loops=0)
    assert len(opened) > 1 and len(clips) > 1                 # in tiles, clipped
    assert max(opened) <= 1 / walls.TURN_ASPECT, opened       # each opened turned
    for common, want, mine in clips:
        assert common == pytest.approx(want, abs=1e-6) and mine == pytest.approx(want, abs=1e-6)
    flat = turned([shape])[0]
    whole = turned_back(flat - real_open(flat, t))
    assert sum(p.area() for p in pieces) == pytest.approx(whole.area(), rel=1e-6, abs=1e-6)


def test_the_webs_distances_in_one_pass_are_each_webs_own():
    """``openings._seg_distances`` (every web's centre to its two features' segments at once,
    in chunks) is each point's distance to its feature's segments as Shapely measures it,
    with features of no segment (inf) and a zero-length segment among them and chunks that
    split the points."""
    import math

    import shapely
    from aidl_lang.output.checks.holes.openings import _seg_distances
    rng = np.random.default_rng(7)
    sf = np.sort(rng.choice([0, 1, 2, 4, 5, 9], size=300))   # features 3, 6-8: no segment
    A, B = rng.normal(size=(300, 2)), rng.normal(size=(300, 2))
    B[5] = A[5]                                               # a zero-length segment
    P = rng.normal(size=(40, 2)) * 2
    F = rng.integers(0, 10, size=40)

    def shapely_distance(p, f):
        pieces = [shapely.LineString([a, b]) if (a != b).any() else shapely.Point(a)
                  for a, b in zip(A[sf == f], B[sf == f])]
        return shapely.distance(shapely.Point(p), shapely.GeometryCollection(pieces)) \
            if pieces else math.inf
    want = [shapely_distance(p, f) for p, f in zip(P, F)]
    assert sum(math.isinf(w) for w in want) >= 5                # points of empty features
    for chunk in (1, 50, 1 << 20):
        assert _seg_distances(P, F, sf, A, B, chunk=chunk).tolist() == pytest.approx(
            want, abs=1e-12)


def test_loops_clipped_in_arrays_are_clippers_intersection():
    """``walls._clip_loops`` (loops crossing the box projected onto it, ``_clip_ring``): the
    region of the clipped loops is Clipper's intersection of the shape with the box, for a
    plate with holes near, across and around the box's edges and corners, boxes cutting
    through holes, between them, inside one and around the whole."""
    from aidl_lang.output.checks.material import walls
    from aidl_lang.output.checks.common import _loop_boxes
    rng = np.random.default_rng(3)
    plate = mf.CrossSection.square((40.0, 20.0)) - mf.CrossSection.batch_boolean(
        [mf.CrossSection.circle(float(r), 24).translate((float(x), float(y)))
         for x, y, r in zip(rng.uniform(0, 40, 30), rng.uniform(0, 20, 30),
                            rng.uniform(0.5, 3, 30))], mf.OpType.Add)
    star = mf.CrossSection([[(20 + 9 * np.cos(k * np.pi / 7) * (1 + k % 2),
                              10 + 4 * np.sin(k * np.pi / 7) * (1 + k % 2))
                             for k in range(14)]])
    for shape in (plate, plate - star, star):
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
        boxes = _loop_boxes(loops)
        for a, b, c, e in [(5, 5, 15, 12), (-1, -1, 41, 21), (0, 0, 40, 20), (19, 9, 21, 11),
                           (10.3, -5, 10.31, 30), (-3, 4, 50, 4.5), *rng.uniform(-2, 42, (8, 4))]:
            a, c = sorted((a, c))
            b, e = sorted((b, e))
            got, got_boxes = walls._clip_loops(loops, boxes, a, b, c, e)
            box = mf.CrossSection.square((c - a, e - b)).translate((a, b))
            want = shape ^ box
            mine = mf.CrossSection([p.tolist() for p in got], mf.FillRule.Positive)
            # (to Clipper's grid: it rounds the points where edges cross the box to 1e-8 mm)
            assert mine.area() == pytest.approx(want.area(), abs=1e-6)
            assert (mine ^ want).area() == pytest.approx(want.area(), abs=1e-6)
            assert np.array_equal(got_boxes, _loop_boxes(got))


def test_holes_whose_boxes_are_apart_are_not_intersected(monkeypatch):
    """W0508's search for overlapping holes (``openings._analyse``) pairs the holes within
    the wall's reach by their boxes; a pair whose boxes do not meet has nothing in common and
    is no longer intersected: 100 holes of r 0.4 mm 1 mm apart (0.2 mm walls, reported as
    W0507 webs) measure each hole's area twice (the region kept, its area: 200 areas; 299
    before, one per neighbour pair's intersection too)."""
    from aidl_lang.output.checks.holes import openings
    from benchmarks.checks.perforated import collinear_aidl
    areas, inside = [], []
    real, analyse = openings._area, checks._analyse

    def counted(*args, **kw):
        inside.append(1)
        try:
            return analyse(*args, **kw)
        finally:
            inside.pop()
    monkeypatch.setattr(openings, "_area", lambda s: (inside and areas.append(1), real(s))[1])
    monkeypatch.setattr(checks, "_analyse", counted)
    res = compile_source(collinear_aidl(100, 0.4), "row.aidl")
    webs = [d for d in res.sink.items if d.code == "W0507"]
    assert len(webs) == 99 and all(" is 0.20 mm wide" in d.message for d in webs)
    assert not [d for d in res.sink.items if d.code == "W0508"]
    assert len(areas) == 200, len(areas)


def test_holes_apart_in_a_row_are_united_in_one_pass(monkeypatch):
    """``openings._united`` (the holes of a part filled, for W0507's outline) of 500 holes of
    r 0.4 mm 1 mm apart in a row: scanned along the row, and, their boxes apart, in one
    ``batch_boolean`` over their vertices once (12,000; in groups of 16, then the groups'
    results, and theirs: 36,000 before), with the same union."""
    from aidl_lang.output.checks.holes import openings
    from aidl_lang.output.part.build.scanwork import plan
    holes = [mf.CrossSection.circle(0.4, 24).translate((float(i), 0.0)) for i in range(500)]
    assert plan(holes)[0]                                     # the row: scanned along it
    work: Counter = Counter()
    monkeypatch.setattr(openings, "mf", _Manifold(work))
    got = openings._united(holes)
    assert work["manifold"] == sum(h.num_vert() for h in holes) == 12_000
    want = mf.CrossSection.batch_boolean(holes, mf.OpType.Add)
    assert got.num_contour() == 500 and got.area() == pytest.approx(want.area(), rel=1e-12)
