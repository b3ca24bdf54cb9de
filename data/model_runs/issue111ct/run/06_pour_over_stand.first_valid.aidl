# Request: a flat-pack pour-over coffee stand for the camping box, 6 mm ply, no glue.
# - Shelf 150 x 130 mm, corners rounded 10 mm, a 60 mm hole in the middle for the dripper's
#   foot; engraved round the hole on a 38 mm circle: "POUR SLOWLY" over the top and
#   "CAMP COFFEE" under it, reading the right way up.
# - Two legs 130 mm deep x 160 mm tall (tabs included), standing 120 mm apart (centre to
#   centre), each with 2 tabs 20 mm wide through slots in the shelf, and a 70 x 100 mm
#   rounded window to save weight.
# - A back brace 150 x 40 mm, cross-halved into both legs 55 mm behind their middle (half
#   its height each way), so the stand does not rack.
# - A 85 mm mug, 110 mm tall, must stand under the hole between the legs and in front of
#   the brace.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 5 mm, max = 7 mm
leg_apart = 120 mm
brace_y = 55 mm
brace_h = 40 mm

def leg() -> solid {
    body = Rectangle(center=(0, 80), width=130, height=160)
    tabs = tab_and_slot(part="tab", length=130 mm, thickness=t, tabs=2, tab=20 mm, screw=0,
                        cx=0 mm, cy=160 mm)
    hole window { w = RoundedRectangle(center=(0, 75), width=70, height=100, corner_radius=15) }
    halving = cross_halving(depth=brace_h / 2, thickness=t, rotation=180 deg, cx=brace_y,
                            cy=0 mm)
    Fixed(body)
    Fixed(window)
}

assembly stand {
    solid shelf {
        plate = RoundedRectangle(center=(0, 0), width=150, height=130, corner_radius=10)
        hole dripper { c = Circle(center=(0, 0), diameter=60) }
        left_slots = tab_and_slot(part="slot", length=130 mm, thickness=t, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-leg_apart / 2, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=130 mm, thickness=t, tabs=2, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=leg_apart / 2, cy=0 mm)
        drawing words {
            ring = Circle(center=(0, 0), radius=38, construction=true)
            top = Text("POUR SLOWLY", along=ring, size=6)
            bottom = Text("CAMP COFFEE", along=ring, size=6, flip=true)
        }
        Fixed(plate)
        Fixed(dripper)
        Fixed(words)
        assert plate.width == 150 mm and plate.height == 130 mm
        assert dripper.c.diameter == 60 mm
        assert right_slots.bb.center_x - left_slots.bb.center_x == 120 mm
    }

    left_leg = leg()
    right_leg = leg()

    solid brace {
        bar = Rectangle(center=(0, brace_h / 2), width=150, height=brace_h)
        left_cut = cross_halving(depth=brace_h / 2, thickness=t, cx=-leg_apart / 2, cy=brace_h)
        right_cut = cross_halving(depth=brace_h / 2, thickness=t, cx=leg_apart / 2, cy=brace_h)
        Fixed(bar)
        assert bar.width == 150 mm and bar.height == 40 mm
    }

    RightOf(left_leg, shelf, gap=10)
    AlignTop(left_leg, shelf)
    RightOf(right_leg, left_leg, gap=10)
    AlignTop(right_leg, shelf)
    Below(brace, shelf, gap=10)
    AlignLeft(brace, shelf)

    Place(shelf, position=(0, 0, 160 - t), face="up")
    Place(left_leg, position=(-leg_apart / 2 - t / 2, 0, 0), face="right", up="up")
    Place(right_leg, position=(leg_apart / 2 - t / 2, 0, 0), face="right", up="up")
    Place(brace, position=(0, brace_y + t / 2, 0), face="front", up="up")

    assert left_leg.body.height == 160 mm and left_leg.body.width == 130 mm
    assert left_leg.body.height - t >= 110 mm, "a 110 mm mug fits under the shelf"
    assert leg_apart - t >= 85 mm, "an 85 mm mug fits between the legs"
    assert brace_y - t / 2 >= 85 mm / 2, "the mug stands in front of the brace"
    assert left_leg.window.w.width == 70 mm and left_leg.window.w.height == 100 mm
}
