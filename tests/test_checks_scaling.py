"""The shape checks grow as n log n on the families of outlines that were quadratic somewhere
(issue 91): concentric circles, nested squares, a chain of rectangles edge to edge, a plate
with a grid of holes, squares touching edge to edge on a grid, squares touching at their
corners, an assembly of square parts touching edge to edge.  A law over generated sizes: the CPU seconds of the check stage alone
(``check_drawing`` on the booleans' result, ``time.process_time``) at 4n over those at n stay
under :data:`RATIO`; n log n gives 4 to 5 at these sizes, n^2 gives 16 (before the fix,
concentric circles at 100 and 400: 41 ms and 2,379 ms, a ratio of 58; nested squares 14).

Cost: about 10 s of CPU for the whole file with its imports (two generated sizes per family,
each compiled at n and 4n, the check timed in three batches of five at n and two at 4n, the
least batch's mean kept: one check at a time, a clock that ticks in milliseconds read a
2 ms check as 0.4 ms in a fresh clone's run, a ratio of 10.9 for nested squares)."""
from __future__ import annotations

import time

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.base.limits import DEFAULT_BUDGET, Deadline, now
from aidl_lang.output import checks
from aidl_lang.pipeline import _compile, run_deep
from benchmarks.checks import check_families as F

pytestmark = pytest.mark.timing

RATIO = 9.0        # t(4n) / t(n): n log n passes with margin, n^2 (16) fails

# family -> (its generator, the range n is drawn from)
SIZES = {
    "concentric": (F.concentric, (80, 120)),
    "concentric01": (lambda n: F.concentric(n, 0.1), (80, 120)),
    "nested": (F.nested, (110, 150)),
    "chain": (F.chain, (120, 180)),
    "grid": (F.grid, (200, 260)),
    "touching": (F.touching, (120, 180)),
    "corners": (F.corners, (50, 70)),
    "parts": (F.parts, (40, 55)),
}


def _drawing(src: str):
    c = run_deep(lambda: _compile(DiagnosticSink(), src, "f.aidl", None, True,
                                  budget=DEFAULT_BUDGET.scaled(8), shape_checks=False))
    assert c.drawing is not None and c.ok, [(d.code, d.message) for d in c.sink.items]
    return c.drawing


BATCH = 5          # checks timed together: a CPU clock that ticks in milliseconds reads
#                    one 2 ms check as 0.4 or 2 (a nested family's ratio came to 10.9 so)


def _check_cpu(drawing, runs: int) -> tuple[float, list]:
    """The least CPU seconds, over ``runs`` batches of :data:`BATCH` runs each (their mean),
    of the shape checks on ``drawing``, and the codes they said."""
    best, said = float("inf"), []
    for _ in range(runs):
        t0 = time.process_time()
        for _ in range(BATCH):
            sink = DiagnosticSink()
            run_deep(lambda: checks.check_drawing(drawing, sink, None,
                                                  Deadline(now() + 600,
                                                           DEFAULT_BUDGET.scaled(8))))
        best = min(best, (time.process_time() - t0) / BATCH)
        said = sorted(d.code for d in sink.items)
    return best, said


@pytest.mark.parametrize("family", list(SIZES))
def test_the_checks_grow_as_n_log_n(family):
    make, (lo, hi) = SIZES[family]

    @settings(max_examples=2, deadline=None,
              suppress_health_check=list(HealthCheck))
    @given(n=st.integers(lo, hi))
    def law(n):
        small, big = _drawing(make(n)), _drawing(make(4 * n))
        t1, said1 = _check_cpu(small, 3)
        t4, said4 = _check_cpu(big, 2)
        assert "W0521" not in said1 + said4          # every check ran to its end
        assert t4 < RATIO * t1, (family, n, t1, t4, t4 / t1)
    law()


boxes = st.lists(st.tuples(st.integers(0, 40), st.integers(0, 40), st.integers(0, 12),
                           st.integers(0, 12)), min_size=1, max_size=40)


@settings(max_examples=150, deadline=None)
@given(bs=boxes, pad=st.sampled_from([0.0, 0.5]), scale=st.sampled_from([1.0, 0.37]))
def test_box_groups_are_the_components_of_box_pairs(bs, pad, scale):
    """:func:`box_groups` (a segment tree, no pair list) labels each box with the least index
    of its component, exactly as the components of :func:`box_pairs`'s pairs do; on integer
    boxes (touching edges and corners, nested, equal) and scaled ones (0.1 s for 150)."""
    import numpy as np
    from aidl_lang.output.part.measure.nearby import box_groups, box_pairs, components
    B = np.array([(x, y, x + w, y + h) for x, y, w, h in bs], dtype=float) * scale
    p = box_pairs(B, pad)
    assert p.tolist() == sorted(p.tolist())      # rows sorted (W0512 walks them in order)
    want = components(len(B), [p[:, 0]], [p[:, 1]])
    assert np.array_equal(box_groups(B, pad), want)


def test_box_groups_of_nested_boxes_list_no_pairs():
    """3,000 nested boxes (4.5 million pairs, past :data:`MAX_PAIRS` for box_pairs) are one
    group, in far less than the pairs' work: under half the CPU seconds of a sort of as many
    numbers as there are pairs (the reference, timed beside it; the least of three runs of
    each: a fifth of one run each failed 2 of 3 quiet runs on 2026-11-29's machine, ratios
    of 3.3 to 4.6)."""
    import numpy as np
    from aidl_lang.output.part.measure.nearby import box_groups
    r = np.arange(1, 3001, dtype=float)
    B = np.column_stack([-r, -r, r, r])
    x = np.random.default_rng(1).random(3000 * 2999 // 2)
    t, ref = [], []
    for _ in range(3):
        t0 = time.process_time()
        g = box_groups(B)
        t.append(time.process_time() - t0)
        t0 = time.process_time()
        np.sort(x)
        ref.append(time.process_time() - t0)
    assert not g.any()
    assert min(t) < min(ref) / 2, (t, ref)


def test_a_moved_part_sums_its_columns_as_the_block_did():
    """sliding._moved (one np.add.at over the columns' entries) gives the rows and the row
    sums of sliding._block's dense block, on 100 random sparse matrices and their dense
    forms."""
    import numpy as np
    import scipy.sparse as sp
    from aidl_lang.solver.diagnosis.sliding import _block, _moved
    rng = np.random.default_rng(91)
    for _ in range(100):
        m, n = (int(v) for v in rng.integers(1, 30, 2))
        A = sp.random(m, n, density=float(rng.uniform(0.05, 0.5)),
                      random_state=int(rng.integers(1 << 30))).tocsc()
        cols = np.flatnonzero(rng.random(n) < 0.5)
        for J in (A, A.toarray()):
            rows, B = _block(J, cols)
            got_rows, got = _moved(J, cols)
            assert np.array_equal(rows, got_rows)
            assert np.allclose(got, B.sum(axis=1), rtol=1e-13, atol=1e-300)


def test_a_bound_grows_with_the_reference(monkeypatch):
    """tests/cpu_reference.py: a machine that runs the reference twice as slow gets twice the
    bound; a faster one keeps the bound as set."""
    import cpu_reference as R
    monkeypatch.setattr(R, "reference", lambda: 2 * R.REFERENCE_HERE)
    assert R.cpu_bound(3.0) == 6.0
    monkeypatch.setattr(R, "reference", lambda: R.REFERENCE_HERE / 2)
    assert R.cpu_bound(3.0) == 3.0
