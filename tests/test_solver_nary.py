"""An n-ary ``min``/``max`` is one tape node (its branch: the position of the chosen argument).
It must be the balanced chain of binary selections it replaced (``q if q < p else p``: ties go
to the earlier argument), value for value, branch for branch and Jacobian for Jacobian, and
agree with the expression evaluator."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from aidl_lang.geometry.core.expr import Lin, Nl, evaluate
from aidl_lang.solver.core.tape import Tape

N = 5      # parameters


def _chain(op: str, args: list):
    """The balanced binary tree the compiler used to build (pairs, the odd one carried)."""
    while len(args) > 1:
        nxt = [Nl(op, (args[j], args[j + 1])) for j in range(0, len(args) - 1, 2)]
        if len(args) % 2:
            nxt.append(args[-1])
        args = nxt
    return args[0]


_leaf = st.builds(lambda i, a, c: Lin({i: float(a)}, float(c)),
                  st.integers(0, N - 1), st.integers(-2, 2), st.integers(-2, 2))
# small integers: ties between arguments are frequent
_x = st.lists(st.integers(-2, 2).map(float), min_size=N, max_size=N).map(np.asarray)


@settings(max_examples=150, deadline=None)
@given(op=st.sampled_from(["min", "max"]), leaves=st.lists(_leaf, min_size=2, max_size=9),
       x=_x, x2=_x, scale=_leaf)
def test_nary_min_max_equals_the_binary_chain(op, leaves, x, x2, scale):
    nary = Nl("mul", (Nl(op, tuple(leaves)), scale))      # inside a row, with an adjoint != 1
    chain = Nl("mul", (_chain(op, list(leaves)), scale))
    a, b = Tape([nary, nary], N), Tape([chain, chain], N)
    assert a.n_choices == 2 and a.n_nodes <= b.n_nodes
    Fa, Fb = a.evaluate(x), b.evaluate(x)
    assert np.array_equal(Fa, Fb)
    assert Fa[0] == evaluate(nary, x)
    # the branch: the first smallest (min) / largest (max) argument, as Python's min/max pick
    vals = [evaluate(e, x) for e in leaves]
    first = (min if op == "min" else max)(range(len(vals)), key=vals.__getitem__)
    ca, cb = a.choose(x), b.choose(x)
    assert ca.dtype == np.int64 and ca.tolist() == [first, first]
    rec = np.full(a.n_choices, -1, dtype=np.int64)       # one pass: values and branches
    assert np.array_equal(a.evaluate(x, record=rec), Fa) and np.array_equal(rec, ca)
    # frozen at those branches, elsewhere: the chosen argument's value, not the true min/max
    assert np.array_equal(a.evaluate(x2, ca), b.evaluate(x2, cb))
    assert a.evaluate(x2, ca)[0] == evaluate(leaves[first], x2) * evaluate(scale, x2)
    cols = np.arange(N)
    for ch_a, ch_b in ((ca, cb), (None, None)):
        Ja = a.jacobian(x2, cols, ch_a, dense=True)
        Jb = b.jacobian(x2, cols, ch_b, dense=True)
        assert np.array_equal(Ja, Jb)
        assert np.array_equal(a.jacobian(x2, cols, ch_a).toarray(), Ja)


@settings(max_examples=60, deadline=None)
@given(leaves=st.lists(_leaf, min_size=2, max_size=7), x=_x, data=st.data())
def test_a_cut_of_nary_rows_equals_a_fresh_compile(leaves, x, data):
    """Rows mixing n-ary min/max, binary ones and affine rows: any row subset cut from the
    whole tape is the fresh compile of those rows (the arguments' run ``marg`` shifted)."""
    rows = [Nl("min", tuple(leaves)), leaves[0], Nl("max", (leaves[-1], leaves[0])),
            Nl("add", (Nl("max", tuple(reversed(leaves))), Nl("min", tuple(leaves[:2])))),
            Nl("mul", (leaves[1], leaves[0]))]
    whole = Tape(rows, N)
    keep = sorted(data.draw(st.sets(st.integers(0, len(rows) - 1))))
    cut = whole.subset(np.asarray(keep, dtype=np.int64))
    fresh = Tape([rows[r] for r in keep], N)
    for name in ("op", "a0", "a1", "level", "root_of", "marg", "root_choice", "leaf_node"):
        assert np.array_equal(getattr(cut, name), getattr(fresh, name)), name
    assert np.array_equal(cut.evaluate(x), fresh.evaluate(x))
    assert np.array_equal(cut.choose(x), fresh.choose(x))
    cols = np.arange(N)
    ch = fresh.choose(x)
    assert np.array_equal(cut.jacobian(x, cols, ch, dense=True),
                          fresh.jacobian(x, cols, ch, dense=True))


def test_nan_argument_picks_the_first_argument():
    nan = Lin({}, float("nan"))
    t = Tape([Nl("min", (Lin({0: 1.0}), nan, Lin({}, -5.0)))], 1)
    assert t.choose(np.zeros(1)).tolist() == [0]


def _depth(e) -> int:
    return 0 if isinstance(e, Lin) else 1 + max(_depth(a) for a in e.args)


@settings(max_examples=40, deadline=None)
@given(leaves=st.lists(_leaf, min_size=2, max_size=6), ops=st.lists(
    st.sampled_from(["add", "mul", "sin", "min", "max"]), min_size=1, max_size=12))
def test_levels_are_depths_by_array_passes_and_by_the_ordered_pass(leaves, ops):
    """A node's level is its depth (leaves 0); the array relaxation and the fallback pass in
    node order (used past _LEVEL_PASSES levels) give the same levels."""
    import aidl_lang.solver.core.tape as tape_mod
    e = leaves[0]
    for i, op in enumerate(ops):
        other = leaves[i % len(leaves)]
        e = Nl(op, (e,)) if op == "sin" else Nl(op, (e, other) if op in ("add", "mul")
                                                 else (other, e, leaves[-1]))
    rows = [e, Nl("min", tuple(leaves)), Nl("add", (e, leaves[1]))]
    t = Tape(rows, N)
    assert t.level[t.nl_roots].tolist() == [_depth(r) for r in rows]
    with pytest.MonkeyPatch.context() as m:
        m.setattr(tape_mod, "_LEVEL_SMALL", 0)          # array passes, even for small tapes
        relaxed = Tape(rows, N).level
        m.setattr(tape_mod, "_LEVEL_PASSES", 1)         # ... stopped early, then the pass
        assert np.array_equal(Tape(rows, N).level, relaxed)
    assert np.array_equal(relaxed, t.level)


def test_min_without_arguments_is_a_tape_error():
    from aidl_lang.solver.core.tape import TapeError
    with pytest.raises(TapeError, match="no arguments"):
        Tape([Nl("max", ())], 1)
