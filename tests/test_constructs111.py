"""Issue 111's language cases: a param's default and range may read the constants above it
(docs/language.md 2.3; two of 16 first tries failed on `hooks = 5` then `param plate_w =
hooks * pitch + 30 mm`), and one that cannot says the real rule once, with no follow-on
error; a failed assert shows the value of each name and member its condition reads."""
import aidl_lang
from aidl_lang.params.sweep import sweep

RACK = """units mm
param n = 5, min = 2, max = 8
hooks = n + 1
pitch = 30 mm
margin = 15 mm
param plate_w = hooks * pitch + 2 * margin, min = 2 * margin + pitch, max = 400 mm
later = plate_w / 2
solid rack {
    body = Rectangle(center=(0, 0), width=plate_w, height=60)
    hole slot { c = Circle(center=(0, 0), radius=3) }
    CenterInside(slot, body)
}
"""


def test_a_params_default_and_range_read_the_constants_above_it():
    r = aidl_lang.compile(source=RACK)
    assert r.ok, [d.message for d in r.errors]
    assert abs(r.compiled.model.constants["plate_w"].const() - 210) < 1e-9
    assert abs(r.compiled.model.constants["later"].const() - 105) < 1e-9
    # the constant follows a param above it; the range follows the constants
    r = aidl_lang.compile(source=RACK, overrides={"n": "3"})
    assert r.ok and abs(r.compiled.model.constants["plate_w"].const() - 150) < 1e-9
    r = aidl_lang.compile(source=RACK, overrides={"plate_w": "50 mm"})
    [e] = r.errors
    assert e.code == "E0124" and "60 mm .. 400 mm" in e.message


def test_the_sweep_reads_the_constants_its_ranges_use():
    rep = sweep(RACK, "rack.aidl", seconds=60)
    assert rep.ok and not rep.findings, [f.message for f in rep.findings]
    assert rep.swept == ["n", "plate_w"]


def test_a_constant_that_reads_a_later_param_says_why_once():
    src = RACK.replace("param n = 5, min = 2, max = 8\nhooks = n + 1\n",
                       "hooks = n + 1\nparam n = 5, min = 2, max = 8\n")
    r = aidl_lang.compile(source=src)
    [e] = r.errors                     # no follow-on "unknown name `plate_w`"
    assert (e.code, e.span.line, e.span.col) == ("E0101", 6, 17)
    assert e.message == ("`hooks` (line 2) is worked out after the params: it reads `n`, "
                         "defined below it (line 3)")
    assert "move line 3 above line 2" in e.hint


def test_a_failed_assert_gives_the_value_of_each_name_and_member_it_reads():
    src = """units mm
wall = 3 mm
solid part {
    body = Rectangle(center=(0, 0), width=120 mm, height=40 mm)
    hole h { c = Circle(center=(0, 0), radius=5 mm) }
    CenterInside(h, body)
    assert abs(body.bb.width - 2 * wall - 110 mm) < 0.01 mm
    assert wall > 5 mm
    assert h.c.radius * 2 + wall == body.bb.height / 2
}
"""
    r = aidl_lang.compile(source=src)
    got = {d.span.line: d.message for d in r.errors}
    assert got[7].endswith(": 4 mm < 0.01 mm is false (where body.bb.width = 120 mm, "
                           "wall = 3 mm)")
    assert got[8].endswith(": 3 mm > 5 mm is false")     # the side is the name: said once
    assert got[9].endswith(": 13 mm == 20 mm is false (where h.c.radius = 5 mm, wall = 3 mm, "
                           "body.bb.height = 40 mm)")
    # in inches, in the file's unit
    r = aidl_lang.compile(source=src.replace("units mm", "units in").replace(" mm", " in"))
    assert {d.span.line: d.message for d in r.errors}[7].endswith(
        "(where body.bb.width = 120 in, wall = 3 in)")
