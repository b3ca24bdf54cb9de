# Request (office): a mouse bungee for my desk so the mouse cable stops dragging. 6 mm ply.
# A heavy base of three glued layers, each 110 x 80 mm with r15 corners: the bottom plain, the
# middle with a 50 mm round pocket for a stack of steel washers as ballast, the top with a
# mortise for the arm and "GG" engraved filled (bold, 14 mm) at the front right. The arm is a
# swan neck 14 mm wide rising from a 50 mm foot with a 30 mm tenon (0.1 mm clearance in the
# mortise) and leaning 50 mm forward to a 24 mm round head; the cable clips into a 4.5 mm seat
# through a 2.6 mm slit from above, the seat 140 mm above the desk.

import "std/joints.aidl"

units mm
thickness 6 mm

ply = 6 mm
mortise_x = -30 mm

assembly bungee {
    solid bottom {
        plate = RoundedRectangle(center=(0, 0), width=110, height=80, corner_radius=15)
    }

    solid middle {
        plate = RoundedRectangle(center=(0, 0), width=110, height=80, corner_radius=15)
        hole pocket { c = Circle(center=(18, 0), diameter=50) }
    }

    solid top {
        plate = RoundedRectangle(center=(0, 0), width=110, height=80, corner_radius=15)
        m = tab_and_slot(part="slot", length=50 mm, thickness=6 mm, tabs=1, tab=30 mm, screw=0,
                         clearance=0.1 mm, cx=mortise_x, cy=0 mm)
        drawing mark {
            gg = Text("GG", position=(30, -25), size=14, font="sans:Bold", valign="middle", fill=true)
        }
    }

    solid arm {
        foot = Rectangle(center=(0, 10), width=50, height=20)
        neck = Stroke(Spline([(0, 18), (0, 70), (20, 112), (50, 128)]), width=14)
        head = Circle(center=(50, 128), radius=12)
        tenon = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=1, tab=30 mm, screw=0,
                             rotation=180 deg, cx=0 mm, cy=0 mm)
        hole seat {
            c = Circle(center=(50, 128), diameter=4.5)
            slit = Rectangle(center=(50, 135), width=2.6, height=12)
        }
    }

    # stacked: bottom on the desk, then middle, then top; the arm's tenon in the top's mortise
    Place(bottom, position=(0, 0, 0))
    Place(middle, position=(0, 0, ply))
    Place(top, position=(0, 0, 2 * ply))
    Place(arm, rotation=(90 deg, 0, 0), position=(mortise_x, ply / 2, 2 * ply))

    # flat on the sheet: a row
    RightOf(middle, bottom, gap=5)
    RightOf(top, middle, gap=5)
    RightOf(arm, top, gap=5)
    AlignBottom(middle, bottom)
    AlignBottom(top, bottom)
    AlignBottom(arm, bottom)

    assert bottom.plate.bb.width == 110 mm and bottom.plate.bb.height == 80 mm, "base 110 x 80"
    assert middle.pocket.c.diameter == 50 mm, "50 mm ballast pocket"
    assert arm.head.radius * 2 == 24 mm, "24 mm head"
    assert arm.seat.c.center.x - arm.foot.center.x == 50 mm, "leans 50 mm forward"
    assert arm.seat.c.center.y - arm.foot.bb.bottom + 2 * ply == 140 mm, "seat 140 mm above the desk"
    assert arm.seat.slit.bb.top >= arm.head.bb.top, "the slit opens at the top of the head"
}
