"""A re-solve with the compiled system kept (what an edit or a live preview does) gives bit for
bit what a fresh solve gives, including when the held values change between solves (the
substitution is remembered per tape, keyed by the held values: docs/dev/performance.md)."""
from __future__ import annotations

import numpy as np
import pytest

from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver, run
from benchmarks.solver.families import FLAT, hierarchy


def _model(src: str):
    c = compile_source(src, "t.aidl", do_solve=False)
    assert c.ok, [d.message for d in c.sink.items]
    return c.model


def _start(s: Solver, start) -> None:
    """New starting guesses, as an edit gives them (``set_value``: pinned geometry keeps the
    values its own rows give it, as a fresh solver's does; since issue 48 the families'
    fixed geometry read by other rows is pinned too)."""
    for i, v in enumerate(start.tolist()):
        s.set_value(i, v)


def _fresh(src: str, x0):
    m = _model(src)
    m.x = list(x0)
    s = Solver(m)
    res = run(s)
    return res, s.x[:s.n_model].copy()


@pytest.mark.parametrize("family,n", [("rectangles", 48), ("ring", 48), ("linkage", 50)])
def test_a_kept_solver_re_solves_exactly_as_a_fresh_one(family, n):
    case = FLAT[family](n, seed=5)
    m = _model(case.source)
    x0 = np.asarray(m.x, dtype=float)
    s = Solver(m)
    first = run(s)
    assert first.converged
    rng = np.random.default_rng(1)
    for k in range(3):
        start = x0 + (rng.normal(0, 0.2, len(x0)) if k else 0.0)   # new starting guesses
        _start(s, start)
        again = run(s)
        ref, xref = _fresh(case.source, start)
        assert again.converged == ref.converged and again.iterations == ref.iterations
        assert np.array_equal(s.x[:s.n_model], xref)


@pytest.mark.parametrize("src", [hierarchy(30, seed=2).source,
                                 open("examples/telephone.aidl").read()],
                         ids=["hierarchy", "telephone"])
def test_a_hierarchical_re_solve_after_the_held_values_move_matches_a_fresh_solve(src):
    # parts are solved first and held while their assembly is solved: moving the starting
    # positions moves the held values too, so a remembered substitution must not be reused
    m = _model(src)
    x0 = np.asarray(m.x, dtype=float)
    s = Solver(m)
    assert run(s).converged
    rng = np.random.default_rng(3)
    for k in range(4):
        start = x0 + (rng.normal(0, 0.5, len(x0)) if k else 0.0)
        _start(s, start)
        again = run(s)
        ref, xref = _fresh(src, start)
        assert again.converged == ref.converged and again.iterations == ref.iterations
        assert np.array_equal(s.x[:s.n_model], xref)
