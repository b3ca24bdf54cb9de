"""Issue 74: a perforated panel written as a loop of holes placed by their coordinates costs
the solver stages a constant, small amount of work per hole: no ladder of attempts, Newton
step, Jacobian column or gauge vector per hole.  Counts of operations, not wall time:
between 2,000 and 20,000 holes the solve starts the same number of iterative-deepening
ladders and Newton steps, the freedom count builds the same number of gauge vectors, and
the Jacobians the redundancy search and the ancestor rows form are over the unknowns rows
use, not every free unknown (nor, in the panel's own count, its 2 frame unknowns per
hole); the structures grow exactly one per hole and the freedom left is what the holes leave
(each hole's position, 2 per hole, and the panel's own 2)."""
from __future__ import annotations

import re

import pytest

from aidl_lang.pipeline import compile_source
from aidl_lang.solver.core import hierarchy
from aidl_lang.solver import solve
from aidl_lang.solver.diagnosis import freedom
from aidl_lang.solver.diagnosis.freedom import degrees_of_freedom, freedom_text
from aidl_lang.solver.diagnosis.redundancy import redundancies
from aidl_lang.solver.core.tape import Tape
from benchmarks.checks.perforated import panel_aidl as panel   # the panel: a loop of holes


def _counts(nx: int, ny: int, monkeypatch) -> dict:
    res = compile_source(panel(nx, ny), "panel.aidl", do_solve=False)
    assert res.ok, [d.message for d in res.sink.items]
    counts = {"ladders": 0, "gauges": 0, "columns": 0}
    steps, gauges, jacobian = hierarchy.Solver.steps, freedom._gauge_shifts, Tape.jacobian

    def counted_steps(self, s):
        counts["ladders"] += 1
        return steps(self, s)

    def counted_gauges(*a, **k):
        counts["gauges"] += 1
        return gauges(*a, **k)

    def counted_jacobian(self, x, cols, *a, **k):
        counts["columns"] = max(counts["columns"], len(cols))
        return jacobian(self, x, cols, *a, **k)
    monkeypatch.setattr(hierarchy.Solver, "steps", counted_steps)
    monkeypatch.setattr(freedom, "_gauge_shifts", counted_gauges)
    monkeypatch.setattr(Tape, "jacobian", counted_jacobian)
    result = solve(res.model)
    assert result.converged
    dofs = degrees_of_freedom(result.solver, floating=False)
    assert redundancies(result.solver) == []
    monkeypatch.undo()
    counts["structures"] = len(res.model.structures)
    counts["dof"] = int(re.match(r"(\d+) degrees", freedom_text(dofs)).group(1))
    counts["iterations"] = result.iterations
    return counts


def test_the_solver_stages_do_no_work_per_hole_of_a_loop_panel(monkeypatch):
    small = _counts(20, 100, monkeypatch)           # 2,000 holes
    large = _counts(100, 200, monkeypatch)          # 20,000 holes
    assert small["structures"] == 2_001 and large["structures"] == 20_001
    assert small["dof"] == 2 * 2_000 + 2 and large["dof"] == 2 * 20_000 + 2
    for what in ("ladders", "gauges", "iterations", "columns"):
        assert small[what] == large[what], (what, small, large)
    # every Jacobian is over the unknowns its rows use (the rectangle's), not every free
    # unknown (4 per hole), nor the panel's children's frames (2 per hole) in its own count
    assert large["ladders"] <= 2 and large["gauges"] <= 1 and large["columns"] <= 16


@pytest.mark.parametrize("where", ["inside", "parent", "none"])
def test_the_count_without_rows_agrees_with_the_full_one(where):
    """The freedom count's short way for a structure without rows (no gauge vectors built)
    gives each structure the rank and freedom the full way (``floating=True``: gauge vectors
    and their null space) gives, beside holes a constraint holds: its own (`Fixed(c)`) or
    its parent's (issue 23's rows of an ancestor)."""
    inside = "Fixed(c)" if where == "inside" else ""
    parent = "Fixed(h[1].c)" if where == "parent" else ""
    src = f"""solid panel {{
  body = Rectangle(center=(0, 0), width=100 mm, height=40 mm)
  Fixed(body)
  for i in range(3) {{
    hole h {{
      c = Circle(center=(-30 mm + i * 30 mm, 0 mm), radius=2 mm)
      {inside}
    }}
  }}
  {parent}
}}
"""
    res = compile_source(src, "panel.aidl", do_solve=False)
    assert res.ok, [d.message for d in res.sink.items]
    result = solve(res.model)
    assert result.converged
    short = degrees_of_freedom(result.solver, floating=False)
    full = degrees_of_freedom(result.solver, floating=True)
    assert [(d.structure.path, d.unknowns, d.rank) for d in short] == \
        [(d.structure.path, d.unknowns, d.rank) for d in full]
    by = {d.structure.path: d for d in short}
    assert all(by[f"panel.h[{i}]"].dof == 0 for i in range(3))   # each hole's own freedom
    # is its frame's (its position), counted by the panel: 2 per hole its parent's row does
    # not hold (a hole's own `Fixed(c)` holds the circle in the hole's frame only); the
    # figures of the tree before the short way (main, 2026-11-25)
    assert by["panel"].dof == (4 if where == "parent" else 6)
