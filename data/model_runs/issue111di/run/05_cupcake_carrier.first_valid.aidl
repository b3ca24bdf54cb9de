# Request (parties): an insert that holds 12 cupcakes upright in a plastic storage box to
# carry them to a birthday party. 3 mm birch ply. A plate 340 x 220 with R10 corners and
# 12 holes 52 mm across (3 rows of 4, 75 mm apart both ways, centred) that grip the paper
# liners, and a finger slot 50 x 15 at each short end, its centre 16 mm in from the end,
# to lift it out. The plate stands 30 mm above the box floor on two legs 200 long x 30 tall
# that run under it front to back between the 1st/2nd and 3rd/4th hole columns (75 mm
# either side of the middle), each glued into the plate by two 20 mm tabs; a rail 300 long
# x 30 tall runs across under the plate between the 2nd and 3rd hole rows (37.5 mm behind
# the middle), cross-halved 15 + 15 with both legs.

import "std/joints.aidl"

thickness 3 mm

def leg() -> solid {
    # 30 tall below the plate, tabs 3 mm into it on top
    body = Rectangle(corner=(-100, -15), opposite=(100, 18))
    tabs = tab_and_slot(part="tab", length=200 mm, thickness=3 mm, tabs=2, tab=20 mm, screw=0,
                        cx=0 mm, cy=18 mm)
    # the rail crosses at 37.5 mm behind the middle, slot from the bottom
    halving = cross_halving(depth=15 mm, thickness=3 mm, rotation=180 deg, cx=37.5 mm,
                            cy=-15 mm)
    assert body.bb.width == 200 mm, "leg 200 long"
    assert tabs.gap[1].bb.bottom - body.bb.bottom == 30 mm, "leg 30 tall under the plate"
}

assembly cupcake_carrier {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=340, height=220, corner_radius=10)
        hole cup { c = Circle(center=(-112.5, -75), diameter=52) }
        cups = GridPattern(cup, 3, 4, 75)
        hole lift_left { s = Slot(center=(-170 + 16, 0), length=50, width=15, rotation=90 deg) }
        hole lift_right { s = Slot(center=(170 - 16, 0), length=50, width=15, rotation=90 deg) }
        left_slots = tab_and_slot(part="slot", length=200 mm, thickness=3 mm, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-75 mm, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=200 mm, thickness=3 mm, tabs=2,
                                   tab=20 mm, screw=0, rotation=90 deg, cx=75 mm, cy=0 mm)
        assert body.bb.width == 340 mm and body.bb.height == 220 mm, "plate 340 x 220"
        assert len(cups) == 12, "12 cupcakes"
        assert cups[1].c.center.x - cups[0].c.center.x == 75 mm, "75 apart across"
        assert cups[4].c.center.y - cups[0].c.center.y == 75 mm, "75 apart front to back"
        assert lift_left.s.center.x - body.bb.left == 16 mm, "lift slot 16 in"
        # the leg slots fall between the hole columns
        assert left_slots.slot[0].bb.left > cups[0].c.center.x + 26 mm, "slots clear of holes"
        assert left_slots.slot[0].bb.right < cups[1].c.center.x - 26 mm, "slots clear of holes"
    }

    left_leg = leg()
    right_leg = leg()

    solid rail {
        body = Rectangle(center=(0, 0), width=300, height=30)
        h1 = cross_halving(depth=15 mm, thickness=3 mm, cx=-75 mm, cy=15 mm)
        h2 = cross_halving(depth=15 mm, thickness=3 mm, cx=75 mm, cy=15 mm)
        assert body.bb.width == 300 mm and body.bb.height == 30 mm, "rail 300 x 30"
    }

    # laid out flat under the plate
    Below(left_leg, plate, gap=10)
    AlignLeft(left_leg, plate)
    RightOf(right_leg, left_leg, gap=10)
    AlignTop(right_leg, left_leg)
    Below(rail, left_leg, gap=10)
    AlignLeft(rail, plate)

    # 3D: the box floor at z = 0, x across, y front to back
    Place(plate, position=(0, 0, 30), face="up")
    Place(left_leg, position=(-76.5, 0, 15), face="right", up="up")
    Place(right_leg, position=(73.5, 0, 15), face="right", up="up")
    Place(rail, position=(0, 39, 15), face="front", up="up")
}
