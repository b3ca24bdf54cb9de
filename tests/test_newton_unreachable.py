"""Newton stops at once when every row that is off has no entry for any unknown (no damping
can move it: ``newton.unreachable``), with exactly the result the 14 rejected tries gave."""
from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from hypothesis import given, settings, strategies as st

from aidl_lang.geometry.core.expr import Lin, Nl
from aidl_lang.solver.core import newton as newton_mod
from aidl_lang.solver.core.newton import newton, unreachable
from aidl_lang.solver.core.tape import Tape

N = 6


def _rows(data):
    """Rows over 6 parameters; each row uses parameters from its own subset."""
    rows = []
    for k in range(data.draw(st.integers(1, 6))):
        idx = data.draw(st.lists(st.integers(0, N - 1), min_size=1, max_size=3, unique=True))
        c = data.draw(st.integers(-3, 3))
        lin = Lin({i: float(data.draw(st.integers(-2, 2)) or 1) for i in idx}, float(c))
        rows.append(Nl("mul", (lin, lin)) if data.draw(st.booleans()) else lin)
    return rows


@settings(max_examples=80, deadline=None)
@given(data=st.data())
def test_stopping_early_gives_the_result_of_all_the_tries(data):
    rows = _rows(data)
    t = Tape(rows, N)
    x = np.asarray(data.draw(st.lists(st.integers(-2, 2).map(float), min_size=N, max_size=N)))
    cols = np.asarray(sorted(data.draw(st.sets(st.integers(0, N - 1), min_size=1))),
                      dtype=np.int64)
    a = newton(t, x, cols, max_iter=5)
    with pytest.MonkeyPatch.context() as m:
        m.setattr(newton_mod, "unreachable", lambda Js, F: False)
        b = newton(t, x, cols, max_iter=5)
    assert np.array_equal(a.x, b.x) and (a.converged, a.iterations) == \
        (b.converged, b.iterations) and a.residual == b.residual


def test_a_row_no_unknown_reaches_stops_newton_without_a_step(monkeypatch):
    # row 0 is off and uses only x2 (held); row 1 uses x0, x1 (free) and is already 0
    t = Tape([Lin({2: 1.0}, -5.0), Nl("mul", (Lin({0: 1.0}), Lin({1: 1.0})))], 3)
    x = np.array([0.0, 1.0, 2.0])
    calls = []
    monkeypatch.setattr(newton_mod._Step, "__call__",
                        lambda self, F, mu: calls.append(mu) or np.zeros(2))
    res = newton(t, x, np.array([0, 1]))
    assert not res.converged and res.iterations == 1 and res.residual == 3.0
    assert np.array_equal(res.x, x) and calls == []


def test_unreachable_dense_and_sparse_agree():
    F = np.array([1.0, 0.0, -2.0])
    J = np.array([[0.0, 0.0], [1.0, 2.0], [0.0, 0.0]])
    assert unreachable(J, F) and unreachable(sp.csr_matrix(J), F)
    J[2, 1] = 1e-300
    assert not unreachable(J, F) and not unreachable(sp.csr_matrix(J), F)
    assert not unreachable(J, np.zeros(3))
