"""Issue 111's round fifteen: what models reach for in the tree of the nineteenth session.

E0101 of a statement word read as a value (run ec's quilt hanger: `position=(0, thickness,
0)` was offered `nut_thickness`, a nut's height); E0134, a Text that draws nothing (run ec's
福 in a font without it: cut as nothing with only W0105)."""
from __future__ import annotations

from pathlib import Path

import aidl_lang
from aidl_lang.library.reference import lookup_text

ROOT = Path(__file__).resolve().parent.parent
RUNS = ROOT / "data" / "model_runs"


def _errors(r):
    return [d for d in r.diagnostics if d.is_error]


def test_run_ec_thickness_read_as_a_value_is_told_it_is_a_statement():
    path = RUNS / "issue111ec" / "drafts" / "07_quilt_hanger.attempt1.aidl"
    src = path.read_text()
    r = aidl_lang.compile(source=src, path=str(path))
    errs = _errors(r)
    assert errs and all(e.code == "E0101" for e in errs)
    e = errs[0]
    assert "`thickness` is a statement, not a value" in e.message
    # the file's own figure, a name the file does not use (its `t` is a loop's), and no near
    # name (`nut_thickness` is a nut's height)
    assert "`thickness_value = 6 mm`, then `thickness thickness_value`" in e.hint
    assert "write `thickness_value` here" in e.hint
    assert not e.suggestions and "nut_thickness" not in e.hint
    # followed: the hanger compiles, its back boards 6 mm back
    fixed = src.replace("thickness 6 mm\n", "thickness_value = 6 mm\nthickness thickness_value\n",
                        1).replace("position=(0, thickness, 0)", "position=(0, thickness_value, 0)")
    r2 = aidl_lang.compile(source=fixed, path=str(path))
    assert r2.ok, [d.message for d in _errors(r2)]


def test_the_hint_names_a_constant_the_program_does_not_use():
    src = ("kerf 0.2 mm\nsolid a {\n    kerf_w = 1 mm\n    body = Rectangle(center=(0, 0), "
           "width=40 + kerf, height=10)\n}\n")
    (e,) = _errors(aidl_lang.compile(source=src))
    assert e.code == "E0101" and "`kerf` is a statement" in e.message
    assert "`kerf_value = 0.2 mm`, then `kerf kerf_value`" in e.hint
    # without the statement: its example figure
    (e,) = _errors(aidl_lang.compile(source=src.replace("kerf 0.2 mm\n", "")))
    assert "`kerf_value = 0.15 mm`" in e.hint


def test_a_text_with_no_glyph_in_its_font_is_an_error():
    """Run ec's fu diamond: the character 福 in `font="sans"`, which has no CJK."""
    src = ('solid tag {\n    body = Circle(center=(0, 0), radius=30)\n'
           '    hole fu { t = Text("福", (0, 0), size=20, font="sans", stencil=true) }\n}\n')
    (e,) = _errors(aidl_lang.compile(source=src))
    assert e.code == "E0134" and "font `sans` has no glyph for any" in e.message
    assert "U+798F" in e.message and (e.span.line, e.span.col) == (3, 24)
    assert "installed here" in e.hint or "fc-list :lang=zh" in e.hint
    # the stroke font likewise; some characters drawn: the warning, as before
    (e,) = _errors(aidl_lang.compile(source=src.replace(', font="sans", stencil=true', "")
                                     .replace("hole fu", "drawing fu")))
    assert e.code == "E0134" and "single-stroke font" in e.message
    r = aidl_lang.compile(source=src.replace('"福"', '"FU 福"'))
    assert r.ok and [d.code for d in r.diagnostics if d.code.startswith("W01")] == ["W0105"]
    # spaces draw nothing either way: a text of a missing character and spaces is E0134
    (e,) = _errors(aidl_lang.compile(source=src.replace('"福"', '" 福 "')))
    assert e.code == "E0134"


def test_docs_fonts_says_which_font_draws_which_script():
    text, found = lookup_text("font")
    assert found and text.startswith("fonts")
    for word in ("single-stroke", "fc-list :lang=zh", "E0134", "W0105", "1.4 x `size`"):
        assert word in text
    text, found = lookup_text("thickness")
    assert found and "name it once, `t = 6 mm` then\n`thickness t`, and write `t`" in text
