"""Every example and every program models wrote is swept (issue 92; all of them:
benchmarks/checks/sweep_programs.py), ranges declared or not, and each finding holds under a plain
`--set` compile at the values it names, with no problem at the clean end it gives.  A few
here: an example with no declared range, and two programs models wrote whose findings were
wrong before the fixes (honeycomb: `param pitch = af + wall` held at its written value
while af moved, a false W0507; bird house: the written slope 33.69 deg snapped to 34 deg and
called clean, where the roof collides).  Cost: about 6 s of CPU."""
import sys

import pytest

from aidl_lang.params.sweep import sweep
from conftest import ROOT

from benchmarks.checks.sweep_programs import verify


@pytest.mark.parametrize("rel", [
    "examples/key.aidl",
    "data/model_runs/issue84b/run/12_honeycomb_coaster.aidl",
    "data/model_runs/issue84b/run/08_bird_house.aidl",
])
def test_each_finding_holds_under_set_at_the_values_it_names(rel):
    p = ROOT / rel
    src = p.read_text()
    rep = sweep(src, str(p))
    assert rep.ok and rep.swept and rep.unranged       # no declared range: swept all the same
    assert rep.findings and rep.skipped == 0
    assert verify(src, str(p), rep) == []
    for name in rep.unranged:
        assert f"`{name}` (no declared range, swept " in rep.text()


@pytest.mark.parametrize("rel", [
    "data/model_runs/issue73/programs/d08_l_profile.aidl",     # drawn by its points only
    "data/model_runs/issue73/programs/e08_door_hanger.aidl",
])
def test_a_program_without_params_is_swept_by_its_numbers(rel):
    """No `param`: the numbers that size the parts are lifted into params of a copy (the
    copy draws what the file draws), each finding is located at the number in the file and
    holds when that value is written there (benchmarks' `verify`, W0510 compared with the
    file as `--set` compares it with the defaults)."""
    import aidl_lang
    from aidl_lang.params.sweep_literals import lift
    p = ROOT / rel
    src = p.read_text()
    rep = sweep(src, str(p))
    assert rep.ok and rep.swept and rep.lifted and rep.findings and rep.skipped == 0
    assert "nothing" not in rep.text() and "no numeric `param`: the numbers" in rep.text()
    for f in rep.findings:
        sp = f.diagnostic.span
        lit = rep.lifted[next(iter(f.clean))]
        assert sp == lit.span and sp.file == str(p) and f.diagnostic.fix is None
        assert src[sp.start:sp.end].lstrip("-").split()[0] == lit.text.split()[0]
    assert verify(src, str(p), rep) == []
    copy = aidl_lang.compile(source=lift(src, str(p)).source, path=str(p))
    mine = aidl_lang.compile(source=src, path=str(p))
    assert [(d.code, d.span and d.span.line) for d in copy.diagnostics] == \
        [(d.code, d.span and d.span.line) for d in mine.diagnostics]
    assert [round(x.area, 6) for x in copy.parts] == [round(x.area, 6) for x in mine.parts]


def test_a_value_the_lifted_sweep_tried_compiles_without_a_traceback():
    """The robot chassis' cable hole at 40 mm (the sweep of its numbers tried it) runs into
    the caster's holes: W0508, whose fix looked for a move and raised a TypeError (a local
    named like the holes' boxes it was given, output/checks/holes/clearing.py)."""
    import aidl_lang
    p = ROOT / "data/model_runs/issue84/run/11_robot_chassis.aidl"
    src = p.read_text()
    assert "diameter=20)" in src
    r = aidl_lang.compile(source=src.replace("diameter=20)", "diameter=40)"), path=str(p))
    assert "W0508" in {d.code for d in r.diagnostics}
