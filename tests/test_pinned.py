"""Geometry pinned in its structure's frame adds no unknowns (issue 38, solver/system.py
`pinned`): the solve, the degrees of freedom, the redundant constraints (W0401), what slides
and every diagnostic are those of the solve that keeps the pinned geometry as unknowns held by
its rows (``Solver.pinning`` off), on the gear pair and on generated programs mixing pinned,
partly pinned, doubly fixed and free geometry across structures."""
from __future__ import annotations

import contextlib
import pathlib

import numpy as np
from hypothesis import given, settings, strategies as st

from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver, diagnose as D
from aidl_lang.solver.system import pinned

ROOT = pathlib.Path(__file__).resolve().parents[1]


@contextlib.contextmanager
def _unpinned():
    Solver.pinning = False
    try:
        yield
    finally:
        Solver.pinning = True


def _facts(c) -> dict:
    """What a user sees of a compile: diagnostics, solved values, --dof, W0401, sliding."""
    out = {"diags": [(d.code, d.message) for d in c.sink.items], "ok": c.ok}
    if c.solve is None or not c.solve.converged:
        return out
    sv = c.solve.solver
    out["x"] = np.asarray(c.model.x)
    out["dof"] = [(d.structure.path, d.unknowns, d.rank, d.floating)
                  for d in D.degrees_of_freedom(sv)]
    out["count"] = [(d.structure.path, d.unknowns, d.rank)
                    for d in D.degrees_of_freedom(sv, floating=False)]
    out["redundant"] = sorted((r.constraint.describe(), r.partly,
                               sorted(b.describe() for b in r.by))
                              for r in D.redundancies(sv))
    sl = D.sliding(sv)
    out["sliding"] = ([(t.path, a) for t, a in sl.placement], [(t.path, a) for t, a in sl.features])
    return out


def _same(src: str, name: str = "t.aidl") -> tuple:
    """Compile ``src`` with and without pinning; assert everything equal; return both."""
    new = compile_source(src, name)
    with _unpinned():
        old = compile_source(src, name)
    a, b = _facts(new), _facts(old)
    assert a.keys() == b.keys()
    for k in a:
        if k == "x":
            assert np.max(np.abs(a[k] - b[k]), initial=0.0) <= 1e-9
        else:
            assert a[k] == b[k], k
    return new, old


def test_gear_pair_teeth_add_no_unknowns():
    src = (ROOT / "examples" / "gear_pair.aidl").read_text()
    new, old = _same(src, str(ROOT / "examples" / "gear_pair.aidl"))
    assert (old.solve.n_unknowns, old.solve.n_equations) == (6658, 6656)
    # left: the frames and the few points tied across structures (hub centers, axes, bores)
    assert new.solve.n_unknowns == 34 and new.solve.n_equations == 32
    sv = new.solve.solver
    rings = [s for s in new.model.structures if s.name == "teeth_ring"]
    assert all(sv.free[s.fx] and sv.free[s.fy] for s in rings)     # the frames stay unknowns
    assert sum(sv.pinned_by.get(id(s), 0) for s in rings) == 6658 - 34   # all in the rings


def test_only_whole_trees_of_affine_rows_pin():
    """A point fixed twice (a dependent row), a point a nonlinear row reads and a point fixed
    across a frame are not pinned; a lone ``Fixed`` point and an arc fixed by its center are."""
    src = """solid top {
    body = Rectangle(center=(0, 0), width=40, height=30)
    solid a {
        p = Point(1, 2)
        Fixed(p)
        q = Point(3, 4)
        Fixed(q)
        Fixed(q)
        r = Point(5, 6)
        Fixed(r)
        s = Point(7, 8)
        Distance(r, s, 3)
        arc = Arc(center=(0, 0), radius=4, start_angle=0 deg, end_angle=90 deg)
        Fixed(arc.center)
    }
    Fixed(a.q)
}
"""
    new, _ = _same(src)
    m, sv = new.model, new.solve.solver
    labels = {m.param_label[v] for v, _ in sv.pins}
    assert {"p.x", "p.y", "center.x", "center.y", "start.x", "start.y", "end.x",
            "end.y"} <= labels
    assert not labels & {"q.x", "q.y", "r.x", "r.y", "s.x", "s.y"}
    # a pinned value satisfies its row exactly
    for v, r in sv.pins:
        e = sv.rows_built.exprs[r]
        assert e.const + sum(c * sv.x[i] for i, c in e.terms.items()) == 0.0


_PIECE = st.sampled_from([
    "Fixed(c.center)",
    "Fixed(c)",
    "Fixed(arc.center)",
    "Fixed(arc)",
    "Fixed(l)",
    "Fixed(l.start)",
    "l.end.x == l.start.x + 6",
    "Horizontal(l)",
    "Distance(c.center, arc.center, 9)",
    "c.center.y == 2",
])
_PARENT = st.sampled_from([
    "AlignCenterX({k}, body)",
    "CenterInside({k}, body)",
    "Fixed({k})",
    "{k}.c.center == body.center + (3, 1)",
    "Inside({k}, body)",
    "",
])


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.lists(_PIECE, max_size=4), _PARENT), min_size=1, max_size=3),
       st.booleans())
def test_pinned_solve_equals_the_unpinned_one(kids, fixed_body):
    """Random structures of pinned, partly pinned and free geometry under a parent relating
    them: the same diagnostics, values, counts, W0401 and sliding with and without pinning."""
    body = ["body = Rectangle(center=(0, 0), width=60, height=40)"]
    if fixed_body:
        body.append("Fixed(body)")
    for i, (pieces, rel) in enumerate(kids):
        k = f"k{i}"
        inner = [f"c = Circle(center=({i * 3 - 4}, 1), radius=2)",
                 f"arc = Arc(center=({i * 3}, -2), radius=3, start_angle=10 deg, end_angle=120 deg)",
                 f"l = Line(({i - 8}, -5), ({i - 2}, -5))", *pieces]
        body.append(f"solid {k} {{\n        " + "\n        ".join(inner) + "\n    }")
        if rel:
            body.append(rel.format(k=k))
    src = "solid top {\n    " + "\n    ".join(body) + "\n}\n"
    _same(src)


def test_pinned_needs_no_walk_without_candidates():
    """A model without affine pinning rows pins nothing (and walks no nonlinear row)."""
    c = compile_source("solid s {\n c = Circle(center=(0, 0), radius=5)\n"
                       " d = Circle(center=(9, 0), radius=2)\n Distance(c.center, d.center, 9)\n}\n",
                       "t.aidl")
    sv = c.solve.solver
    assert pinned(sv.rows_built, sv.free, sv.is_frame, c.model.param_owner) == []
