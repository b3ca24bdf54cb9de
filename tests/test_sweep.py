"""`aidl check --sweep` (aidl_lang/sweep.py, issue 84): the design compiled across its
params' declared ranges through the real parser, solver and Manifold; a hole that leaves its
plate past a value inside the range is found, bisected and located at the `param` line; a
design clean across its ranges has no finding; the budget bound counts the points skipped;
the CLI and the MCP `check` (through the SDK's own stdio client) give the same."""
import json
import os
import subprocess
import sys

import pytest
from hypothesis import given, settings, strategies as st

import aidl_lang
from aidl_lang.sweep import sweep
from conftest import ROOT

# the hole (radius 3) sits at x = offset on a plate 50 mm wide (edges at +-25): past
# offset = 21.5 mm its wall to the edge is thinner than 0.5 mm (W0507), past 22 it breaks
# through, past 28 it cuts nothing (W0502)
HOLE = """param offset = 10 mm, min = 0 mm, max = 30 mm
param r = 3 mm

solid plate {
    body = Rectangle(center=(0, 0), width=50, height=30)
    hole h { c = Circle(center=(offset, 0), radius=r) }
}
"""

CLEAN = """param width = 60 mm, min = 40 mm, max = 80 mm
param r = 3 mm, min = 2 mm, max = 4 mm
param n = 3, min = 1, max = 4

solid plate {
    body = Rectangle(center=(0, 0), width=width, height=30)
    for i in range(n) {
        hole h { c = Circle(center=(-15 + 10 * i, 0), radius=r) }
    }
}
"""


def test_a_hole_leaving_its_plate_inside_the_range_is_found_and_the_range_narrowed():
    rep = sweep(HOLE, "plate.aidl")
    assert rep.ok and rep.swept == ["offset"] and rep.unranged == ["r"]
    [f] = rep.findings
    assert f.values == {"offset": 30.0}          # the high end, where the hole cuts nothing
    assert f.code == "W0502"
    lo, hi = f.clean["offset"]
    # the wall is 25 - 3 - offset: 0.5 mm at 21.5; bisected to 1% of the 30 mm range
    assert lo == 0.0 and 21.5 - 0.3 - 1e-9 <= hi < 21.55
    d = f.diagnostic
    assert d.code == "W0110" and d.severity == "warning"
    assert d.span.line == 1 and d.span.col == 1              # the `param offset` line
    assert "offset=30 mm" in d.message and "W0502" in d.message and "W0507" in d.message
    assert f"max={hi:.12g} mm" in d.hint


def test_a_design_clean_across_its_ranges_has_no_finding():
    rep = sweep(CLEAN, "plate.aidl")
    assert rep.ok and rep.swept == ["width", "r", "n"] and rep.unranged == []
    assert rep.findings == [] and rep.skipped == 0
    # ends and middles (3 x 3, less width's and r's middles: their written values) and 8
    # combinations on the sliders' steps (less one met twice)
    assert 7 + 6 <= rep.points <= 7 + 8
    assert "clean" in rep.text()


def test_the_solver_is_reused_between_points():
    """Points whose model has the written values' equations re-solve on the warm solver
    (Solver.set_value), as the sliders do."""
    rep = sweep(HOLE, "plate.aidl")
    assert rep.warm == rep.points


def test_the_budget_bounds_the_sweep_and_says_how_many_points_were_skipped():
    planned = sweep(CLEAN, "plate.aidl").points
    rep = sweep(CLEAN, "plate.aidl", seconds=0.0)
    assert rep.points == 0 and rep.skipped == planned and rep.findings == []
    assert f"{rep.skipped} points skipped" in rep.text()


def test_params_without_a_range_are_named_once_and_not_swept():
    rep = sweep("param w = 40 mm\nsolid s { b = Rectangle(center=(0, 0), width=w, height=10) }",
                "s.aidl")
    assert rep.swept == [] and rep.unranged == ["w"] and rep.points == 0
    assert rep.text().count("not swept (no declared range): w") == 1
    assert "nothing swept" in rep.text()


def test_a_program_that_does_not_compile_is_not_swept():
    rep = sweep("param w = 40 mm, min = 10 mm, max = 50 mm\nsolid s { b = Circel() }", "s.aidl")
    assert not rep.ok and rep.errors and rep.points == 0


def test_result_sweep_is_the_same_function():
    r = aidl_lang.compile(source=HOLE, path="plate.aidl")
    rep = r.sweep()
    assert [f.values for f in rep.findings] == [{"offset": 30.0}]


@settings(max_examples=6, deadline=None)
@given(edge=st.floats(min_value=12.0, max_value=22.0))
def test_law_the_clean_bound_is_where_the_wall_reaches_the_minimum(edge):
    """Over generated ranges, the clean range's end is within the tolerance below the value
    where the hole's wall to the edge is 0.5 mm (25 - 3 - x = 0.5), whenever the declared
    range reaches past it; a range that stays below it has no finding."""
    top = edge + 10.0
    src = HOLE.replace("max = 30 mm", f"max = {top:.4f} mm")
    rep = sweep(src, "plate.aidl", points=0)
    [f] = rep.findings
    hi = f.clean["offset"][1]
    # the circle is cut as a polygon: its wall is a hair wider than the true circle's
    assert 21.5 - 0.01 * top - 1e-6 <= hi < 21.55
    src = HOLE.replace("max = 30 mm", f"max = {min(edge, 21.0):.4f} mm")
    assert sweep(src, "plate.aidl", points=0).findings == []


def test_cli_check_sweep(tmp_path):
    f = tmp_path / "plate.aidl"
    f.write_text(HOLE)
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(f), "--sweep"],
                       capture_output=True, text=True, env=env, cwd=str(ROOT))
    assert p.returncode == 0                # a finding is a warning
    assert "warning[W0110]" in p.stderr + p.stdout
    assert "1 finding (W0110)" in p.stdout and "not swept (no declared range): r" in p.stdout
    p = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(f), "--sweep",
                        "--json"], capture_output=True, text=True, env=env, cwd=str(ROOT))
    doc = json.loads(p.stdout)
    assert doc["sweep"]["findings"][0]["values"] == {"offset": 30.0}
    assert [d["code"] for d in doc["diagnostics"]] == ["W0110"]


@pytest.mark.asyncio
async def test_mcp_check_with_sweep_through_the_sdk_client(tmp_path):
    pytest.importorskip("mcp")
    from mcp.client.session import ClientSession
    from mcp.client.stdio import StdioServerParameters, stdio_client
    root = tmp_path / "work"
    root.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "AIDL_DEBUG"}
    params = StdioServerParameters(command=sys.executable,
                                   args=["-m", "aidl_lang.cli", "mcp", "--root", str(root)],
                                   env=env, cwd=str(ROOT))
    async with stdio_client(params) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            r = await session.call_tool("check", {"source": HOLE, "sweep": True})
            doc = r.structured_content
            assert doc["ok"] and doc["sweep"]["swept"] == ["offset"]
            [f] = doc["sweep"]["findings"]
            assert f["values"] == {"offset": 30.0} and f["code"] == "W0502"
            assert 21.2 <= f["clean"]["offset"][1] < 21.5
            w = [d for d in doc["diagnostics"] if d["code"] == "W0110"]
            assert len(w) == 1 and w[0]["span"]["line"] == 1
            r = await session.call_tool("check", {"source": HOLE})
            assert "sweep" not in r.structured_content


# ------------------------------------------------------------- the gallery, swept
# every example and generator of the gallery (aidl_lang/studio/gallery.py: examples/*.aidl,
# examples/generators/*.aidl, the studio's forms, the synthesized generator programs) with
# ranged params, swept at each param's ends and middle (no Latin hypercube in the suite: the
# ends find what the combinations found, at a third of the points).  Left as found, with
# what the sweep reports (h12-sweep's closing note): their ranges come from the generators'
# own asserts (gallery.slider_range) or need the generator changed, not one number narrowed.
LEFT = {
    "example/phone_stand": "slot under the 3 mm sheet: the parts collide (W0517); kept: the "
                           "suite shows that collision with slot=2.5 mm (test_assembly, "
                           "test_checks, test_mcp, test_lsp_preview)",
    "generator/divider_tray": "rows=6, cols=6: halving slots of the dividers break through "
                              "their outline (W0510)",
    "generator/flex_box": "height under 22 mm: the flex cuts cut the wall apart (W0510)",
    "generator/gear_train": "module=0.5 mm: thin wall at the bore (W0507); backlash=0: the "
                            "gears collide (W0517)",
    "generator/hinged_box": "thickness=1 mm: thin wall at the cheek's bore (W0507)",
    "generator/mounting_plate": "height=12.5 mm, corner_radius=16 mm, inset at either end: "
                                "holes merge or leave the plate (W0508, W0507, W0510)",
    "generator/planetary": "planets=5 (W0511), planet and sun off the evenly-spaced counts "
                           "(E0405), module=0.5 mm (W0507)",
    "generator/rack_and_pinion": "teeth=8: rack and pinion collide (W0517)",
    "generator/rounded_tab": "width=5 mm, hole_d=24 mm: the eye leaves the tab (W0510, W0504)",
    "generator/text_on_arc": "spacing=0.2: letters drawn over each other (W0513)",
    "generator/washer": "outer=2.5 mm, inner=10.6 mm: the bore removes the washer (W0503)",
}


def _ranged():
    from aidl_lang.studio import gallery
    out = []
    for e in gallery.entries():
        if any(p["declared"] and p["min"] is not None and p["max"] is not None
               and p["kind"] in ("length", "angle", "number", "integer") for p in e.params):
            marks = ([pytest.mark.xfail(run=False, reason=LEFT[e.id])] if e.id in LEFT else [])
            out.append(pytest.param(e, id=e.id, marks=marks))
    return out


@pytest.mark.parametrize("entry", _ranged())
def test_every_gallery_entry_is_clean_across_its_declared_ranges(entry, tmp_path):
    rep = sweep(entry.source, str(tmp_path / "main.aidl"), points=0)
    assert rep.ok
    assert rep.findings == [], "\n".join(
        f"{d.message}\n  {d.hint}" for d in rep.diagnostics)
