"""Issue 91: bidirectional controls and line separators in comments and strings passed
without a word ("Trojan source": a right-to-left override makes a comment seem to end before
code that is really inside it).  Now each is W0112 at the character, its code point named,
with a fix that deletes it; in code it is E0002, which names the code point too; a printed
source line shows it as U+FFFD so the caret stays under it; a U+2028 never shifts the line
numbers (the CLI's and the language server's).  Through `aidl check` on real files.  Cost:
about 20 small parses and compiles, about 1.5 s."""
from __future__ import annotations

import contextlib
import io
import json

import pytest

from aidl_lang.parsing.controls import code_point

RLO, LRI, PDI, LS, PS = "\u202e", "\u2066", "\u2069", "\u2028", "\u2029"
ALL = [chr(c) for c in [*range(0x202A, 0x202F), *range(0x2066, 0x206A), 0x2028, 0x2029]]


def _check(path, *extra) -> tuple:
    from aidl_lang.cli.main import main
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(["check", str(path), *extra])
    return rc, out.getvalue(), err.getvalue()


def _json(path) -> list:
    return json.loads(_check(path, "--json")[1])["diagnostics"]


PLATE = "solid plate {{\n    body = Rectangle(center=(0, 0), width=80, height=40){a}\n" \
        "    label = \"A{b}B\"\n    /* note{c} */\n}}\n"


@pytest.mark.parametrize("ch", ALL, ids=[f"U+{ord(c):04X}" for c in ALL])
def test_each_control_in_a_comment_or_a_string_is_W0112_at_the_character(tmp_path, ch):
    p = tmp_path / "t.aidl"
    p.write_text(PLATE.format(a=f"  # x{ch}y", b=ch, c=ch), encoding="utf-8")
    ds = [d for d in _json(p) if d["code"] == "W0112"]
    got = [(d["span"]["line"], d["span"]["column"]) for d in ds]
    assert got == [(2, 62), (3, 15), (4, 12)], ds            # comment, string, block comment
    name = code_point(ch)
    assert name.startswith(f"U+{ord(ch):04X} ") and all(name in d["message"] for d in ds)
    assert [d["message"].split(": ")[0].rsplit(" ", 1)[-1] for d in ds] == \
        ["comment", "string", "comment"]
    # the fix deletes it, and the file then says nothing
    src = p.read_text(encoding="utf-8")
    for d in sorted(ds, key=lambda d: -d["fix"]["span"]["start"]):
        sp = d["fix"]["span"]
        assert d["fix"]["replacement"] == "" and src[sp["start"]:sp["end"]] == ch
        src = src[:sp["start"]] + src[sp["end"]:]
    p.write_text(src, encoding="utf-8")
    assert _json(p) == []


def test_in_code_it_is_E0002_naming_the_code_point_and_the_line_shows_no_override(tmp_path):
    p = tmp_path / "t.aidl"
    p.write_text(f"solid plate {{\n    body{RLO} = Rectangle(center=(0, 0), width=8, "
                 "height=4)\n}\n", encoding="utf-8")
    rc, _, err = _check(p)
    assert rc != 0
    assert f"{p}:2:9: error[E0002]: unexpected character U+202E RIGHT-TO-LEFT OVERRIDE" in err
    assert RLO not in err and "2 |     body\ufffd = Rectangle" in err
    assert "\n  |         ^\n" in err                       # the caret under column 9


def test_a_line_separator_does_not_shift_the_line_numbers(tmp_path):
    """U+2028 and U+2029 in a comment: the error two lines later is said at its own line,
    by the CLI and by the language server, as an editor that counts LF numbers it."""
    p = tmp_path / "t.aidl"
    src = (f"solid plate {{\n    # one{LS}two{PS}three\n"
           "    body = Rectangle(center=(0, 0), width=80, height=40)\n"
           "    c = Circle(center=(0, 0), radiuss=4)\n}\n")
    p.write_text(src, encoding="utf-8")
    rc, _, err = _check(p)
    assert f"{p}:4:31: error[E0105]" in err and f"{p}:2:10: warning[W0112]" in err
    assert f"{p}:2:14: warning[W0112]" in err
    assert "4 |     c = Circle(center=(0, 0), radiuss=4)" in err
    from aidl_lang.editor.lsp.analysis import diagnostics
    lsp = diagnostics(src, str(p))
    rows = sorted((d.range.start.line, d.range.start.character, d.code) for d in lsp)
    assert rows == [(1, 9, "W0112"), (1, 13, "W0112"), (3, 30, "E0105")], rows


def test_the_override_in_the_issue_shape_is_said_once_per_character(tmp_path):
    """A comment that seems to end before an `if` (the Trojan source paper's "commenting
    out"): both the isolate and its closing are said, each at its column."""
    p = tmp_path / "t.aidl"
    p.write_text(f"param admin = 0\n/* {RLO}{LRI} if admin == 1 {PDI}{LRI} begin admins only */\n"
                 "solid s { b = Circle(center=(0, 0), radius=5) }\n", encoding="utf-8")
    ds = [d for d in _json(p) if d["code"] == "W0112"]
    assert [d["span"]["column"] for d in ds] == [4, 5, 21, 22]


def test_the_editors_quick_fix_names_the_code_point_and_deletes_it():
    from aidl_lang.editor.lsp import plain
    from aidl_lang.pipeline import compile_source
    src = f"solid s {{\n    # a{RLO}b\n    b = Circle(center=(0, 0), radius=5)\n}}\n"
    c = compile_source(src, "quick.aidl")
    (d,) = [d for d in c.sink.items if d.code == "W0112"]
    (edit,) = plain.fix_edits(src, "quick.aidl", d)
    assert edit["title"] == "Remove `U+202E RIGHT-TO-LEFT OVERRIDE`" and edit["newText"] == ""
    assert edit["range"] == {"start": {"line": 1, "character": 7},
                             "end": {"line": 1, "character": 8}}
