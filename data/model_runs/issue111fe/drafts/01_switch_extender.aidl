# Request (home): a light-switch extender so my 4-year-old can reach the hall light.
# UK single rocker switch: face plate 86 x 86 mm, its two M3.5 fixing screws 60.3 mm apart
# on the horizontal centre line, the rocker 20 wide x 28 tall in the middle.
# Cut from 3 mm acrylic, five parts:
# - base: 86 wide x 260 tall, R6 corners, its top edge level with the face plate's top
#   (43 mm above the switch centre); goes on with longer M3.5 screws through two countersunk
#   holes (heads 7 mm) 60.3 apart; a 24 x 32 window lets the rocker through.
# - slider: 36 wide, its top 30 mm above the switch centre, running 250 mm down to a round
#   pull (50 mm disc with a 26 mm finger hole) below; a 24 x 34 catch window round the rocker.
# FIX after the first valid program: W0517 said the pull disc (top 195 below the centre)
# runs into the rails' ends (205 below): rails and keeper are now 130 long, ending 185 below.
# - two rails 10 x 130 glued on the base either side of the slider (0.5 mm play each side),
#   starting 55 mm below the switch centre (clear of the face plate).
# - keeper: 57 x 130, R4, glued on the rails over the slider, engraved "LIGHT" with
#   an up and a down arrow.

units mm
thickness 3 mm

import "std/fasteners.aidl"

rocker_w = 20 mm
rocker_h = 28 mm
screw_pitch = 60.3 mm
slider_w = 36 mm
rail_w = 10 mm
play = 0.5 mm
rail_x = slider_w / 2 + play + rail_w / 2     # centre of a rail from the switch centre
rail_top = -55 mm
rail_len = 130 mm

def rail_bar() -> solid {
    bar = Rectangle(center=(0, 0), width=10, height=rail_len)
}

assembly extender {
    solid base {
        plate = RoundedRectangle(center=(0, 43 - 130), width=86, height=260, corner_radius=6)
        hole rocker_window {
            w = Rectangle(center=(0, 0), width=24, height=32)
        }
        left_screw = clearance_hole(size=3.5, cx=-screw_pitch / 2, cy=0)
        right_screw = clearance_hole(size=3.5, cx=screw_pitch / 2, cy=0)
        Countersink([left_screw, right_screw], diameter=7)
    }

    solid slider {
        bar = Rectangle(center=(0, 30 - 125), width=slider_w, height=250)
        pull = Circle(center=(0, 30 - 250), diameter=50)
        hole catch {
            w = Rectangle(center=(0, 0), width=24, height=34)
        }
        hole finger {
            c = Circle(center=(0, 30 - 250), diameter=26)
        }
    }

    left_rail = rail_bar()
    right_rail = rail_bar()

    solid keeper {
        plate = RoundedRectangle(center=(0, rail_top - rail_len / 2), width=57, height=rail_len,
                                 corner_radius=4)
        drawing marks {
            word = Text("LIGHT", position=(0, rail_top - rail_len / 2), size=9,
                        font="sans:Bold", valign="middle", fill=true, rotation=90)
            up = Triangle(center=(0, rail_top - 25), base=16, height=12, fill=true)
            down = Triangle(center=(0, rail_top - rail_len + 25), base=16, height=12,
                            rotation=180, fill=true)
        }
    }

    # in 3D: base flat on the switch, slider and rails on it, keeper on top
    Place(base, position=(0, 0, 0))
    Place(slider, position=(0, 0, 3))
    Place(left_rail, position=(-rail_x, rail_top - rail_len / 2, 3))
    Place(right_rail, position=(rail_x, rail_top - rail_len / 2, 3))
    Place(keeper, position=(0, 0, 6))

    # on the sheet: side by side, tops aligned
    RightOf(slider, base, gap=6)
    AlignTop(slider, base)
    RightOf(left_rail, slider, gap=6)
    AlignTop(left_rail, base)
    RightOf(right_rail, left_rail, gap=6)
    AlignTop(right_rail, base)
    RightOf(keeper, right_rail, gap=6)
    AlignTop(keeper, base)

    # the request's numbers
    assert base.plate.bb.width == 86 mm, "base as wide as the face plate"
    assert base.plate.bb.height == 260 mm, "base 260 tall"
    assert distance(base.left_screw.c.center, base.right_screw.c.center) == 60.3 mm,
        "screws 60.3 apart"
    assert base.plate.bb.top - base.left_screw.c.center.y == 43 mm, "top level with the plate"
    assert base.rocker_window.w.width >= rocker_w + 4 mm, "rocker passes the base"
    assert slider.catch.w.height - rocker_h == 6 mm, "6 mm of travel for the rocker"
    assert slider.bar.bb.top - slider.catch.w.center.y == 30 mm, "slider top 30 above centre"
    assert slider.bar.bb.height == 250 mm, "slider 250 long"
    assert slider.pull.diameter == 50 mm and slider.finger.c.diameter == 26 mm, "pull"
    assert 2 * (rail_x - rail_w / 2) - slider_w == 2 * play, "0.5 mm play each side"
    assert left_rail.bar.bb.width == rail_w and left_rail.bar.bb.height == rail_len, "rails"
    assert keeper.plate.bb.width == 2 * (rail_x + rail_w / 2), "keeper covers both rails"
    assert keeper.plate.bb.height == 130 mm, "keeper 130 tall"
    assert rail_x - rail_w / 2 > slider_w / 2, "rails clear of the slider"
    assert (rail_top - rail_len) - (slider.pull.center.y + 25 mm) >= 8 mm,
        "the pull clears the rails' ends by 8 mm of travel"
    assert screw_pitch / 2 - 3.5 mm > rail_x + rail_w / 2 or rail_top < -43 mm,
        "screw heads not under the rails"
}
