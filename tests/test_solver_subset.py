"""A tape cut out of the whole model's tape (``Tape.subset``, what the hierarchical solver does
for every attempt) is the tape a fresh compile of the same rows gives: the same arrays, and so
bit for bit the same residuals and Jacobians."""
from __future__ import annotations

import pathlib

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver
from aidl_lang.solver.core.tape import Tape
from benchmarks.solver.families import hierarchy

ROOT = pathlib.Path(__file__).resolve().parents[1]
ARRAYS = ("aff_rows", "a_row", "a_col", "a_val", "b", "l_row", "l_col", "l_val", "lconst",
          "leaf_node", "nl_rows", "nl_roots", "op", "a0", "a1", "level", "root_of",
          "root_choice", "marg")


def _solver(src: str, name: str = "t.aidl") -> Solver:
    c = compile_source(src, name, do_solve=False)
    assert c.ok, [d.message for d in c.sink.items]
    return Solver(c.model)


_SOURCES = {"hierarchy": hierarchy(12, seed=4).source,
            "bracket": (ROOT / "examples/bracket.aidl").read_text(),
            "telephone": (ROOT / "examples/telephone.aidl").read_text()}
_SOLVERS = {k: _solver(v) for k, v in _SOURCES.items()}


def _same(cut: Tape, fresh: Tape) -> None:
    assert cut.n_rows == fresh.n_rows and cut.n_nodes == fresh.n_nodes
    for name in ARRAYS:
        a, b = getattr(cut, name), getattr(fresh, name)
        assert a.dtype == b.dtype and np.array_equal(a, b), name
    assert [(g.op, g.uniq0, g.uniq1) for g in cut.groups] == \
        [(g.op, g.uniq0, g.uniq1) for g in fresh.groups]


@settings(max_examples=40, deadline=None)
@given(which=st.sampled_from(sorted(_SOLVERS)), data=st.data())
def test_a_cut_tape_equals_a_fresh_compile(which, data):
    s = _SOLVERS[which]
    n = len(s.rows.exprs)
    rows = np.asarray(sorted(data.draw(st.sets(st.integers(0, n - 1), min_size=0,
                                                max_size=min(n, 40)))), dtype=np.int64)
    cut = s.whole.subset(rows)
    fresh = Tape([s.rows.exprs[r] for r in rows], s.rows.n_params)
    _same(cut, fresh)
    rng = np.random.default_rng(len(rows))
    x = s.x + rng.normal(0, 0.5, len(s.x))
    assert np.array_equal(cut.evaluate(x), fresh.evaluate(x))
    ch = fresh.choose(x)
    assert np.array_equal(cut.choose(x), ch)
    cols = np.flatnonzero(s.free)
    if len(rows):
        a = cut.jacobian(x, cols, ch, dense=True)
        b = fresh.jacobian(x, cols, ch, dense=True)
        assert np.array_equal(a, b)
    if len(rows) == n:
        assert np.abs(cut.jacobian(x, cols, ch, dense=True)).sum() > 1.0    # not vacuous


@pytest.mark.parametrize("which", sorted(_SOLVERS))
def test_the_solver_compiles_each_expression_once(which, monkeypatch):
    """Every attempt's tape comes from the one whole-model compile."""
    c = compile_source(_SOURCES[which], "t.aidl", do_solve=False)
    walks = []
    init = Tape.__init__

    def counting(self, exprs, n_params):
        walks.append(len(exprs))
        init(self, exprs, n_params)
    monkeypatch.setattr(Tape, "__init__", counting)
    from aidl_lang.solver import run
    s = Solver(c.model)
    res = run(s)
    assert res.converged
    assert walks == [len(s.rows.exprs)]
    assert s.compiles >= 1


@pytest.mark.parametrize("which", sorted(_SOLVERS))
def test_the_whole_row_set_cut_out_is_the_whole_tape(which):
    s = _SOLVERS[which]
    n = len(s.rows.exprs)
    cut = s.whole.subset(np.arange(n))
    _same(cut, s.whole)
    x = s.x + 0.1
    cols = np.flatnonzero(s.free)
    J = cut.jacobian(x, cols, cut.choose(x), dense=True)
    assert np.array_equal(J, s.whole.jacobian(x, cols, cut.choose(x), dense=True))
    assert np.abs(J).sum() > 1.0


@settings(max_examples=25, deadline=None)
@given(which=st.sampled_from(sorted(_SOLVERS)), seed=st.integers(0, 1000))
def test_the_reduced_jacobian_is_j_keep_times_s(which, seed):
    """``Tape.jacobian(reduction=...)`` (summed from the entries) equals ``J[keep] @ S``."""
    from aidl_lang.solver.core.reduce import reduce
    s = _SOLVERS[which]
    rows = np.arange(len(s.rows.exprs))
    t = s.whole
    cols = s._cols(list(np.flatnonzero(s.free[:s.n_model])), rows)
    red = reduce(t, s.x, cols, s.scale[cols])
    assert red is not None
    x = s.x + np.random.default_rng(seed).normal(0, 0.3, len(s.x))
    ch = t.choose(x)
    full = t.jacobian(x, cols, ch)
    want = (full[red.keep] @ red.S).toarray()
    got = t.jacobian(x, cols, ch, dense=True, reduction=red)
    assert got.shape == want.shape and np.array_equal(got, want)
    sparse = t.jacobian(x, cols, ch, reduction=red)
    assert np.array_equal(sparse.toarray(), want)
    assert np.abs(want).sum() > 0


def test_a_very_deep_row_compiles_like_a_shallow_one():
    """A row nested deeper than Python's recursion limit falls back to the explicit stack and
    gives the same tape as the same row nested shallowly would evaluate."""
    import sys
    from aidl_lang.geometry.core.expr import func, var
    depth = sys.getrecursionlimit() + 500
    e = var(0)
    for _ in range(depth):
        e = func("sin", e)                      # sin(sin(...sin(x0)))
    shallow = func("sin", func("sin", var(1)))
    t = Tape([shallow, e, var(0)], 2)
    x = np.array([0.3, 0.3])
    want = 0.3
    for _ in range(depth):
        want = np.sin(want)
    F = t.evaluate(x)
    assert F[1] == want and F[0] == np.sin(np.sin(0.3)) and F[2] == 0.3
    assert t.n_nodes == depth + 1 + 3
    cut = t.subset(np.array([1]))
    assert cut.evaluate(x)[0] == want
