"""Issue 111's model runs v-w, and the list the last round left: a pattern's copy that breaks
out through the edge while its original is a closed hole (W0530), a comprehension filter that
reads solved geometry (E0118's message), the freedom line's "on its part", and what
`start_angle` turns (the CircularPattern line)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

import aidl_lang

RUNS = Path(__file__).resolve().parent.parent / "data" / "model_runs"


def _w(r, code):
    return [d for d in r.diagnostics if d.code == code]


def test_W0530_a_pattern_copy_that_breaks_out_where_its_original_is_closed():
    """Run v's towel-hook plate: `AlignCenterX(peg, body)` centred the pattern's original,
    so the second of two 12 mm pegs 80 mm apart ran 6 mm out of the 160 mm plate's right
    edge: a notch where a hole was drawn, and nothing said so.  W0530 names the copy, the
    depth and where; moving the original by what the hint says clears it."""
    src = (RUNS / "issue111v/run/02_towel_hook_plate.first_valid.aidl").read_text()
    r = aidl_lang.compile(source=src)
    assert r.ok
    w = [d for d in _w(r, "W0530") if "pattern's copy" in d.message]
    assert len(w) == 1
    assert "hole `plate.pegs[1]`, a pattern's copy of `plate.peg`" in w[0].message
    assert "by 6.00 mm" in w[0].message and "(86.00, -14.00)" in w[0].message
    need = float(re.search(r"by at least ([\d.]+) mm", w[0].hint).group(1))
    assert need == 7.0                      # 6 mm out and twice the 0.5 mm minimum wall
    # the model's own fix: the pair centred (original 40 mm left of the centre)
    fixed = src.replace("    AlignCenterX(peg, body, )\n",
                        "    peg.c.center.x == body.center.x - 40 mm\n")
    assert fixed != src
    r2 = aidl_lang.compile(source=fixed)
    assert r2.ok and not _w(r2, "W0530")
    # the copy's notch is real: the plate's area with the copy run out is larger than with
    # both holes closed by the notch's part outside the plate (half a 12 mm circle)
    assert r.parts[0].area - r2.parts[0].area == pytest.approx(
        0.5 * 3.141592653589793 * 36, rel=0.02)


PLATE = """solid plate {{
    body = Rectangle(center=(0, 0), width=100, height=40)
    hole h {{ c = Circle(center=({x}, 0), diameter=8) }}
    row = LinearPattern(h, {n}, ({step}, 0))
    Fixed(body)
    Fixed(h)
}}
"""


def test_W0530_not_for_an_edge_pattern_whose_original_is_open_too():
    """A row of notches along an edge (the original runs out like every copy): drawn open on
    purpose, no warning; nor a row wholly inside."""
    comb = """solid comb {
    body = Rectangle(center=(0, 0), width=100, height=40)
    hole n { r = Rectangle(center=(-40, 20), width=4, height=10) }
    teeth = LinearPattern(n, 9, (10, 0))
    Fixed(body)
    Fixed(n)
}
"""
    r = aidl_lang.compile(source=comb)
    assert r.ok and not _w(r, "W0530")
    inside = aidl_lang.compile(source=PLATE.format(x=-40, n=5, step=20))
    assert inside.ok and not _w(inside, "W0530")
    out = aidl_lang.compile(source=PLATE.format(x=-40, n=6, step=18))    # the 6th at x = 50
    w = _w(out, "W0530")
    assert len(w) == 1 and "hole `plate.row[5]`" in w[0].message and "by 4.00 mm" in w[0].message


def test_W0530_for_copies_of_a_shape_inside_one_hole():
    """A pattern of a circle inside one hole (`vents = CircularPattern(v, 6, ...)`): a copy
    that breaks out of the disc while the original is closed is warned, with how many do."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole vents {
        v = Circle(center=(20, 0), diameter=8)
        ring = CircularPattern(v, 6, (0, 0))
    }
    Fixed(body)
    Fixed(vents)
}
"""
    r = aidl_lang.compile(source=src)
    w = _w(r, "W0530")
    assert len(w) == 1, [d.message for d in r.diagnostics]
    assert "a pattern's copy of `plate.vents.v`" in w[0].message
    assert "(4 of its 5 copies do)" in w[0].message      # at 60, 120, 240 and 300 deg
    assert "by 1.32 mm" in w[0].message                # 20 sin 60 + 4 - 20


def test_E0118_in_a_comprehension_filter_says_the_filter_runs_before_the_solve():
    """Run h's zig-zag: `assert len([p for p in band.zig.points if p.y < 5 mm]) == 3` was
    E0118 with the hint "as a statement of its own, `a == b` is a constraint" (not what the
    model wrote).  The message names the filter and the hint says what to write; the hint's
    loop, written, is valid."""
    src = """solid band {
    plate = Rectangle(center=(10, 5), width=30, height=20)
    drawing d { zig = Polyline(points=[(0, 0), (5, 10), (10, 0), (15, 10), (20, 0)]) }
    Fixed(plate)
}
assert len([p for p in band.d.zig.points if p.y < 5 mm]) == 3
"""
    r = aidl_lang.compile(source=src)
    e = [d for d in r.diagnostics if d.is_error]
    assert [d.code for d in e] == ["E0118"]
    assert e[0].message == "a comprehension's filter cannot read geometry the solver moves"
    assert "in an `assert` too" in e[0].hint and "`for p in ... { assert ... }`" in e[0].hint
    assert (e[0].span.line, e[0].span.col) == (6, 45)
    loop = src.replace("assert len([p for p in band.d.zig.points if p.y < 5 mm]) == 3",
                       "for p in band.d.zig.points { assert p.y <= 10 mm }")
    assert aidl_lang.compile(source=loop).ok
    bad = loop.replace("p.y <= 10 mm", "p.y <= 5 mm")
    assert [d.code for d in aidl_lang.compile(source=bad).diagnostics if d.is_error] == ["E0405"]


def test_the_freedom_line_says_a_free_feature_stays_on_its_part():
    """Run q's pot stand: "hole `stand.b.arch` free but stays where written" read as the
    sheet's coordinates, though `RightOf(b.body, ...)` moved its part 10 mm and the arch went
    with it.  The line says "on its part", and the arch did move with the body."""
    src = """thickness 3 mm
assembly stand {
    solid a { body = Rectangle(center=(0, 0), width=40, height=30) }
    solid b {
        body = Rectangle(center=(100, 0), width=40, height=30)
        hole arch { c = Circle(center=(100, -15), diameter=10) }
    }
    Fixed(a)
    RightOf(b.body, a.body, gap=10)
    AlignBottom(b.body, a.body)
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok
    assert "hole `stand.b.arch` free but stays where written on its part (harmless)" in \
        r.freedom()["text"]
    vals = {v.name: v.value for v in r.values}
    bx, ax = vals["stand.b.body.center"], vals["stand.b.arch.c.center"]
    assert bx[0] == pytest.approx(50.0, abs=1e-6)       # 20 + 10 + 20
    assert ax[0] == pytest.approx(bx[0], abs=1e-6)      # the arch moved with its part


def test_the_circular_pattern_line_says_start_angle_turns_from_where_the_original_is():
    """Run r's utensil crock: the original placed at 45 deg by `polar` AND `start_angle=45
    deg`: the drain holes ended on the axes.  The prompt's and docs' line says both ways of
    putting the first copy at 45 deg."""
    from aidl_lang.llm.prompt import system_prompt
    text = system_prompt()
    line = [ln for ln in text.splitlines() if ln.startswith("- CircularPattern(")][0]
    assert "the original on +x with start_angle=45, or the original at 45 with none" in line
