"""Over-constrained models, as models often write them (issue 48): every analysis of a check
(the solve, the conflict search, W0401's redundancy search, the freedom count, what slides)
stays inside the compile's budget, says why anything was not searched, and names what it
finds.

* The issue's program: ``gear_pair`` under a plate placed by ``Below`` (6,264 unknowns when
  the box spoilt the gears' pinning; a 24 s SVD per constructor span, 99 s in all).
* Every example with consistent constraints added that restate solved values, and with a
  duplicated constraint.
* 100 generated assemblies of fixed parts with holes, each with random redundant (and some
  conflicting) constraints added: a fully constrained model with a consistent constraint
  added must report that constraint (W0401), unless the search says it did not look.
"""
from __future__ import annotations

from aidl_lang.base.limits import now as budget_clock      # the budget's clock: CPU seconds

import random
import re
import time

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

import aidl_lang
from aidl_lang.base.limits import DEFAULT_BUDGET
from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver
from aidl_lang.solver.core import rank as R
from aidl_lang.solver.diagnosis import freedom, redundancy

from conftest import EXAMPLES, ROOT

# Every budget here counts this process's CPU seconds (``time.monotonic`` is the
# ``cpu_clock`` fixture's clock, tests/cpu_clock.py), and so does every `wall` figure: the
# same work meets the same deadline on a busy machine as on a quiet one.
pytestmark = [pytest.mark.timing, pytest.mark.usefixtures("cpu_clock")]

GEAR_PLATE = ROOT / "tests" / "programs" / "gear_pair_plate_below.aidl"
BUDGET = DEFAULT_BUDGET.scaled(0.2)      # 3 s: each program is far smaller


def _check(path: str, source: str | None = None, budget=BUDGET):
    """What ``aidl check`` runs, through the public API: compile, the redundancy search (in
    the CLI's limits), the freedom count and what slides, all in one budget; ``(result,
    seconds, freedom text)`` (CPU seconds: the ``cpu_clock`` fixture)."""
    from aidl_lang.cli.main import REDUNDANCY_ROWS, REDUNDANCY_SECONDS
    t0 = time.monotonic()
    r = aidl_lang.compile(source=source, path=path, budget=budget) if source is not None \
        else aidl_lang.compile(path=path, budget=budget)
    text = ""
    if r.ok:
        end = r.compiled.deadline.at
        r.find_redundant(REDUNDANCY_SECONDS, REDUNDANCY_ROWS, deadline=end)
        dofs = freedom.degrees_of_freedom(r.compiled.solve.solver, floating=False, deadline=end)
        text = freedom.freedom_text(dofs, r.sliding())
    return r, time.monotonic() - t0, text


def _assert_well_behaved(r, wall: float, budget=BUDGET):
    codes = [d.code for d in r.diagnostics]
    assert "E0900" not in codes, [d.message for d in r.diagnostics]
    # the budget's time, a margin for one step past the last look at the clock
    assert wall <= budget.seconds * 1.25 + 1.0, wall
    if r.not_searched:
        assert r.not_searched_why in ("out of time", "too large", "out of time and too large")


def test_the_issue_program_checks_in_well_under_a_second():
    """The issue's 25 lines: the Below's box reads the gears' pinned teeth, which stay
    pinned (26 unknowns, not 6,264) and the whole check takes a fraction of a second."""
    r, wall, text = _check(str(GEAR_PLATE), budget=DEFAULT_BUDGET)
    assert r.ok, [d.message for d in r.diagnostics]
    assert r.compiled.solve.n_unknowns <= 30
    assert r.not_searched == 0 and text == "fully constrained"
    assert wall < 3.0, wall                  # ~0.4 s here; before: 99-190 s and 1.9 GB
    # the assertion in the program holds: the axle holes sit on the gear centers
    gx = r.value("gearset.pair.gear2.hub.center").mm[0]
    assert abs(r.value("gearset.plate.axle2.c.center").mm[0] - gx) < 1e-6


def test_a_conflict_through_pinned_teeth_is_named_at_the_users_line():
    """The plate placed by `Below` under the gears and also at y = 0: the conflict runs
    through the gears' pinned teeth (the box reads them), and names the user's two
    constraints with the stdlib's; the error sits on the user's own line, not on a line of
    std/gears.aidl (without pinning no conflict set was found at all)."""
    src = GEAR_PLATE.read_text().replace(
        "    Below(plate, pair, gap=10)\n",
        "    Below(plate, pair, gap=10)\n    plate.body.center.y == 0\n")
    r, wall, _ = _check(str(GEAR_PLATE), src, budget=DEFAULT_BUDGET)
    (e,) = [d for d in r.diagnostics if d.is_error]
    assert e.code == "E0401" and e.span.file == str(GEAR_PLATE)
    assert src.splitlines()[e.span.line - 1].strip() == "plate.body.center.y == 0"
    # through the teeth ring's axis on its hub (issue 61: that row now reads the ring's own
    # frame, so the set runs on to the pair's placement and the user's `Fixed`); the
    # template's own rows are one entry, the instance as its template draws it (run dn)
    assert "`Below(plate, pair, gap=10)`" in e.hint and "Fixed(pair.gear1.hub.center)" in e.hint
    assert "`gearset.pair` as its template `gear_pair` draws it (its sizes)" in e.hint
    assert "Coincident(teeth_ring.axis, hub.center)" not in e.hint
    assert wall < 5.0, wall


def test_the_unpinned_issue_program_is_searched_without_a_dense_svd(monkeypatch):
    """The same model with pinning off (6,264 unknowns, one block of ~6,000 rows): the
    redundancy search ends in about a second, and no SVD larger than the estimate allows
    is started (the constructors' span is the greedy pass's basis)."""
    big = []
    svd = np.linalg.svd

    def watched(a, *args, **kw):
        big.append(a.shape) if min(a.shape) > 1000 else None
        return svd(a, *args, **kw)
    monkeypatch.setattr(Solver, "pinning", False)
    c = compile_source(GEAR_PLATE.read_text(), str(GEAR_PLATE))
    assert c.ok and c.solve.n_unknowns > 6000
    monkeypatch.setattr(np.linalg, "svd", watched)
    skipped, why = [], set()
    t0 = time.monotonic()
    reds = redundancy.redundancies(c.solve.solver, deadline=budget_clock() + 5.0, skipped=skipped,
                          why=why)
    assert time.monotonic() - t0 < 6.0
    assert big == []
    assert reds == [] and (skipped == [] or why)


def test_no_svd_starts_past_its_estimate(monkeypatch):
    """With the flop limit at 0 every dense factorisation is refused before it starts: the
    constraints it would have measured are "not searched (too large)", never computed late."""
    src = """solid s {
    a = Point(0, 0)
    b = Point(10, 0)
    c = Circle(center=(5, 5), radius=2)
    Distance(a, b, 10)
    b.x - a.x == 10
    Horizontal(Line(a, b))
    Fixed(c.center)
    c.center.x == 5
}
"""
    c = compile_source(src, "t.aidl")
    assert c.ok
    monkeypatch.setattr(R, "MAX_SVD_FLOPS", 0.0)

    def refused(*a, **kw):
        raise AssertionError("an SVD started past its estimate")
    monkeypatch.setattr(np.linalg, "svd", refused)
    skipped, why = [], set()
    redundancy.redundancies(c.solve.solver, skipped=skipped, why=why)
    assert skipped and why == {"too large"}


def test_the_cli_says_why_constraints_were_not_searched(tmp_path, capsys, monkeypatch):
    """Plain ``aidl check`` names the reason on its own line (it said nothing before)."""
    from aidl_lang.cli.main import main
    monkeypatch.setattr(R, "MAX_SVD_FLOPS", 0.0)
    f = tmp_path / "t.aidl"
    f.write_text("solid s {\n    a = Point(0, 0)\n    b = Point(10, 0)\n    Fixed(a)\n"
                 "    Distance(a, b, 10)\n    b.x - a.x == 10\n    Horizontal(Line(a, b))\n}\n")
    assert main(["check", str(f)]) == 0
    out = capsys.readouterr().out
    assert "redundant constraints (W0401): not counted: 2 constraints not searched (too large" \
        in out


# ------------------------------------------------------------------ examples, over-constrained
def _root_end(src: str) -> int:
    """The offset of the closing brace of the last top-level block (the root structure)."""
    depth, last = 0, -1
    for m in re.finditer(r"#[^\n]*|\"(?:\\.|[^\"\\])*\"|[{}]", src):
        t = m.group()
        if t == "{":
            depth += 1
        elif t == "}":
            depth -= 1
            if depth == 0:
                last = m.start()
    return last


def _restatements(r, rng: random.Random, k: int) -> list[str]:
    """``k`` constraints that restate solved point coordinates (consistent: redundant where
    the coordinate is already determined)."""
    root = r.compiled.model.root.name
    pts = [v for v in r.values if v.kind == "point" and v.name.startswith(root + ".")
           and "[" not in v.name and not re.search(r"\.(origin|p\d+)$", v.name)]
    rng.shuffle(pts)
    out = []
    for v in pts[:k]:
        axis = rng.randrange(2)
        name = v.name[len(root) + 1:]
        out.append(f"{name}.{'xy'[axis]} == {v.value[axis]!r}" + (f" {v.unit}" if v.unit else ""))
    return out


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_over_constrained_checks_within_its_budget(path):
    src = path.read_text()
    r, wall, _ = _check(str(path), src, budget=DEFAULT_BUDGET)
    if not r.ok:
        pytest.skip("the example needs an extra it does not have here")
    rng = random.Random(path.stem)
    extra = _restatements(r, rng, 3)
    # and a constraint said twice: the root's first constraint statement, repeated
    model = r.compiled.model
    said = [c for c in model.constraints if c.owner is model.root and not c.implicit
            and c.span is not None and c.span.file == str(path) and c.span.line == c.span.end_line
            and c.span.col == 5]             # a statement of the root's body, not of a loop
    if said:
        line = src.splitlines()[said[0].span.line - 1]
        extra.append(line[said[0].span.col - 1:said[0].span.end_col - 1])
    at = _root_end(src)
    over = src[:at] + "\n    " + "\n    ".join(extra) + "\n" + src[at:]
    r2, wall2, _ = _check(str(path), over, budget=DEFAULT_BUDGET)
    _assert_well_behaved(r2, wall2, DEFAULT_BUDGET)
    assert r2.ok or any(d.code.startswith("E04") for d in r2.diagnostics), \
        [(d.code, d.message) for d in r2.diagnostics if d.is_error]


# ------------------------------------------------------------------ generated assemblies
@st.composite
def _assemblies(draw):
    """An assembly of 1-3 plates, each fixed (or placed beside the previous one), with 0-3
    holes placed by ``At`` from the plate's body center: fully constrained by construction."""
    n = draw(st.integers(1, 3))
    parts = []
    for i in range(n):
        w = draw(st.integers(20, 60))
        h = draw(st.integers(20, 60))
        shape = draw(st.sampled_from(["Rectangle", "RoundedRectangle"]))
        extra = ", corner_radius=3" if shape == "RoundedRectangle" else ""
        lines = [f"body = {shape}(center=({i * 80}, 0), width={w}, height={h}{extra})",
                 "Fixed(body)"]
        for j in range(draw(st.integers(0, 3))):
            dx = draw(st.integers(-(w // 2 - 6), w // 2 - 6))
            dy = draw(st.integers(-(h // 2 - 6), h // 2 - 6))
            lines.append(f"hole h{j} {{ c = Circle(center=({i * 80 + dx}, {dy}), diameter=4) }}")
            lines.append(f"At(h{j}.c.center, body.center, dx={dx}, dy={dy})")
        parts.append((f"p{i}", lines))
    body = []
    for i, (name, lines) in enumerate(parts):
        body.append(f"solid {name} {{\n        " + "\n        ".join(lines) + "\n    }")
        if i == 0 or not draw(st.booleans()):
            body.append(f"Fixed({name})")
        else:
            body.append(f"RightOf({name}, p{i - 1}, gap=10)")
            body.append(f"AlignCenterY({name}, p{i - 1})")
    return "units mm\n\nassembly top {\n    " + "\n    ".join(body) + "\n}\n"


_ADDED = st.lists(st.tuples(st.sampled_from(["restate", "twice", "conflict", "fixed"]),
                            st.integers(0, 10 ** 6)), min_size=1, max_size=3)


# 100 assemblies (200 before h24-suite): every example is held to the same law above
# (test_every_example_over_constrained_checks_within_its_budget)
@settings(max_examples=100, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(_assemblies(), _ADDED)
def test_generated_over_constrained_assemblies(src, added):
    r, wall, text = _check("gen.aidl", src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics if d.is_error]
    _assert_well_behaved(r, wall)
    lines = src.splitlines()
    constraint_lines = [s.strip() for s in lines    # the root's own (4 spaces in)
                        if re.match(r"    (Fixed|RightOf|Align)", s) and s[4] != " "]
    extra, consistent = [], []
    for kind, seed in added:
        rng = random.Random(seed)
        if kind == "restate":
            extra += _restatements(r, rng, 1)
            consistent += extra[-1:]
        elif kind == "twice" and constraint_lines:
            extra.append(rng.choice(constraint_lines))
        elif kind == "fixed":
            extra.append(f"Fixed(p{rng.randrange(src.count('solid p'))}.body.center)")
        else:
            v = _restatements(r, rng, 1)
            if v:
                extra.append(re.sub(r"== (\S+)", lambda m: f"== {float(m.group(1)) + 1.5!r}",
                                    v[0]))
    at = _root_end(src)
    over = src[:at] + "    " + "\n    ".join(extra) + "\n" + src[at:]
    r2, wall2, _ = _check("gen.aidl", over)
    _assert_well_behaved(r2, wall2)
    if not r2.ok:
        # only a conflicting addition may fail (a `Fixed` holds the start, which a part
        # placed by `RightOf` has left), with a located E04xx naming constraints
        assert any(k in ("conflict", "fixed") for k, _ in added)
        assert any(d.code.startswith("E04") and d.span is not None for d in r2.diagnostics)
        event("over-constrained: failed with a located conflict")
        return
    if text == "fully constrained" and consistent and not r2.not_searched:
        # a consistent constraint added to a fully constrained model is implied by the rest:
        # W0401 names it (alone, or in a group of equals)
        event("fully constrained plus a consistent restatement: W0401 checked")
        warned = " ".join(d.message for d in r2.diagnostics if d.code == "W0401")
        for c in consistent:
            assert f"`{c.split(' ==')[0]}" in warned or c.split(" ==")[0] in warned, \
                (c, warned)


def test_the_api_freedom_count_is_bounded():
    """``Result.freedom`` runs in a deadline (by default the program's budget from now):
    past it, a structure is not counted and says why, instead of counting unbounded."""
    r = aidl_lang.compile(path=str(ROOT / "examples" / "telephone.aidl"))
    assert r.ok
    doc = r.freedom(detail=True)
    assert doc["dof"] is not None and all(s["dof"] is not None for s in doc["structures"])
    late = r.freedom(detail=True, deadline=budget_clock() - 1.0)
    assert late["dof"] is None and "not counted (out of time)" in late["text"]
    assert any(s.get("not_counted") == "out of time" and s["dof"] is None
               for s in late["structures"])
