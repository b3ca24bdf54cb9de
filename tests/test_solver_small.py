"""The small-system path (solver/core/small.py) computes the general path's numbers bit for bit.

Laws (hypothesis, on random rows of affine pairs, fixed values, general affine rows and
nonlinear trees of +, *, /, sqrt and abs with shared subexpressions):

* ``SmallTape.evaluate`` equals ``Tape.evaluate``;
* ``reduce`` on a ``SmallTape`` equals ``reduce`` on the ``Tape`` (every array), also when
  the substitution and the class weights come from the caches after an edit;
* the reduced Jacobian summed by the plan equals ``Tape.jacobian(dense=True, reduction=...)``;
* ``newton`` on a ``SmallTape`` returns the general ``newton``'s point, step count and
  residual;
* whole solves (sketch families, every bundled example) give the same parameters and step
  counts with and without the small path.
"""
from __future__ import annotations

import pathlib
import warnings

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from aidl_lang.geometry.core.expr import Lin, Nl
from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver, run
from aidl_lang.solver.core.newton import newton, solve_dense
from aidl_lang.solver.core.reduce import reduce
from aidl_lang.solver.core.small import SMALL_ROWS, SmallTape, small_tape
from aidl_lang.solver.core.tape import Tape

from benchmarks.solver.families import FLAT

ROOT = pathlib.Path(__file__).resolve().parents[1]
N = 7          # parameters of the random systems

coef = st.sampled_from([1.0, -1.0, 2.0, 0.5, -0.25, 3.0, 0.0])
const = st.floats(-5, 5, allow_nan=False).map(lambda v: round(v, 3))


@st.composite
def lin(draw, max_terms=3):
    k = draw(st.integers(0, max_terms))
    idx = draw(st.lists(st.integers(0, N - 1), min_size=k, max_size=k, unique=True))
    return Lin({i: draw(coef) for i in idx}, draw(const))


@st.composite
def tree(draw, depth=3):
    if depth == 0 or draw(st.integers(0, 3)) == 0:
        return draw(lin())
    op = draw(st.sampled_from(["add", "mul", "div", "sqrt", "abs", "square"]))
    a = draw(tree(depth - 1))
    if op == "square":                      # the same object twice: a shared node
        return Nl("mul", (a, a))
    if op in ("sqrt", "abs"):
        return Nl(op, (a,))
    return Nl(op, (a, draw(tree(depth - 1))))


@st.composite
def row(draw):
    kind = draw(st.integers(0, 4))
    i, j = draw(st.lists(st.integers(0, N - 1), min_size=2, max_size=2, unique=True))
    a = draw(st.sampled_from([1.0, -2.0, 0.5]))
    if kind == 0:                           # an equal pair: a x_i - a x_j + c
        return Lin({i: a, j: -a}, draw(const))
    if kind == 1:                           # a fixed value
        return Lin({i: a}, draw(const))
    if kind == 2:
        return draw(lin())
    return draw(tree())


@st.composite
def system(draw):
    rows = draw(st.lists(row(), min_size=1, max_size=10))
    x = np.array(draw(st.lists(st.floats(-3, 3, allow_nan=False), min_size=N, max_size=N)))
    cols = np.array(sorted(draw(st.sets(st.integers(0, N - 1), min_size=1))), dtype=np.int64)
    scale = np.array(draw(st.lists(st.sampled_from([1.0, 100.0, 0.5]), min_size=len(cols),
                                   max_size=len(cols))))
    return rows, x, cols, scale


def _same_reduction(a, b):
    assert (a is None) == (b is None)
    if a is None:
        return
    for f in ("zc", "t", "keep", "z0", "scale"):
        u, v = getattr(a, f), getattr(b, f)
        assert u.dtype == v.dtype and np.array_equal(u, v), f
        assert np.array_equal(np.signbit(u), np.signbit(v)), f


@settings(max_examples=80, deadline=None)
@given(system())
def test_small_tape_is_the_tape(sys_):
    with np.errstate(all="ignore"):         # random rows overflow; the laws hold regardless
        _small_tape_is_the_tape(*sys_)


def _small_tape_is_the_tape(rows, x, cols, scale):
    big, small = Tape(rows, N), SmallTape(rows, N)
    assert np.array_equal(small.evaluate(x), big.evaluate(x), equal_nan=True)
    ra, rb = reduce(small, x, cols, scale), reduce(big, x, cols, scale)
    _same_reduction(ra, rb)
    # the reduced Jacobian, summed by the plan (or the plain one without a substitution)
    colpos = dict(zip(cols.tolist(), range(len(cols))))
    keep = rb.keep.tolist() if rb is not None else list(range(len(rows)))
    nz = len(rb.z0) if rb is not None else len(cols)
    plans = [small.plan(r, colpos, None if rb is None else ra.zc_l) for r in keep]
    _, V = small.values(x.tolist(), keep)
    J = np.array(small.jacobian_rows(keep, V, plans, nz)).reshape(len(keep), nz)
    ch = np.zeros(0, dtype=np.int64)
    want = big.jacobian(x, cols, ch, dense=True, reduction=rb)
    assert np.array_equal(J, want, equal_nan=True)
    # Newton: the same iterates
    a = newton(small, x, cols, scale, ch, max_iter=20, reduction=ra)
    b = newton(big, x, cols, scale, ch, max_iter=20, reduction=rb)
    assert np.array_equal(a.x, b.x, equal_nan=True)
    assert (a.iterations, a.converged) == (b.iterations, b.converged)
    assert a.residual == b.residual or (np.isnan(a.residual) and np.isnan(b.residual))


@pytest.mark.parametrize("p", [0.0, -0.0, 1.0, -2.0])
def test_a_quotient_by_an_exact_zero_differentiates_without_a_warning(p):
    """``x0 / x1`` at ``x1 = 0`` (divided by 1e-300 instead): d/dx0 = 1e300 and
    d/dx1 = -(1/q)(p/q), 0 for p = 0 (it was 0/0 = NaN with a RuntimeWarning, q*q underflowing
    to 0: phone_handset's perturbed solve in test_solver_batch) and -inf by sign otherwise,
    the same on both tapes; Newton from p = 0 stops at once, solved."""
    rows = [Nl("div", (Lin({0: 1.0}, 0.0), Lin({1: 1.0}, 0.0))), Lin({2: 1.0}, -1.0)]
    x, cols, ch = np.array([p, 0.0, 1.0]), np.arange(3), np.zeros(0, dtype=np.int64)
    big, small = Tape(rows, 3), SmallTape(rows, 3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        J = big.jacobian(x, cols, ch, dense=True)
        _, V = small.values(x.tolist(), [0])
        plan = small.plan(0, dict(zip(range(3), range(3))), None)
        Js = small.jacobian_rows([0], V, [plan], 3)
        runs = [newton(t, x, cols, None, ch) for t in (big, small)] if p == 0 else []
    assert J[0, 0] == 1.0 / 1e-300 and J[0, 2] == 0.0
    assert J[0, 1] == (0.0 if p == 0 else -np.inf * np.sign(p))
    assert np.array_equal(np.asarray(Js).reshape(-1), J[0])
    for r in runs:
        assert r.converged and r.iterations == 0 and np.array_equal(r.x, x)


@settings(max_examples=30, deadline=None)
@given(system(), st.lists(st.floats(-3, 3, allow_nan=False), min_size=3, max_size=3),
       st.sampled_from([1.0, 100.0]))
def test_cached_substitutions_equal_fresh_ones(sys_, edits, s2):
    """After edits of held values and a change of scale, the remembered substitution and
    class weights (on either tape) equal those of a fresh tape."""
    with np.errstate(all="ignore"):
        _cached_equal_fresh(*sys_, edits, s2)


def _cached_equal_fresh(rows, x, cols, scale, edits, s2):
    tapes = [Tape(rows, N), SmallTape(rows, N)]
    held = np.setdiff1d(np.arange(N), cols)
    for k, v in enumerate(edits + [None]):
        xx = x.copy()
        if v is not None and len(held):
            xx[held[k % len(held)]] = v
        sc = scale if k % 2 else scale * s2
        fresh = reduce(Tape(rows, N), xx, cols, sc)
        for t in tapes:
            _same_reduction(reduce(t, xx, cols, sc), fresh)


def _solve_both(model):
    x0 = list(model.x)
    out = []
    for small in (True, False):
        model.x = list(x0)
        s = Solver(model)
        s.use_small = small
        r = run(s)
        cold = (list(model.x), r.iterations, r.converged)
        s.x[:s.n_model] = x0                # a warm re-solve on the same solver
        r = run(s)
        out.append((cold, (list(model.x), r.iterations, r.converged), s))
    model.x = x0
    return out


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(sorted(FLAT)), st.integers(8, 24), st.integers(0, 50))
def test_small_sketches_solve_the_same_with_the_small_path(family, n, seed):
    c = compile_source(FLAT[family](n, seed=seed).source, "t.aidl", do_solve=False)
    (ca, wa, sa), (cb, wb, _) = _solve_both(c.model)
    assert ca == cb and wa == wb                # the same floats, the same step counts
    assert ca[2]
    if len(sa.rows.exprs) <= SMALL_ROWS:        # not vacuous: the small path was taken
        assert any(isinstance(t, SmallTape) for t in sa._tapes.values())


@pytest.mark.parametrize("path", sorted((ROOT / "examples").glob("*.aidl")), ids=lambda p: p.stem)
def test_examples_solve_the_same_with_the_small_path(path):
    c = compile_source(path.read_text(), str(path), do_solve=False)
    (ca, wa, sa), (cb, wb, _) = _solve_both(c.model)
    assert ca == cb and wa == wb
    if path.stem in ("bottle_opener", "gear", "phone_handset", "telephone"):
        assert any(isinstance(t, SmallTape) for t in sa._tapes.values())     # not vacuous


@pytest.mark.parametrize("e", [Nl("sin", (Lin({0: 1.0}),)),
                               Nl("min", (Lin({0: 1.0}), Lin({1: 1.0}))),
                               Nl("pow", (Lin({0: 1.0}), Lin({}, 2.0))),
                               Nl("add", (Lin({0: 1.0}),))])
def test_other_operators_are_left_to_the_tape(e):
    assert small_tape([Lin({0: 1.0}), e], 2) is None
    assert small_tape([Lin({0: 1.0}, float(i)) for i in range(SMALL_ROWS + 1)], 2) is None
    assert isinstance(small_tape([Lin({0: 1.0}), Nl("sqrt", (Lin({1: 1.0}),))], 2), SmallTape)


def test_a_small_tape_hands_the_rest_to_the_tape():
    rows = [Lin({0: 1.0, 1: -1.0}), Nl("mul", (Lin({0: 1.0}), Lin({1: 1.0})))]
    s = SmallTape(rows, 2)
    x, cols = np.array([1.5, -2.0]), np.array([0, 1])
    assert np.array_equal(s.jacobian(x, cols, dense=True), [[1.0, -1.0], [-2.0, 1.5]])
    assert s.subset(np.array([1])).n_rows == 1


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 6), st.integers(0, 10_000))
def test_solve_dense_is_numpy_solve(m, seed):
    rng = np.random.default_rng(seed)
    M, b = rng.normal(size=(m, m)), rng.normal(size=m)
    assert np.array_equal(solve_dense(M, b), np.linalg.solve(M, b))
    with pytest.raises(np.linalg.LinAlgError):
        solve_dense(np.zeros((m, m)), b)


def _has_other_op(e) -> bool:
    if isinstance(e, Lin):
        return False
    return e.op not in ("add", "mul", "div", "sqrt", "abs") or any(map(_has_other_op, e.args))


def test_rows_the_small_path_cannot_take_are_marked_from_the_whole_tape():
    """With the whole tape compiled, every row with another operator (a bounding box's
    min/max) is marked at once, and a row set holding one is left to the tape."""
    from benchmarks.solver.families import hierarchy
    c = compile_source(hierarchy(10, seed=3).source, "t.aidl", do_solve=False)
    s = Solver(c.model)
    exprs = s.rows.exprs
    want = {r for r, e in enumerate(exprs) if _has_other_op(e)}
    assert want and len(want) < len(exprs)
    bad: set = set()
    r = min(want)
    assert small_tape(exprs, s.rows.n_params, np.array([r]), bad, s.whole) is None
    assert bad - {-1} == want
    fine = [r for r in range(len(exprs)) if r not in want][:5]
    assert isinstance(small_tape(exprs, s.rows.n_params, np.array(fine), bad, s.whole),
                      SmallTape)
    bad2: set = set()                         # without the whole tape: found by the walk
    assert small_tape(exprs, s.rows.n_params, np.array([r]), bad2) is None
    assert bad2 == {r}
