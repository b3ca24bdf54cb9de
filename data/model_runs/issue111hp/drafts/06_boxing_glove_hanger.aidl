# Request (sport): a wall hanger in 6 mm ply for a pair of boxing gloves and the hand wraps.
# A back plate 260 x 120 with 15 mm corners, on two 4.5 mm countersunk screws (9 mm heads)
# 200 mm apart, 25 mm above its bottom edge. Two hook arms 160 mm apart stand out 110 mm
# from the plate, 40 tall at the root, the underside rising to the tip, which turns up 20 mm
# above the arm's top edge (12 mm wide, outer corners rounded 4 mm) so a glove's cuff cannot
# slide off; each glued through the plate on two 10 mm tabs. Their centre line 15 mm below
# the plate's middle. Between them a 12.2 mm hole for a 12 mm dowel peg for the wraps, at the
# same height. "TRAIN HARD" filled-engraved 14 mm tall in bold across the top, 10 mm below
# the top edge.

import "std/joints.aidl"

thickness 6 mm

def arm() -> solid {
    # x = 0: the plate's front face (the tabs reach x = -6); y = 0: the arm's centre line
    body = Polygon([(-6, -20), (110, 4), (110, 40), (98, 40), (96, 20), (-6, 20)])
    root = tab_and_slot(part="tab", length=40 mm, thickness=6 mm, tabs=2, tab=10 mm, screw=0,
                        rotation=90 deg, cx=-6 mm, cy=0 mm)
    Fillet([body.points[2], body.points[3]], 4)
}

assembly hanger {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=260, height=120, corner_radius=15)
        hole screw { c = Circle(center=(-100, -35), diameter=4.5) }
        screws = Mirrored(screw, about=Line((0, -60), (0, 60), construction=true))
        Countersink([screw, screws], diameter=9)
        slot_l = tab_and_slot(part="slot", length=40 mm, thickness=6 mm, tabs=2, tab=10 mm,
                              screw=0, rotation=90 deg, cx=-80 mm, cy=-15 mm)
        slot_r = tab_and_slot(part="slot", length=40 mm, thickness=6 mm, tabs=2, tab=10 mm,
                              screw=0, rotation=90 deg, cx=80 mm, cy=-15 mm)
        hole peg { c = Circle(center=(0, -15), diameter=12.2) }
        drawing motto {
            m = Text("TRAIN HARD", position=(0, 36), size=14, font="sans:Bold", fill=true)
        }
        Fixed(plate)
    }

    arm_l = arm()
    arm_r = arm()
    Below(arm_l, back, gap=10)
    AlignLeft(arm_l, back)
    RightOf(arm_r, arm_l, gap=10)
    AlignTop(arm_r, arm_l)

    # assembled: the plate's front face at y = 0, the wall at y = 6, z up
    Place(back, position=(0, 6, 0), face="front", up="up")
    Place(arm_l, position=(-77, 0, -15), face="left", up="up")
    Place(arm_r, position=(83, 0, -15), face="left", up="up")

    # the request's numbers
    assert back.plate.bb.width == 260 mm and back.plate.bb.height == 120 mm, "plate 260 x 120"
    assert back.screws.c.center.x - back.screw.c.center.x == 200 mm, "screws 200 apart"
    assert back.screw.c.center.y - back.plate.bb.bottom == 25 mm, "screws 25 above the bottom"
    assert back.slot_r.bb.center_x - back.slot_l.bb.center_x == 160 mm, "arms 160 apart"
    assert back.plate.bb.center_y - back.slot_l.bb.center_y == 15 mm, "arms 15 below the middle"
    assert arm_l.body.bb.right - 0 mm == 110 mm, "arms stand out 110"
    assert arm_l.body.points[5].y - arm_l.body.points[0].y == 40 mm, "40 tall at the root"
    assert arm_l.body.points[2].y - arm_l.body.points[5].y == 20 mm, "tip 20 above the top edge"
    assert arm_l.body.points[2].x - arm_l.body.points[3].x == 12 mm, "tip 12 wide"
    assert back.peg.c.center.y == back.slot_l.bb.center_y, "peg at the arms' height"
    assert back.plate.bb.top - back.motto.m.position.y - 14 mm == 10 mm, "motto 10 below the top"
    assert distance(back.motto, back.slot_l) >= 5 mm, "motto clear of the arms"
}
