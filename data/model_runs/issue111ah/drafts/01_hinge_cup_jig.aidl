# Request (workshop): a drilling jig for 35 mm concealed ("Euro") cabinet hinges, cut from
# 6 mm birch ply. A 140 x 90 mm top plate (top corners rounded R5, the door-edge side square)
# with a 35.2 mm guide hole for a 35 mm Forstner bit whose centre is 22.5 mm from the door
# edge (cup 5 mm in from the edge), and two 2.5 mm pilot holes for the hinge screws 45 mm
# apart (22.5 mm each side of the cup centre) and 9.5 mm further in from the edge than the
# cup centre. A 140 mm fence glued under the plate's door-edge side, hanging 30 mm below it,
# joined by two 25 mm tabs into slots in the plate; the door edge bears on the fence's inner
# face. A V notch 8 mm wide and 6 mm deep in the plate's far edge and an engraved centre line
# to line the jig up with a pencil mark; engraved "35 mm CUP" and "22.5 FROM EDGE".
# A 6 mm hanging hole in the top-right corner, 10 mm in from both edges.

import "std/joints.aidl"

thickness 6 mm

plate_w = 140 mm
plate_h = 90 mm
ply = 6 mm
cup_d = 35.2 mm
cup_from_edge = 22.5 mm
screw_spread = 45 mm
screw_deeper = 9.5 mm
pilot_d = 2.5 mm
fence_drop = 30 mm
tab_w = 25 mm

assembly hinge_jig {
    solid plate {
        body = RoundedRectangle(bottom_left=(-plate_w / 2, 0), width=plate_w, height=plate_h,
                                corner_radii=[5, 5, 0, 0])
        # the fence's two tabs come up through these slots; the fence's middle plane is
        # ply / 2 in from the plate's door-edge side (y = 0)
        joint = tab_and_slot(part="slot", length=plate_w, thickness=ply, tabs=2, tab=tab_w,
                             screw=0, clearance=0.1 mm, cx=0 mm, cy=ply / 2)
        hole cup {
            c = Circle(center=(0, ply + cup_from_edge), diameter=cup_d)
        }
        hole pilots {
            left = Circle(center=(-screw_spread / 2, ply + cup_from_edge + screw_deeper),
                          diameter=pilot_d)
            right = Circle(center=(screw_spread / 2, ply + cup_from_edge + screw_deeper),
                           diameter=pilot_d)
        }
        hole notch {
            v = Polygon([(-4, plate_h + 1), (4, plate_h + 1), (0, plate_h - 6)], overrun=true)
        }
        hole hang {
            c = Circle(center=(plate_w / 2 - 10, plate_h - 10), diameter=6)
        }
        drawing marks {
            centre = Line((0, plate_h - 8), (0, ply + cup_from_edge + cup_d / 2 + 2))
            what = Text("35 mm CUP", position=(-40, 62), size=6, valign="middle")
            where = Text("22.5 FROM EDGE", position=(-40, 52), size=4, valign="middle")
        }
        assert cup.c.diameter == 35.2 mm, "guide hole for a 35 mm Forstner bit"
        assert cup.c.center.y - (body.bb.bottom + ply) == 22.5 mm, "cup centre 22.5 mm from the door edge"
        assert pilots.right.center.x - pilots.left.center.x == 45 mm, "screw holes 45 mm apart"
        assert pilots.left.center.y - cup.c.center.y == 9.5 mm, "screw holes 9.5 mm further in"
        assert body.bb.width == 140 mm and body.bb.height == 90 mm, "plate 140 x 90"
    }

    solid fence {
        # 36 mm tall: the top 6 mm are the tabs that pass through the plate
        bar = Rectangle(bottom_left=(-plate_w / 2, -60), width=plate_w, height=fence_drop + ply)
        joint = tab_and_slot(part="tab", length=plate_w, thickness=ply, tabs=2, tab=tab_w,
                             screw=0, cx=0 mm, cy=-60 + fence_drop + ply)
        assert bar.bb.height - ply == 30 mm, "fence hangs 30 mm below the plate"
    }
    Below(fence, plate, gap=10)
    AlignCenterX(fence, plate)
}
