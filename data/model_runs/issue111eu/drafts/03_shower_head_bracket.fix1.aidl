# Request: a replacement holder for a hand shower, in 6 mm white acrylic, glued together.
# Wall plate 50 wide x 100 tall, corners R6, two 4.5 mm screw holes on the centre line 76 mm
# apart (38 above and below the middle), countersunk for 9 mm heads. An arm 50 wide sticking
# out 60 mm square from the plate's front face, its top face 20 mm above the plate's middle,
# its front corners R8, held by two 12 mm tenons in mortises through the plate; a U notch
# for the shower handle's cone: 18 mm wide (R9 round end), 35 mm deep from the arm's front
# edge. Under the arm two right-triangle gussets, 40 along the wall and 40 under the arm,
# their outer faces flush with the arm's sides, each with one 20 mm tenon into the plate and
# one into the arm. Mortises 0.1 mm over the tenons. Laid out in a row 8 mm apart to cut;
# assembled on the wall for a look.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
plate_w = 50 mm
plate_h = 100 mm
arm_w = 50 mm
arm_d = 60 mm
arm_top = 20 mm        # above the plate's middle
g = 40 mm              # gusset legs
# FIX after the first valid program: W0530 x4 (real): gussets flush with the sides put their
# mortises at the plate's and the arm's edges, cut open into notches. Gussets now 4 mm in.
gx = arm_w / 2 - t / 2 - 4 mm # gusset middle planes, off the centre line

def gusset() -> solid {
    tri = Polygon([(0, 0), (0, g), (g, g)])
    back_strip = Rectangle(bottom_left=(-t, 0), width=t, height=g)
    top_strip = Rectangle(bottom_left=(0, g), width=g, height=t)
    back_tab = tab_and_slot(part="tab", length=g, thickness=t, tabs=1, tab=20 mm, screw=0,
                            rotation=90 deg, cx=-t, cy=g / 2)
    top_tab = tab_and_slot(part="tab", length=g, thickness=t, tabs=1, tab=20 mm, screw=0,
                           rotation=0 deg, cx=g / 2, cy=g + t)
}

assembly holder {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=6)
        hole top_screw { c = Circle(center=(0, 38), diameter=4.5) }
        hole low_screw { c = Circle(center=(0, -38), diameter=4.5) }
        Countersink([top_screw, low_screw], diameter=9)
        arm_mortise = tab_and_slot(part="slot", length=arm_w, thickness=t, tabs=2, tab=12 mm,
                                   screw=0, clearance=0.1 mm, cx=0, cy=arm_top - t / 2)
        left_mortise = tab_and_slot(part="slot", length=g, thickness=t, tabs=1, tab=20 mm,
                                    screw=0, clearance=0.1 mm, rotation=90 deg,
                                    cx=-gx, cy=arm_top - t - g / 2)
        right_mortise = tab_and_slot(part="slot", length=g, thickness=t, tabs=1, tab=20 mm,
                                     screw=0, clearance=0.1 mm, rotation=90 deg,
                                     cx=gx, cy=arm_top - t - g / 2)
    }

    solid arm {
        body = RoundedRectangle(bottom_left=(-arm_w / 2, -t), width=arm_w, height=arm_d + t,
                                corner_radii=[8, 8, 0, 0])
        tenons = tab_and_slot(part="tab", length=arm_w, thickness=t, tabs=2, tab=12 mm,
                              screw=0, rotation=180 deg, cx=0, cy=-t)
        hole notch { u = Slot(start=(0, arm_d + 10), end=(0, arm_d - 35 + 9), width=18, overrun=true) }
        left_mortise = tab_and_slot(part="slot", length=g, thickness=t, tabs=1, tab=20 mm,
                                    screw=0, clearance=0.1 mm, rotation=90 deg, cx=-gx, cy=g / 2)
        right_mortise = tab_and_slot(part="slot", length=g, thickness=t, tabs=1, tab=20 mm,
                                     screw=0, clearance=0.1 mm, rotation=90 deg, cx=gx, cy=g / 2)
    }

    left_gusset = gusset()
    right_gusset = gusset()

    # flat, to cut: a row 8 mm apart, tops aligned
    RightOf(arm, plate, gap=8)
    RightOf(left_gusset, arm, gap=8)
    RightOf(right_gusset, left_gusset, gap=8)
    AlignTop(arm, plate)
    AlignTop(left_gusset, plate)
    AlignTop(right_gusset, plate)

    # on the wall (the plate's back on y = 0, its front face toward -y)
    Place(plate, position=(0, 0, 0), face="front")
    Place(arm, position=(0, -t, arm_top - t), face="up", up="front")
    Place(left_gusset, position=(-gx + t / 2, -t, arm_top - t - g), face="left")
    Place(right_gusset, position=(gx + t / 2, -t, arm_top - t - g), face="left")

    # the request's numbers
    assert plate.body.width == 50 mm and plate.body.height == 100 mm, "plate 50 x 100"
    assert plate.top_screw.c.center.y - plate.low_screw.c.center.y == 76 mm, "screws 76 apart"
    assert plate.top_screw.c.center.y - plate.body.center.y == 38 mm, "38 above the middle"
    assert plate.top_screw.c.diameter == 4.5 mm, "4.5 mm screw holes"
    assert arm.body.bb.top - (arm.body.bb.bottom + t) == 60 mm, "arm sticks out 60 mm"
    assert arm.body.bb.width == 50 mm, "arm 50 wide"
    assert arm.notch.u.width == 18 mm, "notch 18 wide"
    assert arm.body.bb.top - arm.notch.u.bb.bottom == 35 mm, "notch 35 deep"
    assert (plate.arm_mortise.slot[0].bb.top - plate.body.center.y) - 20 mm <= 0.05 mm + 0.001 mm,
        "arm's top face 20 above the plate's middle"
    assert left_gusset.tri.bb.width == 40 mm and left_gusset.tri.bb.height == 40 mm, "gussets 40 x 40"
    assert plate.arm_mortise.slot[0].bb.width == 12.1 mm, "mortise 0.1 over the 12 mm tenon"
    assert arm_w / 2 - (gx + t / 2) == 4 mm, "gussets 4 mm in from the arm's sides"
    assert plate.low_screw.c.center.y + 4.5 mm < plate.left_mortise.slot[0].bb.bottom, "low screw below the gussets"
}
