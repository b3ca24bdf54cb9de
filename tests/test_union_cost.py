"""A union of faces ends within its budget (issue 70): Manifold's ``batch_boolean`` (Clipper2's
scan line) costs about the distinct heights of the vertices times the edges crossing each
scan line, so 4,000 disjoint circles of different radii on one row along x took 45 s of CPU
in one uninterruptible union (the per-vertex estimate said 0.6 s) and then an unlocated
E0304.  Now the union's scan-line work is estimated (output/part/build/scanwork.py): a row along x
is united along x (an exact quarter turn and back), and a union sure to end past the
deadline is refused before it starts, at the structure being united."""
from __future__ import annotations

from aidl_lang.base.limits import now as budget_clock      # the budget's clock: CPU seconds

import math
import resource
import subprocess

import ezdxf
import manifold3d as mf
import numpy as np
import pytest

from aidl_lang.base.limits import Deadline, OutOfBudget
from aidl_lang.output.part.build import scanwork
from aidl_lang.pipeline import compile_source
from cpu_clock import AIDL_CPU

pytestmark = pytest.mark.timing          # budgets: run again beside a CPU hog in .ci/run

ROW = """units mm
assembly a {{
    ps = [Circle(center=({x}, {y}), radius=1 + i*0.0001) for i in range({n})]
}}
"""

# two rows of circles crossing at the origin: scanned along y or along x, one of them is a row
CROSS = """units mm
assembly a {{
    row = [Circle(center=(i*3 + 3, 0), radius=1 + i*0.0001) for i in range({n})]
    col = [Circle(center=(0, i*3 + 3), radius=1 + i*0.0001) for i in range({n})]
}}
"""


def _cli(*args) -> tuple[subprocess.CompletedProcess, float]:
    """Run ``aidl ARGS`` with its budget on the CPU clock (tests/cpu_clock.py: the same work
    reaches the same deadline on a busy machine); its result and the CPU seconds (user +
    system) of the child."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([*AIDL_CPU, *map(str, args)],
                       capture_output=True, text=True, timeout=900)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return r, cpu


def _circle(cx: float, cy: float, r: float, n: int = 32) -> mf.CrossSection:
    a = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    return mf.CrossSection([np.c_[cx + r * np.cos(a), cy + r * np.sin(a)]])


def _vertices(shape: mf.CrossSection) -> set:
    return {tuple(p) for poly in shape.to_polygons() for p in np.asarray(poly).tolist()}


def test_a_row_of_4000_different_circles_lists_its_part_within_the_budget(tmp_path):
    """Before: `aidl parts` ran 45 s of CPU in one union and ended with an unlocated E0304 at
    `--budget 0.5`; now the row is united along x: ok, one part of 4,000 circles, about 1 s
    (asserted: under 7.5 s, the budget of `--budget 0.5`, with the default budget)."""
    f = tmp_path / "many.aidl"
    f.write_text(ROW.format(x="i*3", y="0", n=4000))
    r, cpu = _cli("parts", f)
    assert r.returncode == 0, r.stderr[-2000:]
    assert "1 part, 1 shape" in r.stdout
    # the row: 4 000 circles 3 mm apart, the last of radius 1.3999
    assert "11999.400" in r.stdout and "2.800" in r.stdout, r.stdout
    assert cpu < 7.5, cpu


def test_a_row_of_4000_different_circles_is_checked_and_rendered_whole(tmp_path):
    """`aidl render` of the row writes all 4,000 circles, exact (DXF re-read by ezdxf), in a
    few seconds of CPU (before: 45 s and an E0304 at `--budget 0.5`)."""
    f = tmp_path / "many.aidl"
    f.write_text(ROW.format(x="i*3", y="0", n=4000))
    out = tmp_path / "many.dxf"
    r, cpu = _cli("render", f, "-o", out, "--budget", "0.5")
    assert r.returncode == 0, r.stderr[-2000:]
    circles = sorted((e.dxf.center.x, e.dxf.center.y, e.dxf.radius)
                     for e in ezdxf.readfile(out).modelspace() if e.dxftype() == "CIRCLE")
    assert len(circles) == 4000
    for i, (x, y, rad) in enumerate(circles):
        assert abs(x - 3 * i) < 1e-9 and abs(y) < 1e-9 and abs(rad - (1 + i * 0.0001)) < 1e-9
    assert cpu < 7.5, cpu


def test_the_estimate_of_a_row_is_quadratic_along_y_and_linear_along_x():
    """scan_work: n faces on a row along x overlap every other along y (~n^2) and only their
    own along x (~n); a column is the row turned; the exact count from the vertices agrees
    on the row within a factor of 2.5 (a circle's upper and lower halves share heights)."""
    def row(n):
        return [_circle(3 * i, 0, 1 + i * 1e-4) for i in range(n)]

    def column(n):
        return [_circle(0, 3 * i, 1 + i * 1e-4) for i in range(n)]

    for n in (200, 400):
        r1, r2 = row(n), row(2 * n)
        assert scan_work_ratio(r1, r2, 1) == pytest.approx(4.0, rel=0.01)     # n^2
        assert scan_work_ratio(r1, r2, 0) == pytest.approx(2.0, rel=0.01)     # n
        c1, c2 = column(n), column(2 * n)
        assert scan_work_ratio(c1, c2, 1) == pytest.approx(2.0, rel=0.01)
        assert scan_work_ratio(c1, c2, 0) == pytest.approx(4.0, rel=0.01)
        # 32 vertices x 2 edges x n faces overlapping: exactly
        assert scanwork.scan_work(r1, 1) == 32 * 2 * n * n
        assert scanwork.scan_work(r1, 0) == 32 * 2 * n
        narrow, wide = scanwork.exact_scan_work(r1, 1)
        assert 0.4 * scanwork.scan_work(r1, 1) < narrow + wide <= scanwork.scan_work(r1, 1)
        assert sum(scanwork.exact_scan_work(r1, 0)) < 0.01 * (narrow + wide)
    assert scanwork.plan(row(800)) == (True, False)
    assert scanwork.plan(column(800)) == (False, False)
    assert scanwork.plan(row(100)) == (False, False)          # cheap either way: left alone
    assert scanwork.plan(row(800) + column(800), left=1.0) == (False, True)   # a cross: weighed


def scan_work_ratio(a, b, axis):
    return scanwork.scan_work(b, axis) / scanwork.scan_work(a, axis)


def test_equal_circles_on_a_row_share_their_scan_beams():
    """The exact count takes each height once (equal circles on a row: 17 scan beams), so a
    row of equal circles, cheap for Clipper, is never refused on the estimate's n^2."""
    faces = [_circle(3 * i, 0, 1) for i in range(2000)]
    assert scanwork.scan_work(faces) == 32 * 2 * 2000 * 2000
    assert sum(scanwork.exact_scan_work(faces)) <= 17 * 4000
    assert scanwork.union_seconds(faces, left=0.01) < 0.01


def test_the_estimate_refuses_a_union_that_would_take_too_long(cpu_clock):
    """union_seconds: the row of 4,000 different circles scanned along y is ~10 s of work
    (it took 31-45 s), along x (turned) well under 0.1 s; with plenty of time left the exact
    count is not even taken (0)."""
    row = [_circle(3 * i, 0, 1 + i * 1e-4) for i in range(4000)]
    assert scanwork.union_seconds(row, left=1.0) > 5.0
    assert scanwork.union_seconds(scanwork.turned(row), left=1.0) < 0.1
    assert scanwork.union_seconds(row, left=1000.0) == 0.0
    # through the renderer: refused before it starts, at the structure being united
    from aidl_lang.output.part.build.booleans import Renderer
    import time
    c = compile_source(ROW.format(x="i*3", y="0", n=10), "r.aidl")
    from aidl_lang.base.limits import Work
    ren = Renderer(c.model, Deadline(budget_clock() + 600, work=Work(1.0 / 7.5e-6)))  # 1 s
    with pytest.raises(OutOfBudget) as ex:
        ren.tick(c.model.root, row)
    assert ex.value.where is c.model.root and "work units, past its budget of 133,333" \
        in ex.value.what


# the faces are made in the test (a CrossSection held by the collected parameters outlives the
# interpreter's teardown of manifold3d: nanobind reports it as leaked)
CASES = {
    "row": lambda: [_circle(3 * i, 0, 1 + i * 1e-4) for i in range(100)],       # disjoint
    "equal": lambda: [_circle(3 * i, 0, 1) for i in range(100)],
    "overlapping": lambda: [_circle(1.3 * i + 0.1234567, 0.3, 1 + i * 1e-3) for i in range(100)],
    "random": lambda: [_circle(x, y, r) for x, y, r in np.random.default_rng(0).uniform(
        (0, 0, 0.5), (20, 20, 3), (100, 3))],                                   # overlapping
    "annulus": lambda: [_circle(0, 0, 5) - _circle(0, 0, 3), _circle(4, 0, 1.5),
                        _circle(7.7, 1.1, 2)],
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_turned_union_is_the_plain_union(case):
    """A quarter turn and back is exact: the union scanned along x has exactly the vertices
    of the union scanned along y (as sets), the same contours and area."""
    faces = CASES[case]()
    plain = mf.CrossSection.batch_boolean(faces, mf.OpType.Add)
    turned = scanwork.turned_back(mf.CrossSection.batch_boolean(scanwork.turned(faces),
                                                                mf.OpType.Add))
    assert _vertices(turned) == _vertices(plain)
    assert turned.num_contour() == plain.num_contour()
    assert turned.area() == pytest.approx(plain.area(), rel=1e-12)


def test_a_row_united_along_x_writes_the_same_circles(tmp_path, monkeypatch):
    """Through the pipeline: 600 circles on a row (united along x) give the same part as
    united along y (turning off), vertex for vertex, and the same exact circles in the DXF
    (re-read by ezdxf, as sets: the order of the loops may differ)."""
    from aidl_lang.output.part.build import booleans
    src = ROW.format(x="i*3", y="0", n=600)
    turns = []
    real = booleans.plan

    def spy(faces, left=math.inf):
        turns.append(real(faces, left)[0])
        return real(faces, left)

    def plain(faces, left=math.inf):
        return False, real(faces, left)[1]

    monkeypatch.setattr(booleans, "plan", spy)
    a = compile_source(src, "row.aidl")
    assert turns == [True]
    monkeypatch.setattr(booleans, "plan", plain)
    b = compile_source(src, "row.aidl")
    assert a.ok and b.ok
    assert _vertices(a.drawing.parts[0].shape) == _vertices(b.drawing.parts[0].shape)
    sets = []
    for how in (real, plain):
        monkeypatch.setattr(booleans, "plan", how)
        out = tmp_path / "row.dxf"
        _cli_render(src, tmp_path, out)
        sets.append(sorted((round(e.dxf.center.x, 9), round(e.dxf.center.y, 9),
                            round(e.dxf.radius, 9))
                           for e in ezdxf.readfile(out).modelspace() if e.dxftype() == "CIRCLE"))
    assert len(sets[0]) == 600 and sets[0] == sets[1]


def _cli_render(src, tmp_path, out):
    from aidl_lang.cli.main import main
    f = tmp_path / "row.aidl"
    f.write_text(src)
    assert main(["render", str(f), "-o", str(out)]) == 0


def test_a_diagonal_row_ends_ok_within_the_budget(tmp_path):
    """4,000 different circles on a diagonal (turning does not help, nor is it needed: each
    scan line crosses a circle or two): ok, within the budget of `--budget 0.5`."""
    f = tmp_path / "diag.aidl"
    f.write_text(ROW.format(x="i*3", y="i*3", n=4000))
    r, cpu = _cli("parts", f, "--budget", "0.5")
    assert r.returncode == 0, r.stderr[-2000:]
    assert "1 part, 1 shape" in r.stdout
    assert cpu < 7.5, cpu


def test_two_crossing_rows_are_refused_before_the_union_located(tmp_path):
    """Two rows of 4,000 circles crossing (a row whichever way it is scanned): the last
    union, ~30 s, is refused before it starts with a located E0304 at the assembly, within
    the 7.5 s budget of `--budget 0.5` plus slack (before: 40 s or more, unlocated)."""
    f = tmp_path / "cross.aidl"
    f.write_text(CROSS.format(n=4000))
    r, cpu = _cli("parts", f, "--budget", "0.5")
    assert r.returncode == 1, r.stdout[-2000:]
    assert f"{f}:2:1: error[E0304]: the program ran out of its evaluation budget in the " \
           "booleans of `a`: it needs more than " in r.stderr, r.stderr[-2000:]
    assert "work units, past its budget of 1,000,000" in r.stderr
    assert cpu < 7.5 + 4, cpu


class _Recorder(Deadline):
    """A deadline far away that records every check (stage, where)."""
    def __init__(self):
        import time
        super().__init__(budget_clock() + 3600)
        self.calls = []

    def check(self, stage, where=None, ahead=0.0):
        self.calls.append((stage, where, ahead))


def test_a_union_that_ends_past_the_deadline_is_reported_at_its_structure():
    """After the last union of a structure the deadline is looked at again, at that
    structure: a union that overran is an E0304 "in the booleans of `a`", not the next
    stage's."""
    from aidl_lang.output.part.build.booleans import Renderer
    c = compile_source(ROW.format(x="i*3", y="0", n=40), "r.aidl")
    d = _Recorder()
    Renderer(c.model, d).run()
    a = c.model.root
    last = [i for i, (st, w, ahead) in enumerate(d.calls) if w is a and ahead > 0]
    assert last, d.calls
    after = d.calls[last[-1] + 1]
    assert after[:2] == ("the booleans", a) and after[2] == 0.0


def test_the_shape_checks_past_the_deadline_are_located(monkeypatch):
    """Before: past the deadline the shape checks' first step over all parts (before the
    engraving) raised with no structure, an E0304 with no place in the file; now it is at
    the first part (and any stage of no one structure at the program's first)."""
    real = Deadline.check

    def late(self, stage, where=None, ahead=0.0):
        if stage == "the shape checks":
            raise OutOfBudget(f"more than {self.budget.seconds:g} s of wall time", stage,
                              where)
        return real(self, stage, where, ahead)

    monkeypatch.setattr(Deadline, "check", late)
    c = compile_source(ROW.format(x="i*3", y="0", n=3), "r.aidl")
    [e] = [d for d in c.sink.items if d.code == "E0304"]
    assert e.span is not None and e.span.line == 2, e
    assert "in the shape checks of `a`" in e.message, e.message


def test_a_solid_row_of_4000_circles_says_it_falls_apart_within_the_budget(tmp_path):
    """The same row as a `solid`: W0504's pieces (Manifold's decompose, Clipper's scan line
    again) took 40 s and ended with E0304 in the shape checks; scanned along x `aidl check` is
    ok,
    W0504 naming the first pieces, within the 7.5 s of `--budget 0.5`."""
    f = tmp_path / "solid.aidl"
    f.write_text(ROW.format(x="i*3", y="0", n=4000).replace("assembly a", "solid a"))
    r, cpu = _cli("check", f, "--budget", "0.5")
    assert r.returncode == 0, r.stderr[-2000:]
    out = r.stdout + r.stderr
    assert "solid `a` falls apart into 4000 separate pieces: {`a.ps[0]`}" in out, out[-2000:]
    assert "E0304" not in out
    assert cpu < 7.5, cpu


def test_the_turned_pieces_are_the_plain_pieces():
    """scanwork.decompose turns a row's shape and its pieces back exactly: the same pieces
    (vertex sets) as Manifold's own decompose."""
    faces = [_circle(3 * i, 0, 1 + i * 1e-4) for i in range(800)]
    shape = mf.CrossSection.batch_boolean(faces, mf.OpType.Add)
    loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    plain = {frozenset(_vertices(p)) for p in shape.decompose()}
    turned = {frozenset(_vertices(p)) for p in scanwork.decompose(shape, loops)}
    assert len(plain) == 800 and turned == plain
