"""Errors raised inside a template of another file are at the call in the program (issue 86).

A diagnostic located in a standard-library template or an imported file is reported at the
outermost call in the program compiled (file, line, column, the caret on the call), each call
between and the template's own line kept as notes: in the API's diagnostics, `aidl check`
(text and ``--json``), the MCP ``check`` tool and the language server (its
``relatedInformation``).  A table calls every standard-library template with arguments it
refuses; a law nests templates of imported files at generated depths and lines."""
import json
import re

import pytest
from hypothesis import given, settings, strategies as st
from lsprotocol import types as T
from pytest_lsp import LanguageClient

import aidl_lang
from aidl_lang.base.diagnostics import STDLIB
from aidl_lang.mcp import tools as M
from test_lsp import _open, client  # noqa: F401 - the language server over stdio (pytest-lsp)
from lsp_published import published

# the issue's case: five lines, the template's assert on gears.aidl's own line
ISSUE = """import "std/gears.aidl"
units mm
param lift = -1
train = gear_train(lift=lift)
# the gears stand on the train's plate
"""

# every standard-library template, with arguments it refuses (its first `assert`, when it has
# one; else a negative size or a zero division inside it)
TABLE = [
    ("boxes", "lid_box", "clearance=5 mm"),
    ("boxes", "sliding_lid_box", "clearance=5 mm"),
    ("boxes", "divider_tray", "rows=0"),
    ("boxes", "hinged_box", "clearance=5 mm"),
    ("boxes", "drawer", "clearance=5 mm"),
    ("boxes", "flex_box", "clearance=5 mm"),
    ("enclosures", "board_enclosure", 'vent="holes"'),
    ("fasteners", "clearance_hole", "size=7"),
    ("fasteners", "nut_trap", "size=7"),
    ("fasteners", "t_slot", "size=7"),
    ("gears", "spur_gear", "teeth=2"),
    ("gears", "gear_pair", "teeth1=2"),
    ("gears", "gear_train", "lift=-1 mm"),
    ("gears", "ring_gear", "teeth=5"),
    ("gears", "rack_and_pinion", "rack_teeth=1"),
    ("gears", "planetary", "planets=1"),
    ("joints", "finger_panel", 'top="teeth"'),
    ("joints", "finger_box", "thickness=-3 mm"),
    ("joints", "cross_halving", "depth=-1 mm"),
    ("joints", "finger_edge", 'start="slot"'),
    ("joints", "tab_and_slot", 'part="pin"'),
    ("joints", "dovetail", 'part="pin"'),
    ("plates", "rounded_plate", "width=-80 mm"),
    ("plates", "chamfered_plate", "chamfer=30 mm"),
    ("plates", "mounting_plate", "width=-80 mm"),
    ("plates", "keyhole", "slot_width=9 mm"),
    ("plates", "slot", "width=-5 mm"),
    ("plates", "living_hinge", "pitch=0 mm"),
    ("plates", "text_on_arc", "radius=-30 mm"),
    ("shapes", "washer", "inner=-5 mm"),
    ("shapes", "bolt_circle", "hole_d=-5 mm"),
    ("shapes", "rounded_tab", "length=5 mm"),
    ("shapes", "slot_hole", "width=-5 mm"),
    ("shapes", "hex_pocket", "across_flats=-8 mm"),
    ("stands", "tablet_stand", "angle=20 deg"),
    ("stands", "laptop_stand", "angle=50 deg"),
    ("stands", "tool_holder", "rows=0"),
    ("stands", "wall_shelf", "length=100 mm"),
]


def _program(lib: str, name: str, args: str) -> str:
    """The template called on line 4, column 9, inside a plate large enough for any of them."""
    return (f'import "std/{lib}.aidl"\nsolid plate {{\n'
            f"    body = Rectangle(center=(0, 0), width=400, height=400)\n"
            f"    t = {name}({args})\n}}\n")


def _templates() -> dict[str, set[str]]:
    """file stem -> the templates (``def``) the bundled standard library defines."""
    return {p.stem: set(re.findall(r"^def (\w+)\(", p.read_text(), re.M))
            for p in sorted(STDLIB.glob("*.aidl"))}


def _has_assert(lib: str, name: str) -> bool:
    text = (STDLIB / f"{lib}.aidl").read_text()
    body = re.split(r"^def ", text.split(f"\ndef {name}(", 1)[1], flags=re.M)[0]
    return re.search(r"^\s+assert ", body, re.M) is not None


def _line(file: str, line: int) -> str:
    return open(file, encoding="utf-8").read().splitlines()[line - 1]


def test_the_table_calls_every_standard_library_template():
    assert {lib: {n for l, n, _ in TABLE if l == lib} for lib in _templates()} == _templates()


def _check_at_call(diags: list[dict], path: str, lib: str, name: str) -> None:
    """``diags`` (JSON: ``aidl check --json``, the MCP tool) hold an error at the call
    (line 4, from column 9: the call, or the argument an assert over the arguments names,
    issue 95) with a note in ``std/LIB.aidl`` inside ``name``; none is located in another
    file; a template with an ``assert`` fails one (E0405 at its line)."""
    assert diags and all(d["span"]["file"] == path for d in diags), \
        [(d["code"], d["span"]["file"], d["span"]["line"]) for d in diags]
    errs = [d for d in diags if d["severity"] == "error"]
    assert errs and all(d["span"]["line"] == 4 and d["span"]["column"] >= 9 for d in errs)
    for d in errs:
        # the notes: the calls between (`gear_pair` calls `spur_gear`), then the template's line
        assert d["labels"][0]["message"].startswith(f"inside `{name}`")
        note = next(lab for lab in d["labels"] if ", at std/" in lab["message"])
        assert note["span"]["file"] == str(STDLIB / f"{lib}.aidl")
        assert note["message"].endswith(f", at std/{lib}.aidl:{note['span']['line']}:"
                                        f"{note['span']['column']}")
    if _has_assert(lib, name):
        e = next(d for d in errs if d["code"] == "E0405")
        assert _line(e["labels"][0]["span"]["file"], e["labels"][0]["span"]["line"]).lstrip() \
            .startswith("assert ")


@pytest.mark.parametrize("lib,name,args", TABLE, ids=[t[1] for t in TABLE])
def test_an_error_inside_a_std_template_is_at_the_call(lib, name, args, tmp_path, capsys):
    from aidl_lang.cli.main import main
    src = _program(lib, name, args)
    p = tmp_path / "t.aidl"
    p.write_text(src)
    # the API
    r = aidl_lang.compile(source=src, path=p)
    assert not r.ok and all(d.span.file == str(p) for d in r.diagnostics)
    assert all(lab.span.file == str(STDLIB / f"{lib}.aidl") for d in r.errors
               for lab in d.labels[:1])
    # `aidl check --json`
    assert main(["check", str(p), "--json"]) == 1
    _check_at_call(json.loads(capsys.readouterr().out)["diagnostics"], str(p), lib, name)
    # the MCP tool, by path in its root
    doc = M.check(M.Workspace(tmp_path), path="t.aidl")
    _check_at_call(doc["diagnostics"], str(p.resolve()), lib, name)
    assert doc["summary"].split(": ", 1)[1].startswith(f"{r.errors[0].code} line 4: ")
    assert re.search(rf"\(inside `{name}`( > `\w+`)*, at std/{lib}\.aidl:\d+:\d+\)",
                     doc["summary"])


@pytest.mark.parametrize("name,args,said", [
    ("living_hinge", "width=-30 mm", "the hinge's width and height are more than 0"),
    ("living_hinge", "cut=-5 mm", "the pitch, the cuts and the bridges are more than 0"),
    ("text_on_arc", "size=-5 mm", "the arc's radius and the text's size are more than 0"),
    ("text_on_arc", "radius=-30 mm", "the arc's radius and the text's size are more than 0"),
])
def test_a_negative_size_of_a_hinge_or_an_arc_of_text_is_refused_at_the_call(name, args, said,
                                                                             tmp_path):
    """Found with the table: these compiled without a word (a hinge of negative width cut its
    slits mirrored, text of negative size was drawn upside down); now each is the template's
    assert (E0405) at the call, line 4."""
    p = tmp_path / "t.aidl"
    r = aidl_lang.compile(source=_program("plates", name, args), path=p)
    [e] = r.errors
    assert e.code == "E0405" and said in e.message and (e.span.file, e.span.line) == (str(p), 4)


def test_the_issue_s_five_line_program_names_line_4(tmp_path, capsys):
    """`gear_train(lift=-1)`: E0405 at line 4, the template's assert on std/gears.aidl's
    line a note (it was `E0405 line 155`, in no file the program has)."""
    from aidl_lang.cli.main import main
    p = tmp_path / "train.aidl"
    p.write_text(ISSUE)
    assert main(["check", str(p)]) == 1
    got = capsys.readouterr()
    text = got.err + got.out
    gears = (STDLIB / "gears.aidl").read_text().splitlines()
    at = next(i for i, s in enumerate(gears, 1) if s.strip().startswith("assert lift >= 0 mm"))
    # at the argument (issue 95: an assert over the arguments is checked before the body)
    assert f"{p}:4:25: error[E0405]: argument `lift` of `gear_train`: assertion failed: " \
        "`lift >= 0 mm`" in text
    assert f"inside `gear_train`, at std/gears.aidl:{at}:5" in text
    assert main(["check", str(p), "--json"]) == 1
    diags = json.loads(capsys.readouterr().out)["diagnostics"]
    # the train is not built (its assert reads `lift` alone, checked before the body: issue
    # 95), so no gear sinks into the plate (W0517 was said beside it)
    assert {(d["code"], d["span"]["file"], d["span"]["line"]) for d in diags} == \
        {("E0405", str(p), 4)}
    (d,) = [d for d in diags if d["code"] == "E0405"]
    assert [(lab["span"]["line"], lab["primary"]) for lab in d["labels"]] == [(at, False)]
    doc = M.check(M.Workspace(tmp_path), source=ISSUE)
    assert doc["summary"] == ("1 error: E0405 line 4: argument `lift` of `gear_train`: "
                              "assertion failed: `lift >= 0 mm` (lift "
                              "is a height above the plate: 0 or more): -1 mm >= 0 mm is false "
                              f"(inside `gear_train`, at std/gears.aidl:{at}:5)")


# ------------------------------------------------------------------ templates of imported files
def _nested(depth: int, gap: int, width: int) -> tuple[str, dict[str, str], int, list[int]]:
    """A program calling ``t1`` of ``lib1.aidl``, which calls ``t2`` of ``lib2.aidl`` ... down
    to ``t{depth}``, whose assert fails when ``width`` > 20: (program, files, the call's line,
    the lines of the calls between and of the assert)."""
    files, lines = {}, []
    for k in range(1, depth + 1):
        if k < depth:
            body = f'import "lib{k + 1}.aidl"\n# level {k}\ndef t{k}(w=10 mm) -> solid {{\n' \
                   f"    inner = t{k + 1}(w=w)\n}}\n"
            lines.append(4)
        else:
            body = f"# level {k}\n\ndef t{k}(w=10 mm) -> solid {{\n" \
                   "    body = Rectangle(center=(0, 0), width=w, height=5 mm)\n" \
                   '    assert w <= 20 mm, "too wide"\n}\n'
            lines.append(5)
        files[f"lib{k}.aidl"] = body
    src = 'import "lib1.aidl"\n' + "\n" * gap + \
        f"solid top {{\n    base = Rectangle(center=(0, 0), width=90, height=90)\n" \
        f"    part = t1(w={width} mm)\n}}\n"
    return src, files, 4 + gap, lines


@settings(max_examples=12, deadline=None)
@given(depth=st.integers(1, 3), gap=st.integers(0, 6), width=st.integers(21, 60))
def test_law_nested_templates_report_at_the_outermost_call(tmp_path_factory, depth, gap, width):
    """Whatever the depth of templates in imported files and the call's line: the error is
    at the call in the program, then one note per call between (outermost first, each in
    the file that makes it) and the assert's line last."""
    d = tmp_path_factory.mktemp("nest")
    src, files, line, lines = _nested(depth, gap, width)
    for name, text in files.items():
        (d / name).write_text(text)
    p = d / "main.aidl"
    r = aidl_lang.compile(source=src, path=p)
    (e,) = r.errors
    assert e.code == "E0405" and f"{width} mm <= 20 mm is false" in e.message
    # a call in the program is at its argument's value (the assert reads `w` alone: issue 95); a
    # call inside another file at the program's call
    assert (e.span.file, e.span.line, e.span.col) == (str(p), line, 17 if depth == 1 else 12)
    assert [(lab.span.file, lab.span.line) for lab in e.labels] == \
        [(str(d / f"lib{k}.aidl"), n) for k, n in enumerate(lines, 1)]
    assert all(lab.message.startswith(f"inside `t{k}`")
               for k, lab in enumerate(e.labels[:-1], 1))
    assert e.labels[-1].message == f"inside `t{depth}`, at {d / f'lib{depth}.aidl'}:5:5"
    assert not any(lab.primary for lab in e.labels)


def _with_lib(folder, lib: str, src: str, name: str = "lib.aidl"):
    """``src`` compiled as ``folder/m.aidl`` beside ``lib`` written as ``folder/name``."""
    (folder / name).write_text(lib)
    return aidl_lang.compile(source=src, path=folder / "m.aidl")


def test_two_calls_of_one_template_each_named(tmp_path):
    """The same template called twice, failing twice (once while interpreting, once after
    solving): one error at each call, not one at the template's line."""
    r = _with_lib(tmp_path, "def post(w=10 mm, n=1) -> solid {\n"
                  "    body = Rectangle(center=(0, 0), width=w, height=5 mm)\n"
                  '    assert n >= 1, "at least one"\n'
                  '    assert body.width <= 20 mm, "too wide"\n}\n',
                  'import "lib.aidl"\nsolid top {\n    a = post(n=0)\n    b = post(n=-1)\n'
                  "    c = post(w=30 mm)\n    d = post(w=40 mm)\n}\n")
    got = sorted((d.span.line, d.message.split(": ")[-1], d.labels[-1].span.line)
                 for d in r.errors)
    assert got == [(3, "0 >= 1 is false", 3), (4, "-1 >= 1 is false", 3),
                   (5, "30 mm <= 20 mm is false", 4), (6, "40 mm <= 20 mm is false", 4)]


def test_a_conflict_inside_the_second_call_is_at_the_second_call(tmp_path):
    """A conflict found by the solver inside a template's instance is at that instance's
    call (by its structure), not at the template's first call."""
    r = _with_lib(tmp_path, "def bar(w=10 mm) -> solid {\n"
                  "    body = Rectangle(center=(0, 0), width=10, height=5 mm)\n"
                  "    Length(body.top, w)\n}\n",
                  'import "lib.aidl"\nsolid top {\n    a = bar(w=10 mm)\n    b = bar(w=12 mm)\n}\n')
    (e,) = r.errors
    assert e.code == "E0401" and "`top.b`" in e.message and e.span.line == 4
    assert [(lab.span.line, lab.message.split(",")[0]) for lab in e.labels[:1]] == \
        [(3, "inside `bar`")]
    assert "line 3 of " in e.hint and "line 2 of " in e.hint


def test_a_shape_warning_is_at_the_call_of_the_instance_it_names(tmp_path):
    """A shape check's warning on the second instance of a std template (its eye refilled by
    the plate) is at the second call: the instance its message names, not the first call."""
    src = ('import "std/shapes.aidl"\nsolid plate {\n'
           "    body = Rectangle(center=(0, 0), width=100, height=100)\n"
           "    a = rounded_tab(cx=0 mm, cy=200 mm)\n    b = rounded_tab(cx=0 mm, cy=0 mm)\n}\n")
    r = aidl_lang.compile(source=src, path=tmp_path / "m.aidl")
    (w,) = [d for d in r.diagnostics if d.code == "W0501"]
    assert "`plate.b.eye`" in w.message and (w.span.line, w.span.col) == (5, 9)
    assert w.labels[0].message.startswith("inside `rounded_tab`, at std/shapes.aidl:")
    assert _line(w.labels[0].span.file, w.labels[0].span.line).strip() == "hole eye {"


def test_a_line_named_inside_a_template_says_its_file(tmp_path):
    """A message or hint naming a line of the template names the file too, and a fix located
    in the template is left out (the user edits the call)."""
    r = _with_lib(tmp_path, "# helpers\ndef post(h=10 mm) -> solid {\n"
                  "    body = Rectangle(center=(0, 0), width=w, height=h)\n    w = 4 mm\n}\n",
                  'import "lib.aidl"\nsolid top {\n    p = post()\n}\n')
    (e,) = r.errors
    lib = str(tmp_path / "lib.aidl")
    assert e.code == "E0101" and e.span.line == 3 and e.fix is None
    assert e.message.endswith(f"defined later, on line 4 of {lib}")
    assert f"move line 4 of {lib} above line 3 of {lib}" in e.hint


def test_an_imported_file_s_syntax_error_is_at_the_import(tmp_path):
    r = _with_lib(tmp_path, "def bad() -> solid {\n"
                  "    body = Rectangle(center=(0, 0), width=, height=5)\n}\n",
                  '# a plate\nimport "broken.aidl"\nsolid top { body = Circle(center=(0, 0), radius=3) }\n',
                  "broken.aidl")
    (e,) = r.errors
    assert e.code == "E0001" and (e.span.file, e.span.line) == (str(tmp_path / "m.aidl"), 2)
    (note,) = e.labels
    assert (note.span.file, note.span.line, note.span.col) == (str(tmp_path / "broken.aidl"), 2, 43)
    assert note.message == f"inside the file `broken.aidl`, at {tmp_path / 'broken.aidl'}:2:43"


# ------------------------------------------------------------------ the language server
async def _solved_diagnostics(client: LanguageClient, uri: str):
    """The diagnostics published for ``uri`` once they hold an error (the start-up's
    parse-and-check ones, empty here, come first)."""
    return await published(client, uri, where=lambda p: any(
        d.severity == T.DiagnosticSeverity.Error for d in p.diagnostics))


LSP_ROWS = [t for t in TABLE if t[1] in ("gear_train", "finger_panel", "keyhole", "washer",
                                         "tool_holder")]


@pytest.mark.asyncio(loop_scope="module")   # test_lsp's client: one server per module
async def test_language_server_puts_template_errors_on_the_call(client: LanguageClient, tmp_path):
    """The editor shows the error on the call's line (0-based 3 for line 4), the template's
    line as related information in the template's own file."""
    for k, (lib, name, args) in enumerate([("gears", "gear_train", "lift=-1 mm")] + LSP_ROWS):
        p = tmp_path / f"t{k}.aidl"
        src = ISSUE if k == 0 else _program(lib, name, args)
        p.write_text(src)
        uri = p.as_uri()
        _open(client, uri, src)
        diags = await _solved_diagnostics(client, uri)
        errs = [d for d in diags if d.severity == T.DiagnosticSeverity.Error]
        # the call's line, the argument the assert reads (issue 95) or the call
        assert all(d.range.start.line == 3 and d.range.start.character >= 8 for d in errs), \
            [(d.code, d.range) for d in errs]
        for d in errs:
            rel = d.related_information[0]
            assert rel.location.uri == (STDLIB / f"{lib}.aidl").as_uri()
            assert rel.message.startswith(f"inside `{name}`, at std/{lib}.aidl:")
            line = int(rel.message.rsplit(":", 2)[1])
            assert rel.location.range.start.line == line - 1
            assert not d.message.startswith("std/")       # no longer put on line 1
