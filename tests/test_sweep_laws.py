"""`aidl check --sweep` (aidl_lang/params/sweep.py, issue 92): one answer on any machine and bounds
within the stated tolerance, over generated designs with a known breaking value, through
the real parser, solver and Manifold.

- a row of holes that runs into a slot: the last hole's wall to the slot is thinner than
  0.5 mm past pitch p* = (slot edge - 0.5 - d/2 - x0) / (n - 1);
- a plate whose wall breaks: a hole at `off` leaves less than 0.5 mm to the plate's edge
  below width w* = 2 (off + d/2 + 0.5).

The sweep's clean bound lies within the stated tolerance (a fraction of the range, plus
the grid it reports on) of the computed value, on the clean side; the same file gives the
same lines beside two busy loops on the cores (the budget counts work, not seconds).
Cost: about 6 s of CPU (hypothesis 4 + 4 examples of one-param sweeps with no Latin
hypercube, one sweep run twice).
"""
import subprocess
import sys

from hypothesis import given, settings, strategies as st

from aidl_lang.serve.params import _nice
from aidl_lang.params.sweep import TOLERANCE, sweep

ROW = """param pitch = {p:.3f} mm, min = {lo:.3f} mm, max = {hi:.3f} mm

solid tray {{
    body = Rectangle(center=(0, 0), width=240, height=60)
    for i in range({n}) {{
        hole pen {{ c = Circle(center=({x0} + i * pitch, 0), diameter={d}) }}
    }}
    hole slot {{ s = Rectangle(center=({xs} + 10, 0), width=20, height=40) }}
}}
"""

PLATE = """param width = {w:.3f} mm, min = {lo:.3f} mm, max = {hi:.3f} mm

solid plate {{
    body = Rectangle(center=(0, 0), width=width, height=40)
    hole h {{ c = Circle(center=({off}, 0), diameter={d}) }}
}}
"""


def _slack(lo, hi):
    """How far the clean bound may stay short of the breaking value: the stated tolerance of
    the range, plus the grid the bounds are reported on, plus the circle's polygon."""
    return TOLERANCE * (hi - lo) + _nice(TOLERANCE * (hi - lo) / 2) + 0.02


@settings(max_examples=4, deadline=None)
@given(n=st.integers(2, 5), d=st.sampled_from([4, 6, 8, 10]), x0=st.sampled_from([-100, -90]),
       xs=st.sampled_from([60, 80, 95]))
def test_law_a_row_running_into_a_slot_is_bounded_at_the_computed_pitch(n, d, x0, xs):
    brk = (xs - 0.5 - d / 2 - x0) / (n - 1)              # the wall to the slot reaches 0.5
    merge = d + 0.5                                       # two pens' wall reaches 0.5
    # the high end puts the last hole's centre 10 mm past the breaking place: in the slot
    lo, hi = max(merge + 1, brk * 0.5), brk + 10 / (n - 1)
    written = (lo + brk) / 2
    rep = sweep(ROW.format(p=written, lo=lo, hi=hi, n=n, d=d, x0=x0, xs=xs), "row.aidl",
                points=0)
    assert rep.ok and rep.skipped == 0
    [f] = rep.findings
    a, b = f.clean["pitch"]
    assert a == round(lo, 3)
    assert brk - _slack(lo, hi) <= b <= brk + 0.02, (brk, b)
    assert not f.cut and "(bisected: " in f.diagnostic.hint


@settings(max_examples=4, deadline=None)
@given(off=st.sampled_from([5, 10, 15]), d=st.sampled_from([3, 5, 8]),
       wide=st.floats(1.5, 3.0))
def test_law_a_plate_whose_wall_breaks_is_bounded_at_the_computed_width(off, d, wide):
    brk = 2 * (off + d / 2 + 0.5)
    lo, hi = brk * 0.6, brk * wide
    rep = sweep(PLATE.format(w=brk * 1.2, lo=lo, hi=hi, off=off, d=d), "plate.aidl", points=0)
    assert rep.ok
    [f] = rep.findings
    a, b = f.clean["width"]
    assert b == round(hi, 3)
    assert brk - 0.02 <= a <= brk + _slack(lo, hi), (brk, a)


def _lines(rep):
    return [rep.text()] + [(d.message, d.hint, d.fix and d.fix.replacement)
                           for d in rep.diagnostics]


def test_the_same_file_gives_the_same_lines_beside_two_busy_loops():
    """The budget is work (steps, objects, unknowns, diagnostics), not seconds: the report
    is the same when two busy loops share the cores, and a budget that ends mid-bisection
    says so (not judged), never a bisection it did not do."""
    src = ROW.format(p=20, lo=11, hi=60, n=4, d=8, x0=-100, xs=60)
    quiet = sweep(src, "row.aidl", points=2, work=12_000)
    busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(2)]
    try:
        loaded = sweep(src, "row.aidl", points=2, work=12_000)
    finally:
        for p in busy:
            p.kill()
            p.wait()
    assert _lines(quiet) == _lines(loaded)
    assert quiet.points == loaded.points and quiet.work == loaded.work
    # the budget ran out in a bisection: its values are not judged, and no hint says bisected
    cut = [f for f in quiet.findings if f.cut]
    assert cut and quiet.not_judged()
    assert all("bisected" not in f.diagnostic.hint for f in cut)
    assert "not judged, out of budget" in quiet.text()


LITERAL_PLATE = """solid plate {{
    body = Rectangle(center=(0, 0), width={w:.3f}, height=40)
    hole h {{ c = Circle(center=({off}, 0), diameter={d}) }}
}}
"""


@settings(max_examples=3, deadline=None)
@given(off=st.sampled_from([5, 10, 15]), d=st.sampled_from([3, 5, 8]),
       over=st.floats(1.3, 1.9))
def test_law_a_plate_without_params_is_bounded_at_the_computed_width(off, d, over):
    """No `param`: the literal width is lifted and swept across its slider's span (a quarter
    to twice it); its clean low end is where the wall breaks, and the finding is located at
    the literal."""
    brk = 2 * (off + d / 2 + 0.5)
    w = brk * over
    src = LITERAL_PLATE.format(w=w, off=off, d=d)
    rep = sweep(src, "plate.aidl", points=0)
    assert rep.ok and "body_width" in rep.lifted
    [f] = [f for f in rep.findings if list(f.clean) == ["body_width"]
           and f.values["body_width"] < w]
    a, _ = f.clean["body_width"]
    lo, hi = rep.ranges["body_width"]
    assert lo <= w / 4 + 0.01 and hi >= 2 * w - 0.01
    assert brk - 0.02 <= a <= brk + _slack(lo, hi), (brk, a)
    sp = f.diagnostic.span
    assert src[sp.start:sp.end] == f"{w:.3f}" and sp.line == 2


CORNER = """param n = 2, min = 1, max = {N}, step = 1
param d = 4 mm, min = 2 mm, max = {dmax} mm

solid strip {{
    body = Rectangle(center=(0, 0), width={W:.3f}, height=30)
    for i in range(n) {{
        hole h {{ c = Circle(center=({x0:.3f} + i * {P}, 0), diameter=d) }}
    }}
}}
"""


@settings(max_examples=3, deadline=None)
@given(N=st.integers(3, 12), P=st.sampled_from([10, 12, 14]), slack=st.floats(0.6, 2.4))
def test_law_a_count_breaking_only_with_another_params_end_is_found(N, P, slack):
    """A row of `n` holes of diameter `d` at pitch P: its last hole's wall to the edge is
    `slack` + 0.5 mm at n = N with the written d, and breaks only with d at its high end too
    (each alone is clean).  With no Latin hypercube the sweep finds the combination: the
    count is tried at each of its values against the other param's ends; it holds under
    `--set`."""
    from benchmarks.checks.sweep_programs import verify
    dmax = P - 1                          # neighbours never merge
    W = P * (N - 1) + 10 + 2 + 0.5 + slack  # first centre 10 mm in; d=4 leaves slack + 0.5
    src = CORNER.format(N=N, dmax=dmax, W=W, x0=-W / 2 + 10, P=P)
    rep = sweep(src, "strip.aidl", points=0)
    assert rep.ok and rep.skipped == 0
    assert all(len(f.clean) == 2 for f in rep.findings), rep.text()   # neither alone
    assert any(f.values == {"n": N, "d": dmax} for f in rep.findings), rep.text()
    assert rep.combinations() and verify(src, "strip.aidl", rep) == []
