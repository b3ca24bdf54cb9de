# Request: A wall rack that holds one skateboard flat, grip side up, from 6 mm plywood. A back
# plate 330 x 70 mm (corners rounded 6 mm) screws to the wall with two countersunk M4 screws
# (9 mm heads) 140 mm apart, centred; "SKATE" engraved filled in bold 12 mm letters between
# them. Two arms 250 mm apart (centre to centre, centred on the plate) stick out from it and
# go under the deck between the trucks: each arm is 50 mm tall at the wall tapering to 25 mm,
# its top edge flat for 215 mm from the wall's face (a 205 mm deck fits), then a lip 10 mm
# thick rising 15 mm above the top edge so the board cannot slide off; lip corners rounded
# 3 mm. Each arm joins the plate with two 12 mm tabs and a captive M3 nut and screw between
# them (T-slot), so it can be taken apart. Show it assembled and flat.

units mm
thickness 6 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

param ply = 6 mm, min = 4 mm, max = 9 mm
param arm_pitch = 250 mm, min = 200 mm, max = 300 mm
param deck = 205 mm, min = 180 mm, max = 260 mm

PLATE_W = 330 mm
PLATE_H = 70 mm
ARM_H = 50 mm
END_H = 25 mm
LIP = 10 mm
LIP_H = 15 mm
REACH = deck + 10 mm        # from the wall's face to the lip

def arm(ply=6 mm, reach=215 mm) -> solid {
    # drawn on its side: x out from the wall (x = 0: the tabs' tips at the wall, x = ply: the
    # plate's front face), y up; the top edge at y = ARM_H
    side = Polygon([(0, 0), (0, ARM_H), (ply + reach, ARM_H), (ply + reach, ARM_H + LIP_H),
                    (ply + reach + LIP, ARM_H + LIP_H), (ply + reach + LIP, ARM_H - END_H)])
    joint = tab_and_slot(part="tab", length=ARM_H, thickness=ply, tabs=2, tab=12 mm, screw=3,
                         rotation=90 deg, cx=0, cy=ARM_H / 2)
    Fillet([side.points[3], side.points[4]], 3 mm)
}

assembly skate_rack {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=PLATE_W, height=PLATE_H, corner_radius=6)
        for i in range(2) {
            mount = tab_and_slot(part="slot", length=ARM_H, thickness=ply, tabs=2, tab=12 mm,
                                 screw=3, rotation=90 deg, cx=(i - 0.5) * arm_pitch, cy=0)
        }
        for i in range(2) {
            screw = clearance_hole(size=4, cx=(i - 0.5) * 140 mm, cy=0)
        }
        Countersink(screw, diameter=9 mm)
        drawing name {
            t = Text("SKATE", position=(0, 0), size=12, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
    for i in range(2) {
        a = arm(ply=ply, reach=REACH)
    }
    # flat for cutting: the arms below the plate, side by side
    Below(a[0], back, gap=8)
    AlignLeft(a[0], back)
    RightOf(a[1], a[0], gap=8)
    AlignBottom(a[1], a[0])

    # assembled: the plate upright on the wall (x along the wall, its face toward -y, z up),
    # each arm standing out from it at its slots
    Place(back, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    # FIX after the first valid program (W0517, the arms in the plate): the arm's frame turns
    # (x, y, z) -> (-z, -x, y), so its tabs' tips (x = 0) land at y = position; the wall side of
    # the plate is y = 0 (its face at y = -ply), so the tips go at y = 0, not y = ply
    for i in range(2) {
        Place(a[i], rotation=(90 deg, 0, -90 deg),
              position=((i - 0.5) * arm_pitch + ply / 2, 0, -ARM_H / 2))
    }

    assert len(a) == 2, "two arms"
    assert abs(back.plate.width - 330 mm) < 0.001 mm and abs(back.plate.height - 70 mm) < 0.001 mm,
        "plate 330 x 70"
    assert abs(back.screw[1].c.center.x - back.screw[0].c.center.x - 140 mm) < 0.001 mm,
        "screws 140 mm apart"
    assert abs(back.mount[1].bb.center_x - back.mount[0].bb.center_x - 250 mm) < 0.001 mm,
        "arms 250 mm apart"
    assert abs((back.mount[1].bb.center_x + back.mount[0].bb.center_x) / 2 - back.plate.center.x) < 0.001 mm,
        "arms centred on the plate"
    assert abs(a[0].side.points[1].y - a[0].side.points[0].y - 50 mm) < 0.001 mm, "arm 50 mm at the wall"
    assert abs(a[0].side.points[2].x - a[0].side.points[1].x - ply - 215 mm) < 0.001 mm,
        "215 mm from the wall's face to the lip"
    assert abs(a[0].side.points[3].y - a[0].side.points[2].y - 15 mm) < 0.001 mm, "lip 15 mm high"
    assert back.name.bb.left > back.screw[0].bb.right + 3 mm and back.name.bb.right < back.screw[1].bb.left - 3 mm,
        "SKATE between the screws"
}
