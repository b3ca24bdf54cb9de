"""Issue 111's round eighteen: what models reach for in the tree of the twenty-second session.

E0405 of an assert that reads a Spline's box names the point it swells past (runs gr and gs:
`head.profile.bb.right - head.neck.bb.left == 200 mm` failed at 200.075 mm, the design right,
the assert reading the curve's box where its nose point was meant)."""
from __future__ import annotations

from pathlib import Path

import aidl_lang

ROOT = Path(__file__).resolve().parent.parent
RUNS = ROOT / "data" / "model_runs"


def _codes(r):
    return sorted(d.code for d in r.diagnostics)


def _said(r, code):
    return [d for d in r.diagnostics if d.code == code]


def test_run_gs_e0405_of_a_spline_box_names_the_point_it_swells_past():
    path = RUNS / "issue111gs" / "drafts" / "08_deer_head_trophy.attempt1.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    [e] = _said(r, "E0405")
    assert "200.075 mm == 200 mm is false" in e.message
    assert ("`head.profile.bb` is the curve's box, 0.0751928 mm past its rightmost point "
            "`head.profile.points[5]` (a spline swells between its points): where a point "
            "is meant, assert on it; a limit on the cut part (a rule, the bed) reads the box "
            "rightly, and the points must come in") in e.message
    # the model's fix, the point it names: valid
    fixed = path.read_text().replace("head.profile.bb.right - head.neck.bb.left",
                                     "head.profile.points[5].x - head.neck.bb.left")
    assert aidl_lang.compile(source=fixed, path=str(path)).ok


SPLINE = """solid head {
    profile = Spline([(0 mm, 0 mm), (60 mm, 30 mm), (100 mm, 10 mm), (60 mm, -20 mm)],
                     closed=true)
}
"""


def test_e0405_of_a_spline_box_says_only_the_sides_read():
    r = aidl_lang.compile(source=SPLINE + "assert head.bb.height == 50 mm\n"
                          "assert head.profile.bb.left == 0 mm\n")
    e1, e2 = _said(r, "E0405")
    assert "past its topmost point `head.profile.points[1]`" in e1.message
    assert "past its bottommost point `head.profile.points[3]`" in e1.message
    assert "rightmost" not in e1.message and "leftmost" not in e1.message
    assert "past its leftmost point `head.profile.points[0]`" in e2.message
    # a side the curve does not pass (symmetric about y = 0: its nose point is its right)
    sym = SPLINE.replace("(60 mm, 30 mm), (100 mm, 10 mm)", "(60 mm, 20 mm), (100 mm, 0 mm)")
    r = aidl_lang.compile(source=sym + "assert head.profile.bb.right == 101 mm\n")
    [e] = _said(r, "E0405")
    assert "100 mm == 101 mm is false" in e.message and "spline" not in e.message


def test_run_gm_w0517_of_tabs_off_their_slots_along_a_slope_says_how_far():
    # the roof tabs sit 0.964 mm down the slope from their slots at each end; the two
    # slivers of each tab join along the roof's underside, which both parts lie on (a hull
    # 9 mm across every way said "9 mm deep"); each is measured on its own now
    path = RUNS / "issue111gm" / "drafts" / "03_mower_garage.attempt1.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    said = _said(r, "W0517")
    assert len(said) == 2 and all("0.964 mm deep" in d.message for d in said)
    # the model's fix (the joint's centre square above the edge's middle): they fit
    fixed = RUNS / "issue111gm" / "drafts" / "03_mower_garage.fix1.aidl"
    assert not _said(aidl_lang.compile(source=fixed.read_text(), path=str(fixed)), "W0517")
    # the corpus's others of the kind: run ff's slant board, tenons 3.3 mm down the slope
    # from their mortises (the model's own figure), was "9 mm deep"; run dj's trail camera
    # mount, tabs "1.6 mm up the slope from their slots", was "6 mm deep"
    for run, name, deep in (("issue111ff", "run/05_slant_board.first_valid.aidl", "3.28 mm"),
                            ("issue111dj", "dropped/07_trail_cam_mount.first_valid.aidl",
                             "1.61 mm")):
        path = RUNS / run / name
        said = _said(aidl_lang.compile(source=path.read_text(), path=str(path)), "W0517")
        assert len(said) == 2 and all(f"{deep} deep" in d.message for d in said), run


def test_run_gn_a_scales_zero_tick_at_an_inside_corner_is_a_tick():
    # a depth scale's 16 ticks end square on the fence's inner edge; the zero tick ends where
    # that edge meets the body's bottom edge, in line with the body's: square to one edge it
    # ends on, so one of the scale (W0516 x2 "ends on the cut edge", the model's false alarm)
    path = RUNS / "issue111gn" / "run" / "01_scratch_stock.first_valid.aidl"
    src = path.read_text()
    assert "tick = Line((hand * (40 - (5 if d % 5 == 0 else 3)), 20 - d), (hand * 40, 20 - d))" in src
    r = aidl_lang.compile(source=src, path=str(path))
    assert r.ok and "W0516" not in _codes(r)
    # a mark running into that corner at a slant is still warned
    slant = src.replace("(hand * 40, 20 - d))", "(hand * 40, 20 - d))\n"
                        "            slash = Line((hand * 36, 17), (hand * 40, 20))", 1)
    said = _said(aidl_lang.compile(source=slant, path=str(path)), "W0516")
    assert said and all("slash" in d.message for d in said)


def test_run_gx_a_length_floor_divided_in_range_gets_the_count_in_its_own_words():
    # `range(slot_len // 10 + 1)`: 31 mm, a length; W0106's "replace with `/`" beside E0108
    # would not make it a count: E0108 alone, with the program's own fix
    path = RUNS / "issue111gx" / "drafts" / "01_stair_gauge.attempt1.aidl"
    src = path.read_text()
    r = aidl_lang.compile(source=src, path=str(path))
    assert "W0106" not in _codes(r)
    e1, e2 = _said(r, "E0108")
    assert e1.hint.endswith("`range(slot_len // 10 mm + 1)`")
    assert e2.hint.endswith("`range(slot_len // 50 mm + 1)`")
    fixed = src.replace("slot_len // 10 + 1", "slot_len // 10 mm + 1").replace(
        "slot_len // 50 + 1", "slot_len // 50 mm + 1")
    assert aidl_lang.compile(source=fixed, path=str(path)).ok
    # W0106 still where `//` makes a length: `width=80 // 3`
    r = aidl_lang.compile(source="solid s {\n    r = Rectangle(center=(0, 0), "
                          "width=80 mm // 3, height=10)\n}\n")
    assert "W0106" in _codes(r)


def test_run_gw_e0204_of_a_shapes_size_says_why_and_what_takes_it():
    path = RUNS / "issue111gw" / "drafts" / "05_balloon_bouquet_base.attempt1.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    [e] = _said(r, "E0204")
    assert e.hint == ("`word.bb.width` is read from a shape, known only after solving; a "
                      "template is made from numbers known before: give it numbers (the ones "
                      "that drew the shape), or draw the feature with shapes here, which take "
                      "solved values (`Rectangle(..., width=word.bb.width)`)")
    from aidl_lang.llm.prompt import system_prompt
    assert "`part = NAME(p1=...)`, numbers known before solving, not a shape's `bb`" in \
        " ".join(system_prompt().split())


def test_runs_gu_gx_a_spline_swinging_off_a_straight_run_of_its_points_is_a_note():
    # gu's fern board: a flat top through (-100, 318), (0, 320), (100, 318) humps 5.6 mm;
    # gx's canoe yoke: a near straight edge swells 9.66 mm into a knob before its end
    for run, name, said in (
            ("issue111gu", "04_fern_mount", "`fern_mount.board.outline` swings 5.6 mm off the "
             "straight run of its points between points[0] and points[1] (and in 1 more "
             "place): a smooth curve through the points overshoots there to round the turn "
             "at points[2]"),
            ("issue111gx", "06_canoe_yoke", "`yoke.outline` swings 9.66 mm off the straight "
             "run of its points between points[18] and points[19] (and in 3 more places)")):
        path = RUNS / run / "run" / f"{name}.first_valid.aidl"
        r = aidl_lang.compile(source=path.read_text(), path=str(path))
        [n] = _said(r, "W0412")
        assert n.severity == "note" and n.message.startswith(said), n.message
    # the hint's first way, a point where the turn begins (fern: (110, 315)), keeps the
    # top within 1 mm of its line: no note, and the top's highest point is 320 mm as drawn
    path = RUNS / "issue111gu" / "run" / "04_fern_mount.first_valid.aidl"
    src = path.read_text().replace("(0, 320), (100, 318), (125, 300)",
                                   "(0, 320), (90, 319), (110, 315), (125, 300)").replace(
        "corners=[6]", "corners=[7]").replace("points[6]", "points[7]")
    r = aidl_lang.compile(source=src, path=str(path))
    assert r.ok and not _said(r, "W0412")
    from aidl_lang.geometry.shapes.spline import interpolate, strays
    half = [(0, 320), (90, 319), (110, 315), (125, 300), (128, 220), (110, 120), (60, 40),
            (0, 0)]
    c = interpolate(half + [(-x, y) for x, y in reversed(half[1:-1])], True, [7])
    assert strays(c, [7]) == []
    from aidl_lang.geometry.shapes.spline import bez_box
    top = max(bez_box(c.span(i))[3] for i in range(c.n))
    assert 320 <= top < 321, top


def test_run_gw_w0517_of_a_part_with_no_place_among_placed_ones_says_it_lies_flat():
    # the backboard had no Place: it lay flat as drawn while the pegs stood up through it;
    # W0517 said "move each peg 0.343 mm" and labelled the board "placed here"
    path = RUNS / "issue111gw" / "run" / "01_hat_rack.first_valid.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    said = _said(r, "W0517")
    assert len(said) == 3
    for w in said:
        assert w.hint.startswith(
            "`board` has no `Place`, so it lies as drawn, flat on the x-y plane (z 0 to 6 mm), "
            "while `p[")
        assert "if it is to stand, give it its `Place` (`face=\"front\"` stands it up " \
               "facing -y)" in w.hint
        assert [lb.message for lb in w.labels] == [
            "`hat_rack.board` has no `Place`: it lies as drawn"]
    # the model's fix, as the hint says: `Place(board, position=(0, 0, 0), face="front",
    # up="up")`: no collision
    fixed = RUNS / "issue111gw" / "drafts" / "01_hat_rack.aidl"
    assert "Place(board, position=(0, 0, 0), face=\"front\", up=\"up\")" in fixed.read_text()
    assert not _said(aidl_lang.compile(source=fixed.read_text(), path=str(fixed)), "W0517")


def test_run_gv_w0519_of_a_long_seam_offers_to_end_one_short():
    # a glue flap's side along the next face's edge, 0.01 mm apart over 3.9 mm: the corner's
    # Fillet fills it all (only 0.42 mm fits, W0406) and joins the flap to the face, so it no
    # longer folds; the model ended each flap 1.5 mm short of the corners
    path = RUNS / "issue111gv" / "run" / "07_dodecahedron_net.first_valid.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    said = _said(r, "W0519")
    assert said and all(
        "which joins them along the slit's" in w.hint and "if they are to stay apart there "
        "(a flap that folds, a tab), end one at least 0.5 mm short of the other instead"
        in w.hint for w in said if "Fillet(at=" in w.hint)
    assert sum("Fillet(at=" in w.hint for w in said) >= 3
    # a short nick (the issue-84 kind) keeps the one fix
    from aidl_lang.output.checks.material.nicks import SEAM
    assert SEAM == 4


def test_run_hb_points_in_line_mean_a_straight_side():
    # the paddle's sides through five points on x = 97.5 bowed 0.672 mm each way (196.34 mm
    # across where 195 was asked, and the model's assert on the points passed): points in
    # line are held to 1 % of the span; the model's fix, a Polygon rounded by Fillet, is
    # what the hint's last way says
    path = RUNS / "issue111hb" / "run" / "06_pickleball_paddle.first_valid.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    [n] = _said(r, "W0412")
    assert n.message.startswith("`paddle.core.outline` swings 0.672 mm off the straight run")
    assert "or draw the outline as a Polygon rounded by `Fillet` (its sides stay straight)" \
        in n.hint
    # an S's middle point (a snake's body: its neighbours turn each way) is no straight run
    from aidl_lang.geometry.shapes.spline import interpolate, strays
    s = [(0, 0), (20, 10), (40, 0), (60, -10), (80, 0), (100, 10), (120, 0), (120, -8),
         (0, -8)]
    assert [f for f in strays(interpolate(s, True, [6, 7, 8]), [6, 7, 8])] == []


def test_run_hb_fillet_where_a_shape_meets_a_rounded_rectangle_of_several_radii():
    # `Fillet([throat, head], 25)` with head's corner_radii=[70, 70, 60, 60]: E0408 "their
    # outlines do not cross there" (the head was taken as its sharp rectangle); one radius
    # for all four corners checked fine
    from test_exact_formats import svg_segments
    path = RUNS / "issue111hb" / "drafts" / "06_probe_fillet_corner_radii.aidl"
    src = path.read_text()
    for radii in ("[70, 70, 60, 60]", "[0, 0, 60, 60]"):
        r = aidl_lang.compile(source=src.replace("[70, 70, 60, 60]", radii), path=str(path))
        assert r.ok and not r.diagnostics, [d.message for d in r.diagnostics]
        segs, _ = svg_segments(r.to_svg())
        arcs = sorted(round(float(s.rx), 6) for s in segs if type(s).__name__ == "Arc")
        assert arcs.count(25.0) == 2 and arcs.count(60.0) == 2, arcs


def test_run_ha_w0502_of_a_joint_turned_the_wrong_way_gives_the_rotation_that_turns_it():
    # a gusset's side tenon at `rotation=270 deg` ran off its part; the hint's fixed
    # "`rotation=180 deg` runs it the other way" still cut nothing
    path = RUNS / "issue111ha" / "run" / "05_embroidery_hoop_stand.first_valid.aidl"
    src = path.read_text()
    r = aidl_lang.compile(source=src, path=str(path))
    [w] = _said(r, "W0502")
    assert "and `rotation=90 deg` (it has 270 deg) runs it the other way" in w.hint
    line = "screw=0, rotation=270 deg, cx=0 mm, cy=t + gusset / 2)"
    assert src.count(line) == 1
    r = aidl_lang.compile(source=src.replace(line, line.replace("270", "90")), path=str(path))
    assert "W0502" not in _codes(r) and "W0517" not in _codes(r)


def test_run_ha_w0405_of_a_hole_run_out_through_the_side_is_a_note():
    # an arm's fork, a slot run 1 mm past the round end it notches: the arm's outline
    # reaches 0.635 mm less far than the Slot drawn (the notch takes the tip); the asserts on
    # the Slot's 220 mm are the size meant (the model: "219.4 by design"), a note
    path = RUNS / "issue111ha" / "run" / "05_embroidery_hoop_stand.first_valid.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    notes = _said(r, "W0405")
    assert len(notes) == 2 and all(n.severity == "note" for n in notes)
    assert all("(the shape as drawn, a hole run out through that side cutting it back)"
               in n.message and "(its left 0.635 mm in)" in n.message for n in notes)
    # a hole that trims the whole side back is still a warning
    trim = """solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    hole trim { r = Rectangle(bottom_left=(-51, 25), width=102, height=6) }
}
assert plate.body.bb.height == 60 mm
"""
    [w] = _said(aidl_lang.compile(source=trim), "W0405")
    assert w.severity == "warning" and "(its top 5.000 mm in)" in w.message


def test_run_hf_fillet_where_a_spline_meets_a_shape_says_no_corner_on_it_rounds():
    # E0108 said to give the corner's point or `Fillet(r)`: both end in E0407 on a spline
    path = RUNS / "issue111hf" / "drafts" / "01_strop_paddle.attempt1.aidl"
    src = path.read_text()
    r = aidl_lang.compile(source=src, path=str(path))
    [e] = _said(r, "E0108")
    assert "`grip` is a Spline, and no corner where a spline meets another shape can be " \
           "rounded exactly" in e.message and "Fillet((x, y), r)" not in e.message
    assert "draw that end of the outline with Lines and Arcs" in e.message
    # the two ways it named before fail, as it now says
    for other in ("Fillet(8)",):
        r = aidl_lang.compile(source=src.replace("Fillet([grip, face], 8)", other),
                              path=str(path))
        assert "E0407" in _codes(r)


def test_run_hd_w0513_of_a_loops_boxes_side_by_side_says_draw_the_shared_sides_once():
    # "draw `plaque.eons.e` without the side that lies on `plaque.eons.e`" dropped the
    # indices its headline gives; "leave out the copies ... that lie on" would delete boxes
    path = RUNS / "issue111hd" / "run" / "07_geologic_timescale.first_valid.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    warned = [d for d in _said(r, "W0513") if d.severity == "warning"]
    assert len(warned) == 2
    for w in warned:
        assert w.hint.startswith("draw each stroke once: draw the copies of `plaque.")
        assert "without the sides they share: one outline round them all and a `Line` at " \
               "each boundary, or move one of them clear" in w.hint
        assert "leave out the copies" not in w.hint


def test_run_he_fillet_where_a_stroke_meets_a_shape():
    # `Fillet([horn, body], 4)` of a hook drawn as a Stroke along a three-point Arc: E0108
    # ("the corners where two outlines cross are found for Circle, ..."); the model worked
    # the two crossings out by hand, (-55, -112.92) and (-54.91, -123.19)
    from test_exact_formats import svg_segments
    src = """solid back {
    body = RoundedRectangle(center=(0, 0), width=110, height=260, corner_radii=[55, 55, 8, 8])
    horn = Stroke(Arc(start=(-45, -118), through=(-66, -112), end=(-72, -92)), width=10)
    Fillet(CHOSEN, 4)
}
"""
    by_shapes = aidl_lang.compile(source=src.replace("CHOSEN", "[horn, body]"))
    by_points = aidl_lang.compile(source=src.replace(
        "CHOSEN", "[(-55, -112.920081), (-54.910368, -123.194184)]"))
    assert by_shapes.ok and not by_shapes.diagnostics, [d.message for d in by_shapes.diagnostics]
    segs, _ = svg_segments(by_shapes.to_svg())
    assert sum(abs(float(s.rx) - 4) < 1e-9 for s in segs if type(s).__name__ == "Arc") >= 2
    assert by_shapes.to_svg() == by_points.to_svg()      # the corners the model found


def test_run_hi_text_shows_its_position_as_required():
    # the prompt's and the hint's `Text(text, position=none, ...)` read as optional (E0108 "a
    # Text needs a position")
    from aidl_lang.llm.prompt import system_prompt
    from aidl_lang.registry import ENTRIES
    assert "- Text(text, position, size=5," in system_prompt()
    assert "  Text(text, position, size=5," in lookup("Text")
    assert ENTRIES["Text"].signature().startswith("Text(text: string, position: point, ")
    r = aidl_lang.compile(source='solid s {\n    body = Rectangle(center=(0, 0), width=50, '
                          'height=20)\n    drawing d { t = Text("HI", size=5) }\n}\n')
    [e] = _said(r, "E0108")
    assert e.hint.startswith("Text(text: string, position: point, size: length = 5")


def lookup(name):
    from aidl_lang.library.reference import lookup_text
    return lookup_text(name)[0]


def test_run_hi_e0405_names_a_shape_for_the_material_only_when_it_is_all_of_it():
    # `self.bb` of a silhouette of child solids (a moon, a sleigh) and its own harness: "its
    # material alone spans 280 x 280 mm (`silhouette.harness.bb`)", the harness named for the
    # moon's box
    src = """solid silhouette {
    harness = Rectangle(center=(0, 0), width=40, height=4)
    solid moon {
        disc = Circle(center=(0, 0), diameter=280)
        hole bite { c = Circle(center=(100, 30), diameter=200) }
    }
    assert self.bb.width <= 300 mm
}
"""
    [e] = _said(aidl_lang.compile(source=src), "E0405")
    assert "its material alone spans 280 x 280 mm" in e.message
    assert "harness.bb" not in e.message


def test_run_hj_a_centre_line_through_a_hole_is_not_off_the_material():
    # a unit circle's x and y axes through the pointer's 6 mm pivot hole: W0505 x2 "runs
    # across a hole", a false alarm (a centre line through a hole is drafting)
    path = RUNS / "issue111hj" / "run" / "07_unit_circle.first_valid.aidl"
    r = aidl_lang.compile(source=path.read_text(), path=str(path))
    assert "W0505" not in _codes(r)
    # a line across a hole off its middle is still said
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole pivot { c = Circle(center=(0, 0), diameter=6) }
    drawing d { l = Line((-25, Y), (25, Y)) }
}
"""
    assert "W0505" not in _codes(aidl_lang.compile(source=src.replace("Y", "0")))
    assert "W0505" in _codes(aidl_lang.compile(source=src.replace("Y", "2")))
    # the corpus's others: run dh's kanban dividers through the feet's mortises (the model's
    # false alarm) are clear; run cc's lamp veins that start inside the well are still said
    for run, name, said in (("issue111dh", "02_kanban_board", 0),
                            ("issue111cc", "06_lotus_diya", 1)):
        path = RUNS / run / "run" / f"{name}.first_valid.aidl"
        r = aidl_lang.compile(source=path.read_text(), path=str(path))
        assert _codes(r).count("W0505") == said, run


def test_run_ho_radians_of_an_angle_is_that_angle():
    # `radians(sweep)` of an angle read its radians as degrees: 0.0061 for 0.3485, and the
    # model's arc-length asserts failed by 247 mm, silently wrong arithmetic
    path = RUNS / "issue111ho" / "drafts" / "07_slab_mug_template.attempt1.aidl"
    src = path.read_text()
    assert "r_out * radians(sweep) - pi * 80 mm" in src
    r = aidl_lang.compile(source=src, path=str(path))
    assert not [d for d in _said(r, "E0405") if "radians" in d.message]
    r = aidl_lang.compile(source="""r = 721.11 mm
sw = 19.9692 deg
solid s { q = Rectangle(center=(0, 0), width=10, height=10) }
assert abs(r * radians(sw) - 251.33 mm) < 0.01 mm
assert abs(r * radians(19.9692) - 251.33 mm) < 0.01 mm
""")
    assert r.ok and not r.diagnostics


def test_a_stroke_along_a_spline_in_fillet_is_said_not_a_traceback():
    # (found in the review) `Fillet(2)` of a solid with a Stroke along a Spline ended in
    # "internal error: AttributeError" (E0407 named the structure, which has no owner);
    # `Fillet([band, body], 2)` named the corner's point, which E0407 refuses too
    src = """solid s {
    body = Rectangle(center=(0, 0), width=40, height=40)
    band = Stroke(Spline([(-30, 0), (-10, 10), (10, -10), (30, 0)]), width=4)
    FILLET
}
"""
    r = aidl_lang.compile(source=src.replace("FILLET", "Fillet(2)"))
    assert "E0407" in _codes(r)
    r = aidl_lang.compile(source=src.replace("FILLET", "Fillet([band, body], 2)"))
    [e] = _said(r, "E0108")
    assert e.message.startswith("Fillet at [a, b]: `band` is a Stroke along a Spline or "
                                "Bezier, and no corner where a spline meets another shape")
