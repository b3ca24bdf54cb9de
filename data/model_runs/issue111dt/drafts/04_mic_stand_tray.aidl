# Request: a clip-on tray for a microphone stand, for picks, a capo and the set list, in 4 mm
# ply. The tray is an open finger-jointed box 200 x 140 x 30 mm outside (12 mm fingers), the
# band name "THE LOW TIDES" engraved filled on the front, 10 mm bold letters. It hangs on the
# stand's 22 mm tube behind the tray: a bracket plate 80 wide and 90 tall bolted to the
# outside of the tray's back wall with two M4 bolts 50 mm apart, 15 mm up the wall, and
# two horizontal arms 80 x 50 mm glued into the bracket by two 15 mm tabs each (mortises),
# 68 mm apart centre to centre, each with a 23 mm hole for the tube 25 mm from the bracket.
# (The boom unscrews; the tray slides down the tube and wedges by its own weight.) The arms'
# far corners rounded R15.

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
thickness 4 mm

t = 4 mm
tube_hole = 23 mm
arm_w = 80 mm
arm_d = 50 mm
arm_pitch = 68 mm

def arm() -> solid {
    body = RoundedRectangle(bottom_left=(-arm_w / 2, 0), width=arm_w, height=arm_d + t,
                            corner_radii=[15, 15, 0, 0])
    # the tabs' tips on y = 0, the arm above them
    tabs = tab_and_slot(part="tab", length=arm_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole tube {
        c = Circle(center=(0, t + 25 mm), diameter=tube_hole)
    }
}

assembly mic_stand_tray {
    tray = finger_box(length=200 mm, depth=140 mm, height=30 mm, thickness=t, finger=12 mm,
                      closed=false)

    drawing band {
        name = Text("THE LOW TIDES", position=(0, 0), size=10, font="sans:Bold",
                    valign="middle", fill=true)
    }
    CenterInside(band, tray.front)
    CutInto(band, tray.front)

    hole wall_bolts {
        a = clearance_hole(size=4, cx=-25 mm, cy=0 mm)
        b = clearance_hole(size=4, cx=25 mm, cy=0 mm)
    }
    AlignCenterX(wall_bolts, tray.back)
    wall_bolts.a.c.center.y == tray.back.bb.bottom + 15 mm
    CutInto(wall_bolts, tray.back)

    # FIX after the first valid program: the top arm (z 18..22) sat on the bolt heads
    # (z 15) and its mortises were 0.75 mm from the bolt holes. The bracket now stands 6 mm
    # above the tray (y -54..36), the arms at z 24..28 and -44..-40, 68 mm apart as asked.
    # the bracket, drawn with its bottom edge at y = -54 and top at 36 (y is height in 3D)
    solid bracket {
        plate = Rectangle(bottom_left=(-40, -54), width=80, height=90)
        hole bolts {
            a = clearance_hole(size=4, cx=-25 mm, cy=15 mm)
            b = clearance_hole(size=4, cx=25 mm, cy=15 mm)
        }
        upper = tab_and_slot(part="slot", length=arm_w, thickness=t, tabs=2, tab=15 mm,
                             screw=0, cx=0 mm, cy=26 mm)
        lower = tab_and_slot(part="slot", length=arm_w, thickness=t, tabs=2, tab=15 mm,
                             screw=0, cx=0 mm, cy=26 mm - arm_pitch)
    }
    arm_top = arm()
    arm_bottom = arm()

    # flat on the sheet: beside the tray's net
    RightOf(bracket, tray, gap=10)
    AlignTop(bracket, tray)
    RightOf(arm_top, bracket, gap=10)
    AlignTop(arm_top, bracket)
    Below(arm_bottom, arm_top, gap=10)
    AlignLeft(arm_bottom, arm_top)

    # in 3D: the tray stands on z = 0, its back wall's outside at y = 70; the bracket on it,
    # its top face looking back at the tube; the arms level, their tab tips at y = 70
    Place(bracket, position=(0, 70, 0), face="back", up="up")
    Place(arm_top, position=(0, 70, 24), face="up")
    Place(arm_bottom, position=(0, 70, 24 - arm_pitch), face="up")

    # the request's numbers
    assert tray.length == 200 mm and tray.depth == 140 mm and tray.height == 30 mm, "tray size"
    assert bracket.plate.width == 80 mm and bracket.plate.height == 90 mm, "bracket 80 x 90"
    assert bracket.bolts.b.c.center.x - bracket.bolts.a.c.center.x == 50 mm, "bolts 50 apart"
    assert bracket.bolts.a.c.center.y == 15 mm, "bolts 15 mm up the tray wall (y is z)"
    assert bracket.upper.slot[0].bb.bottom - bracket.bolts.a.c.center.y >= 6 mm,
        "an M4 head clears the top arm"
    assert wall_bolts.b.c.center.x - wall_bolts.a.c.center.x == 50 mm, "wall bolts 50 apart"
    assert bracket.upper.slot[0].bb.center_y - bracket.lower.slot[0].bb.center_y == 68 mm,
        "arms 68 mm apart"
    assert arm_top.tube.c.center.y - arm_top.body.bb.bottom == 25 mm + 4 mm,
        "tube 25 mm from the bracket"
    assert arm_top.tube.c.diameter == 23 mm, "23 mm tube hole"
    assert arm_top.body.bb.height - 4 mm == 50 mm and arm_top.body.bb.width == 80 mm,
        "arms 80 x 50"
}
