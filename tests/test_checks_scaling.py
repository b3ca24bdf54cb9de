"""The shape checks grow as n log n on the families of outlines that were quadratic somewhere
(issue 91): concentric circles, nested squares, a chain of rectangles edge to edge, a plate
with a grid of holes, squares touching edge to edge on a grid, squares touching at their
corners.  A law over generated sizes: the CPU seconds of the check stage alone
(``check_drawing`` on the booleans' result, ``time.process_time``) at 4n over those at n stay
under :data:`RATIO`; n log n gives 4 to 5 at these sizes, n^2 gives 16 (before the fix,
concentric circles at 100 and 400: 41 ms and 2,379 ms, a ratio of 58; nested squares 14).

Cost: about 5 s of CPU for the whole file (two generated sizes per family, each compiled at n
and 4n, the check timed three times at n and twice at 4n, the least kept)."""
from __future__ import annotations

import time

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from aidl_lang.diagnostics import DiagnosticSink
from aidl_lang.limits import DEFAULT_BUDGET, Deadline, now
from aidl_lang.output import checks
from aidl_lang.pipeline import _compile, run_deep
from benchmarks import check_families as F

pytestmark = pytest.mark.timing

RATIO = 9.0        # t(4n) / t(n): n log n passes with margin, n^2 (16) fails

# family -> (its generator, the range n is drawn from)
SIZES = {
    "concentric": (F.concentric, (80, 120)),
    "concentric01": (lambda n: F.concentric(n, 0.1), (80, 120)),
    "nested": (F.nested, (110, 150)),
    "chain": (F.chain, (120, 180)),
    "grid": (F.grid, (300, 400)),
    "touching": (F.touching, (120, 180)),
    "corners": (F.corners, (50, 70)),
}


def _drawing(src: str):
    c = run_deep(lambda: _compile(DiagnosticSink(), src, "f.aidl", None, True,
                                  budget=DEFAULT_BUDGET.scaled(8), shape_checks=False))
    assert c.drawing is not None and c.ok, [(d.code, d.message) for d in c.sink.items]
    return c.drawing


def _check_cpu(drawing, runs: int) -> tuple[float, list]:
    """The least CPU seconds of ``runs`` runs of the shape checks on ``drawing``, and the
    codes they said."""
    best, said = float("inf"), []
    for _ in range(runs):
        sink = DiagnosticSink()
        t0 = time.process_time()
        run_deep(lambda: checks.check_drawing(drawing, sink, None,
                                              Deadline(now() + 600, DEFAULT_BUDGET.scaled(8))))
        best = min(best, time.process_time() - t0)
        said = sorted(d.code for d in sink.items)
    return best, said


@pytest.mark.parametrize("family", list(SIZES))
def test_the_checks_grow_as_n_log_n(family):
    make, (lo, hi) = SIZES[family]

    @settings(max_examples=2, deadline=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    @given(n=st.integers(lo, hi))
    def law(n):
        small, big = _drawing(make(n)), _drawing(make(4 * n))
        t1, said1 = _check_cpu(small, 3)
        t4, said4 = _check_cpu(big, 2)
        assert "W0521" not in said1 + said4          # every check ran to its end
        assert t4 < RATIO * t1, (family, n, t1, t4, t4 / t1)
    law()
