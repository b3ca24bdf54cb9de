"""Through-cuts on sheets of many pieces stay O(n log n) in the booleans (issue 58, real size).

Boxes.py's Lamp sheet (`aidl import --roles laser`: 247 pieces in one solid, 2,180 open cut
paths) took 15.3 s in the booleans, past the default budget (E0304): every through-cut's band
was intersected with the whole part to find its area on the material, and each piece a cut
freed was intersected with every piece of the part as it was (and, to find whether it falls
out, compared with the union of all the others).  Now each band and each piece meets only
the pieces whose bounding boxes meet its own (:func:`~aidl_lang.output.part.measure.nearby.meeting`):
the Lamp in 3.6 s, the sheets below in a few seconds where they took 11 to 60 s.  And
the exact output drops the through-cuts that run along a split part's outline (cut once, as
the outline) by asking a grid of their sample points for the edges near each
(:func:`~aidl_lang.output.part.part._off_outlines`), not every point against every edge.
"""
from __future__ import annotations

import time

import manifold3d as mf
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from aidl_lang import api
from aidl_lang.base.limits import Budget
from aidl_lang.output.part.measure.nearby import meeting as _meeting
from aidl_lang.pipeline import compile_source
from cpu_clock import make_clock
from cpu_reference import cpu_bound

# the budgets count CPU seconds (the cpu_clock fixture, tests/cpu_clock.py), as the figures do
pytestmark = [pytest.mark.timing, pytest.mark.usefixtures("cpu_clock")]

COLS = 40


def _split_sheet(n: int) -> str:
    """``n`` discs in one solid, each cut in two along a diameter by a through-cut that runs
    past both its edges: every disc's smaller half is freed (a part of its own)."""
    return f"""solid sheet {{
    for i in range({n}) {{
        disc = Circle(center=((i % {COLS}) * 12, (i // {COLS}) * 12), radius=5)
    }}
    cut slits {{
        for i in range({n}) {{
            s = Line(start=((i % {COLS}) * 12 - 6, (i // {COLS}) * 12 + 1), end=((i % {COLS}) * 12 + 6, (i // {COLS}) * 12 + 1))
        }}
    }}
}}
"""


def _square_cuts(n: int) -> str:
    """One plate with ``n`` closed squares drawn as through-cuts: each square's inside falls
    out with the scrap (a hole), nothing else is freed."""
    rows = (n + COLS - 1) // COLS
    return f"""solid plate {{
    body = Rectangle(center=({COLS * 6}, {rows * 6}), width={COLS * 12 + 10}, height={rows * 12 + 10})
    cut squares {{
        for i in range({n}) {{
            a = Line(start=((i % {COLS}) * 12 + 3, (i // {COLS}) * 12 + 3), end=((i % {COLS}) * 12 + 9, (i // {COLS}) * 12 + 3))
            b = Line(start=a.end, end=((i % {COLS}) * 12 + 9, (i // {COLS}) * 12 + 9))
            c = Line(start=b.end, end=((i % {COLS}) * 12 + 3, (i // {COLS}) * 12 + 9))
            d = Line(start=c.end, end=a.start)
        }}
    }}
}}
"""


@pytest.fixture(scope="module")
def discs_2000():
    """The sheet of 2,000 discs each cut in two (:func:`_split_sheet`), compiled once for the
    tests below (5 s of CPU), on the CPU clock as the module's tests are: ``(the compile, its
    CPU seconds)``."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(time, "monotonic", make_clock())
        t = time.process_time()           # a wide budget: the CPU bound below is the test
        c = compile_source(_split_sheet(2000), "discs.aidl", budget=Budget(seconds=60))
        return c, time.process_time() - t


def test_a_sheet_of_2000_discs_each_cut_in_two_compiles_in_seconds(discs_2000):
    """Before: 1,000 discs took 12.8 s of CPU (every freed half intersected with every disc),
    2,000 ran out of the default 15 s budget (E0304); now about 3 s."""
    c, cpu = discs_2000
    codes = [d.code for d in c.sink.items]
    assert c.ok and "E0304" not in codes and "W0521" not in codes, codes[:5]
    assert len(c.drawing.parts) == 2001                  # the sheet and the 2,000 freed halves
    # each freed half is the disc's smaller segment, 1 mm off the centre (r = 5)
    seg = 25 * np.arccos(1 / 5) - 1 * np.sqrt(24)
    freed = [p.shape.area() for p in c.drawing.parts[1:]]
    assert np.allclose(freed, seg, rtol=2e-3), (min(freed), max(freed), seg)
    assert cpu < cpu_bound(10), cpu       # (4.9 s here: scaled, tests/cpu_reference.py)


def test_the_kerf_on_a_sheet_of_2000_discs_cut_in_two_stays_o_n_log_n(discs_2000):
    """Each piece of the offset sheet is asked only of the pieces whose boxes meet its own:
    about 3 s of CPU here for the 4,001 parts (asked of the whole sheet, each piece made it
    n^2: 68 s).  The bound is wide: the CPU of this process, not the wall clock.  (The kerf's
    other tests are tests/test_cut_grid.py's.)"""
    import math

    from aidl_lang.output import for_cutting
    from aidl_lang.output.part.part import build
    c, _ = discs_2000
    out = build(c.drawing, "sheet")
    t = time.process_time()
    cut = for_cutting(out, 0.2)
    cpu = time.process_time() - t
    assert len(cut.parts) == 2001 and cpu < 30, cpu
    # every freed half: its arc offset by 0.1 mm, its chord on the cut (the disc's segment
    # 1 mm off the centre, r = 5, grown by the arc's 0.1 mm band and the chord's ends)
    seg = 25 * math.acos(1 / 5) - math.sqrt(24)
    halves = [p for p in cut.parts if p.name != "sheet"]
    assert all(seg < p.area < seg + 0.1 * (2 * 5 * math.acos(1 / 5)) + 0.2 for p in halves)


def test_a_plate_with_2000_closed_cuts_drops_each_inside_as_a_hole():
    """Before: 2,000 squares took 10.9 s of CPU (each freed square compared with the union of
    all 2,000 others); now each is compared with the pieces whose boxes meet its own."""
    src = _square_cuts(2000)
    t = time.process_time()
    c = compile_source(src, "squares.aidl", budget=Budget(seconds=60))
    cpu = time.process_time() - t
    assert c.ok and not [d for d in c.sink.items if d.code in ("E0304", "W0521")]
    (part,) = c.drawing.parts
    rows = 2000 // COLS
    whole = (COLS * 12 + 10) * (rows * 12 + 10)
    assert part.shape.area() == pytest.approx(whole - 2000 * 36, rel=1e-6)
    assert cpu < cpu_bound(6), cpu
    res = api.Result(c, "squares.aidl", src)     # the compile above, not a second one
    t = time.process_time()
    (p,) = res.parts              # the exact output: each cut on a split outline drawn once
    cpu = time.process_time() - t
    assert p.holes == 2000
    assert cpu < cpu_bound(4), cpu   # 11.4 s before (_off_outlines: every point against every edge)
    assert not [st for st in res.output.engrave if st.style == "cut"]   # all on the outlines


def test_each_band_on_the_material_is_its_area_in_the_whole_part():
    """A through-cut's area on the material (W0522's measure) summed over the pieces its box
    meets equals its intersection with the whole part, on and off the material."""
    src = """solid sheet {
    for i in range(12) {
        disc = Circle(center=(i * 12, 0), radius=5)
    }
    cut slits {
        for i in range(12) {
            s = Line(start=(i * 12 - 6 + i * 0.7, 1 - i * 0.2), end=(i * 12 + 4 + i * 0.7, 2))
        }
        off = Line(start=(0, 20), end=(10, 20))
    }
}
"""
    c = compile_source(src, "bands.aidl")
    whole, _ = c.drawing.slit_shapes["sheet"]
    assert len(c.drawing.through) == 13
    for th in c.drawing.through:
        assert th.inside == pytest.approx((th.band ^ whole).area(), rel=1e-9, abs=1e-15)
    assert c.drawing.through[-1].inside == 0.0
    assert [d.code for d in c.sink.items].count("W0522") == 1    # `off`, and only it


boxes = st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(0.1, 30),
                           st.floats(0.1, 30)), min_size=0, max_size=40)


@settings(max_examples=60, deadline=None)
@given(boxes, boxes)
def test_meeting_is_every_pair_of_boxes_that_meet(a, b):
    """_meeting lists, for each shape of ``a``, exactly the shapes of ``b`` whose bounding
    boxes meet its own, in ascending order (the pairwise test as the reference)."""
    def squares(spec):
        return [mf.CrossSection.square((w, h)).translate((x, y)) for x, y, w, h in spec]
    A, B = squares(a), squares(b)
    got = _meeting(A, B)
    for i, p in enumerate(A):
        px0, py0, px1, py1 = p.bounds()
        want = [j for j, q in enumerate(B)
                if px0 <= q.bounds()[2] and q.bounds()[0] <= px1
                and py0 <= q.bounds()[3] and q.bounds()[1] <= py1]
        assert got[i] == want


# ------------------------------------------------------------------ _off_outlines
def _off_outlines_reference(strokes, parts):
    """The measure before issue 58's second round: every sample point against every edge."""
    from aidl_lang.output.part.build.booleans import _chain_points
    from aidl_lang.output.part.part import ON_OUTLINE, Stroke
    A = np.vstack([np.asarray(lp.points(), float) for p in parts for lp in p.loops])
    B = np.vstack([np.roll(np.asarray(lp.points(), float), -1, axis=0)
                   for p in parts for lp in p.loops])
    D = B - A
    L2 = np.maximum((D * D).sum(axis=1), 1e-300)
    out = []
    for st in strokes:
        if st.style != "cut":
            out.append(st)
            continue
        kept = []
        for seg in st.segments:
            pts = _chain_points([seg])
            a, b = pts[:-1], pts[1:]
            mids = np.vstack([a + f * (b - a) for f in (0.02, 0.25, 0.5, 0.75, 0.98)])
            t = np.clip(((mids[:, None, :] - A) * D).sum(axis=2) / L2, 0.0, 1.0)
            d = np.hypot(*np.moveaxis(A + t[:, :, None] * D - mids[:, None, :], 2, 0)).min(axis=1)
            if (d > ON_OUTLINE).any():
                kept.append(seg)
        if kept:
            out.append(Stroke(kept, st.style, st.closed, st.source, st.part))
    return out


class _Poly:
    def __init__(self, P):
        self.P = np.asarray(P, float)

    def points(self):
        return self.P


@settings(max_examples=80, deadline=None)
@given(st.integers(0, 2 ** 32 - 1), st.sampled_from([(1.0, 65_536, 1_000_000), (0.05, 3, 7)]))
def test_off_outlines_is_the_every_pair_measure(seed, sizes):
    """The grid's answer is the every-point-against-every-edge answer, segment for segment, on
    random outlines (long edges and short chords) and cuts on them, beside them (within and
    past ON_OUTLINE) and across them; also with tiny stretches, queries and candidate limits
    (the halving path)."""
    import aidl_lang.output.part.part as P
    from aidl_lang.geometry.shapes.curves import Arc, Line
    rng = np.random.default_rng(seed)
    old = P._STRETCH, P._QUERY, P._CANDIDATES
    P._STRETCH, P._QUERY, P._CANDIDATES = sizes
    try:
        loops = []
        for _ in range(int(rng.integers(1, 4))):
            c, r = rng.uniform(-20, 20, 2), rng.uniform(2, 15)
            k = int(rng.choice([3, 4, 7, 60]))
            ang = np.sort(rng.uniform(0, 2 * np.pi, k))
            loops.append(_Poly(c + r * np.column_stack([np.cos(ang), np.sin(ang)])))
        parts = [P.PartOutline("p", "solid", loops)]
        edges = [(lp.P[i], lp.P[(i + 1) % len(lp.P)]) for lp in loops for i in range(len(lp.P))]
        strokes = []
        for _ in range(int(rng.integers(1, 5))):
            segs = []
            for _ in range(int(rng.integers(1, 6))):
                a, b = edges[int(rng.integers(len(edges)))]
                n = (b - a)[::-1] * [1, -1] / max(np.hypot(*(b - a)), 1e-9)
                off = float(rng.choice([0.0, 0.01, 0.019, 0.021, 0.5, 3.0]))
                u, v = sorted(rng.uniform(0, 1, 2))
                p, q = a + u * (b - a) + off * n, a + v * (b - a) + off * n
                if rng.random() < 0.2:              # an arc bulging off the edge
                    segs.append(Arc(tuple((p + q) / 2 - 2 * n), float(np.hypot(*((q - p) / 2 + 2 * n))),
                                    float(rng.uniform(0, 2 * np.pi)), float(rng.uniform(0.1, 2))))
                else:
                    segs.append(Line(tuple(p), tuple(q)))
            strokes.append(P.Stroke(segs, "cut" if rng.random() < 0.8 else "drawing"))
        got = P._off_outlines(strokes, parts)
        want = _off_outlines_reference(strokes, parts)
        assert [(s.style, s.segments) for s in got] == [(s.style, s.segments) for s in want]
    finally:
        P._STRETCH, P._QUERY, P._CANDIDATES = old


def test_the_dxf_of_closed_cuts_holds_each_square_once_at_its_design_place():
    """Re-read by ezdxf: the plate's outline and each closed cut's square as one closed
    polyline on the cut layer, 6.000000 mm a side where the program puts it, and no second
    stroke along it (the cut runs on the freed piece's outline: cut once)."""
    import io

    import ezdxf
    data = api.compile(source=_square_cuts(50), path="squares.aidl").encode("dxf")
    doc = ezdxf.read(io.StringIO(data.decode()))
    ents = list(doc.modelspace())
    assert all(e.dxftype() == "LWPOLYLINE" and e.closed and e.dxf.layer == "CUT" for e in ents)
    assert len(ents) == 51
    boxes = set()
    for e in ents:
        P = np.array([(x, y) for x, y, *_ in e.get_points()])
        x0, y0 = P.min(axis=0)
        x1, y1 = P.max(axis=0)
        if x1 - x0 < 100:
            assert x1 - x0 == pytest.approx(6, abs=1e-9) and y1 - y0 == pytest.approx(6, abs=1e-9)
            boxes.add((round(x0, 9), round(y0, 9)))
    assert boxes == {((i % COLS) * 12 + 3, (i // COLS) * 12 + 3) for i in range(50)}


def test_meeting_of_90601_squares_is_listed_in_blocks():
    """The 301 x 301 squares a grid of 300 slits each way cuts a plate into (2 mm each, the
    pieces of `aidl parts` on such a plate): each meets itself and its 8 neighbours, (3 x 301
    - 2)^2 pairs in all.  Before: the grid query listed its 6.3 million candidates at once and
    refused past 3 million (TooManyPairs: an internal error of `aidl parts`); now the queries
    go in blocks of at most 3 million, and only a dense cluster is refused."""
    from aidl_lang.output.part.measure.nearby import MAX_PAIRS, TooManyPairs, box_pairs_between
    n = 301
    i, j = np.divmod(np.arange(n * n), n)
    boxes = np.column_stack([2.0 * i, 2.0 * j, 2.0 * i + 2, 2.0 * j + 2])
    pairs = box_pairs_between(boxes, boxes)
    assert len(pairs) == (3 * n - 2) ** 2
    di = np.abs(i[pairs[:, 0]] - i[pairs[:, 1]])
    dj = np.abs(j[pairs[:, 0]] - j[pairs[:, 1]])
    assert di.max() == 1 and dj.max() == 1
    # a cluster where every box meets every other is still refused, not listed
    k = int(np.sqrt(2 * MAX_PAIRS)) + 64
    same = np.tile([0.0, 0.0, 1.0, 1.0], (k, 1)) + np.linspace(0, 1e-3, k)[:, None]
    with pytest.raises(TooManyPairs):
        box_pairs_between(same, same)
