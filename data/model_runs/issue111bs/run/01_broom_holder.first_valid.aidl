# Request: a wall-mounted broom and mop holder for the utility cupboard, 6 mm birch ply.
# A back plate 420 x 150 mm (corners r8) screwed to the wall with four M4 flat-head screws
# (4.5 mm holes, countersunk 9 mm, 15 mm in from each side). A horizontal arm reaching 110 mm
# from the wall, 420 mm wide, its outer corners rounded r10, glued into the back with three
# 30 mm through tenons; its middle plane 10 mm above the back's centre line. Three grip slots
# 30 mm wide and 75 mm deep from the arm's front edge, 130 mm apart, mouths rounded r5.
# Two triangular gussets (90 mm along the arm, 80 mm down the wall) under the arm, 25 mm in
# from its ends, each with one 30 mm tenon into the back and one into the arm. The labels
# "BROOM", "MOP", "DUSTER" engraved filled, 14 mm bold, above their slots.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm            # ply
W = 420 mm          # back and arm width
ARM_D = 110 mm      # arm reach from the wall
PITCH = 130 mm      # grip spacing
GX = 185 mm         # gusset middle planes at +-GX
ARM_Y = 10 mm       # arm middle plane on the back
NAMES = ["BROOM", "MOP", "DUSTER"]

def gusset() -> solid {
    # right angle at (0, 0): top edge along +x under the arm, back edge down -y on the wall;
    # the tabs' tips stand T beyond, on y = T and x = -T
    body = Polygon([(-6, 6), (90, 6), (-6, -80)])
    top = tab_and_slot(part="tab", length=96 mm, thickness=6 mm, tabs=1, tab=30 mm, screw=0,
                       cx=42 mm, cy=6 mm)
    back = tab_and_slot(part="tab", length=86 mm, thickness=6 mm, tabs=1, tab=30 mm, screw=0,
                        rotation=90 deg, cx=-6 mm, cy=-37 mm)
}

assembly broom_holder {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=W, height=150, corner_radius=8)
        hole screw { c = Circle(center=(-195, -60), diameter=4.5) }
        Fixed(body)
        screws = CornerPattern(screw, body, inset=15 mm)
        Countersink(screws, diameter=9 mm)
        arm_slots = tab_and_slot(part="slot", length=W, thickness=6 mm, tabs=3, tab=30 mm,
                                 screw=0, cx=0 mm, cy=ARM_Y)
        left_slot = tab_and_slot(part="slot", length=86 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=-GX, cy=ARM_Y - 3 mm - 37 mm)
        right_slot = tab_and_slot(part="slot", length=86 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                  screw=0, rotation=90 deg, cx=GX, cy=ARM_Y - 3 mm - 37 mm)
        drawing labels {
            for i in range(3) {
                t = Text(NAMES[i], position=(-PITCH + i * PITCH, 40), size=14, font="sans:Bold",
                         fill=true)
            }
        }
    }

    solid arm {
        # flat: the back edge (tab tips) on y = 55, the front edge on y = -55
        body = RoundedRectangle(center=(0, 0), width=W, height=ARM_D, corner_radii=[0, 0, 10, 10])
        Fixed(body)
        tabs = tab_and_slot(part="tab", length=W, thickness=6 mm, tabs=3, tab=30 mm, screw=0,
                            cx=0 mm, cy=55 mm)
        hole grips {
            for i in range(3) {
                s = Slot(start=(-PITCH + i * PITCH, -70), end=(-PITCH + i * PITCH, 5), width=30)
            }
        }
        # gusset top tabs: the joint's middle 42 mm from the wall face -> y = 55 - 6 - 42
        left_slot = tab_and_slot(part="slot", length=96 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=-GX, cy=7 mm)
        right_slot = tab_and_slot(part="slot", length=96 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                  screw=0, rotation=90 deg, cx=GX, cy=7 mm)
        Fillet([[body.bottom, grips.s[0]], [body.bottom, grips.s[1]], [body.bottom, grips.s[2]]], 5)
    }

    left_gusset = gusset()
    right_gusset = gusset()

    # the sheet: arm under the back, gussets under the arm
    Below(arm, back, gap=10)
    AlignCenterX(arm, back)
    Below(left_gusset, arm, gap=10)
    AlignLeft(left_gusset, arm)
    RightOf(right_gusset, left_gusset, gap=10)
    AlignTop(right_gusset, left_gusset)

    # 3D: the back stands on the wall (its rear face on y = 0), the arm sticks out toward -y
    Place(back, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(arm, position=(0, -55, ARM_Y - 3 mm))
    Place(left_gusset, rotation=(90 deg, 0, -90 deg), position=(-GX + 3 mm, -6, ARM_Y - 3 mm))
    Place(right_gusset, rotation=(90 deg, 0, -90 deg), position=(GX + 3 mm, -6, ARM_Y - 3 mm))

    # the request's numbers
    assert back.body.bb.width == 420 mm and back.body.bb.height == 150 mm, "back 420 x 150"
    assert arm.body.bb.height == 110 mm, "arm reaches 110 mm from the wall"
    assert len(arm.grips.s) == 3, "three grips"
    assert arm.grips.s[1].center.x - arm.grips.s[0].center.x == 130 mm, "grips 130 mm apart"
    assert arm.grips.s[0].width == 30 mm, "grips 30 mm wide"
    assert arm.grips.s[0].bb.top - arm.body.bb.bottom == 75 mm, "grips 75 mm deep"
    assert back.screws[1].c.center.x - back.screws[0].c.center.x == 420 mm - 2 * 15 mm,
        "screws 15 mm in"
    assert arm.body.bb.right - (GX + 3 mm) == 25 mm - 3 mm, "gussets 25 mm in from the ends"
}
