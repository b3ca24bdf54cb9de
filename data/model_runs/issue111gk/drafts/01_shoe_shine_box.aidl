# Request: a shoe-shine box for the hallway, from 6 mm birch ply. A finger-jointed box
# 320 mm long, 180 mm deep and 150 mm tall outside (lid included), fingers at least 20 mm,
# with a lift-off lid (a lip under it, 0.3 mm clearance). On the lid stands a foot rest: a
# shoe-sole outline 250 mm long, 95 mm wide at the ball and 70 mm at the heel, raised 45 mm
# above the lid on two risers 60 mm long, 65 mm either side of the sole's middle; each riser
# has two 15 mm tabs glued into slots (0.2 mm clearance) in the lid and two in the sole.
# A 90 x 25 mm hand hole in each end, its centre 35 mm below the top of the wall, and
# "POLISH & BRUSHES" engraved 14 mm tall across the middle of the front.

import "std/boxes.aidl"
import "std/joints.aidl"

thickness 6 mm

def riser() -> solid {
    # tab tips at y = 0 (into the lid) and y = 57 (into the sole), the 45 mm rise between
    body = Rectangle(bottom_left=(-30, 0), width=60, height=45 + 2 * 6)
    down = tab_and_slot(part="tab", length=60 mm, thickness=6 mm, tabs=2, tab=15 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    up = tab_and_slot(part="tab", length=60 mm, thickness=6 mm, tabs=2, tab=15 mm,
                      screw=0, rotation=0 deg, cx=0 mm, cy=57 mm)
}

assembly shoe_shine {
    box = lid_box(length=320 mm, width=180 mm, height=150 mm, thickness=6 mm,
                  finger=20 mm, clearance=0.3 mm)

    # the foot rest, heel at -x, toe at +x, drawn about (0, 0)
    solid sole {
        s = Spline([(-125, 0), (-118, 25), (-100, 34), (-75, 35), (-45, 30), (-10, 30),
                    (25, 40), (60, 47.5), (95, 42), (117, 25), (125, 0), (117, -25),
                    (95, -42), (60, -47.5), (25, -40), (-10, -30), (-45, -30), (-75, -35),
                    (-100, -34), (-118, -25)], closed=true)
        heel_slots = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=2,
                                  tab=15 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                  cx=-65 mm, cy=0 mm)
        toe_slots = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=2,
                                 tab=15 mm, screw=0, clearance=0.2 mm, rotation=90 deg,
                                 cx=65 mm, cy=0 mm)
    }
    heel_riser = riser()
    toe_riser = riser()

    # the risers' slots in the lid, centred on it like the sole
    hole lid_slots {
        a = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=2, tab=15 mm,
                         screw=0, clearance=0.2 mm, rotation=90 deg, cx=-65 mm, cy=0 mm)
        b = tab_and_slot(part="slot", length=60 mm, thickness=6 mm, tabs=2, tab=15 mm,
                         screw=0, clearance=0.2 mm, rotation=90 deg, cx=65 mm, cy=0 mm)
    }
    CenterInside(lid_slots, box.lid)
    CutInto(lid_slots, box.lid)

    # hand holes in the ends (a side's top edge lies outward in the net)
    hole grip_l { s = Slot(center=(0, 0), length=90, width=25, rotation=90) }
    hole grip_r { s = Slot(center=(0, 0), length=90, width=25, rotation=90) }
    AlignCenterY(grip_l, box.body.left)
    grip_l.s.center.x == box.body.left.bb.left + 35 mm
    CutInto(grip_l, box.body.left)
    AlignCenterY(grip_r, box.body.right)
    grip_r.s.center.x == box.body.right.bb.right - 35 mm
    CutInto(grip_r, box.body.right)

    drawing label { t = Text("POLISH & BRUSHES", position=(0, 0), size=14, valign="middle") }
    CenterInside(label, box.body.front)
    CutInto(label, box.body.front)

    # on the sheet: the foot rest and risers beside the box's net
    RightOf(sole, box, gap=15)
    AlignTop(sole, box)
    Below(heel_riser, sole, gap=10)
    AlignLeft(heel_riser, sole)
    RightOf(toe_riser, heel_riser, gap=10)
    AlignTop(toe_riser, heel_riser)

    # assembled: the box stands on z = 0 centred on x = y = 0, its lid's top at 150
    Place(sole, position=(0, 0, 150 + 45), face="up")
    Place(heel_riser, position=(-65 - 3, 0, 150 - 6), face="right", up="up")
    Place(toe_riser, position=(65 - 3, 0, 150 - 6), face="right", up="up")

    assert box.lid.bb.width == 320 mm, "the lid is the box's 320 mm length"
    assert box.lid.bb.height == 180 mm, "the lid is the box's 180 mm depth"
    assert sole.s.points[10].x - sole.s.points[0].x == 250 mm, "the sole is 250 mm long"
    assert sole.s.points[7].y - sole.s.points[13].y == 95 mm, "95 mm wide at the ball"
    assert sole.s.points[3].y - sole.s.points[17].y == 70 mm, "70 mm wide at the heel"
    assert heel_riser.body.bb.height - 2 * 6 mm == 45 mm, "a 45 mm rise between lid and sole"
    assert heel_riser.body.bb.width == 60 mm, "risers 60 mm long"
    assert sole.toe_slots.bb.center_x - sole.heel_slots.bb.center_x == 2 * 65 mm,
        "risers 65 mm either side of the sole's middle"
    assert grip_l.s.center.x - box.body.left.bb.left == 35 mm, "hand hole 35 below the top"
    assert box.body.right.bb.right - grip_r.s.center.x == 35 mm, "hand hole 35 below the top"
    assert label.t.size == 14 mm, "lettering 14 mm tall"
}
