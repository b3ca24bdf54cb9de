# Request (home): a pair of curtain pole brackets for a 28 mm wooden pole, cut from 6 mm birch
# ply. Each bracket is two parts glued together: a wall plate 50 x 90 mm with 6 mm rounded
# corners and two 4.5 mm screw holes 70 mm apart (on the plate's centre line), countersunk
# 9 mm for flat-head screws; and an arm standing square off the plate, 40 mm tall at the wall,
# ending in a round cup whose 29 mm seat (1 mm play round the pole) opens at the top so the
# pole drops in; the pole's centre is 65 mm out from the wall. The arm has two 10 mm tabs on
# its wall edge that go right through two mortises in the plate. The cup's wall is 7.5 mm.
# Show the pair assembled on the wall, 1200 mm apart would be the real spacing (drawn 150).

thickness 6 mm

import "std/joints.aidl"

POLE_D = 28 mm
SEAT_D = 29 mm
OUT = 65 mm        # pole centre from the wall
CUP_WALL = 7.5 mm
ARM_H = 40 mm

def wall_plate() -> solid {
    body = RoundedRectangle(center=(0, 0), width=50, height=90, corner_radius=6)
    hole screw_top { c = Circle(center=(0, 35), diameter=4.5) }
    hole screw_bottom { c = Circle(center=(0, -35), diameter=4.5) }
    Countersink([screw_top, screw_bottom], diameter=9 mm)
    mortise = tab_and_slot(part="slot", length=ARM_H, thickness=6 mm, tabs=2, tab=10 mm,
                           screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
}

def arm() -> solid {
    # local frame: x = 0 is the wall (the tabs' tips), y up, the pole's centre at (OUT, 5)
    root = Rectangle(bottom_left=(0, -ARM_H / 2), width=12, height=ARM_H)
    cup = Circle(center=(OUT, 5), radius=SEAT_D / 2 + CUP_WALL)
    body = Hull(root, cup)
    hole seat {
        c = Circle(center=(OUT, 5), diameter=SEAT_D)
        mouth = Rectangle(bottom_left=(OUT - SEAT_D / 2, 5), width=SEAT_D, height=30)
    }
    tabs = tab_and_slot(part="tab", length=ARM_H, thickness=6 mm, tabs=2, tab=10 mm,
                        screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
}

assembly curtain_brackets {
    plate_l = wall_plate()
    arm_l = arm()
    plate_r = wall_plate()
    arm_r = arm()

    # flat on the sheet: each arm beside its plate
    RightOf(arm_l, plate_l, gap=8)
    AlignCenterY(arm_l, plate_l)
    RightOf(plate_r, arm_l, gap=8)
    AlignCenterY(plate_r, plate_l)
    RightOf(arm_r, plate_r, gap=8)
    AlignCenterY(arm_r, plate_l)

    # on the wall (the wall is the plane y = 0, the room toward -y, z up)
    Place(plate_l, position=(0, 0, 0), rotation=(90 deg, 0, 0))
    Place(arm_l, position=(3, 0, 0), rotation=(90 deg, 0, -90 deg))
    Place(plate_r, position=(150, 0, 0), rotation=(90 deg, 0, 0))
    Place(arm_r, position=(153, 0, 0), rotation=(90 deg, 0, -90 deg))

    # the request's numbers
    assert plate_l.body.bb.width == 50 mm and plate_l.body.bb.height == 90 mm, "plate 50 x 90"
    assert plate_l.screw_top.c.center.y - plate_l.screw_bottom.c.center.y == 70 mm, "screws 70 apart"
    assert arm_l.seat.c.diameter - POLE_D == 1 mm, "1 mm play round the pole"
    assert arm_l.seat.c.center.x - arm_l.root.bb.left == 65 mm, "pole centre 65 mm from the wall"
    assert arm_l.root.bb.height == 40 mm, "arm 40 mm tall at the wall"
    assert len(arm_l.tabs.slot) == 2, "two tabs"
}
