"""Defects issue 84's fresh-model run (data/model_runs/issue84/) saw that no message named,
each on the run's program, trimmed."""
from hypothesis import HealthCheck, given, settings, strategies as st


def _codes(compile_text, src, code):
    c = compile_text(src)
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    return [d for d in c.sink.items if d.code == code]


CHASSIS = """solid chassis {
    plate = RoundedRectangle(center=(0, 0), width=160, height=120, corner_radius=6)
    hole uno {
        h1 = Circle(center=(-26, 22), diameter=3.2)
        h2 = Circle(center=(-24.7, Y), diameter=3.2)
        h3 = Circle(center=(26.1, 27.1), diameter=3.2)
    }
}"""


def test_W0502_one_shape_of_a_hole_off_the_plate_is_named(compile_text):
    # 11_robot_chassis.first_valid.aidl: an Arduino hole written at y = 70.2 on a plate 120 mm
    # high (top at 60) vanished with no message: the hole as a whole cut something
    (w,) = _codes(compile_text, CHASSIS.replace("Y", "70.2"), "W0502")
    assert w.span.line == 5 and "`chassis.uno.h2`" in w.message and "`chassis`" in w.message
    assert "delete" not in w.hint
    assert not _codes(compile_text, CHASSIS.replace("Y", "50.2"), "W0502")


@settings(max_examples=12, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(x=st.floats(-120, 120), y=st.floats(-100, 100))
def test_W0502_law_a_shape_of_a_hole_is_named_when_it_lies_off_the_solid(compile_text, x, y):
    # a 3 mm circle beside a hole that cuts the plate: named when wholly off the 160 x 120 mm
    # plate's box, never when wholly on the plate
    off = abs(x) > 80 + 1.6 + 0.01 or abs(y) > 60 + 1.6 + 0.01
    on = abs(x) < 80 - 6 - 1.6 and abs(y) < 60 - 6 - 1.6
    src = CHASSIS.replace("(-24.7, Y)", f"({x:.3f}, {y:.3f})")
    named = [w for w in _codes(compile_text, src, "W0502") if "`chassis.uno.h2`" in w.message]
    if off:
        assert len(named) == 1
    if on:
        assert not named


SIGN = """solid sign {
    plate = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=8)
    hole screws {
        l = Circle(center=(-88, 0), diameter=4)
        r = Circle(center=(88, 0), diameter=4)
    }
    drawing engraving {
        label = Text("MEETING ROOM", (0, 0), size=SIZE, valign="middle")
    }
}"""


def test_W0505_text_over_a_screw_hole_says_a_small_share_and_names_the_hole(compile_text):
    # 13_door_sign.first_valid.aidl: 172 mm of text over the two screw holes at x = +-88 was
    # said "(0% of it is off the material)" with the hint `Inside(label, body)` (no `body`, and
    # the text is inside the plate's box already)
    (w,) = _codes(compile_text, SIGN.replace("SIZE", "16"), "W0505")
    # (issue 105: a text's share is said in letters, each M over its screw hole)
    assert '"M" (letter 1) and "M" (letter 11), 2 of its 11' in w.message and "0%" not in w.message
    assert "`sign.screws`" in w.hint and "Inside(" not in w.hint
    assert not _codes(compile_text, SIGN.replace("SIZE", "13"), "W0505")


TICTAC = """def o_piece() -> solid {
    ring = Circle(center=(0, 0), diameter=28)
    hole inside { c = Circle(center=(0, 0), diameter=16) }
}

assembly set {
    for i in range(2) {
        o = o_piece()
        o.bb.center == (118, -50 + i * PITCH)
    }
}"""


def test_W0511_hint_of_two_rings_says_nothing_of_gears(compile_text):
    # 16_tic_tac_toe.first_valid.aidl: two O pieces 25 mm apart (28 mm across) were told about
    # meshing gears' centre distance
    (w,) = _codes(compile_text, TICTAC.replace("PITCH", "25 mm"), "W0511")
    assert "gear" not in w.hint and "2.99 mm" in w.hint and "AllowOverlap(o[0], o[1])" in w.hint
    assert not _codes(compile_text, TICTAC.replace("PITCH", "32 mm"), "W0511")


def test_W0511_hint_of_two_gears_keeps_the_centre_distance(compile_text):
    src = """import "std/gears.aidl"
assembly drive {
    a = spur_gear(teeth=12, module=1.5 mm, bore=3 mm)
    b = spur_gear(teeth=36, module=1.5 mm, bore=8 mm, phase=185 deg)
    a.bb.center == (0, 0)
    b.bb.center == (34, 0)
}"""
    (w,) = _codes(compile_text, src, "W0511")
    assert "gear_pair" in w.hint and "module * (teeth1 + teeth2) / 2" in w.hint


@settings(max_examples=40, deadline=None)
@given(text=st.text("ABCDEFGHJKLMNOPQRSTUVWXYZ0123456789", min_size=3, max_size=16),
       size=st.floats(2, 40))
def test_prompt_text_width_law_a_capital_or_digit_takes_about_its_size(text, size):
    # the prompt's Text line (13_door_sign: 16 mm "MEETING ROOM" ran over the screw holes: the
    # model had no way to know a text's width): `size = room / characters` fits
    from aidl_lang.geometry.shapes.text import text_extent
    from aidl_lang.llm.prompt import system_prompt
    assert "size: cap height (a capital ~ size wide" in system_prompt()
    x0, x1, _, _ = text_extent(text, size)
    assert 0.6 * len(text) * size <= x1 - x0 <= 1.14 * len(text) * size
