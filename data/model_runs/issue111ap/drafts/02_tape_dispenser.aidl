# Request (office): a desk tape dispenser for a 19 mm roll (75 mm across at most) on a
# 25 mm dowel axle, from 3 mm acrylic. Four parts:
# - two side plates, 140 mm long: a 20 mm high strip along the bottom, swelling round the
#   axle to a 32 mm radius, tapering to a 6 mm rounded nose at the front; a 25.5 mm axle
#   hole 45 mm from the back, 55 mm up; their bottom edges finger-jointed into the base;
# - a base, 140 x 31 (25 mm between the sides), fingers along both long edges, with a
#   mortise 12 mm from the front for the cutter's tenon;
# - a cutter: a 25 x 31 plate standing across the front of the base (10 mm tenon, glued),
#   its top edge serrated with 10 teeth 1.5 mm tall;
# - "TAPE" engraved in bold letters (filled) on one side plate, in front of the axle.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
length = 140 mm
inner = 25 mm
axle_d = 25.5 mm
axle_x = 45 mm
axle_y = 55 mm
roll_d = 75 mm
cutter_x = 128 mm        # the cutter's back face, from the back of the base

def side() -> solid {
    outline = Hull(Rectangle(bottom_left=(0, 0), width=length, height=20),
                   Circle(center=(axle_x, axle_y), radius=32),
                   Circle(center=(length - 6, 30), radius=6))
    hole axle { c = Circle(center=(axle_x, axle_y), diameter=axle_d) }
    fingers = finger_edge(length=length, thickness=t, finger=10, start="gap", rotation=180,
                          cx=length / 2, cy=0)
}

assembly tape_dispenser {
    left = side()
    right = side()

    solid base {
        plate = Rectangle(center=(length / 2, 0), width=length, height=inner + 2 * t)
        back_edge = finger_edge(length=length, thickness=t, finger=10, start="tab",
                                cx=length / 2, cy=(inner + 2 * t) / 2)
        front_edge = finger_edge(length=length, thickness=t, finger=10, start="tab",
                                 rotation=180, cx=length / 2, cy=-(inner + 2 * t) / 2)
        mortise = tab_and_slot(part="slot", length=inner, thickness=t, tabs=1, tab=10, screw=0,
                               rotation=90, cx=cutter_x + t / 2, cy=0)
    }

    solid cutter {
        body = Rectangle(bottom_left=(0, 0), width=inner, height=31)
        tenon = tab_and_slot(part="tab", length=inner, thickness=t, tabs=1, tab=10, screw=0,
                             rotation=180, cx=inner / 2, cy=0)
        solid teeth {
            for i in range(10) {
                tooth = Polygon([(i * 2.5, 31), (i * 2.5 + 2.5, 31), (i * 2.5 + 1.25, 32.5)])
            }
        }
    }

    drawing logo {
        word = Text("TAPE", (0, 0), size=10, font="sans:Bold", fill=true, valign="middle")
    }
    CutInto(logo, left)
    logo.bb.center_x == left.bb.left + 95
    logo.bb.center_y == left.bb.bottom + 12

    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    Below(base, left, gap=6)
    AlignLeft(base, left)
    RightOf(cutter, base, gap=6)
    AlignBottom(cutter, base)

    assert base.plate.bb.width == 140 mm, "base 140 long"
    assert base.plate.bb.height - 2 * t == 25 mm, "25 mm between the sides"
    assert len(cutter.teeth.tooth) == 10, "10 teeth"
    assert axle_y - roll_d / 2 > t + 2 mm, "the full roll clears the base"
    assert axle_x + roll_d / 2 < cutter_x - 5 mm, "the full roll clears the cutter"
    assert left.axle.c.diameter == 25.5 mm, "axle hole 25.5"
}
