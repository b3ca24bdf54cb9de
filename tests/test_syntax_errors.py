"""Syntax errors where the mistake is (issue 28): an unbalanced bracket is reported at the
bracket never closed (or where the missing opener goes), with the place it probably closes;
Python-style colons and top-level statements inside a structure get hints that say what to
write.  The law: delete any one bracket of an example, standard-library file or test program,
and the first error (or one of its labels) is on the line of the deleted bracket or of its
partner."""
from __future__ import annotations

import pathlib
import subprocess
import sys

import pytest
from hypothesis import given, settings, strategies as st

from conftest import EXAMPLES, ROOT
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.parser import parse
from benchmarks.compile.syntax_errors import bracket_pairs as _pairs

FILES = EXAMPLES + sorted((ROOT / "stdlib").glob("*.aidl")) + \
    sorted((ROOT / "tests/programs").glob("*.aidl"))


def _first_error(src: str, name: str = "t.aidl"):
    sink = DiagnosticSink()
    parse(src, name, sink)
    errors = [d for d in sink.items if d.is_error]
    assert errors, "a deleted bracket must be an error"
    return errors[0]


def _check_deletion(src: str, off: int, line: int, partner: int) -> None:
    d = _first_error(src[:off] + src[off + 1:])
    lines = {d.span.line} | {lab.span.line for lab in d.labels}
    assert lines & {line, partner}, (line, partner, d.span.line, d.message, d.hint)


SAMPLE = 16     # deletions tried per file before it is sampled (see _selection)


def _selection(src: str) -> list[tuple[int, int, int]]:
    """The deletions tried in a file: all of its brackets when it has at most ``SAMPLE``;
    else every k-th bracket in file order (k = ceil(n / SAMPLE), starting at the first), and
    the first and the last of each kind (``(``, ``)``, ``[``, ``]``, ``{``, ``}``) present.  A
    fixed selection (the same on every run): each deletion reparses the whole file, so
    trying all 416 brackets of std/gears.aidl took 15 s of the suite's 10 minutes, and
    SAMPLE 40 19 s of CPU over the 36 files (16: 8.8 s; each deletion's recovery reparses the
    file 6-12 times); test_deleting_brackets_anywhere_in_a_program draws from every bracket
    of every file."""
    pairs = _pairs(src)
    if len(pairs) <= SAMPLE:
        return pairs
    step = -(-len(pairs) // SAMPLE)
    keep = set(pairs[::step])
    for kind in "()[]{}":
        of_kind = [p for p in pairs if src[p[0]] == kind]
        keep.update(of_kind[:1] + of_kind[-1:])
    return sorted(keep)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_every_deleted_bracket_is_reported_where_it_was(path):
    src = path.read_text()
    for off, line, partner in _selection(src):
        _check_deletion(src, off, line, partner)


def test_the_selection_covers_every_kind_of_bracket_in_every_file():
    """The sample above keeps, in each file, every bracket kind the file has, its first and
    last bracket, and at most SAMPLE + 12 deletions."""
    for path in FILES:
        src = path.read_text()
        pairs, chosen = _pairs(src), _selection(src)
        assert set(chosen) <= set(pairs) and (chosen[0], chosen[-1]) == (pairs[0], pairs[-1])
        assert {src[p[0]] for p in chosen} == {src[p[0]] for p in pairs}, path.name
        assert len(chosen) <= SAMPLE + 12 and (len(pairs) > SAMPLE or chosen == pairs)


@settings(max_examples=60, deadline=None)
@given(st.data())
def test_deleting_brackets_anywhere_in_a_program(data):
    """Hypothesis picks the file and the bracket from all of them (the test above tries a
    fixed selection of each file's brackets)."""
    path = data.draw(st.sampled_from(FILES))
    src = path.read_text()
    off, line, partner = data.draw(st.sampled_from(_pairs(src)))
    _check_deletion(src, off, line, partner)


UNCLOSED_BLOCK = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole bore {
        c = Circle(center=(0, 0), radius=5)

    CenterInside(bore, self)
}

solid other {
    r = Rectangle(center=(0, 50), width=10, height=10)
}
"""


def test_unclosed_brace_at_its_opener_with_where_it_ends():
    d = _first_error(UNCLOSED_BLOCK)
    assert (d.code, d.message, d.span.line, d.span.col) == ("E0001", "`{` is never closed", 4, 15)
    assert d.hint == ("add `}` after line 5, where the block probably ends (line 7 is back at "
                      "the indentation of line 4)")
    assert [(lab.span.line, lab.message) for lab in d.labels] == [
        (7, "the block probably ends before this line")]


def test_missing_paren_before_the_next_line():
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20\n"
           "    hole bore {\n        c = Circle(center=(0, 0), radius=5)\n    }\n}\n")
    sink = DiagnosticSink()
    parse(src, "t.aidl", sink)
    (d,) = sink.items                    # not also "unexpected `hole`" and "unexpected `{`"
    assert (d.message, d.span.line, d.span.col) == ("`(` is never closed", 2, 21)
    assert d.hint == ("add `)` at the end of line 2, where the statement ends (the next line "
                      "starts a new one)")
    assert [(lab.span.line, lab.span.col, lab.message) for lab in d.labels] == [
        (2, 56, "`)` probably missing here")]


def test_missing_opening_brace_is_reported_where_it_goes():
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    hole bore\n        c = Circle(center=(0, 0), radius=5)\n    }\n}\n")
    d = _first_error(src)
    assert d.span.line == 3 and d.message == ("`}` on line 5 closes nothing: the `{` that it "
                                              "closes is probably missing here")
    assert d.hint.startswith("add `{` at the end of line 3")
    assert [(lab.span.line, lab.message) for lab in d.labels] == [(5, "`}` closes nothing")]


def test_a_stray_closer_on_one_line_keeps_the_errors_elsewhere():
    src = "solid a {\n    x = = 1\n}\nsolid b {\n    y = (1, 2))\n}\nsolid c {\n    w = 1 2\n}\n"
    sink = DiagnosticSink()
    parse(src, "t.aidl", sink)
    assert [(d.span.line, d.message.split(";")[0]) for d in sink.items] == [
        (2, "unexpected `=`"), (5, "`)` closes nothing"), (8, "unexpected `2`")]


@pytest.mark.parametrize("lines, kw, stmt", [
    (["for i in range(3):"], "for", "for i in range(3)"),
    (["if n > 3:"], "if", "if n > 3"),
    (["if n > 3 {", "    c = Circle((0, 0), 1)", "} else:"], "else", "else"),
])
def test_python_colon_hint(lines, kw, stmt):
    body = "\n".join("    " + ln for ln in lines)
    src = f"n = 4\nsolid s {{\n{body}\n        c = Circle((0, 0), 2)\n}}\n"
    d = _first_error(src)
    assert d.message == f"unexpected `:` after `{kw}`: a block is written in braces"
    assert d.span.line == 2 + len(lines) and src.splitlines()[d.span.line - 1][d.span.col - 1] == ":"
    assert d.hint.startswith(f"AIDL writes blocks with braces, not a colon and indentation: "
                             f"`{stmt} {{` on this line and `}}` after the block's last line")


def test_param_inside_a_structure_says_where_params_go(tmp_path):
    f = tmp_path / "p.aidl"
    f.write_text("units mm\n\nsolid plate {\n    param w = 40 mm, min=10 mm\n"
                 "    body = Rectangle(center=(0, 0), width=w, height=20)\n}\n")
    r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(f)],
                       capture_output=True, text=True, timeout=120, cwd=ROOT)
    assert r.returncode == 1
    first = r.stderr.splitlines()[0]
    assert first.endswith("p.aidl:4:5: error[E0116]: `param` is only allowed at the top level "
                          "of a file, not inside a structure")
    assert ("= hint: params are declared at the top level of the file, before the structures: "
            "move `param w = 40 mm, min=10 mm` above line 3 (`solid plate {`); a value used "
            "only here can be a plain assignment, e.g. `w = 40 mm`") in r.stderr


def test_unclosed_brace_through_the_cli(tmp_path):
    f = tmp_path / "u.aidl"
    f.write_text(UNCLOSED_BLOCK)
    r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(f)],
                       capture_output=True, text=True, timeout=120, cwd=ROOT)
    assert r.returncode == 1 and "u.aidl:4:15: error[E0001]: `{` is never closed" in r.stderr
    assert "end of file" not in r.stderr and r.stderr.count("error[") == 1


def test_missing_comma_between_arguments():
    d = _first_error("solid s {\n    r = Rectangle(center=(0, 0) width=40, height=20)\n}\n")
    assert (d.span.line, d.span.col) == (2, 33) and d.message.startswith("unexpected `width`")
    assert d.hint == "a `,` is probably missing before `width`"
    # not outside brackets: two names side by side there are not an argument list
    d = _first_error("solid s {\n    r = 3 w\n}\n")
    assert d.hint != "a `,` is probably missing before `w`"


def test_line_break_in_an_expression_outside_brackets():
    d = _first_error("solid s {\n    x = 3 +\n    c = Circle((0, 0), x)\n}\n")
    assert (d.span.line, d.span.col) == (2, 12) and d.message.startswith("unexpected newline")
    assert d.hint == ("the statement ended early: an operand is missing before the line break; "
                      "to go on with an expression on the next line, end this line with its "
                      "operator (or `,`) and indent the next one deeper, or wrap it in `( )`")
