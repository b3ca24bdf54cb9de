"""E0124 for a range whose ``min`` comes out larger than its ``max`` (issue 92,
aidl_lang/interpreter/empty_range.py): "swap them" only where the swapped range holds the
value (bounds written as numbers); bounds that follow other params are never swapped, and the
hint says which values of which param empty the range.  The law: over generated dependent
ranges, following every E0124 hint (the swap, or moving the named param to the clean side of
the value it names) never makes things worse: the range is no longer empty and no error is
added.  Cost: about 60 small compiles (no solve past a rectangle), under 2 s CPU."""
import re

import pytest

from hypothesis import given, settings, strategies as st

import aidl_lang
from aidl_lang.base.diagnostics import DiagnosticSink  # noqa: F401 (the compile's sink)

RANGES = {"a": (0, 100), "c": (10, 100)}
EMPTY = ("param `b`: its range is empty", "min is larger than max")


def _errors(src: str, tmp_path, name="r.aidl") -> list:
    p = tmp_path / name
    p.write_text(src)
    res = aidl_lang.compile(src, str(p))
    return [d for d in res.diagnostics if d.is_error]


def _empty(errs) -> list:
    return [d for d in errs if d.code == "E0124" and any(s in d.message for s in EMPTY)]


def _program(a: float, c: float, lo: float, hi: float, b: float, form: int) -> str:
    bounds = {0: "min = max(a, {lo} mm), max = min(c, {hi} mm)",
              1: "min = a + {lo} mm, max = {hi} mm",
              2: "min = {lo} mm, max = c - {hi} mm"}[form].format(lo=lo, hi=hi)
    return (f"param a = {a} mm, min = {RANGES['a'][0]} mm, max = {RANGES['a'][1]} mm\n"
            f"param c = {c} mm, min = {RANGES['c'][0]} mm, max = {RANGES['c'][1]} mm\n"
            f"param b = {b} mm, {bounds}\n"
            "solid plate { r = Rectangle(center=(0, 0), width=b + 30 mm, height=20 mm) }\n")


def test_the_issues_range_is_not_swapped_and_says_which_values_empty_it(tmp_path):
    src = _program(66, 60, 10, 70, 60, 0)
    (d,) = _empty(_errors(src, tmp_path))
    assert "swap them" not in d.hint
    assert "min = 66 mm (`max(a, 10 mm)`), max = 60 mm (`min(c, 70 mm)`)" in d.message
    assert "`a` above 60 mm empties it with `c` = 60 mm" in d.hint
    assert "`c` below 66 mm empties it with `a` = 66 mm" in d.hint


def test_numbers_the_wrong_way_round_are_swapped_only_when_that_holds_the_value(tmp_path):
    src = "param b = 60 mm, min = 80 mm, max = 20 mm\nsolid p { r = Rectangle(center=(0, 0), width=b, height=5 mm) }\n"
    (d,) = _empty(_errors(src, tmp_path))
    assert d.hint == "swap them"
    assert not _errors(src.replace("min = 80 mm, max = 20 mm", "min = 20 mm, max = 80 mm"), tmp_path)
    src = src.replace("max = 20 mm", "max = 70 mm")
    (d,) = _empty(_errors(src, tmp_path))
    assert "swap" not in d.hint.split("(")[0] and "would not hold it" in d.hint


def _followed(src: str, hint: str) -> list[str]:
    """The programs a hint leads to: each `P above X` / `P below X` moved to the clean side of
    X (1 % of X inside), the rest as they are."""
    out = []
    for name, side, x in re.findall(r"`(\w+)` (above|below) (-?[\d.]+) mm empties it", hint):
        x = float(x)
        y = round(x - 0.01 * max(abs(x), 1.0) if side == "above" else x + 0.01 * max(abs(x), 1.0), 6)
        y = min(max(y, RANGES[name][0]), RANGES[name][1])      # inside its own range
        out.append(re.sub(rf"^param {name} = [-\d.]+ mm", f"param {name} = {y} mm", src, flags=re.M))
    return out


@settings(max_examples=25, deadline=None)
@given(a=st.integers(0, 100), c=st.integers(10, 100), lo=st.integers(0, 40),
       hi=st.integers(0, 80), form=st.integers(0, 2))
def test_following_an_E0124_hint_never_makes_things_worse(tmp_path_factory, a, c, lo, hi, form):
    tmp = tmp_path_factory.mktemp("er")
    src = _program(a, c, lo, hi, 50, form)
    errs = _errors(src, tmp)
    empty = _empty(errs)
    if not empty:
        return
    (d,) = empty
    assert "swap them" not in d.hint          # every bound here follows another param
    followed = _followed(src, d.hint)
    if not followed:                          # no value of either param helps: said so
        assert re.findall(r"`\w+` empties it anywhere in its range", d.hint) == [
            f"`{n}` empties it anywhere in its range" for n in ("a", "c") if f"`{n}`" in
            d.hint.split(":")[0]], d.hint
    for fixed in followed:
        after = _errors(fixed, tmp)
        assert not _empty(after), (d.hint, fixed)
        # no new kind of error (the value of `b` may still lie outside its range: E0124)
        assert {e.code for e in after} <= {e.code for e in errs} | {"E0124"}


@pytest.mark.parametrize("bound", ["max(10 mm, 25 mm)", "2 * 12.5 mm", "25 mm + 0 mm"])
def test_no_swap_for_bounds_written_as_expressions(bound):
    """`min = max(10 mm, 25 mm)` above `max = 20 mm`: swapping the expressions would change
    what they compute (issue 105), so E0124 proposes no swap, even where the swapped range
    would hold the value; bounds written as numbers still get "swap them"."""
    src = (f"param w = 22 mm, min = {bound}, max = 20 mm\n"
           "solid s { c = Circle(center=(0, 0), radius=w) }\n")
    [e] = aidl_lang.compile(source=src).errors
    assert e.code == "E0124" and "min = 25 mm" in e.message and f"`{bound}`" in e.message
    assert "swap" not in e.hint.replace("swapping the expressions would change", "")
    plain = aidl_lang.compile(source=src.replace(bound, "25 mm"))
    assert plain.errors[0].hint == "swap them"
