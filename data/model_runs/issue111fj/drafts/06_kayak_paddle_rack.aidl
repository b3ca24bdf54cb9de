# Request: a wall rack for two kayak paddles (32 mm shafts), 9 mm birch ply: two identical
# brackets screwed to the wall 1200 mm apart. Each bracket: a back plate 60 wide x 180 tall
# with two countersunk M5 screw holes (10 mm heads) on its centre line, 18 mm in from the top
# and bottom ends, and an arm standing out 200 mm from the back plate's face, 120 mm tall at
# the wall, its bottom edge sloping up to 80 mm at the tip (so 40 tall there). The arm's top
# edge has two round-bottomed cradles 34 wide and 35 deep, centred 60 and 150 mm out, their
# mouths eased R4. The arm holds to the back plate on two 30 mm tenons through it (flush
# with the wall side). "PADDLES" engraved filled on each arm (sans bold, 12 mm, at most
# 80 wide), centred 90 mm out, its baseline 56 mm up.

units mm
thickness 9 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

T = 9 mm
REACH = 200 mm
ARM_H = 120 mm
TIP_RISE = 80 mm
CRADLE_W = 34 mm
CRADLE_D = 35 mm
CRADLES = [60 mm, 150 mm]
BACK_W = 60 mm
BACK_H = 180 mm
APART = 1200 mm

# the arm, drawn with the back plate's face at x = 0 and its bottom at y = 0
def arm() -> solid {
    body = Polygon([(-T, 0), (0, 0), (REACH, TIP_RISE), (REACH, ARM_H), (-T, ARM_H)])
    tenons = tab_and_slot(part="tab", length=ARM_H, thickness=T, tabs=2, tab=30 mm,
                          screw=0, rotation=90 deg, cx=-T, cy=ARM_H / 2)
    hole cradle {
        for x in CRADLES {
            u = Slot(start=(x, ARM_H - CRADLE_D + CRADLE_W / 2), end=(x, ARM_H + CRADLE_W),
                     width=CRADLE_W)
        }
    }
    Fillet([body, cradle.u[0]], 4 mm)
    Fillet([body, cradle.u[1]], 4 mm)
    drawing word {
        t = Text("PADDLES", position=(90 mm, 56 mm), size=12, font="sans:Bold", fill=true,
                 max_width=80 mm)
    }
}

# the back plate, drawn with the arm's bottom at y = 0, on its centre line x = 0
def back_plate() -> solid {
    body = Rectangle(bottom_left=(-BACK_W / 2, -30 mm), width=BACK_W, height=BACK_H)
    mortise = tab_and_slot(part="slot", length=ARM_H, thickness=T, tabs=2, tab=30 mm,
                           screw=0, rotation=90 deg, cx=0, cy=ARM_H / 2)
    low = clearance_hole(size=5, cx=0, cy=-30 mm + 18 mm)
    high = clearance_hole(size=5, cx=0, cy=-30 mm + BACK_H - 18 mm)
    Countersink([low, high], diameter=10 mm)
}

assembly paddle_rack {
    left_back = back_plate()
    right_back = back_plate()
    left_arm = arm()
    right_arm = arm()

    # flat layout
    RightOf(right_back, left_back, gap=8)
    AlignBottom(right_back, left_back)
    RightOf(left_arm, right_back, gap=8)
    AlignBottom(left_arm, left_back)
    Above(right_arm, left_arm, gap=8)
    AlignLeft(right_arm, left_arm)

    # 3D: the wall is the plane y = 0, the arms stand out toward -y
    for b in [[left_back, left_arm, -APART / 2], [right_back, right_arm, APART / 2]] {
        Place(b[0], position=(b[2], 0, 0), face="front", up="up")
        Place(b[1], position=(b[2] + T / 2, -T, 0), face="left", up="up")
    }

    assert left_arm.cradle.u[1].start.x - left_arm.cradle.u[0].start.x == 90 mm, "cradles 60 and 150 out"
    assert left_arm.cradle.u[0].width == 34 mm, "cradles 34 wide"
    assert left_arm.body.bb.top - left_arm.cradle.u[0].bb.bottom == 35 mm, "cradles 35 deep"
    assert left_arm.body.bb.right == 200 mm, "reaches 200 out"
    assert left_back.body.bb.height == 180 mm and left_back.body.bb.width == 60 mm, "back 60 x 180"
}
