# Request (workshop): a tap and die stand for my metric set, 7 sizes M3, M4, M5, M6, M8, M10, M12,
# in 6 mm birch ply, glued. Top plate 300 x 130 mm with 8 mm corner radius: a die pocket for each
# size at the back (DIN 223 round dies: 20 mm for M3-M6, 25 mm for M8, 30 mm for M10, 38 mm for
# M12; pockets 0.4 mm over), the matching tap hole in front of it (nominal + 0.5 mm), the columns
# 36 mm apart, the size engraved between die and tap, "TAPS & DIES" engraved along the front.
# A base plate of the same outline glued under it closes the pockets, with a 10 mm push-out hole
# under each die. Two legs 110 x 50 mm (44 mm clear under the base) with two 20 mm tabs each,
# glued into mortises in the base plate 15 mm in from its ends, a 60 x 15 mm opening between the feet.

import "std/joints.aidl"

thickness 6 mm

sizes = [3, 4, 5, 6, 8, 10, 12]
dies = [20, 20, 20, 20, 25, 30, 38]
def col_x(i) = (i - 3) * 36 mm

def leg() -> solid {
    body = Rectangle(center=(0, 0), width=110, height=50)
    tabs = tab_and_slot(part="tab", length=110 mm, thickness=6 mm, tabs=2, tab=20 mm, screw=0,
                        cx=0 mm, cy=25 mm)
    hole feet { r = RoundedRectangle(center=(0, -18.5), width=60, height=17,
                                     corner_radii=[5, 5, 0, 0]) }
}

assembly stand {
    solid top {
        plate = RoundedRectangle(center=(0, 0), width=300, height=130, corner_radius=8)
        for i in range(7) {
            hole die { c = Circle(center=(col_x(i), 30), diameter=dies[i] + 0.4) }
            hole tap { c = Circle(center=(col_x(i), -25), diameter=sizes[i] + 0.5) }
        }
        drawing labels {
            for i in range(7) {
                t = Text(f"M{sizes[i]}", position=(col_x(i), 2), size=6, valign="middle")
            }
            title = Text("TAPS & DIES", position=(0, -52), size=7)
        }
    }
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=300, height=130, corner_radius=8)
        for i in range(7) {
            hole push { c = Circle(center=(col_x(i), 30), diameter=10) }
        }
        left_mortise = tab_and_slot(part="slot", length=110 mm, thickness=6 mm, tabs=2, tab=20 mm,
                                    screw=0, rotation=90 deg, cx=-135 mm, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=110 mm, thickness=6 mm, tabs=2, tab=20 mm,
                                     screw=0, rotation=90 deg, cx=135 mm, cy=0 mm)
    }
    leg_l = leg()
    leg_r = leg()

    # on the sheet: base under the top, the legs under the base
    Below(base, top, gap=10)
    AlignCenterX(base, top)
    Below(leg_l, base, gap=10)
    AlignLeft(leg_l, base)
    RightOf(leg_r, leg_l, gap=10)
    AlignCenterY(leg_r, leg_l)

    # assembled: legs stand at the ends, base on their shoulders, top glued on the base
    Place(top, position=(0, 0, 50))
    Place(base, position=(0, 0, 44))
    Place(leg_r, position=(132, 0, 25), face="right", up="up")
    Place(leg_l, position=(-132, 0, 25), face="left", up="up")

    # the request's numbers
    assert len(top.die) == 7, "7 die pockets"
    assert len(top.tap) == 7, "7 tap holes"
    assert top.plate.bb.width == 300 mm and top.plate.bb.height == 130 mm, "top 300 x 130"
    assert top.die[0].c.diameter == 20.4 mm, "M3 die 20 mm + 0.4"
    assert top.die[4].c.diameter == 25.4 mm, "M8 die 25 mm + 0.4"
    assert top.die[5].c.diameter == 30.4 mm, "M10 die 30 mm + 0.4"
    assert top.die[6].c.diameter == 38.4 mm, "M12 die 38 mm + 0.4"
    assert top.tap[0].c.diameter == 3.5 mm and top.tap[6].c.diameter == 12.5 mm, "taps + 0.5"
    assert top.die[1].c.center.x - top.die[0].c.center.x == 36 mm, "columns 36 apart"
    assert top.tap[3].c.center.x - top.die[3].c.center.x == 0 mm, "tap in front of its die"
    assert base.push[2].c.diameter == 10 mm, "10 mm push-out holes"
    assert base.plate.bb.right - base.right_mortise.slot[0].bb.center_x == 15 mm, "mortise 15 in"
    assert base.left_mortise.slot[0].bb.center_x - base.plate.bb.left == 15 mm, "mortise 15 in"
    assert leg_l.body.bb.width == 110 mm and leg_l.body.bb.height == 50 mm, "legs 110 x 50"
    assert leg_l.body.bb.height - 6 mm == 44 mm, "44 mm clear under the base"
    assert leg_l.feet.r.bb.width == 60 mm, "60 mm opening between the feet"
    # the M12 pocket keeps clear of the mortise
    assert base.right_mortise.slot[0].bb.left - top.die[6].c.right.x >= 3 mm, "pocket clear of mortise"
}
