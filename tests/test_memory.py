"""Memory per structure (issue 26, item 5): the exact-outline recovery, the largest transient
of a compile of thousands of structures (``benchmarks/compile/memory_per_structure.py``), works in
blocks whose size does not grow with the drawing."""
from __future__ import annotations

import tracemalloc

import numpy as np

from aidl_lang.output.part.edges import exact


def chords(m: int):
    """``m`` chords of 32-gons of radius 1 mm, 3 mm apart (what 2,000 circles give)."""
    k = np.arange(m)
    c, j = k // 32, k % 32
    t0, t1 = 2 * np.pi * j / 32, 2 * np.pi * (j + 1) / 32
    A = np.c_[3.0 * c + np.cos(t0), np.sin(t0)]
    B = np.c_[3.0 * c + np.cos(t1), np.sin(t1)]
    return A, B, c.astype(np.int64)


def test_recovery_transients_stay_bounded_however_many_chords():
    """128,000 chords (4,000 circles): building the chord grid and matching every edge to its
    chord takes ~15 MiB beyond the arrays themselves (all at once it was ~125 MiB: the
    samples of every chord, then 1,000,000 candidate pairs at a time); the answer is the same."""
    A, B, C = chords(128_000)
    P, Q = A[::-1].copy(), B[::-1].copy()
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        grid = exact._Grid(A, B, C)
        cid = grid.match(P, Q, exact.MATCH_TOL)
        held = tracemalloc.get_traced_memory()[0] - before
        peak = tracemalloc.get_traced_memory()[1] - before
    finally:
        tracemalloc.stop()
    assert np.array_equal(cid, C[::-1])
    MiB = 1024 * 1024
    assert held < 20 * MiB                   # the grid itself: its samples' keys and chords
    assert peak - held < 30 * MiB, (peak / MiB, held / MiB)   # main before: 125 MiB
