"""Issue 111's round sixteen: what models reach for in the tree of the twentieth session.

E0109 of a point scaled by a 1/length says what the factor was and that a bare number passed
to a `def` keeps no unit (run ew's candy-cane holder: `toward(a, b, 10)`); the `distance` of
a list left empty by an earlier error says it follows from it (the same run: its hint had the
model swap the arguments)."""
from __future__ import annotations

from pathlib import Path

import aidl_lang
from aidl_lang.library.reference import lookup_text

ROOT = Path(__file__).resolve().parent.parent
RUNS = ROOT / "data" / "model_runs"


def _errors(r):
    return [d for d in r.diagnostics if d.is_error]


def test_run_ew_a_bare_number_passed_to_a_def_is_named_and_the_follow_on_said():
    path = RUNS / "issue111ew" / "drafts" / "06_candy_cane_holder.attempt1.aidl"
    src = path.read_text()
    r = aidl_lang.compile(source=src, path=str(path))
    e1, e2 = _errors(r)
    assert e1.code == "E0109" and e1.message.endswith("not a 1/length")
    assert "a bare number passed to a `def` stays a plain number: `10 mm`" in e1.hint
    assert e2.code == "E0108" and "an error above left its shapes out" in e2.message
    assert "follows from it" in e2.hint and "draws a line" not in e2.hint
    # followed: `10 mm`, and both errors are gone
    fixed = src.replace("toward(STEPS[i], TIPS[i], 10)", "toward(STEPS[i], TIPS[i], 10 mm)")
    assert fixed != src
    r2 = aidl_lang.compile(source=fixed, path=str(path))
    assert not _errors(r2), [d.message for d in _errors(r2)]


def test_a_point_times_a_length_and_an_empty_list_alone():
    r = aidl_lang.compile(source="solid a { c = Circle(center=(10, 0) * 2 mm, radius=3) }\n")
    (e,) = _errors(r)
    assert e.code == "E0109" and e.message.endswith("not a length") and "`p * 2`" in e.hint
    # a drawing of nothing with no error before it keeps the plain hint
    r = aidl_lang.compile(source="""solid a {
    c = Circle(center=(0, 0), radius=3)
    drawing marks { t = Text("", position=(0, 0), size=3) }
    assert distance(c, marks) >= 1 mm
}
""")
    (e,) = _errors(r)
    assert e.code == "E0108" and "error above" not in e.message and "draws a line" in e.hint


def test_the_docs_say_a_bare_number_in_a_def_stays_plain():
    assert "pass `10 mm`" in lookup_text("def")[0]
    assert "passed to\na `def`, it stays a plain number" in lookup_text("units")[0]
    from aidl_lang.llm.prompt import system_prompt
    assert "passed to a\n`def`, it stays plain" in system_prompt()


def test_run_eh_e0405_names_the_constraint_that_moved_the_word_within_its_part():
    """Run eh's sign: the word moved 4.25 mm up inside `letters` by the backer's height
    relation; E0405 named only the layout's `Below`.  Now: what moved, from where to where,
    by which constraint, and not the layout's relation (it moves the part whole)."""
    path = RUNS / "issue111eh" / "drafts" / "05_staff_only_sign.attempt3.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    es = [e for e in _errors(r) if e.code == "E0405"]
    assert len(es) == 2
    for e in es:
        assert ("the solve moved `letters.word.position.y` from 0 mm as written to 4.25374 "
                "mm, by `backer.plate.bb.height == letters.bb.height + 2 * 10 mm` (line 32)"
                in e.message)
        assert "Below" not in e.message


def test_e0405_of_a_value_as_written_or_a_pattern_copy_says_nothing_moved():
    """An assert failing on values the solve left where written says nothing of moves; a
    pattern's copy (its start is its original's) is not said to have moved from it."""
    r = aidl_lang.compile(source="""solid plate {
    body = Rectangle(center=(0, 0), width=100, height=40)
    hole h { c = Circle(center=(-30, 0), radius=3) }
    row = LinearPattern(h, 3, (30, 0))
    AlignLeft(row[0], body)
    assert body.width == 90 mm
    assert row[2].c.center.x == 0 mm
}
""")
    es = [e for e in _errors(r) if e.code == "E0405"]
    assert len(es) == 2 and not any("the solve moved" in e.message for e in es)


def test_runs_fd_fe_w0517_says_how_deep_not_the_sheet():
    """Run fd's touchscreen stand: a 0.07 mm nib beside a joint's end was "3.84 mm deep";
    run fe's switch extender: a pull disc 1.2-1.5 mm into its rails' ends (the plates side by
    side in one plane) was "3 mm deep", the sheet's thickness.  Both now say the overlap's
    own thickness; a slot too narrow still says the whole shortfall (test_checks)."""
    for run, name, lo, hi in (("issue111fd", "02_touchscreen_stand", 0.05, 0.3),
                              ("issue111fe", "01_switch_extender", 1.0, 1.6)):
        path = RUNS / run / "run" / f"{name}.first_valid.aidl"
        r = aidl_lang.compile(source=path.read_text(), path=str(path))
        ws = [d for d in r.diagnostics if d.code == "W0517"]
        assert len(ws) == 2
        for w in ws:
            deep = float(w.message.split(" mm deep")[0].rsplit(" ", 1)[1])
            assert lo <= deep <= hi, w.message


def test_run_ff_a_layout_on_a_given_sheet_is_not_told_of_the_default_one(tmp_path):
    """Run ff's tip-up: `aidl render --layout sheet --sheet 800x600mm` said the 450 x 550 mm
    frame "does not fit the 600 x 400 mm sheet" above a layout on the 800 x 600 one.  A
    layout speaks of its own sheet; `aidl check` keeps the note."""
    import subprocess
    import sys
    path = RUNS / "issue111ff" / "run" / "06_ice_tip_up.first_valid.aidl"
    src = path.read_text()
    assert "W0534" in [d.code for d in aidl_lang.compile(source=src, path=str(path)).diagnostics]
    (tmp_path / "t.aidl").write_text(src)
    run = subprocess.run([sys.executable, "-m", "aidl_lang", "render", "t.aidl", "--layout",
                          "sheet", "--sheet", "800x600mm", "-o", "t.svg"], cwd=tmp_path,
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "W0534" not in run.stderr and "800 x 600 mm" in run.stderr + run.stdout
