"""Nothing silently wrong about through-cuts (issue 70): the bridges a slit's end leaves, a
cut that severs a part only under `--set`, and a `min_wall` written where nothing reads it.

* Two slits ending 0.05 mm apart held the two halves of a plate by a 50 um bridge and a slit
  ending 0.01 mm from the edge left a 10 um one: `aidl check` said "ok".  The web check opens
  the part less the cuts by a disc of `min_wall` and a bridge has no length, so the opening
  removed next to nothing there.  Now each free end's bridge is measured (through.py,
  `_end_bridges`): W0507 names the cut, what it stops short of and the width; a bridge of
  exactly `min_wall`, on lines or arcs, and a living hinge as meant stay silent.
* A cut that frees a piece only with `--set L=30` gave no W0510: the part keeps one piece
  (the rest is a part of its own, `plate.piece1`).  Now the pieces a part's through-cuts cut
  off are compared too.
* `min_wall` inside a `cut` (or a `hole`) did nothing, without a word: now W0101 at the
  statement says where to write it.
"""
import pytest

from aidl_lang.api import compile as aidl_compile
from aidl_lang.pipeline import compile_source

# the budgets count CPU seconds (the cpu_clock fixture, tests/cpu_clock.py): big drawings
# compiled under the default budget reach the same stage however busy the machine is
pytestmark = [pytest.mark.timing, pytest.mark.usefixtures("cpu_clock")]


def _plate(cuts: str, before: str = "", part_wall: str = "") -> str:
    return f"""{before}solid plate {{
    {part_wall}body = Rectangle(center=(0, 0), width=60, height=30)
    cut slits {{
{cuts}
    }}
    Fixed(body)
}}
"""


def _walls(src):
    c = aidl_compile(src, path="p.aidl")
    assert c.ok, [d.message for d in c.sink.items]
    return c, [d for d in c.sink.items if d.code == "W0507"]


@pytest.mark.parametrize("gap, width", [(0.05, "0.05"), (0.499, "0.499"), (0.01, "0.01")])
def test_two_slits_ending_close_leave_a_bridge_named_with_its_width(gap, width):
    src = _plate(f"        a = Line((0, -15), (0, {-gap / 2}))\n"
                 f"        b = Line((0, {gap / 2}), (0, 15))")
    c, ws = _walls(src)
    (w,) = ws                                            # one bridge, told once
    assert "plate.slits.a" in w.message and "plate.slits.b" in w.message, w.message
    assert f"is {width} mm wide, thinner than 0.5 mm" in w.message, w.message
    assert (w.span.line, w.span.col) == (4, 13)          # the first cut
    # the bridge holds: one part, not two halves
    assert [p.name for p in c.output.parts] == ["plate"]


def test_a_cut_stopping_short_of_another_at_an_angle_leaves_a_bridge():
    _, ws = _walls(_plate("        a = Line((15, 0), (25, 0))\n"
                          "        b = Line((15, -5), (19.9, -0.1))"))
    (w,) = ws
    assert "`plate.slits.b`" in w.message and "through-cut `plate.slits.a` is 0.1 mm wide" \
        in w.message, w.message


@pytest.mark.parametrize("end, width", [("(0, 14.99)", "0.01"), ("(29.99, 0)", "0.01"),
                                        ("(0, 14.6)", "0.4")])
def test_a_slit_ending_short_of_the_edge_leaves_a_bridge(end, width):
    start = "(0, -15)" if end.startswith("(0,") else "(-10, 0)"
    c, ws = _walls(_plate(f"        a = Line({start}, {end})"))
    (w,) = ws
    assert "the outer edge of `plate`" in w.message and f"is {width} mm wide" in w.message, \
        w.message


@pytest.mark.parametrize("cuts", [
    # exactly the minimum: to the edge, between two slits, from a slit to the edge
    "        a = Line((0, -15), (0, 14.5))",
    "        a = Line((0, -15), (0, -0.25))\n        b = Line((0, 0.25), (0, 15))",
    # reaching the edge, or past it: no bridge (a cut through)
    "        a = Line((-10, 0), (30, 0))",
    "        a = Line((-10, 0), (31, 0))",
    # a cut that crosses another and overshoots it by 0.1 mm, square or at 45 degrees: the
    # corner it leaves is no bridge
    "        a = Line((-10, 0), (10, 0))\n        b = Line((0, -10), (0, 0.1))",
    "        a = Line((15, 0), (25, 0))\n        b = Line((15, -5), (20.1, 0.1))",
    # a chain of short lines joined end to end bends within the minimum: no bridge
    "        a = Line((0, -15), (0.2, -14.8))\n        b = Line(a.end, (0.4, -14.8))\n"
    "        c = Line(b.end, (0.4, -10))",
])
def test_no_bridge_warning_where_there_is_no_thin_bridge(cuts):
    c, ws = _walls(_plate(cuts))
    assert ws == [], [w.message for w in ws]


DISC = """solid disc {{
    body = Circle(center=(0, 0), radius=20)
    hole bore {{ c = Circle(center=(0, 0), radius=5) }}
    cut slits {{
        a = Line((5, 0), (19.5, 0))
        b = Line((0, 5), (0, 20))
        c = Line(({c0}, 0), ({c1}, 0))
        e = Arc(center=(0, 0), radius=10, start_angle=100 deg, end_angle=170 deg)
        f = Arc(center=(0, 0), radius=10.5, start_angle=100 deg, end_angle=170 deg)
        g = Line((0, -5.5), (0, -10))
        h = Line((0, {h0}), (0, -15))
    }}
    Fixed(body)
    Fixed(bore.c)
}}
"""


def test_bridges_to_circles_are_measured_exactly():
    """Slits from a bore's edge, to its rim, between arcs: every bridge exactly 0.5 mm passes
    (the circles' chords are 0.005 mm inside them); 0.49 mm is told, by name."""
    _, ws = _walls(DISC.format(c0=-5.5, c1=-19.5, h0=-10.5))
    assert ws == [], [w.message for w in ws]
    _, ws = _walls(DISC.format(c0=-5.49, c1=-19.51, h0=-10.49))
    got = sorted((w.message.split(" and ")[1].split(" is ")[0], w.message.split(" is ")[1][:4])
                 for w in ws)
    assert got == [("hole `disc.bore`", "0.49"), ("the outer edge of `disc`", "0.49"),
                   ("through-cut `disc.slits.h`", "0.49")], [w.message for w in ws]


HINGE = """import std.plates
solid panel {{
    body = Rectangle(center=(0, 0), width=40, height=30)
    cut hinge = living_hinge(width=20 mm, height=30 mm, pitch=1 mm, cut=5 mm, bridge={bridge})
    Fixed(body)
}}
"""


def test_a_living_hinge_as_meant_is_silent_and_each_thin_bridge_is_told():
    _, ws = _walls(HINGE.format(bridge="0.5 mm"))
    assert ws == [], [w.message for w in ws]
    # 21 columns 1 mm apart (20 / 1 + 1), 5 rows of 5 mm cuts (floor((30 - 0.45) / 5.45)):
    # 11 full columns of 5 cuts (4 bridges), 10 shifted ones of 4 cuts and 2 end cuts (5)
    _, ws = _walls(HINGE.format(bridge="0.45 mm"))
    assert len(ws) == 11 * 4 + 10 * 5, len(ws)
    assert all("0.45 mm wide" in w.message for w in ws)


def test_a_bridge_stated_as_meant_with_min_wall_in_the_part_is_silent():
    cuts = "        a = Line((0, -15), (0, 14.99))"
    _, ws = _walls(_plate(cuts, part_wall="min_wall 0.005 mm\n    "))
    assert ws == []
    _, ws = _walls(_plate(cuts, part_wall="min_wall 0\n    "))
    assert ws == []


# ------------------------------------------------------------------ W0510
SEVER = """param L = {L} mm
solid plate {{
    body = Rectangle(center=(0, 0), width=60, height=30)
    cut slits {{
        a = Line((0, -15), (0, -15 + L))
    }}
    Fixed(body)
}}
"""


@pytest.mark.parametrize("default, value, words", [
    (20, "30", "its through-cuts cut it into 2 parts instead of 1"),
    (30, "20", "its through-cuts cut it into 1 part instead of 2")])
def test_a_cut_that_severs_the_part_only_under_a_param_value_is_w0510(default, value, words):
    src = SEVER.format(L=default)
    base = compile_source(src, "s.aidl")
    assert not [d for d in base.sink.items if d.code == "W0510"]
    res = compile_source(src, "s.aidl", {"L": value})
    # the cut runs from edge to edge at L = 30 mm: the left half is a part of its own
    assert sorted(p.name for p in res.drawing.parts) == (
        ["plate", "plate.piece1"] if value == "30" else ["plate"])
    (w,) = [d for d in res.sink.items if d.code == "W0510"]
    assert f"with L={value}, part `plate` changes" in w.message and words in w.message, \
        w.message
    # a value that changes nothing is silent
    res = compile_source(src, "s.aidl", {"L": str(default + 1)})
    assert not [d for d in res.sink.items if d.code == "W0510"]


# ------------------------------------------------------------------ min_wall out of place
@pytest.mark.parametrize("kind, body, where", [
    ("cut", "a = Line((-10, 0), (29.99, 0))", "cut `plate.x`"),
    ("hole", "c = Circle(center=(0, 6.7), radius=3)", "hole `plate.x`")])
def test_min_wall_where_nothing_reads_it_is_w0101_with_where_to_write_it(kind, body, where):
    src = f"""solid plate {{
    body = Rectangle(center=(0, 0), width=60, height=20)
    {kind} x {{
        min_wall 0.001 mm
        {body}
    }}
    Fixed(body)
}}
"""
    c = aidl_compile(src, path="p.aidl")
    (w,) = [d for d in c.sink.items if d.code == "W0101"]
    assert f"`min_wall` in {where} has no effect" in w.message, w.message
    assert (w.span.line, w.span.col) == (4, 9)
    assert "in `solid plate`" in w.hint, w.hint
    # it is not honoured (the wall checks still warn at 0.5 mm) ...
    assert [d for d in c.sink.items if d.code == "W0507"]
    # ... and written in the part, it is, without W0101
    moved = src.replace("        min_wall 0.001 mm\n", "").replace(
        "solid plate {\n", "solid plate {\n    min_wall 0.001 mm\n")
    c = aidl_compile(moved, path="p.aidl")
    assert not [d for d in c.sink.items if d.code in ("W0101", "W0507")], \
        [d.message for d in c.sink.items]


def test_a_thin_web_between_two_slits_is_told_once_not_again_at_their_ends():
    _, ws = _walls(_plate("        a = Line((-10, 0), (10, 0))\n"
                          "        b = Line((-10, 0.2), (10, 0.2))"))
    (w,) = ws
    assert w.message.startswith("a web of `plate` beside through-cuts `plate.slits.a` and "
                                "`plate.slits.b`"), w.message
