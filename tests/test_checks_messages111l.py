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
    assert "passed to a\n`def`, it stays a plain number" in system_prompt()
