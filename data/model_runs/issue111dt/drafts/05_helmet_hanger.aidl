# Request: a wall hanger for a cycling helmet, in 6 mm birch ply. A wall plate 80 x 180 mm
# with R10 corners, two countersunk 4.5 mm screw holes (9 mm heads) 150 mm apart on the
# centre line. A rounded arm stands out of the plate, glued into two mortises by two 20 mm
# tabs along its 90 mm root: it reaches 110 mm in front of the plate and ends in a 70 mm
# round head (top of the arm level with the root's top). A saddle 140 mm wide, arched to the
# same 70 mm round top, crosses the arm 75 mm out by a cross halving, so the helmet sits on
# a cross of two rounded ribs. The rider's name "MAYA" engraved filled (12 mm bold letters)
# up the plate's left side.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
root = 90 mm
reach = 110 mm
cross_at = 75 mm

assembly helmet_hanger {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=80, height=180, corner_radius=10)
        hole screw_top {
            c = Circle(center=(0, 75), diameter=4.5)
        }
        hole screw_bottom {
            c = Circle(center=(0, -75), diameter=4.5)
        }
        mortise = tab_and_slot(part="slot", length=root, thickness=t, tabs=2, tab=20 mm,
                               screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
        drawing name {
            word = Text("MAYA", position=(-22, 0), size=12, font="sans:Bold", rotation=90 deg,
                        valign="middle", fill=true)
        }
        Countersink([screw_top, screw_bottom], diameter=9 mm)
    }

    # the arm seen from the side: x out from the plate's face, y up; tab tips at x = -6
    solid arm {
        body = Hull(Rectangle(bottom_left=(-t, -root / 2), width=16, height=root),
                    Circle(center=(cross_at, 10), radius=35))
        tabs = tab_and_slot(part="tab", length=root, thickness=t, tabs=2, tab=20 mm, screw=0,
                            rotation=90 deg, cx=-t, cy=0 mm)
        halving = cross_halving(depth=35 mm, thickness=t, rotation=0 deg, cx=cross_at, cy=45 mm)
    }

    # the saddle seen from the front: x across, y up
    solid saddle {
        body = Hull(Circle(center=(0, 10), radius=35), Circle(center=(-55, -10), radius=15),
                    Circle(center=(55, -10), radius=15))
        halving = cross_halving(depth=35 mm, thickness=t, rotation=180 deg, cx=0 mm, cy=-25 mm)
    }

    # flat on the sheet
    RightOf(arm, plate, gap=10)
    AlignTop(arm, plate)
    RightOf(saddle, arm, gap=10)
    AlignTop(saddle, arm)

    # in 3D: the wall is the plane y = 0; the plate's face looks to the front (-y)
    Place(plate, position=(0, 0, 0), face="front", up="up")
    Place(arm, position=(3, -6, 0), face="left", up="up")
    Place(saddle, position=(0, -6 - 72, 0), face="front", up="up")

    # the request's numbers
    assert plate.body.bb.width == 80 mm and plate.body.bb.height == 180 mm, "plate 80 x 180"
    assert plate.screw_top.c.center.y - plate.screw_bottom.c.center.y == 150 mm,
        "screws 150 mm apart"
    assert arm.body.bb.right == 110 mm, "arm reaches 110 mm in front of the plate"
    assert arm.body.bb.top == root / 2 and arm.body.bb.top - arm.body.bb.bottom == 90 mm,
        "arm's top level with its 90 mm root"
    assert saddle.body.bb.width == 140 mm, "saddle 140 wide"
    assert saddle.body.bb.top == arm.body.bb.top, "saddle and arm share the top"
    assert arm.halving.cut.bb.center_x == 75 mm, "crossing 75 mm out"
    assert arm.halving.depth + saddle.halving.depth ==
        saddle.body.bb.height, "the halvings add up to the overlap"
}
