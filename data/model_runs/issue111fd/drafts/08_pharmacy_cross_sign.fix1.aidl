# Request (signs): a projecting pharmacy sign in 6 mm ply (painted green), three parts. The
# sign is a Greek cross 300 x 300 mm with arms 100 mm wide, every corner rounded 12 mm, an
# engraved border 10 mm in from the edge, and "PHARMACY" in filled bold letters 22 mm high across
# the middle. It hangs on two S-hooks through two 8 mm holes 60 mm apart, 20 mm below the top of
# the upper arm. The bracket arm is 420 mm long: a bar 40 mm high with a curved brace under its
# wall end reaching 200 mm down the wall, a 40 mm round opening in the brace, and two 8 mm
# hook holes 60 mm apart, centred 206 mm from the wall, 20 mm below the bar's top. The arm's wall
# edge goes through a wall plate 80 x 240 mm (8 mm corners) on two 40 mm glued tenons, tips flush
# with the plate's back; the plate is screwed to the wall with four M5 countersunk screws
# (10 mm heads): two on the centre line 105 mm above and below the middle, two 25 mm either side
# of the middle.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

T = 6 mm
ARM_W = 100 mm
SPAN = 300 mm
CROSS = [(-50, -150), (50, -150), (50, -50), (150, -50), (150, 50), (50, 50), (50, 150),
         (-50, 150), (-50, 50), (-150, 50), (-150, -50), (-50, -50)]
HOOKS = 60 mm
ARM_L = 420 mm
BAR_H = 40 mm
DROP = 200 mm
HANG_X = 206 mm

def cross_part() -> solid {
    body = Polygon(CROSS)
    Fillet(body, 12)
    for s in [-1, 1] {
        hole hook {
            c = Circle(center=(s * HOOKS / 2, SPAN / 2 - 20 mm), diameter=8)
        }
    }
    drawing face {
        border = Inset(Polygon(CROSS), 10)
        word = Text("PHARMACY", position=(0, 0), size=22, font="sans:Bold", valign="middle",
                    fill=true)
    }
}

def arm_part() -> solid {
    # FIX after the first valid program: the brace's curve met the wall edge at a 22-degree
    # point, and the tenons' end gap left it a bare spike 16 mm long (no message named it);
    # the brace now ends in a 22 mm flat foot on the plate
    body = Spline([(0, 0), (ARM_L, 0), (ARM_L, -BAR_H), (230, -BAR_H), (110, -62), (40, -115),
                   (26, -165), (22, -DROP), (0, -DROP)], closed=true, corners=[0, 1, 2, 3, 7, 8])
    tenons = tab_and_slot(part="tab", length=DROP, thickness=T, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=0, cy=-DROP / 2)
    hole window {
        c = Circle(center=(60, -50), diameter=40)
    }
    for s in [-1, 1] {
        hole hook {
            c = Circle(center=(HANG_X + s * HOOKS / 2, -20), diameter=8)
        }
    }
}

def plate_part() -> solid {
    body = RoundedRectangle(center=(0, 0), width=80, height=240, corner_radius=8)
    mortises = tab_and_slot(part="slot", length=DROP, thickness=T, tabs=2, tab=40 mm, screw=0,
                            rotation=90 deg, cx=0, cy=0)
    for p in [[0, 105], [0, -105], [25, 0], [-25, 0]] {
        screw = clearance_hole(size=5, cx=p[0], cy=p[1])
    }
    Countersink(screw, diameter=10 mm)
}

assembly pharmacy_sign {
    plate = plate_part()
    arm = arm_part()
    sign = cross_part()
    # the wall is the plane x = 0; the plate's countersunk face looks out along +x
    Place(plate, position=(0, 0, 300 mm), face="right", up="up")
    # the arm stands in the plane y = 0, its wall edge at x = 0 through the plate
    Place(arm, position=(0, T / 2, 300 mm + DROP / 2), face="front", up="up")
    # the cross hangs 30 mm under the bar on the S-hooks, in the arm's plane
    Place(sign, position=(HANG_X, T / 2, 300 mm + DROP / 2 - BAR_H - 30 mm - SPAN / 2),
          face="front", up="up")

    # flat on the sheet
    RightOf(arm, plate, gap=10)
    AlignTop(arm, plate)
    Below(sign, arm, gap=10)
    AlignLeft(sign, arm)

    assert sign.body.bb.width == 300 mm and sign.body.bb.height == 300 mm, "cross 300 x 300"
    assert sign.body.points[1].x - sign.body.points[0].x == 100 mm, "arms 100 wide"
    assert sign.hook[1].c.center.x - sign.hook[0].c.center.x == 60 mm, "hook holes 60 apart"
    assert sign.body.bb.top - sign.hook[0].c.center.y == 20 mm, "20 below the top"
    assert arm.body.points[1].x - arm.body.points[0].x == 420 mm, "arm 420 long"
    assert arm.body.points[0].y - arm.body.points[8].y == 200 mm, "brace 200 down the wall"
    assert arm.hook[1].c.center.x - arm.hook[0].c.center.x == 60 mm, "arm hook holes 60 apart"
    assert (arm.hook[0].c.center.x + arm.hook[1].c.center.x) / 2 - arm.body.points[0].x == 206 mm,
        "centred 206 from the wall"
    assert arm.window.c.diameter == 40 mm, "40 mm opening"
    assert plate.body.bb.width == 80 mm and plate.body.bb.height == 240 mm, "plate 80 x 240"
    assert len(plate.screw) == 4, "four screws"
    assert plate.screw[0].c.center.y - plate.body.bb.center_y == 105 mm, "top screw 105 up"
    assert distance(plate.screw, plate.mortises) >= 3 mm, "screws clear of the mortises"
    assert distance(arm.window, arm.tenons) >= 3 mm, "opening clear of the tenons"
    assert distance(sign.face.word, sign.face.border) >= 3 mm, "word inside the border"
}
