"""Issue 111's third fresh-model run (data/model_runs/issue111c/REPORT.md, "Messages found
confusing or wrong"), each on the run's own program through the real checker: W0505 said as
meant with `AllowOverlap(lines, self)` (a checkerboard's grid lines over its dovetail band),
W0508 silent where a joint's slot opens into an arch through its mouth, E0408 naming the
edges of a turned Trapezoid that do meet, E0108 on a coordinate given to
`HorizontalDistance`, W0505's wording for a window no hole cut, E0405 on a structure's box widened
by its drawings."""
from __future__ import annotations

import re
from pathlib import Path

import aidl_lang

RUN = Path(__file__).resolve().parent.parent / "data" / "model_runs" / "issue111c"


def _read(name: str) -> str:
    return (RUN / name).read_text()


def _w(r, code):
    return [d for d in r.diagnostics if d.code == code]


def _codes(r) -> set:
    return {d.code for d in r.diagnostics if d.severity in ("warning", "error")}


# ------------------------------------------------------------------------------ W0505
def test_W0505_grid_lines_over_a_joint_band_are_said_meant_as_the_hint_writes():
    """10_checkerboard: each half's grid lines run across the dovetail band on purpose (11 %
    off the material).  W0505 warns each half and its hint writes the call that says so,
    `AllowOverlap(grid.h, self)` in the half; written where the hint says, neither W0505 nor
    W0523 is left and the part is unchanged (the same engraved lines, the same cut)."""
    src = _read("run/10_checkerboard.first_valid.aidl")
    r = aidl_lang.compile(src)
    assert r.ok
    ws = _w(r, "W0505")
    assert len(ws) == 2
    said = {}
    for w in ws:
        m = re.search(r"`(AllowOverlap\([^`]*\))` in `([\w.]+)`", w.hint)
        assert m, w.hint
        said[m.group(2)] = m.group(1)
    assert said == {"board.left": "AllowOverlap(grid.h, self)",
                    "board.right": "AllowOverlap(grid.h, self)"}
    fixed = src.replace("        drawing grid {",
                        "        AllowOverlap(grid.h, self)\n        drawing grid {")
    assert fixed.count("AllowOverlap") == 2
    r2 = aidl_lang.compile(fixed)
    assert r2.ok and not {"W0505", "W0523"} & _codes(r2), [d.message for d in r2.diagnostics]
    assert r2.to_svg() == r.to_svg()
    # naming the lines that lie on the material silences nothing, and says so
    wrong = fixed.replace("AllowOverlap(grid.h, self)", "AllowOverlap(grid.v, self)")
    r3 = aidl_lang.compile(wrong)
    assert len(_w(r3, "W0505")) == 2 and len(_w(r3, "W0523")) == 2
    assert "the engraving lies on its part's material" in _w(r3, "W0523")[0].message


def test_W0505_text_in_the_air_keeps_its_own_hint():
    """11_rainbow: the word written in the arch's opening is a real slip; its hint is the
    move (the width it has room for), never the call that would silence it."""
    r = aidl_lang.compile(_read("run/11_rainbow.first_valid.aidl"))
    (w,) = _w(r, "W0505")
    assert "AllowOverlap" not in w.hint
    # the space under the arch, closed by the bar, is a window the shapes enclose, not a
    # hole structure: said as an opening
    assert "runs across an opening of `rainbow`" in w.message, w.message


# ------------------------------------------------------------------------------ W0508
def test_W0508_a_cross_halving_slot_opening_into_the_arch_is_as_drawn():
    """05_plant_stand: panel B's cross-halving slot is cut up from the bottom edge, where the
    arch between the feet has taken the edge away: the slot reaches the edge through the
    arch, as it must.  No W0508; a round hole the same slot crosses higher up still is."""
    src = _read("run/05_plant_stand.first_valid.aidl")
    r = aidl_lang.compile(src)
    assert r.ok and _w(r, "W0508") == [], [d.message for d in _w(r, "W0508")]
    crossed = src.replace(
        "    solid b {\n        p = panel_shape()\n",
        "    solid b {\n        p = panel_shape()\n"
        "        hole pin { c = Circle(center=(0, -h / 2 + 80), radius=5) }\n")
    assert crossed != src
    ws = _w(aidl_lang.compile(crossed), "W0508")
    assert [("stand.b.pin" in w.message and "stand.b.s" in w.message) for w in ws] == [True]


# ------------------------------------------------------------------------------ E0408
def test_E0408_names_the_edges_of_a_turned_trapezoid_that_meet():
    """15_cheese_board's first try: `Fillet([body.right, neck.top], 10)` on a Trapezoid turned
    -90 deg (its `top` and `bottom` are the parallel ends).  The hint names the pairs that do
    meet, `[body.right, neck.right]` and `[body.right, neck.left]`; written, they round the
    two corners where the handle joins the board (no E0408, no W0406)."""
    src = _read("drafts/15_cheese_board.attempt1.aidl")
    r = aidl_lang.compile(src)
    es = _w(r, "E0408")
    assert len(es) == 2
    for e in es:
        assert "`[body.right, neck.right]` and `[body.right, neck.left]` do meet" in e.hint
        assert "rotation=" in e.hint
    fixed = src.replace("Fillet([body.right, neck.top], 10)",
                        "Fillet([body.right, neck.right], 10)").replace(
        "Fillet([body.right, neck.bottom], 10)", "Fillet([body.right, neck.left], 10)")
    r2 = aidl_lang.compile(fixed)
    assert r2.ok and not {"E0408", "W0406"} & _codes(r2), [d.message for d in r2.diagnostics]
    # two fillets of R10 at the joint: two more arcs of radius 10 than without them
    bare = aidl_lang.compile(re.sub(r"    Fillet\(.*\n", "", fixed))

    def tens(res):
        return [round(float(m), 6) for m in re.findall(r"A([\d.]+),", res.to_svg())].count(10.0)
    assert bare.ok and tens(r2) == tens(bare) + 2


# ------------------------------------------------------------------------------ E0108
def test_E0108_a_coordinate_given_to_HorizontalDistance_says_the_equation():
    """02_zipper_pull's first try: `HorizontalDistance(tab.bb.left, ring.s.center, 7 mm)`.
    The hint says `HorizontalDistance` is between two points and writes the equation on
    `.x`; the program written that way (as the model did) is valid."""
    src = _read("drafts/02_zipper_pull.attempt1.aidl")
    r = aidl_lang.compile(src)
    es = _w(r, "E0108")
    assert len(es) == 2
    assert all("write an equation on the other point's `.x`" in e.hint for e in es)
    assert all("== tab.bb.left + 7 mm" in e.hint for e in es)


# ------------------------------------------------------------------------------ E0405
def test_E0405_on_a_structure_box_says_what_its_drawings_add():
    """01_plant_marker's first try: `assert marker.bb.width == 25 mm` failed at 30.1 mm, the
    engraved word being wider than the 25 mm stake (the model had to find that out).  The
    message says that `marker.bb` holds the drawing `marker.label` and the material's own
    width, 25 mm; an assert on a structure without drawings says nothing of the kind."""
    src = _read("drafts/01_plant_marker.attempt1.aidl")
    r = aidl_lang.compile(src)
    (e,) = _w(r, "E0405")
    assert "30.0952 mm == 25 mm is false" in e.message
    assert "`marker.bb` holds its drawing `marker.label`: its material alone spans 25 x " \
        in e.message, e.message
    plain = aidl_lang.compile("solid p {\n    body = Rectangle(center=(0, 0), width=30, "
                              "height=10)\n}\nassert p.bb.width == 25 mm\n")
    (e2,) = _w(plain, "E0405")
    assert "holds its drawing" not in e2.message


# ------------------------------------------------------------------------------ E0102
def test_E0102_on_an_item_of_a_nested_loops_list_says_to_index_twice():
    """issue111d's trellis, first try: `lattice.dia[0].bb.width` where `dia` was set in two
    nested loops (a list of rows): the hint names the row's items and says the list holds
    one list per outer pass; written so, the assert reads the diamond's box."""
    run = RUN.parent / "issue111d"
    src = (run / "drafts" / "03_trellis.attempt1.aidl").read_text()
    r = aidl_lang.compile(src)
    (e,) = _w(r, "E0102")
    assert "`lattice.dia[0]` is a list of 6 (`lattice.dia[0][0]` to `lattice.dia[0][5]`)" in e.hint
    assert "holds one list per pass of the outer loop that set it" in e.hint
    fixed = src.replace("lattice.dia[0].bb.width", "lattice.dia[0][0].bb.width").replace(
        "len(lattice.dia) >= 40", "len(lattice.dia) == 7")
    r2 = aidl_lang.compile(fixed)
    assert r2.ok, [d.message for d in r2.errors]


# ------------------------------------------------------------------------------ Hull
def test_a_point_in_a_Hull_is_its_sharp_corner():
    """issue111d's heart tag wanted a sharp tip and drew an R1 circle: `Hull([lobe, tip])`
    with a Point runs straight from the lobe to the tip, exactly (two lines tangent to the
    circle that meet at the point), the tip in its box; points alone are E0108."""
    import math
    r = aidl_lang.compile("""solid heart {
    a = Circle(center=(-10, 0), radius=10)
    b = Circle(center=(10, 0), radius=10)
    tip = Point(0, -25)
    left = Hull([a, tip])
    right = Hull([b, tip])
}
assert heart.left.bb.bottom == -25 mm and heart.left.bb.left == -20 mm
assert heart.right.bb.right == 20 mm and heart.right.bb.top == 10 mm
""")
    assert r.ok, [d.message for d in r.diagnostics]
    (part,) = r.output.parts
    (loop,) = part.loops
    ends = [tuple(round(v, 9) for v in s.start) for s in loop.segments]
    assert (0.0, -25.0) in ends                          # the tip is a corner
    lines = [s for s in loop.segments if type(s).__name__ == "Line"]
    assert len(lines) == 2
    for s in lines:       # each side tangent to its circle: 10 mm from the centre
        (x0, y0), (x1, y1) = s.start, s.end
        c = (-10.0, 0.0) if min(x0, x1) < 0 else (10.0, 0.0)
        d = abs((x1 - x0) * (y0 - c[1]) - (y1 - y0) * (x0 - c[0])) / math.hypot(x1 - x0, y1 - y0)
        assert abs(d - 10.0) < 1e-9
    bad = aidl_lang.compile("solid s {\n    a = Point(0, 0)\n    b = Point(10, 0)\n"
                            "    h = Hull([a, b])\n}\n")
    (e,) = _w(bad, "E0108")
    assert "Hull of points and lines alone encloses no curve" in e.message


# ------------------------------------------------------------------------------ the prompt
def test_what_a_structure_holds_moves_with_it_as_the_prompt_says():
    """The prompt: `Fixed` holds in its structure, which carries it when placed (run g
    threaded an offset through 16 coordinates of its own template for want of it): an
    instance moved by `RightOf` takes its hole and its Fixed polygon along."""
    from aidl_lang.llm.prompt import system_prompt
    assert "an instance moved by `RightOf` takes its holes along" in " ".join(
        system_prompt().split())
    r = aidl_lang.compile("""def car() -> solid {
    body = Rectangle(center=(0, 0), width=40, height=20)
    hole w { c = Circle(center=(10, 0), radius=3) }
    win = Polygon([(-15, 0), (-5, 0), (-5, 5)])
    Fixed(win)
}
assembly toys {
    a = car()
    b = car()
    Fixed(a)
    RightOf(b, a, gap=10)
    AlignCenterY(b, a)
    assert b.w.c.center.x - a.w.c.center.x == 50 mm
    assert b.win.bb.left - a.win.bb.left == 50 mm
}
""")
    assert r.ok, [d.message for d in r.errors]


def test_sum_adds_a_list_of_one_kind():
    """`sum` (run d wanted it to count a nested loop's copies): numbers, lengths, a nested
    list's row lengths; 0 for an empty list; a length and an angle together are E0109."""
    r = aidl_lang.compile("a = [3 mm, 4 mm, 5 mm]\nassert sum(a) == 12 mm\n"
                          "assert sum([len(r) for r in [[1, 2], [3]]]) == 3\n"
                          "assert sum([]) == 0\nassert sum([10 deg, 20 deg]) == 30 deg\n"
                          "solid s { b = Rectangle(center=(0, 0), width=sum(a), height=5) }\n"
                          "assert s.b.width == 12 mm\n")
    assert r.ok, [d.message for d in r.errors]
    bad = aidl_lang.compile("x = sum([3 mm, 10 deg])\n")
    assert [d.code for d in bad.errors] == ["E0109"]


def test_an_assert_compares_strings():
    """`assert str(x) == "1.0"` was E0108 ("cannot constrain a string == a string"): two
    strings compare with `==` and `!=`, a false one said with its strings; `<` is E0108."""
    r = aidl_lang.compile('x = 1\nassert f"{x:.1f}" == "1.0"\nassert "a" != "b"\n'
                          'assert str(x) == "1.0", "one decimal"\n')
    (e,) = _w(r, "E0405")
    assert e.message == ('assertion failed: `str(x) == "1.0"` (one decimal): "1" == "1.0" is '
                         'false (where x = 1)'), e.message
    bad = aidl_lang.compile('assert "a" < "b"\n')
    assert "compare with `==` and `!=`" in _w(bad, "E0108")[0].message


# ------------------------------------------------------------------------------ run i
def test_W0502_on_a_pattern_copy_points_at_the_pattern_not_the_copy():
    """issue111i's clamp rack, first try: a LinearPattern's last two copies ran off the plate
    (its original centred alone); W0502's hint offered `CenterInside(row[3], self)`, which
    moves one copy apart from the row.  The hint now names the pattern to move; the row
    centred by its original's offset (as the model fixed it) cuts all five slots."""
    run = RUN.parent / "issue111i"
    src = (run / "drafts" / "01_clamp_rack.attempt1.aidl").read_text()
    r = aidl_lang.compile(src)
    ws = _w(r, "W0502")
    assert [w.message.split("`")[1] for w in ws] == ["rack.row[3]", "rack.row[4]"]
    for w in ws:
        assert "CenterInside" not in w.hint
        assert "is a copy a pattern (or a mirror) made: move the pattern" in w.hint


def test_E0109_on_an_angle_times_a_radian_says_atan2_is_an_angle():
    r = aidl_lang.compile("x = sin(atan2(35, 35) * 1 rad)\ny = cos(3 mm)\n")
    e1, e2 = _w(r, "E0109")
    assert e1.message == "`sin` needs an angle, got an angle^2"
    assert "give an angle already: drop the `* 1 rad`" in e1.hint
    assert e2.message == "`cos` needs an angle, got a length"


def test_W0404_not_on_holes_a_loose_box_inequality_reads():
    """issue111h's glass charms: six charms in a row by `AlignBottom`, each a disc with a
    stem hole whose throat pokes past the top edge (as asked).  The charm's box reads the
    hole's points through an inequality that pins nothing at the solution, and W0404 warned
    all six holes exactly where written; now none, and the ok line says they stay."""
    src = (RUN.parent / "issue111h" / "run" / "05_glass_charms.first_valid.aidl").read_text()
    r = aidl_lang.compile(src)
    assert r.ok
    r.find_redundant(seconds=None)
    assert _w(r, "W0404") == []
    assert "free but stay where written on their parts (harmless)" in r.freedom()["text"]


# ------------------------------------------------------------------------------ run k
def test_a_fillet_at_a_corner_an_earlier_fillet_took_is_E0408_not_a_crash():
    """issue111k's tent stake: `Fillet(2)` then `Fillet((20, 10), 0.5)` on a part with a round
    hole was an internal error (a whole circle's loop has no corner to measure).  Now E0408,
    which says the earlier Fillet finished that corner; written in the other order, both
    round as asked."""
    src = ("solid p {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    hole h { c = Circle(center=(0, 0), diameter=6) }\n"
           "    Fillet(2)\n    Fillet((20, 10), 0.5)\n}\n")
    r = aidl_lang.compile(src)
    (e,) = _w(r, "E0408")
    assert "(it was a corner before an earlier `Fillet` or `Chamfer` of `p` finished it)" \
        in e.message
    assert e.hint.startswith("write this `Fillet` before the one that finishes the whole")
    swapped = aidl_lang.compile(src.replace("    Fillet(2)\n    Fillet((20, 10), 0.5)\n",
                                            "    Fillet((20, 10), 0.5)\n    Fillet(2)\n"))
    assert swapped.ok and not [d for d in swapped.diagnostics if d.severity != "note"]
    radii = sorted(round(float(m), 6) for m in
                   re.findall(r"A([\d.]+),", swapped.to_svg().split('id="cut"')[1]))
    assert radii.count(0.5) == 1 and radii.count(2.0) == 3


def test_E0101_on_a_name_bound_inside_a_structure_gives_its_path():
    """issue111k's golf-ball rack, first try: `grid` read in the assembly beside `solid top {
    grid = GridPattern(...) }`: E0101's hint said "define it first" (it was defined); now it
    gives the path, `top.grid`, and the program written so checks."""
    src = (RUN.parent / "issue111k" / "drafts" / "06_golf_ball_rack.attempt1.aidl").read_text()
    # the assert itself reads `top.grid` since round thirteen (test_checks_messages111i); a
    # shape that reads the name still names its path
    assert not [d for d in _w(aidl_lang.compile(src), "E0101") if "`grid`" in d.message]
    src = src.replace('    assert len(grid) == 12, "12 ball holes"',
                      "    pin = Circle(center=grid[0].center, radius=1)")
    r = aidl_lang.compile(src)
    (e,) = [d for d in _w(r, "E0101") if "`grid`" in d.message]
    assert e.hint == "`grid` is defined inside `top`: reach it by its path, `top.grid`"
    plain = aidl_lang.compile("x = foo + 1\n")
    assert _w(plain, "E0101")[0].hint.startswith("define it first")


def test_W0405_on_an_assert_of_a_shape_box_a_fillet_shortened():
    """issue111k's tent stake: `Fillet(2)` on the whole outline took 21.4 mm off its 9.8 deg
    point, and `assert body.bb.height == 180 mm` (the shape as drawn) held with no word.
    W0405 now reads a shape's box where it is its structure's outline: it names the shape
    and the side that moved; the same assert on a side the fillet does not move is silent."""
    src = (RUN.parent / "issue111k" / "run" / "07_tent_stake.first_valid.aidl").read_text()
    r = aidl_lang.compile(src)
    ws = [w for w in _w(r, "W0405") if "body.bb.height == 180 mm" in w.message]
    assert len(ws) == 1
    assert "reads the box of `stake.body`, the outline of `stake`, before its Fillet" in \
        ws[0].message and "its bottom 21.419 mm in" in ws[0].message
    square = aidl_lang.compile("solid p {\n    body = Rectangle(center=(0, 0), width=40, "
                               "height=20)\n    Fillet(2)\n    assert body.bb.height == 20 mm\n}\n")
    assert square.ok and _w(square, "W0405") == []


def test_E0109_on_an_arc_angle_times_a_radian_says_acos_is_an_angle():
    """issue111m's tactics board: `start_angle=180 deg - acos(16 / 20) * 1 rad` said "cannot
    combine an angle with an angle^2" with a hint about ratios; now the hint says `acos`
    gives an angle already, as it does for an argument given an angle^2."""
    r = aidl_lang.compile("solid s {\n    a = Arc(center=(0, 0), radius=10, start_angle=180 deg "
                          "- acos(16 / 20) * 1 rad, end_angle=180 deg)\n}\n")
    (e,) = _w(r, "E0109")
    assert "cannot combine an angle with an angle^2" in e.message
    assert e.hint.startswith("`atan2`, `asin`, `acos` and `atan` give an angle already")
    r2 = aidl_lang.compile("solid s {\n    a = Arc(center=(0, 0), radius=10, start_angle="
                           "acos(0.8) * 1 rad, end_angle=180 deg)\n}\n")
    (e2,) = _w(r2, "E0109")
    assert "must be an angle, got an angle^2" in e2.message and "give an angle already" in e2.hint


def test_E0401_lists_a_templates_loop_copies_once():
    """issue111k's note holder: E0401 listed two tabs of finger_box's loop twice each (the
    same statement, the same words); each was made one label and one name, "(2 of them)".
    Since round fourteen (run dn) the template's own rows are one entry, at the program's
    call: the instance as its template draws it; the count of the set is still the whole."""
    src = (RUN.parent / "issue111k" / "drafts" / "02_note_holder.attempt1.aidl").read_text()
    r = aidl_lang.compile(src)
    (e,) = _w(r, "E0401")
    assert e.message.startswith("these 6 constraints conflict in `holder`")
    texts = [lb.message for lb in e.labels]
    assert len(texts) == len(set(texts)) == 2
    assert not any("std/" in (lb.span.file or "") or "joints.aidl" in (lb.span.file or "")
                   for lb in e.labels)
    assert e.hint.count("`holder.box` as its template `finger_box` draws it (its sizes)") == 1
    assert "Fixed(tab.center)" not in e.hint
