"""Geometry pinned in its structure's frame adds no unknowns (issue 38, solver/core/system.py
`pinned`): the solve, the degrees of freedom, the redundant constraints (W0401), what slides
and every diagnostic are those of the solve that keeps the pinned geometry as unknowns held by
its rows (``Solver.pinning`` off), on the gear pair and on generated programs mixing pinned,
partly pinned, doubly fixed and free geometry across structures."""
from __future__ import annotations

import contextlib
import re
import pathlib

import numpy as np
from hypothesis import example, given, settings, strategies as st

from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver
from aidl_lang.solver.diagnosis import freedom, redundancy, sliding
from aidl_lang.solver.core.system import pinned

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
                  for d in freedom.degrees_of_freedom(sv)]
    out["count"] = [(d.structure.path, d.unknowns, d.rank)
                    for d in freedom.degrees_of_freedom(sv, floating=False)]
    out["redundant"] = sorted((r.constraint.describe(), r.partly,
                               sorted(b.describe() for b in r.by))
                              for r in redundancy.redundancies(sv))
    sl = sliding.sliding(sv)
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
    # left: the frames only (issue 48: the hub centers and bores, which rows across
    # structures read, are pinned too; a reader no longer spoils what it reads)
    assert new.solve.n_unknowns == 14 and new.solve.n_equations == 12
    sv = new.solve.solver
    m = new.model
    assert all(sv.is_frame[i] for i in np.flatnonzero(sv.free[:sv.n_model]))
    rings = [s for s in m.structures if s.name == "teeth_ring"]
    assert all(sv.free[s.fx] and sv.free[s.fy] for s in rings)     # the frames stay unknowns
    assert sum(sv.pinned_by.get(id(s), 0) for s in rings) == 1658 + 4970
    assert sum(sv.pinned_by.values()) == 6658 - 14


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


# random again (issue 105): derandomized for a while because a random run found pinned and
# unpinned solves naming different conflict sets (the example below); fixed in the product
# (rows in their built order either way, each set made minimal), then 900 random programs
# agreed
@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.lists(_PIECE, max_size=4), _PARENT), min_size=1, max_size=3),
       st.booleans())
# the part (the circle, the solid's first closed shape) placed by its own row `c.center.y
# == 2` (pinned, or stage own) before the arc goes to it (stage shapes): was 2.658 mm apart
@example([(["Distance(c.center, arc.center, 9)", "c.center.y == 2"], "AlignCenterX({k}, body)")],
         False)
# the falsifying example of before: `Fixed(c.center)`'s rows were taken y before x when its
# y row was pinned by the later `c.center.y == 2`, and the sets named were 2 and 3 pinned, 3
# and 4 unpinned (now: rows in their built order either way, each set made minimal)
@example([(["Fixed(arc.center)", "Distance(c.center, arc.center, 9)", "Fixed(c.center)",
            "c.center.y == 2"], "AlignCenterX({k}, body)")], False)
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
    assert not pinned(sv.rows_built, sv.free, sv.is_frame, c.model.param_owner)


def test_a_row_without_its_unknown_pins_nothing():
    """``p.x == p.x`` is the row ``0 p.x == 0``: a zero coefficient pins nothing (it was an
    internal error, a division by zero); the point stays an unknown, the compile succeeds."""
    c = compile_source("solid s {\n p = Point(1, 2)\n p.x == p.x\n"
                       " c = Circle(center=(0, 0), radius=5)\n}\n", "t.aidl")
    assert c.solve is not None and c.solve.converged
    assert not any(d.code == "E0900" for d in c.sink.items)
    assert not c.solve.solver.pins


# ---------------------------------------------------------------- the peel on arrays
# The dict walk `pinned` was before it took the rows into arrays (a zero or NaN
# coefficient aside: it pinned with it, then divided by it).

def _reference_pinned(rows, free, is_frame, owner):
    from aidl_lang.geometry.core.expr import Expr, Lin, Nl
    from aidl_lang.solver.core.system import EQ, PIVOT
    exprs, kind, cons = rows.exprs, rows.kind, rows.constraint
    n = rows.n_model
    ok_var = (np.asarray(free[:n], dtype=bool) & ~np.asarray(is_frame[:n], dtype=bool)).tolist()
    home = [o if ok else None for o, ok in zip(owner, ok_var)] + [None] * (rows.n_params - n)
    cand, var_rows, seeds, other = [], {}, set(), []
    left = [0] * len(exprs)
    for r, e in enumerate(exprs):
        if kind[r] != EQ or type(e) is not Lin:
            other.append(r)
            continue
        if not e.terms:
            continue
        o = cons[r].owner
        if o is not None and all(home[i] is o for i in e.terms):
            cand.append(r)
            left[r] = len(e.terms)
            for i in e.terms:
                var_rows.setdefault(i, []).append(r)
            continue
        # any other row may read pinned geometry (issue 48): it spoils nothing
    if not cand:
        return []
    pin_of, order = {}, []
    todo = [r for r in cand if left[r] == 1]
    while todo:
        r = todo.pop()
        if left[r] != 1:
            continue
        terms = exprs[r].terms
        v = next(u for u in terms if u not in pin_of)
        c = abs(terms[v])
        if not (c > 0 and c >= PIVOT * max(map(abs, terms.values()))):
            seeds.add(v)
            continue
        left[r] = -1
        pin_of[v] = r
        order.append((v, r))
        for r2 in var_rows[v]:
            if r2 != r and left[r2] > 0:
                left[r2] -= 1
                if left[r2] == 1:
                    todo.append(r2)
    if not order:
        return []
    for r in cand:
        if left[r] >= 0:
            seeds.update(exprs[r].terms)
    spoilt, stack, done = set(seeds), list(seeds), set()
    while stack:
        for r in var_rows.get(stack.pop(), ()):
            if r not in done:
                done.add(r)
                new = [u for u in exprs[r].terms if u not in spoilt]
                spoilt.update(new)
                stack += new
    return [(v, r) for v, r in order if v not in spoilt]


def _reference_values(rows, pins, x):
    xl = x.tolist()
    for v, r in pins:
        e = rows.exprs[r]
        s = e.const
        for i, c in e.terms.items():
            if i != v:
                s += c * xl[i]
        xl[v] = -s / e.terms[v]
    return np.asarray(xl)


class _Owner:
    def __init__(self, owner):
        self.owner = owner


_COEF = st.sampled_from([1.0, -1.0, 0.5, -0.25, 2.5, 0.3, -0.7, 1e3, 1e-7, 1e-5, 0.0])


@st.composite
def _row_sets(draw):
    """Random rows over a few structures: affine equations (mostly over one structure's
    unknowns, some reaching into another's), nonlinear rows and inequalities; parameters
    held, frames or free."""
    from aidl_lang.geometry.core.expr import Lin, mul, var
    from aidl_lang.solver.core.system import Rows
    structs = [object() for _ in range(draw(st.integers(1, 3)))]
    n = draw(st.integers(1, 14))
    owner = [draw(st.sampled_from(structs + [None])) if draw(st.integers(0, 7)) == 0
             else structs[i % len(structs)] for i in range(n)]
    free = np.array([draw(st.integers(0, 7)) > 0 for _ in range(n)])
    is_frame = np.array([draw(st.integers(0, 11)) == 0 for _ in range(n)])
    rows = Rows(n_model=n, n_params=n)
    coef, const = lambda: draw(_COEF), lambda: draw(st.sampled_from([0.0, -0.0, 1.5, -2.0, 1e3]))
    # triangular sets: each row pins one new unknown from earlier ones of its structure
    for s in structs:
        mine = [i for i in range(n) if owner[i] is s]
        order = draw(st.permutations(mine))
        for k, v in enumerate(order[:draw(st.integers(0, len(order)))]):
            vs = [v] + draw(st.lists(st.sampled_from(order[:k]), max_size=3, unique=True)) \
                if k else [v]
            rows.add(_Owner(s), Lin({i: coef() for i in draw(st.permutations(vs))}, const()))
    # and rows that may spoil them: any unknowns, nonlinear rows, inequalities
    for _ in range(draw(st.integers(0, 4))):
        s = owner[draw(st.integers(0, n - 1))] if draw(st.integers(0, 7)) else None
        vs = draw(st.lists(st.integers(0, n - 1), max_size=4, unique=True))
        what = draw(st.integers(0, 5))
        if what == 0 and len(vs) >= 2:
            rows.add(_Owner(s), mul(var(vs[0]), var(vs[1])))
        elif what == 1 and vs:
            rows.add_inequality(_Owner(s), var(vs[0]))
        else:
            rows.add(_Owner(s), Lin({i: coef() for i in vs}, const()))
    return rows, free, is_frame, owner


@settings(max_examples=150, deadline=None)
@given(_row_sets(), st.lists(st.floats(-1e3, 1e3), min_size=40, max_size=40))
def test_the_array_peel_pins_what_the_dict_walk_pins(case, xs):
    """Law: on random affine row sets the array peel pins exactly the (parameter, row)
    pairs of the dict walk, in a valid order (each row reads only parameters pinned at a
    lower level), and :func:`pin_values` gives the walk's floats bit for bit; whether a
    level is peeled and valued in array operations or in Python (``SMALL_LEVEL``)."""
    _check_peel(*case, xs)


def test_the_peel_from_a_python_level_into_an_array_level():
    """A level peeled in Python can leave a row with no unknown in the next level's list
    (two of its unknowns pinned in that level): the array level must skip it.  Rows
    ``a``, ``b``, ``a + b`` (dependent: it spoils the component), ``a + c``, ``b + d``."""
    from aidl_lang.geometry.core.expr import Lin
    from aidl_lang.solver.core.system import Rows
    s = object()
    rows = Rows(n_model=4, n_params=4)
    for terms in ({0: 1.0}, {1: 1.0}, {0: 1.0, 1: 1.0}, {0: 1.0, 2: 1.0}, {1: 1.0, 3: 1.0},
                  {}):
        rows.add(_Owner(s), Lin(terms, 1.0))
    _check_peel(rows, np.ones(4, dtype=bool), np.zeros(4, dtype=bool), [s] * 4, [2.0] * 4)


def _check_peel(rows, free, is_frame, owner, xs):
    from aidl_lang.solver.core import system
    free_all = np.concatenate([free, np.ones(rows.n_params - len(free), dtype=bool)])
    frame_all = np.concatenate([is_frame, np.zeros(rows.n_params - len(free), dtype=bool)])
    want = _reference_pinned(rows, free_all, frame_all, owner)
    x0 = np.asarray(xs[:rows.n_params], dtype=float)
    x0 = np.concatenate([x0, np.zeros(rows.n_params - len(x0))])
    want_x = _reference_values(rows, want, x0)
    small = system.SMALL_LEVEL
    try:
        for system.SMALL_LEVEL in (0, 2, 3, small):
            got = pinned(rows, free_all, frame_all, owner)
            assert sorted(got) == sorted(want)
            level = dict(zip(got.var.tolist(), got.level.tolist()))
            assert list(got.level) == sorted(got.level)
            for (v, r), lv, en in zip(got, got.level.tolist(), got.entry.tolist()):
                assert got.cols[en] == v and got.indptr[r] <= en < got.indptr[r + 1]
                assert all(level.get(i, 0) < lv for i in rows.exprs[r].terms if i != v)
            x = x0.copy()
            system.pin_values(rows, got, x)
            assert x.tobytes() == want_x.tobytes()
    finally:
        system.SMALL_LEVEL = small


def test_conflict_sets_are_minimal_and_the_same_pinned_or_not():
    """The law's example of issue 105: `Fixed(c.center)` and `c.center.y == 2` conflict on
    their own (2 constraints) and `Fixed(arc.center)`, the `Distance` and `Fixed(c.center)` too
    (3): both solves name exactly those two sets (before: 2 and 3 pinned, 3 and 4 unpinned)."""
    src = """solid top {
    body = Rectangle(center=(0, 0), width=60, height=40)
    solid k0 {
        c = Circle(center=(-4, 1), radius=2)
        arc = Arc(center=(0, -2), radius=3, start_angle=10 deg, end_angle=120 deg)
        Fixed(arc.center)
        Distance(c.center, arc.center, 9)
        Fixed(c.center)
        c.center.y == 2
    }
    AlignCenterX(k0, body)
}
"""
    new, old = _same(src)
    for c in (new, old):
        sets = sorted(sorted(re.findall(r"`([^`]+)` \(line", d.hint)) for d in c.sink.items
                      if d.code == "E0401")
        assert sets == [["Distance(c.center, arc.center, 9)", "Fixed(arc.center)", "Fixed(c.center)"],
                        ["Fixed(c.center)", "c.center.y == 2"]]
