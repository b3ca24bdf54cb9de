# Request: a wall-mounted clothes airer for the utility room, cut from 9 mm birch ply.
# A back rail 600 x 90 mm with R10 corners, screwed to the wall with three countersunk M5
# screws (at the middle and 200 mm either side of it). Two arms stand straight out from the
# wall, 300 mm long overall (tenons included), 90 mm tall at the wall and tapering to a round
# tip 50 mm tall (R25); each arm sits on two 25 mm tenons that pass through mortises in the
# rail, the arms' centres 40 mm in from the rail's ends (520 mm apart). Each arm carries four
# 12.5 mm holes for 12 mm hardwood dowels, 70 mm apart, the first 60 mm from the wall, on a
# line 25 mm below the arm's top edge so the dowels sit level. "WASH" and "DRY" engraved
# (filled) on the rail either side of the middle screw.

import "std/joints.aidl"
import "std/fasteners.aidl"

t = 9 mm
thickness t

def arm() -> solid {
    # drawn with the tenons' tips on x = 0 (the wall) and the top edge on y = 0
    body = Hull(Point(0, 0), Point(0, -90), Circle(center=(275, -25), radius=25))
    tenons = tab_and_slot(part="tab", length=90 mm, thickness=t, tabs=2, tab=25 mm, screw=0,
                          rotation=90 deg, cx=0 mm, cy=-45 mm)
    hole dowels {
        for i in range(4) {
            c = Circle(center=(60 + i * 70, -25), diameter=12.5)
        }
    }
    Rigid(self)
}

assembly airer {
    solid rail {
        body = RoundedRectangle(center=(0, 0), width=600, height=90, corner_radius=10)
        for sx in [-1, 1] {
            m = tab_and_slot(part="slot", length=90 mm, thickness=t, tabs=2, tab=25 mm,
                             screw=0, rotation=90 deg, cx=sx * 260 mm, cy=0 mm)
        }
        for x in [-200, 0, 200] {
            s = clearance_hole(size=5, cx=x * 1 mm, cy=0 mm)
        }
        Countersink(s, diameter=10 mm)
        drawing words {
            w = Text("WASH", position=(-100, 0), size=30, font="sans:Bold", valign="middle",
                     fill=true)
            d = Text("DRY", position=(100, 0), size=30, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
    left_arm = arm()
    right_arm = arm()

    # flat on the sheet: the arms under the rail
    Below(left_arm, rail, gap=10)
    AlignLeft(left_arm, rail)
    RightOf(right_arm, left_arm, gap=10)
    AlignTop(right_arm, left_arm)

    # in 3D: the wall is the plane y = 0, the rail's face (engraving, countersinks) to the front
    Place(rail, position=(0, 0, 0), face="front", up="up")
    # each arm's tenon tips on the wall, its top edge level with the rail's top, centred on its mortises
    Place(left_arm, position=(-260 + 4.5, 0, 45), face="left", up="up")
    Place(right_arm, position=(260 + 4.5, 0, 45), face="left", up="up")

    assert rail.body.bb.width == 600 mm, "rail 600 long"
    assert rail.body.bb.height == 90 mm, "rail 90 tall"
    assert left_arm.body.bb.width == 300 mm, "arm 300 overall"
    assert left_arm.body.bb.height == 90 mm, "arm 90 tall at the wall"
    assert len(left_arm.dowels.c) == 4, "four dowels"
    assert left_arm.dowels.c[1].center.x - left_arm.dowels.c[0].center.x == 70 mm, "dowels 70 apart"
    assert left_arm.dowels.c[0].center.x - left_arm.body.bb.left == 60 mm, "first dowel 60 from the wall"
    assert left_arm.body.bb.top - left_arm.dowels.c[0].center.y == 25 mm, "dowels 25 below the top"
    assert rail.m[1].bb.center_x - rail.m[0].bb.center_x == 520 mm, "arms 520 apart"
    assert rail.m[0].bb.center_x - rail.body.bb.left == 40 mm, "arms 40 in from the ends"
}
