# Request (pets): a hang-on planter for the fish tank, so pothos cuttings can root in the
# water and eat the nitrates. 3 mm black acrylic. A shelf 220 long x 70 deep with three
# 48 mm holes 70 mm apart, centred, for 50 mm net pots (their rims rest on the shelf). The
# shelf is glued with two 15 mm tabs at each end into two hook brackets that hang on the
# tank's 6 mm back glass: each bracket is 70 deep and 46 tall (40 below the glass top, 6
# above it), with a bar 6 mm thick over the glass, a 6.5 mm gap for the glass and an outer
# leg 5 mm thick reaching 25 mm below the glass top; the bracket's lower front corner
# rounded R12. The shelf's top is 10 mm below the glass top, the shelf's back edge against
# the glass.

import "std/joints.aidl"

thickness 3 mm

def bracket() -> solid {
    # x: from the shelf's front edge (0) to the glass (70); y: 0 at the glass top
    body = Rectangle(corner=(0, -40), opposite=(70, 6))
    bar = Rectangle(corner=(70, 0), opposite=(81.5, 6))
    leg = Rectangle(corner=(76.5, -25), opposite=(81.5, 6))
    # slots for the shelf's tabs: the shelf's middle is 11.5 below the glass top
    j = tab_and_slot(part="slot", length=70 mm, thickness=3 mm, tabs=2, tab=15 mm, screw=0,
                     cx=35 mm, cy=-11.5 mm)
    Fillet(body.bottom_left, 12)
    assert body.bb.width == 70 mm, "70 deep"
    assert bar.bb.top - body.bb.bottom == 46 mm, "46 tall"
    assert bar.bb.height == 6 mm, "bar 6 over the glass"
    assert leg.bb.left - body.bb.right == 6.5 mm, "6.5 gap for the glass"
    assert leg.bb.width == 5 mm, "leg 5 thick"
    assert bar.bb.bottom - leg.bb.bottom == 25 mm, "leg 25 below the glass top"
}

assembly aquarium_planter {
    solid shelf {
        plate = Rectangle(center=(0, 0), width=220, height=70)
        hole pots {
            for i in range(3) {
                c = Circle(center=((i - 1) * 70, 0), diameter=48)
            }
        }
        # tabs on both ends: the panel lies toward +x of the left edge, -x of the right edge
        left_tabs = tab_and_slot(part="tab", length=70 mm, thickness=3 mm, tabs=2, tab=15 mm,
                                 screw=0, rotation=90 deg, cx=-110 mm, cy=0 mm)
        right_tabs = tab_and_slot(part="tab", length=70 mm, thickness=3 mm, tabs=2, tab=15 mm,
                                  screw=0, rotation=-90 deg, cx=110 mm, cy=0 mm)
        assert plate.bb.width == 220 mm and plate.bb.height == 70 mm, "shelf 220 x 70"
        assert len(pots.c) == 3, "three pots"
        assert pots.c[1].center.x - pots.c[0].center.x == 70 mm, "pots 70 apart"
        assert pots.c[0].diameter == 48 mm, "48 mm holes"
    }

    left_bracket = bracket()
    right_bracket = bracket()
    Below(left_bracket, shelf, gap=10)
    AlignLeft(left_bracket, shelf)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignCenterY(right_bracket, left_bracket)

    # 3D: x along the shelf, y toward the glass, z up, 0 at the glass top
    Place(shelf, position=(0, 0, -13), face="up")
    Place(left_bracket, position=(-110, -35, 0), face="right", up="up")
    Place(right_bracket, position=(107, -35, 0), face="right", up="up")
}
