# Request: a shelf rack that stands ten disc golf discs (210 mm across, up to 21 mm thick)
# on edge like records, in 6 mm birch ply. Two rails 372 x 70 mm, 120 mm apart, each with
# ten U notches 24 mm wide and 35 mm deep (round bottoms) at 32 mm pitch, their mouths
# rounded R3 and the rails' top corners R6; the disc rests in a notch of each rail and
# hangs below the notch bottoms between them. Two end panels 150 x 70 mm with a rounded
# handle bump (a 90 x 40 stadium centred on the top edge, blended R6) and a 50 x 16 mm hand
# hole in it. Rails and ends lock by cross halvings 35 mm deep, 171 mm either side of the
# middle and 60 mm either side of the ends' middle. The front rail is engraved with the
# numbers 1-10 under the notches, 8 mm tall.

import "std/joints.aidl"

t = 6 mm
thickness t

DISC_D = 210 mm
N = 10
PITCH = 32 mm
NOTCH_W = 24 mm
NOTCH_D = 35 mm
RAIL_L = 372 mm
RAIL_H = 70 mm
RAIL_GAP = 120 mm        # rail centre to rail centre
END_W = 150 mm
JOINT_X = 171 mm
def notch_x(i) = (i - (N - 1) / 2) * PITCH

def rail(numbered=false) -> solid {
    body = Rectangle(corner=(-RAIL_L / 2, 0), opposite=(RAIL_L / 2, RAIL_H))
    hole notches {
        for i in range(N) {
            u = Rectangle(corner=(notch_x(i) - NOTCH_W / 2, RAIL_H - NOTCH_D + NOTCH_W / 2),
                          opposite=(notch_x(i) + NOTCH_W / 2, RAIL_H + 1))
            r = Circle(center=(notch_x(i), RAIL_H - NOTCH_D + NOTCH_W / 2), diameter=NOTCH_W)
        }
    }
    for i in range(N) {
        Fillet([body.top, notches.u[i]], 3)
    }
    Fillet(body.top_left, 6)
    Fillet(body.top_right, 6)
    left_joint = cross_halving(depth=RAIL_H / 2, thickness=t, clearance=0.2, rotation=180,
                               cx=-JOINT_X, cy=0)
    right_joint = cross_halving(depth=RAIL_H / 2, thickness=t, clearance=0.2, rotation=180,
                                cx=JOINT_X, cy=0)
    if numbered {
        drawing numbers {
            for i in range(N) {
                n = Text(str(i + 1), position=(notch_x(i), 17), size=8, valign="middle")
            }
        }
    }
}

def end_panel() -> solid {
    body = Rectangle(corner=(-END_W / 2, 0), opposite=(END_W / 2, RAIL_H))
    bump = Slot(center=(0, RAIL_H), length=90, width=40)
    Fillet([body.top, bump], 6)
    hole hand {
        h = Slot(center=(0, RAIL_H + 2), length=50, width=16)
    }
    front_joint = cross_halving(depth=RAIL_H / 2, thickness=t, clearance=0.2,
                                cx=-RAIL_GAP / 2, cy=RAIL_H)
    back_joint = cross_halving(depth=RAIL_H / 2, thickness=t, clearance=0.2,
                               cx=RAIL_GAP / 2, cy=RAIL_H)
}

assembly disc_rack {
    front = rail(numbered=true)
    back = rail()
    left_end = end_panel()
    right_end = end_panel()

    # flat on the sheet
    Below(back, front, gap=10)
    AlignLeft(back, front)
    RightOf(left_end, front, gap=10)
    AlignTop(left_end, front)
    Below(right_end, left_end, gap=10)
    AlignLeft(right_end, left_end)

    # in 3D: x along the rails, y front to back, z up from the shelf
    Place(front, position=(0, -RAIL_GAP / 2 + t / 2, 0), face="front", up="up")
    Place(back, position=(0, RAIL_GAP / 2 + t / 2, 0), face="front", up="up")
    Place(left_end, position=(-JOINT_X + t / 2, 0, 0), face="left", up="up")
    Place(right_end, position=(JOINT_X - t / 2, 0, 0), face="right", up="up")

    assert len(front.notches.u) == 10, "ten notches"
    assert front.notches.r[1].center.x - front.notches.r[0].center.x == 32 mm, "32 pitch"
    assert front.notches.u[0].width == 24 mm, "24 wide"
    assert front.body.bb.top - front.notches.r[0].bb.bottom == 35 mm, "35 deep"
    assert front.body.bb.width == 372 mm and front.body.bb.height == 70 mm, "rails 372 x 70"
    assert left_end.body.bb.width == 150 mm and left_end.body.bb.height == 70 mm, "ends 150 x 70"
    # the disc sags between the rails: its lowest point must clear the shelf
    SAG = DISC_D / 2 - sqrt((DISC_D / 2) ** 2 - (RAIL_GAP / 2) ** 2)
    assert RAIL_H - NOTCH_D - SAG >= 10 mm, "disc clears the shelf by 10 mm"
    assert front.left_joint.depth + left_end.front_joint.depth == 70 mm, "halvings meet"
    assert front.right_joint.cut.bb.center_x - front.left_joint.cut.bb.center_x == 342 mm,
        "joints 171 either side"
    assert left_end.back_joint.cut.bb.center_x - left_end.front_joint.cut.bb.center_x == 120 mm,
        "rails 120 apart"
    assert left_end.hand.h.length == 50 mm and left_end.hand.h.width == 16 mm, "hand hole"
}
