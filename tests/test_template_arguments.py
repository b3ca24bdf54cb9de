"""A template called wrongly is one error at the caller, naming the argument (issue 95).

`spur_gear(teeth="twelve")` was 14 errors at the caller's line about the library's insides
("cannot apply `*` to length and string", then "unknown name `base_r`", `t0`, ...), the
template's own check on `teeth` 13th; `spur_gear(module=0 mm)` began with "division by zero"
inside the library.  Now the arguments are checked at the call, before the body runs: their
kinds against the defaults' and the template's asserts written over them.  The laws run every
standard-library template with every argument given a wrong kind, and every argument an
assert over the arguments reads given values until one breaks it: exactly one error each, at
the call's line, naming that argument.  (About 600 compiles of a few ms: ~5 s CPU.)"""
import re

import pytest

import aidl_lang
from aidl_lang import ast as A
from aidl_lang.base.diagnostics import STDLIB, DiagnosticSink
from aidl_lang.interpreter.arguments import _plan, default_kind
from aidl_lang.interpreter.common import _definition_lines
from aidl_lang.parser import parse


def _defs() -> list[tuple[str, A.Def]]:
    out = []
    for p in sorted(STDLIB.glob("*.aidl")):
        prog = parse(p.read_text(), str(p), DiagnosticSink())
        out += [(p.stem, st) for st in prog.stmts if isinstance(st, A.Def)]
    return out


DEFS = _defs()


def _program(lib: str, call: str) -> str:
    return (f'import "std/{lib}.aidl"\nsolid plate {{\n'
            f"    body = Rectangle(center=(0, 0), width=400, height=400)\n"
            f"    t = {call}\n}}\n")


def _errors(lib: str, call: str, tmp_path) -> list:
    return aidl_lang.compile(source=_program(lib, call), path=tmp_path / "t.aidl").errors


def _unit(p: A.TemplateParam) -> str | None:
    d = p.default.operand if isinstance(p.default, A.Neg) else p.default
    return d.unit if isinstance(d, A.Num) else None


def _wrong(p: A.TemplateParam) -> list[tuple[str, str]]:
    """(argument text, the code expected) of another kind than ``p``'s default."""
    kind = default_kind(p)
    if kind is None:
        return []
    out = [{"number": '"x"', "string": "5", "list": "5", "boolean": "5",
            "point": '"x"'}[kind]]
    out = [(t, "E0108") for t in out]
    if kind == "number" and _unit(p) not in ("mm", "cm", "m", "in"):
        # a length for an angle or a count (an angle for a length: tests/test_stdlib_call_errors)
        out.append(("5 mm", "E0109"))
    return out


def test_the_issue_s_two_calls_are_one_error_each_at_the_argument(tmp_path):
    """The issue's calls: one error each, at the argument, naming `teeth` and `module`."""
    [e] = _errors("gears", 'spur_gear(teeth="twelve")', tmp_path)
    assert e.code == "E0108" and (e.span.line, e.span.col) == (4, 25)
    assert e.message == ('`teeth` of `spur_gear` is a number like its default `20`, got the '
                         'string "twelve"')
    assert "a gear has a whole number of teeth, at least 3" in e.hint
    [e] = _errors("gears", "spur_gear(module=0 mm)", tmp_path)
    assert e.code == "E0405" and (e.span.line, e.span.col) == (4, 26)
    assert e.message.startswith("argument `module` of `spur_gear`: assertion failed: "
                                "`module > 0 mm`")
    # the assert's own line is the note, in the library's file as the program imports it
    assert e.labels[0].message.startswith("inside `spur_gear`, at std/gears.aidl:")


@pytest.mark.parametrize("lib,d", DEFS, ids=[d.name for _, d in DEFS])
def test_law_a_wrong_kind_is_one_error_naming_the_argument(lib, d, tmp_path):
    """Every argument of every standard-library template, given a value of another kind than
    its default (a string for a number, a number for a string, a list or a flag; a length
    for an angle or a count): exactly one error, at the call's line,
    whose message begins with that argument's name."""
    seen = 0
    for p in d.params:
        for text, code in _wrong(p):
            errs = _errors(lib, f"{d.name}({p.name}={text})", tmp_path)
            assert [(e.code, e.span.line) for e in errs] == [(code, 4)], (p.name, text, [
                (e.code, e.message) for e in errs])
            assert errs[0].message.startswith(f"`{p.name}` of `{d.name}` is "), errs[0].message
            seen += 1
    assert seen >= len(d.params)


# values tried, in each argument's unit, until one breaks an assert that reads it
TRIES = {"number": ["0", "-1", "0.5", "7", "-100", "1000", "100000"],
         "string": ['"zzz"'], "list": ["[]", "[12]", "[12, 12, 12, 12, 12, 12, 12, 12, 12]"]}


def _asserted(d: A.Def) -> set[str]:
    """The parameters an assert over the arguments reads."""
    _assigns, asserts = _plan(d, set(_definition_lines(d.body.stmts)))
    return set().union(*(deps for _st, deps in asserts)) if asserts else set()


@pytest.mark.parametrize("lib,d", DEFS, ids=[d.name for _, d in DEFS])
def test_law_a_value_an_assert_refuses_is_one_error_naming_the_argument(lib, d, tmp_path):
    """Every argument that a template's assert over the arguments reads: the first value of a
    list of tries that the template refuses is exactly one error (E0405, or E0108/E0109 when
    the condition cannot compare it), at the call's line, naming that argument; and some try
    is refused for every such argument but a few whose asserts need another's value."""
    broken = set()
    for p in d.params:
        if p.name not in _asserted(d):
            continue
        unit = _unit(p) or ""
        for v in TRIES.get(default_kind(p), []):
            text = f"{v} {unit}" if unit else v
            errs = _errors(lib, f"{d.name}({p.name}={text})", tmp_path)
            if not errs:
                continue
            assert [(e.code, e.span.line) for e in errs] == [("E0405", 4)], (p.name, text, [
                (e.code, e.message) for e in errs])
            assert re.match(rf"arguments? (`\w+`, )*`{p.name}`", errs[0].message), \
                errs[0].message
            broken.add(p.name)
            break
    assert broken or not _asserted(d)


def test_an_item_of_another_kind_in_a_list_argument_is_one_error(tmp_path):
    """`gear_train(teeth=[12, "a"])` was three errors inside the train ("cannot apply `+` to
    number and string", ...): one at the argument, naming the item, the train's reason (read
    through `n = len(teeth)`) in the hint; a list of lists the same."""
    [e] = _errors("gears", 'gear_train(teeth=[12, "a"])', tmp_path)
    assert e.code == "E0108" and (e.span.line, e.span.col) == (4, 26)
    assert e.message.startswith("`teeth` of `gear_train` is a list of numbers like its default")
    assert e.message.endswith('got the string "a" as item 1')
    assert "a gear train has 2 to 8 gears" in e.hint
    [e] = _errors("enclosures", "board_enclosure(holes=[[1, 2], 5])", tmp_path)
    assert e.message.startswith("`holes` of `board_enclosure` is a list of lists")
