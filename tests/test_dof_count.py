"""The freedom count on `aidl check`'s ok line (each structure's unknowns against its own rows
and its ancestors' rows that use them) (solver/diagnosis/diagnose.py `degrees_of_freedom(...,
floating=False)`) takes each structure's Jacobian out of the whole model's one, and ranks
single-row blocks without an SVD: the same matrices, bit for bit, and the same counts as each
structure's own tape and an SVD per block, on every example, test program and generated
hierarchy."""
from __future__ import annotations

from aidl_lang.base.limits import now as budget_clock      # the budget's clock: CPU seconds

import functools
import pathlib
import time

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from aidl_lang.pipeline import compile_source
from aidl_lang.solver.core import rank as R
from aidl_lang.solver.diagnosis import diagnose as D, freedom, redundancy, sliding
from aidl_lang.solver.core.arrays import unique

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROGRAMS = sorted((ROOT / "examples").glob("*.aidl")) + sorted((ROOT / "tests/programs").glob("*.aidl"))


def _generated():
    from benchmarks.solver.families import hierarchy
    return [hierarchy(n, seed=s).source for n, s in ((3, 1), (10, 2), (25, 3))]


def _solved(src: str, name: str):
    c = compile_source(src, name)
    assert c.ok and c.solve is not None and c.solve.converged
    return c.solve.solver


@functools.cache
def _solved_once(src: str, name: str):
    """:func:`_solved`, once for each program of :func:`_sources` in this process: three
    tests read every example's solver (and none changes it), 3 compiles of each were 1."""
    return _solved(src, name)


def _unpinned(solver):
    """A solver of the same model at the same point that keeps every unknown and every row
    (``Solver.pinning`` off)."""
    from aidl_lang.solver import Solver, run
    Plain = type("Plain", (Solver,), {"pinning": False})
    plain = Plain(solver.model)
    assert not plain.pins
    assert run(plain).converged
    return plain


def _system(solver, s) -> tuple:
    """A structure's own unknowns (its geometry and its children's frames), its rows, and
    the columns of those rows: the unknowns and the rows' slacks."""
    params = list(solver.own.get(id(s), ()))
    for c in s.children.values():
        params += list(solver.frame.get(id(c), ()))
    rows = solver.rows_of([s])
    # and the rows of every ancestor that use one of these unknowns (issue 23), found here
    # from the ancestors' own tape (the count finds them in the whole model's Jacobian)
    chain, a = [], s.parent
    while a is not None:
        chain.append(a)
        a = a.parent
    anc = np.asarray(sorted(r for a in chain for r in solver.rows_of([a])), dtype=np.int64)
    if len(anc) and params:
        Ja = solver.tape(anc).jacobian(solver.x, np.asarray(sorted(params), dtype=np.int64),
                                       dense=True)
        rows = np.union1d(rows, anc[np.any(Ja != 0, axis=1)]).astype(np.int64)
    sl = solver.slack[rows] if len(rows) else np.zeros(0, dtype=np.int64)
    cols = unique(np.concatenate([np.asarray(params, dtype=np.int64), sl[sl >= 0]]))
    return params, rows, cols


def _reference(solver) -> list[tuple]:
    """(path, unknowns, rank) per structure the way it was counted before: each structure's
    own tape, one SVD per block."""
    out = []
    for s in solver.model.structures:
        params, rows, cols = _system(solver, s)
        if not len(cols):
            out.append((s.path, 0, 0))
            continue
        J = (solver.tape(rows).jacobian(solver.x, cols, dense=True) if len(rows)
             else np.zeros((0, len(cols))))
        out.append((s.path, len(params),
                    _svd_rank(J) + len(_frame_moves(solver, s, J, cols))
                    - (len(cols) - len(params))))
    return out


def _frame_moves(solver, s, J, cols) -> list:
    """The shifts of all of ``s``'s content (own points, children's frames) along x and y
    that change nothing (``J t = 0``): each is the move of ``s``'s frame, which its parent
    counts (issue 38), so the count leaves it out; none for the root or a structure whose
    frame is held."""
    if s.parent is None or not solver.free[s.fx]:
        return []
    xs, ys = set(), set()
    for g in solver.model.all_geometry():
        for p in g.points.values():
            xs.add(p.ix)
            ys.add(p.iy)
    own = set(solver.own.get(id(s), ()))
    T = []
    for axis, frame in ((xs, [c.fx for c in s.children.values()]),
                        (ys, [c.fy for c in s.children.values()])):
        t = np.array([1.0 if (c in own and c in axis) or c in frame else 0.0 for c in cols])
        if t.any():
            T.append(t)
    if J.shape[0] == 0:
        return T
    tol = 1e-9 * max(1.0, float(np.abs(J).max()))
    return [t for t in T if np.linalg.norm(J @ t) <= tol]


def _svd_rank(J: np.ndarray) -> int:
    """:func:`R._dense_block_rank` with an SVD for every block (no single-row shortcut)."""
    if J.shape[0] == 0:
        return 0
    lab = R._dense_components(J)
    rank = 0
    for k in unique(lab):
        sub = J[lab == k]
        sub = sub[:, np.any(sub != 0, axis=0)]
        if sub.shape[1]:
            sv = np.linalg.svd(sub, compute_uv=False)
            rank += int(np.sum(sv > 1e-9 * max(1.0, float(sv[0]))))
    return rank


def _sources():
    return [(str(p), p.read_text()) for p in PROGRAMS] + \
        [(f"hierarchy{i}.aidl", src) for i, src in enumerate(_generated())]


@pytest.mark.parametrize("name,src", _sources(), ids=lambda v: pathlib.Path(v).stem if len(v) < 200 else "")
def test_count_equals_per_structure_tapes(name, src):
    solver = _solved_once(src, name)
    got = [(d.structure.path, d.unknowns, d.rank) for d in freedom.degrees_of_freedom(solver, floating=False)]
    # the reference keeps pinned geometry (a gear's teeth, system.pinned) as unknowns held
    # by their rows, as every solve did before issue 38: the counts are the same
    assert got == _reference(_unpinned(solver))
    # the blocks cut from the whole Jacobian are each structure's own, bit for bit
    systems = []
    for s in solver.model.structures:
        _params, rows, cols = _system(solver, s)
        if len(rows) and len(cols):
            systems.append((rows, cols))
    whole = freedom._whole_jacobian(solver, solver.x, [c for _, c in systems])
    if whole is None:       # no structure has rows
        return
    W, wcols = whole        # dense, or CSR for a large model (the protractor)
    for rows, cols in systems:
        own = solver.tape(rows).jacobian(solver.x, cols, dense=True)
        cut = R._dense_cut(W, wcols, rows, cols)
        assert own.shape == cut.shape and np.array_equal(own, cut)
        assert (np.signbit(own) == np.signbit(cut)).all()


_entry = st.one_of(st.just(0.0), st.floats(-3, 3), st.sampled_from([1e-12, 4e-10, 1e-9, 1.0000001e-9,
                                                                     2e-9, -1e-9, 1e6]))


@settings(max_examples=200, deadline=None)
@given(st.integers(1, 6), st.integers(1, 6), st.data())
def test_block_rank_equals_an_svd_per_block(m, n, data):
    """The single-row shortcut counts what the SVD counts, right at its 1e-9 threshold too."""
    J = np.array(data.draw(st.lists(st.lists(_entry, min_size=n, max_size=n), min_size=m,
                                    max_size=m)), dtype=float)
    assert R._dense_block_rank(J) == _svd_rank(J)


# ------------------------------------------------------------------ ancestors (issue 23)
PINNED_BY_PARENT = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    Fixed(body)
    hole bore {
        c = Circle(center=(0, 0), radius=5)
    }
    CenterInside(bore, self)
}
"""

PINNED_BY_GRANDPARENT = """assembly top {
    solid plate {
        body = Rectangle(center=(0, 0), width=40, height=20)
        hole bore { c = Circle(center=(0, 0), radius=5) }
    }
    Fixed(plate.body)
    CenterInside(plate.bore, plate)
}
"""


def _check(tmp_path, src, *flags):
    import json
    import subprocess
    import sys
    f = tmp_path / "p.aidl"
    f.write_text(src)
    out = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(f), *flags],
                         capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout) if "--json" in flags else out.stdout


@pytest.mark.parametrize("src", [PINNED_BY_PARENT, PINNED_BY_GRANDPARENT],
                         ids=["parent", "grandparent"])
def test_a_hole_placed_by_an_ancestor_is_not_floating(tmp_path, src):
    """The hole's circle has no constraint of its own, but an ancestor's CenterInside reads it:
    it is pinned, the ok line says fully constrained and --dof lists nothing floating."""
    assert "; fully constrained)" in _check(tmp_path, src)
    doc = _check(tmp_path, src, "--dof", "--json")
    assert doc["freedom"] == "fully constrained"
    assert [(d["structure"].split(".")[-1], d["dof"], d["floating"]) for d in doc["dof"]][-1] \
        == ("bore", 0, [])
    assert all(d["dof"] == 0 and d["floating"] == [] for d in doc["dof"])


def test_without_the_ancestor_constraint_the_hole_floats(tmp_path):
    """The control: the same part without the CenterInside, whose hole really is free."""
    src = PINNED_BY_PARENT.replace("    CenterInside(bore, self)\n", "")
    doc = _check(tmp_path, src, "--dof", "--json")
    dof = {d["structure"]: d for d in doc["dof"]}
    # the circle moving inside the hole is the hole's frame moving (issue 38): counted once,
    # in the plate
    assert dof["plate.bore"]["dof"] == 0 and dof["plate.bore"]["floating"] == []
    assert dof["plate"]["dof"] == 2 and dof["plate"]["floating"] == ["plate.bore (position)"]
    # placed by its coordinates alone, the hole stays where written (issue 84: "can slide
    # along x, y" read as a problem to three of four models)
    assert doc["freedom"] == ("2 degrees of freedom left (hole `plate.bore` free but stays "
                              "where written on its part (harmless)), see --dof")


def test_an_ancestor_row_pins_only_what_it_reads(tmp_path):
    """RightOf in the parent fixes the child circle's x, not its y: one freedom left, b's
    position along y (counted in `top`, b's frame; b's circle moving with it inside b is the
    same move, issue 38)."""
    src = """assembly top {
    solid a { c = Circle(center=(0, 0), radius=5)
              Fixed(c) }
    solid b { c = Circle(center=(20, 0), radius=5) }
    Fixed(a)
    RightOf(b, a, gap=3)
}
"""
    doc = _check(tmp_path, src, "--dof", "--json")
    dof = {d["structure"]: (d["dof"], d["floating"]) for d in doc["dof"]}
    assert dof["top.b"] == (0, []) and dof["top.a"] == (0, [])
    assert dof["top"] == (1, ["top.b (position)"])


# ------------------------------------------------------------------ --dof: floating entities
def _svd_null_support(J: np.ndarray) -> tuple[int, np.ndarray]:
    """What `--dof` computed before propagation: one full SVD of the whole block."""
    _, sv, Vt = np.linalg.svd(J, full_matrices=True)
    rank = int(np.sum(sv > 1e-9 * max(1.0, float(sv[0]) if len(sv) else 1.0)))
    return rank, np.linalg.norm(Vt[rank:], axis=0) > 1e-6


_jac_entry = st.one_of(st.just(0.0), st.just(0.0), st.just(0.0), st.sampled_from([1.0, -1.0, 2.0]),
                       st.floats(-3, 3).filter(lambda v: abs(v) > 1e-3))


@settings(max_examples=300, deadline=None)
@given(st.integers(1, 9), st.integers(1, 9), st.data())
def test_null_support_equals_a_full_svd(m, n, data):
    """The propagated null space (determined columns found row by row, the SVD only for the
    rest) gives the rank and the moving unknowns one SVD of the whole Jacobian gives;
    repeated rows make dependent sets."""
    import scipy.sparse as sp
    rows = data.draw(st.lists(st.lists(_jac_entry, min_size=n, max_size=n), min_size=m,
                              max_size=m))
    rows += [rows[i] for i in data.draw(st.lists(st.integers(0, m - 1), max_size=2))]
    J = np.array(rows, dtype=float)
    rank, moving = R.null_support(sp.csr_matrix(J))
    want_rank, want_moving = _svd_null_support(J)
    assert rank == want_rank
    assert moving.tolist() == want_moving.tolist()


def test_floating_entities_equal_a_full_svd_on_every_program():
    """`--dof` lists, per structure, the same count and floating entities as one SVD of the
    structure's whole Jacobian, on every example and test program (structures of up to 600
    columns: the gear pair's 3 000-column SVDs take half a minute each)."""
    for name, src in _sources():
        solver = _solved_once(src, name)
        plain = _unpinned(solver)       # the reference: pinned geometry as unknowns again
        for d in freedom.degrees_of_freedom(solver, floating=True):
            params, rows, cols = _system(plain, d.structure)
            if not len(rows) or not len(cols) or len(cols) > 600:     # the SVD's seconds
                continue
            J = plain.tape(rows).jacobian(plain.x, cols, dense=True)
            J = np.vstack([J] + _frame_moves(plain, d.structure, J, cols))
            rank, moving = _svd_null_support(J)
            assert d.rank == rank - (len(cols) - len(params)), (name, d.structure.path)
            pos = {int(c): k for k, c in enumerate(cols)}
            n_moving = sum(bool(moving[pos[i]]) for i in params)
            assert (n_moving == 0) == (d.floating == []), (name, d.structure.path)


# ------------------------------------------------------------------ what the freedom means
GAUGE = """param count = 4
pitch = 11 mm
solid gauge {
    plate = Rectangle(center=(0, 0), width=60, height=40)
    hole bits {
        for i in range(count) {
            h = Circle(center=(-(count - 1) * pitch / 2 + i * pitch, 5), diameter=(i + 1) * 1 mm)
        }
    }
    drawing labels {
        for i in range(count) {
            t = Text(str(i + 1), (-(count - 1) * pitch / 2 + i * pitch, -12), size=5)
        }
    }
    AlignCenterX(bits, labels)
    AlignCenterX(labels, plate)
    Below(labels, bits, gap=4)
    EXTRA
}
"""


def test_a_feature_that_can_slide_is_named_and_warned(tmp_path):
    """The drill gauge of issue 35: x of the holes and labels is placed, and the labels hang
    4 mm below the holes, but nothing ties the pair to the plate in y, and each is placed on
    the other (the holes' x on the labels, the labels' y on the holes: a cycle, so neither
    stays where written; issue 111: labels `Below` holes that nothing else moves are placed
    on them, harmless).  The ok line says so, W0404 warns at each of them, and one more
    constraint leaves only the part's placement (harmless, no warning)."""
    doc = _check(tmp_path, GAUGE.replace("EXTRA", ""), "--json")
    # (issue 105: the part's own placement said beside what slides)
    assert "(free: hole `gauge.bits` can slide along y; drawing `gauge.labels` can slide along " \
           "y; 2 where the whole part sits (harmless))" in doc["freedom"]
    ws = [d for d in doc["diagnostics"] if d["code"] == "W0404"]
    assert [(w["span"]["line"], w["message"]) for w in ws] == [
        (5, "hole `gauge.bits` can slide along y relative to `gauge`: only its starting "
            "position places it there"),
        (10, "drawing `gauge.labels` can slide along y relative to `gauge`: only its starting "
             "position places it there")]
    assert "`AlignCenterY(bits, ...)`" in ws[0]["hint"]
    fixed = _check(tmp_path, GAUGE.replace("EXTRA", "bits.bb.top == plate.bb.top - 5"), "--json")
    assert not [d for d in fixed["diagnostics"] if d["code"] == "W0404"]
    assert "free: hole" not in fixed["freedom"]


def test_a_feature_placed_by_its_coordinates_alone_stays_where_written(tmp_path):
    """Issue 84: "free: hole `plate.recess` can slide along x, y" read as a problem to three
    of four models, though the solve keeps a feature nothing else places where it is written.
    Such a feature is "free but stays where written on its part (harmless)", on the ok line, in the API's
    and the MCP answer's freedom text; one a constraint places and that still slides (W0404)
    keeps "can slide"."""
    from aidl_lang import api
    from aidl_lang.mcp.tools import Workspace, check
    src = GAUGE.replace("EXTRA", "hole recess { r = Rectangle(center=(20, -5), width=6, "
                                 "height=4) }")
    said = ("(free: hole `gauge.bits` can slide along y; drawing `gauge.labels` can slide "
            "along y; hole `gauge.recess` free but stays where written on its part (harmless); 2 where the "
            "whole part sits (harmless))")
    doc = _check(tmp_path, src, "--json")
    assert said in doc["freedom"]
    assert [d["message"].split()[1] for d in doc["diagnostics"] if d["code"] == "W0404"] == [
        "`gauge.bits`", "`gauge.labels`"]                       # the recess: no warning
    assert said in api.compile(src).freedom()["text"]
    assert "hole `gauge.recess` free but stays where written on its part (harmless)" in \
        check(Workspace(tmp_path), source=src, dof=True)["freedom"]["text"]
    placed = src.replace("\n}\n", "\n    bits.bb.top == plate.bb.top - 5\n}\n")
    doc = _check(tmp_path, placed, "--json")
    assert doc["freedom"].endswith("degrees of freedom left (hole `gauge.recess` free but "
                                   "stays where written on its part (harmless); 2 where the whole part "
                                   "sits (harmless)), see --dof")
    assert not [d for d in doc["diagnostics"] if d["code"] == "W0404"]


def test_only_the_placement_of_the_whole_part_is_harmless(tmp_path):
    """Every shape tied to the plate, nothing fixed: the 2 freedoms left are where the part
    sits, said as harmless; `Fixed(body)` makes it fully constrained."""
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=60, height=40)\n"
           "    hole bore { c = Circle(center=(10, 0), radius=5) }\n"
           "    CenterInside(bore, body)\nFIX}\n")
    doc = _check(tmp_path, src.replace("FIX", ""), "--json")
    assert doc["freedom"] == ("2 degrees of freedom left (free: only where the whole part sits "
                              "(harmless)), see --dof")
    assert not [d for d in doc["diagnostics"] if d["code"] == "W0404"]
    doc = _check(tmp_path, src.replace("FIX", "    Fixed(body)\n"), "--json")
    assert doc["freedom"] == "fully constrained"


def test_rigid_takes_any_number_of_structures_and_holds_their_inside(tmp_path):
    """`Rigid([a, b, c, d, body])` (issue 35: at most 3 shapes or structures were accepted;
    each argument may now be a list, and a drawing is one of them): the five move as one body, and nothing inside a rigid structure floats in
    `--dof`, so the 2 freedoms left are the part's placement (10 without Rigid: the placement
    and 2 for each hole and the drawing)."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole a { c = Circle(center=(10, 0), radius=3) }
    hole b { c = Circle(center=(-10, 0), radius=3) }
    hole c { c = Circle(center=(0, 10), radius=3) }
    drawing d { t = Text("X", (0, -10), size=5) }
    RIGID
}
"""
    free = _check(tmp_path, src.replace("RIGID", ""), "--json", "--dof")
    assert free["freedom"] == ("10 degrees of freedom left (hole `plate.a`, hole `plate.b`, "
                               "hole `plate.c` and 1 more free but stay where written "
                               "on their parts (harmless); 2 where the whole part sits (harmless)), see --dof")
    doc = _check(tmp_path, src.replace("RIGID", "Rigid([a, b, c, d, body])"), "--json", "--dof")
    assert doc["freedom"] == ("2 degrees of freedom left (free: only where the whole part sits "
                              "(harmless)), see --dof")
    dof = {d["structure"]: (d["dof"], d["floating"]) for d in doc["dof"]}
    assert all(dof[f"plate.{k}"] == (0, []) for k in "abcd")
    listed = _check(tmp_path, src.replace("RIGID", "Rigid([a, b], [c, d], body)"), "--json")
    assert listed["freedom"] == doc["freedom"]


def test_the_count_of_a_generated_hierarchy_is_the_placement_of_the_whole(tmp_path):
    """Issue 38: 1,000 structures gave 2 freedoms on main and 2,002 on the older tree.  The
    older tree counted, per part, the part's shapes against its own frame and the hole's circle
    against the hole's frame: moves that change nothing drawn (a frame shifted one way, its
    contents the other).  What is visible is the whole row's position: 2, harmless."""
    from benchmarks.solver.families import hierarchy
    doc = _check(tmp_path, hierarchy(60, seed=3).source, "--json")
    assert doc["freedom"] == ("2 degrees of freedom left (free: only where the whole part sits "
                              "(harmless)), see --dof")


def test_the_ancestor_rows_of_a_large_pattern_take_linear_work():
    """Issue 37: each copy of a GridPattern gathered its parent's rows into a sorted list of
    its own (10 000 copies: 31 s, 2.6 GB).  Now each row knows its structure, and a copy
    looks only at the rows of its own unknowns: the rows of every structure are asked for
    once for the count and once for the owners, whatever the number of copies."""
    src = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=10, height=10)\n"
           "    hole h { c = Circle(center=(0, 0), radius=0.5) }\n"
           "    g = GridPattern(h, rows=20, cols=20, spacing=2)\n}\n")
    solver = _solved(src, "grid.aidl")
    calls = []
    rows_of = solver.rows_of

    def counted(structs):
        calls.append(len(structs))
        return rows_of(structs)
    solver.rows_of = counted
    dofs = freedom.degrees_of_freedom(solver)
    n = len(solver.model.structures)
    parents = sum(1 for s in solver.model.structures if s.children)
    assert n == 401 and len(calls) <= n + parents
    # the count itself: every copy is placed by the pattern; the plate's body is free to move
    by = {d.structure.path: d for d in dofs}
    assert by["plate"].dof == 2 and all(d.dof == 0 for p, d in by.items() if p != "plate")


@pytest.mark.timing
def test_a_dof_count_too_large_for_a_dense_svd_is_not_counted_and_stops(tmp_path, capsys,
                                                                        monkeypatch, cpu_clock):
    """Issue 37: `aidl check --dof` of 2,500 chained points took 80 s and 1 GB (a full SVD of
    2 499 x 5 000, then an unbounded redundancy search).  Past MAX_SVD_FLOPS the count peels
    the rows independent by structure and ranks the rest by the greedy pass: a chain is
    counted; a ring (nothing peels) whose rest is past the bound too is "not counted".
    Shown here on 300 points with the bound lowered."""
    from aidl_lang.cli.main import main
    monkeypatch.setattr(R, "MAX_SVD_FLOPS", 1e6)
    f = tmp_path / "pts.aidl"
    f.write_text(_chain(300))
    assert main(["check", "--dof", str(f)]) == 0
    out = capsys.readouterr().out
    assert "301 degrees of freedom left" in out
    assert "d       600  301  d.pts[0], d.pts[100]" in out
    f.write_text(_chain(300, "    Distance(pts[299], pts[0], 29.9)\n"))
    assert main(["check", "--dof", str(f)]) == 0
    out = capsys.readouterr().out
    assert "degrees of freedom not counted (model too large)" in out
    assert "d       600    ?  not counted (too large)" in out
    assert main(["check", "--dof", "--json", str(f)]) == 0
    import json
    doc = json.loads(capsys.readouterr().out)
    assert doc["dof"] == [{"structure": "d", "unknowns": 600, "dof": None, "floating": [],
                           "not_counted": "too large"}]
    monkeypatch.setattr(R, "MAX_SVD_FLOPS", 1e10)      # counted: 600 unknowns, rank 299
    assert main(["check", "--dof", str(f)]) == 0
    assert "301 degrees of freedom left" in capsys.readouterr().out


def test_a_structure_moving_with_its_frame_is_counted_once(tmp_path):
    """Issue 38, by hand.  One part of the generated hierarchy (`row > g0 > p0 > bore`: a
    rectangle of 4 points held by 6 constraints, a hole placed by CenterInside) can only move
    as a whole: 2.  Its shapes shifted inside p0's frame, p0 shifted inside g0's and g0 inside
    the row's are that one move, which was counted 3 times (6).  Three solids of a rectangle
    and a free round hole each (benchmarks/compile/compare_trees.py `structures(3)`): each solid's place
    (2) and its hole's slide (2), 12, was 18 (the circle moving inside its hole counted
    beside the hole's frame), and 24 on the older tree."""
    import sys
    sys.path.insert(0, str(ROOT))
    from benchmarks.solver.families import hierarchy
    from benchmarks.compile.compare_trees import structures
    doc = _check(tmp_path, hierarchy(3).source, "--json", "--dof")
    assert doc["freedom"] == ("2 degrees of freedom left (free: only where the whole part sits "
                              "(harmless)), see --dof")
    assert [(d["structure"], d["dof"]) for d in doc["dof"]] == [
        ("row", 2), ("row.g0", 0), ("row.g0.p0", 0), ("row.g0.p0.bore", 0)]
    doc = _check(tmp_path, structures(3), "--json", "--dof")
    assert doc["freedom"].startswith("12 degrees of freedom left (hole `a.s[0].h`, hole "
                                     "`a.s[1].h`, hole `a.s[2].h` free but stay where written "
                                     "on their parts (harmless); 6 where the parts sit (harmless))")
    dof = {d["structure"]: (d["dof"], d["floating"]) for d in doc["dof"]}
    assert dof["a"] == (6, ["a.s[0] (position)", "a.s[1] (position)", "a.s[2] (position)"])
    assert all(dof[f"a.s[{i}]"] == (2, [f"a.s[{i}].h (position)", f"a.s[{i}].r"])
               and dof[f"a.s[{i}].h"] == (0, []) for i in range(3))


# ------------------------------------------------------------------ issue 37: the whole run's budget
def _chain(n: int, extra: str = "") -> str:
    return (f"units mm\ndrawing d {{\n    pts = [Point(i * 0.1, 0) for i in range({n})]\n"
            f"    for i in range({n - 1}) {{ Distance(pts[i], pts[i + 1], 0.1) }}\n{extra}}}\n")


def _sparse_model(seed: int) -> str:
    """~550 points (a Jacobian past DENSE_CELLS over the unknowns its rows use: the sparse
    path) in chains and small loops, with repeated and implied constraints among them."""
    import random
    rnd = random.Random(seed)
    n = 550
    lines = [f"    pts = [Point(i * 1.0, (i % 7) * 1.0) for i in range({n})]"]
    for i in range(n - 1):
        if rnd.random() < 0.9:
            lines.append(f"    HorizontalDistance(pts[{i}], pts[{i + 1}], 1)")
    for _ in range(25):
        i = rnd.randrange(n - 3)
        k = rnd.choice([1, 2, 3])
        lines.append(f"    HorizontalDistance(pts[{i}], pts[{i + k}], {k})")   # often implied
    for _ in range(10):
        i = rnd.randrange(n - 1)
        lines.append(f"    VerticalDistance(pts[{i}], pts[{i + 1}], "
                     f"{((i + 1) % 7) - (i % 7)})")
        lines.append(f"    VerticalDistance(pts[{i}], pts[{i + 1}], "
                     f"{((i + 1) % 7) - (i % 7)})")                            # repeated
    return "units mm\ndrawing d {\n" + "\n".join(lines) + "\n}\n"


def _said(reds) -> list:
    return sorted((r.constraint.span.line, r.partly,
                   tuple(sorted(b.span.line for b in r.by))) for r in reds)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_redundancy_search_peels_independent_rows_and_finds_the_same(seed, monkeypatch):
    """Issue 37: the redundancy search of `aidl check --dof` decomposed the whole block of
    rows sharing unknowns (2 500 chained points: 14 s of Gram-Schmidt).  Rows that hold the
    only entry of some column take part in no dependency and are peeled off first; what it
    finds is the same as without peeling, on models past the dense path's size."""
    solver = _solved(_sparse_model(seed), "sparse.aidl")
    assert solver.whole.n_rows * len(D.used_free_columns(solver)) > R.DENSE_CELLS
    sizes = []
    dependencies = R.dependencies

    def counted(J, order, deadline=None, basis=None):
        sizes.append(J.shape[0])
        return dependencies(J, order, deadline, basis)
    monkeypatch.setattr(redundancy, "dependencies", counted)
    peeled = redundancy.redundancies(solver)
    peeled_sizes, sizes[:] = list(sizes), []
    monkeypatch.setattr(redundancy, "_peeled_rows", lambda J, lab=None: np.zeros(J.shape[0], dtype=bool))
    whole = redundancy.redundancies(solver)
    assert _said(peeled) == _said(whole) and len(peeled) >= 10
    assert sum(peeled_sizes) < sum(sizes) / 2          # most rows never decomposed


@pytest.mark.timing
def test_a_chain_of_2500_points_is_searched_for_redundancy_in_a_blink(monkeypatch, cpu_clock):
    """The issue's reproducer: 2 500 chained points, and one Distance said twice.  The whole
    chain peels to the two rows of the repeated constraint."""
    src = _chain(2500, "    Distance(pts[0], pts[1], 0.1)\n")
    from aidl_lang.base.limits import DEFAULT_BUDGET
    c = compile_source(src, "chain.aidl", budget=DEFAULT_BUDGET.scaled(5))
    assert c.ok
    sizes = []
    dependencies = R.dependencies

    def counted(J, order, deadline=None, basis=None):
        sizes.append(J.shape)
        return dependencies(J, order, deadline, basis)
    monkeypatch.setattr(redundancy, "dependencies", counted)
    skipped: list = []
    reds = redundancy.redundancies(c.solve.solver, skipped=skipped)
    assert skipped == [] and sizes == [(2, 2)]         # x of pts[0] and pts[1]
    # the loop's first Distance and the repeated one: each follows from the other
    assert sorted((r.constraint.span.line, [b.span.line for b in r.by]) for r in reds) \
        == [(4, [5]), (5, [4])]


@pytest.mark.timing
def test_check_dof_spends_the_compile_budget_not_a_fresh_one(tmp_path, capsys, monkeypatch,
                                                             cpu_clock):
    """Issue 37: `aidl check --dof` gave the redundancy search a fresh 15 s after the compile
    (2 500 chained points: 15.9 s in all).  The freedom count and the search now end at the
    compile's own deadline, and a search cut short says so.  (The budget counts CPU seconds,
    ``cpu_clock``: 7.5 s of a loaded machine's wall clock could end the count itself.)"""
    from aidl_lang import pipeline
    from aidl_lang.cli.main import main
    made, given = [], {}

    class Recorded(pipeline.Deadline):
        @classmethod
        def starting(cls, budget=pipeline.DEFAULT_BUDGET, work=None):
            d = super().starting(budget, work)
            made.append(d.at)            # the compile's backstop: what the count gets too
            return d
    monkeypatch.setattr(pipeline, "Deadline", Recorded)
    searched, dof = redundancy.search, freedom.degrees_of_freedom

    def red(solver, deadline=None, **kw):
        given["redundancy"] = deadline
        return searched(solver, deadline=deadline, **kw)

    def counted(solver, floating=True, deadline=None):
        given["dof"] = deadline
        return dof(solver, floating, deadline)
    monkeypatch.setattr(redundancy, "search", red)
    monkeypatch.setattr(freedom, "degrees_of_freedom", counted)
    f = tmp_path / "pts.aidl"
    f.write_text(_chain(300))
    assert main(["check", "--dof", "--budget", "0.5", str(f)]) == 0
    (at,) = made
    assert given["dof"] == at and given["redundancy"] == at
    assert "not counted" not in capsys.readouterr().out


@pytest.mark.timing
def test_check_dof_out_of_time_says_what_was_not_counted(tmp_path, capsys, monkeypatch,
                                                         cpu_clock):
    """When the compile has used the whole budget, --dof counts nothing more and says so: the
    structures "not counted (out of time)", the constraints not searched for redundancy."""
    import json
    from aidl_lang import api
    from aidl_lang.cli.main import main
    real = api.compile

    def spent(*a, **kw):                # the compile ends just as its budget runs out
        program = real(*a, **kw)
        program.compiled.deadline.at = budget_clock()
        return program
    monkeypatch.setattr(api, "compile", spent)
    f = tmp_path / "pts.aidl"
    f.write_text(_chain(300, "    Distance(pts[0], pts[1], 0.1)\n"))
    assert main(["check", "--dof", str(f)]) == 0
    out = capsys.readouterr().out
    assert "degrees of freedom not counted (out of time)" in out
    assert "d       600    ?  not counted (out of time)" in out
    assert ("redundant constraints (W0401): not counted: 300 constraints not searched (out "
            "of time: the backstop's 90 s of CPU time; --budget K gives K times more)") in out
    assert main(["check", "--dof", "--json", str(f)]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["dof"] == [{"structure": "d", "unknowns": 600, "dof": None, "floating": [],
                           "not_counted": "out of time"}]
    assert doc["redundancy"] == {"not_searched": 300, "why": "out of time"}


def _dense_null_support(J: np.ndarray) -> tuple[int, np.ndarray]:
    """The dense reference: the rank and the moving columns of one thin SVD."""
    if J.shape[0] == 0:
        return 0, np.ones(J.shape[1], dtype=bool)
    _, sv, Vt = np.linalg.svd(J, full_matrices=False)
    rank = int(np.sum(sv > 1e-9 * max(1.0, float(sv[0]))))
    rest = 1.0 - np.einsum("ij,ij->j", Vt[:rank], Vt[:rank])
    return rank, rest > 1e-12


RING = "    Distance(pts[59], pts[0], 5.9)\n"       # closes the chain: no row peels


@pytest.mark.parametrize("name,src", _sources() + [("sparse.aidl", _sparse_model(4)),
                                                   ("chain.aidl", _chain(120)),
                                                   ("ring.aidl", _chain(60, RING))],
                         ids=lambda v: pathlib.Path(v).stem if len(v) < 200 else "")
def test_the_sparse_null_space_counts_what_the_svd_counts(name, src):
    """Issue 37: past the dense SVD's size, `--dof` ranks by peeling and the greedy pass, and
    finds the moving columns by projecting random vectors on the null space (one sparse LU):
    the same rank and the same floating columns as the thin SVD, on every structure of every
    example, test program, generated hierarchy and a few sketches made to peel or not."""
    solver = _solved_once(src, name)
    seen = 0
    for s in solver.model.structures:
        _params, rows, cols = _system(solver, s)
        if not len(rows) or not len(cols) or len(cols) > 1500:
            continue
        J = solver.tape(rows).jacobian(solver.x, cols)
        J = J[np.flatnonzero(np.diff(J.tocsr().indptr))]
        rank, moving = R._sparse_null_support(J)
        want_rank, want_moving = _dense_null_support(J.toarray())
        assert rank == want_rank, s.path
        assert np.array_equal(moving, want_moving), s.path
        seen += 1
    assert seen



@pytest.mark.parametrize("extra", ["", "bits.bb.top == plate.bb.top - 5"])
def test_sliding_by_sparse_columns_finds_what_the_dense_jacobian_finds(extra, monkeypatch):
    """`sliding` reads a large model's Jacobian by columns (each part's moves touch a few of
    them, and only the rows those touch are formed: 1,000 parts 1.2 s -> 0.4 s); forced onto
    that path, the drill gauge names the same sliding features, placements and constrained
    features as the dense Jacobian does."""
    c = compile_source(GAUGE.replace("EXTRA", extra), "gauge.aidl")
    assert c.ok
    dense = sliding.sliding(c.solve.solver)
    monkeypatch.setattr(sliding, "DENSE_CELLS", 0)
    sparse = sliding.sliding(c.solve.solver)
    names = lambda pairs: [(t.path, a) for t, a in pairs]    # noqa: E731
    assert names(sparse.features) == names(dense.features)
    assert names(sparse.placement) == names(dense.placement)
    assert sparse.constrained == dense.constrained and sparse.bounded == dense.bounded
    assert bool(extra) != bool(dense.features)      # the gauge slides until the extra row


_peel_entry = st.one_of(st.just(0.0), st.floats(-3, 3), st.sampled_from([1e-13, 5e-12, 1e-9, 1e6]))


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(st.integers(1, 5), st.integers(1, 5)), min_size=1, max_size=5),
       st.data())
def test_peeling_every_block_at_once_is_peeling_each_block(blocks, data):
    """The redundancy search peels the rows of every block in one pass (``lab``: each row's
    block); that is the peel of each block on its own, each entry counted as zero against
    its own block's largest (blocks of 1e6 beside blocks of 1e-9), rows taken in any order."""
    import scipy.sparse as sp
    parts, lab = [], []
    for k, (m, n) in enumerate(blocks):
        vals = data.draw(st.lists(_peel_entry, min_size=m * n, max_size=m * n))
        parts.append(np.array(vals).reshape(m, n))
        lab += [k] * m
    lab = np.array(lab)
    J = sp.block_diag(parts, format="csr")
    order = np.array(data.draw(st.permutations(range(J.shape[0]))))
    together = R._peeled_rows(J[order], lab[order])[np.argsort(order)]
    alone = np.concatenate([R._peeled_rows(sp.csr_matrix(P)) for P in parts])
    assert (together == alone).all()
