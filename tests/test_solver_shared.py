"""The compile that walks shared subexpressions once (``Tape(..., shared=True)``,
``Tape._compile_shared``) gives the same tape as the row-by-row walk: every array equal, the
same node groups, so the same residuals and Jacobians bit for bit.  Law checked on random
expression DAGs (nodes shared within and across rows, every operator and arity the compile
knows) and on the generated 60-structure model; the errors are the same too."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from aidl_lang.geometry.core.expr import Lin, Nl
from aidl_lang.solver import Solver
from aidl_lang.solver.core.tape import Tape, TapeError
from benchmarks.solver.families import hierarchy

ARRAYS = ("aff_rows", "a_row", "a_col", "a_val", "b", "l_row", "l_col", "l_val", "lconst",
          "leaf_node", "nl_rows", "nl_roots", "op", "a0", "a1", "level", "root_of", "marg",
          "root_choice")
UNARY = ["sin", "cos", "atan", "sqrt", "abs", "exp"]
BINARY = ["add", "mul", "div", "atan2", "pow"]
N_PARAMS = 6


def _same(t1: Tape, t2: Tape) -> None:
    for k in ARRAYS:
        a, b = getattr(t1, k), getattr(t2, k)
        assert a.dtype == b.dtype and np.array_equal(a, b), k
    assert (t1.n_rows, t1.n_nodes, t1.n_choices) == (t2.n_rows, t2.n_nodes, t2.n_choices)
    assert [(g.op, g.uniq0, g.uniq1) for g in t1.groups] == \
        [(g.op, g.uniq0, g.uniq1) for g in t2.groups]
    for g1, g2 in zip(t1.groups, t2.groups):
        assert np.array_equal(g1.idx, g2.idx) and np.array_equal(g1.a0, g2.a0)


@st.composite
def dags(draw):
    """Rows over a pool of expression nodes, each new node's arguments drawn from the pool
    (so nodes are shared within rows and across rows)."""
    pool = []
    for _ in range(draw(st.integers(1, 6))):
        terms = {draw(st.integers(0, N_PARAMS - 1)): draw(st.sampled_from([1.0, -1.0, 0.5]))
                 for _ in range(draw(st.integers(0, 3)))}
        pool.append(Lin(terms, draw(st.sampled_from([0.0, 1.5, -2.0]))))
    for _ in range(draw(st.integers(0, 14))):
        kind = draw(st.sampled_from(["unary", "binary", "one", "minmax"]))
        pick = lambda: pool[draw(st.integers(0, len(pool) - 1))]  # noqa: E731
        if kind == "unary":
            pool.append(Nl(draw(st.sampled_from(UNARY)), (pick(),)))
        elif kind == "binary":
            pool.append(Nl(draw(st.sampled_from(BINARY)), (pick(), pick())))
        elif kind == "one":                       # a binary operator given one argument
            pool.append(Nl(draw(st.sampled_from(BINARY)), (pick(),)))
        else:
            k = draw(st.integers(1, 5))
            pool.append(Nl(draw(st.sampled_from(["min", "max"])),
                           tuple(pick() for _ in range(k))))
    n_rows = draw(st.integers(1, 10))
    return [pool[draw(st.integers(0, len(pool) - 1))] for _ in range(n_rows)]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rows=dags(), seed=st.integers(0, 1000))
def test_shared_compile_equals_the_row_by_row_compile(rows, seed):
    plain = Tape(rows, N_PARAMS, shared=False)
    shared = Tape(rows, N_PARAMS, shared=True)
    _same(plain, shared)
    x = np.random.default_rng(seed).uniform(0.2, 2.0, N_PARAMS)
    cols = np.arange(N_PARAMS)
    with np.errstate(all="ignore"):
        F1, F2 = plain.evaluate(x), shared.evaluate(x)
        assert np.array_equal(F1, F2, equal_nan=True)
        ch = plain.choose(x)
        assert np.array_equal(ch, shared.choose(x))
        J1 = plain.jacobian(x, cols, ch, dense=True)
        J2 = shared.jacobian(x, cols, ch, dense=True)
    assert np.array_equal(J1, J2, equal_nan=True)


def test_shared_compile_of_a_generated_model_equals_the_plain_one():
    s = Solver(_model(hierarchy(60, seed=7).source))
    plain = Tape(s.rows.exprs, s.rows.n_params, shared=False)
    shared = Tape(s.rows.exprs, s.rows.n_params, shared=True)
    _same(plain, shared)
    assert len(s.rows.exprs) < 1024 and plain.n_nodes > 5000


def test_a_deep_expression_falls_back_to_the_row_by_row_walk():
    e = Lin({0: 1.0})
    for _ in range(3000):                     # deeper than the recursion limit
        e = Nl("sin", (e,))
    t = Tape([e, Lin({1: 1.0}, -1.0)], 2, shared=True)
    assert t.n_nodes == 3001
    assert t.evaluate(np.array([0.3, 1.0]))[0] == pytest.approx(_nested_sin(0.3, 3000))


def _nested_sin(v, n):
    for _ in range(n):
        v = np.sin(v)
    return v


@pytest.mark.parametrize("bad, message", [
    (Nl("frob", (Lin({0: 1.0}),)), "unknown operator `frob`"),
    (Nl("min", ()), "operator `min` with no arguments"),
    (Nl("add", (Lin({0: 1.0}),) * 3), "operator `add` with 3 arguments"),
    (Nl("sin", ("x",)), "cannot compile str into a residual"),
])
def test_the_shared_compile_rejects_what_the_plain_one_rejects(bad, message):
    for shared in (False, True):
        with pytest.raises(TapeError, match=message):
            Tape([Lin({0: 1.0}), bad], 2, shared=shared)


def _model(src):
    from aidl_lang.pipeline import compile_source
    c = compile_source(src, "t.aidl", do_solve=False)
    assert c.ok
    return c.model
