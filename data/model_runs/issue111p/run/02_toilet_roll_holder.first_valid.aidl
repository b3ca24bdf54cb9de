# Bathroom: toilet-roll holder in 3 mm plywood, three parts. A back plate 160 x 130 mm with
# 6 mm corners, two 4.5 mm screw holes countersunk 9 mm at 50 mm either side of the centre and
# 40 mm above it, and two pairs of 3.2 x 20.2 mm slots (x = +-65 mm from the centre, centred
# at y = -15 and +15 mm) that take the arms' tabs. Two arms 110 x 80 mm (reaching out from the
# wall) each with two 3 x 20 mm tabs on the wall edge (their centres 25 and 55 mm above the
# arm's bottom, the arm's bottom 40 mm below the plate's centre) and a U notch for a 25 mm
# dowel: a 25.5 mm round seat 25 mm from the arm's free end and 25 mm below its top, open to
# the top edge.

thickness 3 mm

param slot_x = 65 mm, min = 50 mm, max = 75 mm

def arm() -> solid {
    body = Rectangle(bottom_left=(0, 0), width=110, height=80)
    tab1 = Rectangle(center=(-1.5, 25), width=3, height=20)
    tab2 = Rectangle(center=(-1.5, 55), width=3, height=20)
    hole notch {
        seat = Circle(center=(85, 55), diameter=25.5)
        mouth = Rectangle(bottom_left=(72.25, 55), width=25.5, height=25)
    }
    Fillet(body.top_right, 6)
    Fillet(body.bottom_right, 6)
}

assembly holder {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=160, height=130, corner_radius=6)
        hole screws {
            s1 = Circle(center=(-50, 40), diameter=4.5)
            s2 = Circle(center=(50, 40), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        hole slots {
            for i in range(2) {
                for j in range(2) {
                    r = Rectangle(center=((2 * i - 1) * slot_x, (2 * j - 1) * 15), width=3.2, height=20.2)
                }
            }
        }
    }
    left_arm = arm()
    right_arm = arm()
    RightOf(left_arm, back, gap=10)
    AlignBottom(left_arm, back)
    RightOf(right_arm, left_arm, gap=10)
    AlignBottom(right_arm, back)

    assert back.plate.bb.width == 160 mm and back.plate.bb.height == 130 mm, "plate 160 x 130"
    assert left_arm.body.bb.width == 110 mm and left_arm.body.bb.height == 80 mm, "arm 110 x 80"
    assert left_arm.notch.seat.diameter == 25.5 mm, "25.5 mm dowel seat"
    assert left_arm.body.right.midpoint.x - left_arm.notch.seat.center.x == 25 mm, "seat 25 from the end"
    assert left_arm.body.top.midpoint.y - left_arm.notch.seat.center.y == 25 mm, "seat 25 below the top"
    # tabs (25 and 55 above the arm's bottom, bottom 40 below the plate centre) meet the slots at -15 and +15
    assert 25 mm - 40 mm == -15 mm and 55 mm - 40 mm == 15 mm, "tabs meet the slots"
    assert back.slots.r[0][0].height == 20.2 mm and back.slots.r[0][0].width == 3.2 mm, "slots 3.2 x 20.2"
}
