# Request: a link of a cable drag chain for my laser cutter's gantry, 3 mm acrylic. Each
# link: two side plates, 56 mm long and 26 mm high with round ends, an M3 pivot hole
# (3.2 mm) at each end's centre, 30 mm pitch; two crossbars (top and bottom, 14 mm along the
# chain) glued into 10 mm mortises in the side plates, leaving a cable space 25 mm wide and
# 15 mm high. Links alternate: an "inner" link is 25 mm between its plates, an "outer"
# link 31 mm (it straddles the inner ones); the crossbar says IN or OUT on its top.

import "std/joints.aidl"

thickness 3 mm

param outer = false
T = 3 mm
inside = 25 mm + (2 * T if outer else 0 mm)   # clear width between this link's plates

def side_plate() -> solid {
    body = Slot(center=(0, 0), length=56, width=26)
    hole pivots {
        a = Circle(center=(-15, 0), diameter=3.2)
        b = Circle(center=(15, 0), diameter=3.2)
    }
    upper = tab_and_slot(part="slot", length=14 mm, thickness=3 mm, tabs=1, tab=10 mm,
                         screw=0, cx=0 mm, cy=9 mm)
    lower = tab_and_slot(part="slot", length=14 mm, thickness=3 mm, tabs=1, tab=10 mm,
                         screw=0, cx=0 mm, cy=-9 mm)
}

def crossbar(gap=25 mm, word="IN") -> solid {
    body = Rectangle(center=(0, 0), width=gap + 6 mm, height=14)
    left_end = tab_and_slot(part="tab", length=14 mm, thickness=3 mm, tabs=1, tab=10 mm,
                            screw=0, rotation=90 deg, cx=-gap / 2 - 3 mm, cy=0 mm)
    right_end = tab_and_slot(part="tab", length=14 mm, thickness=3 mm, tabs=1, tab=10 mm,
                             screw=0, rotation=-90 deg, cx=gap / 2 + 3 mm, cy=0 mm)
    drawing mark {
        t = Text(word, (0, 0), size=4, valign="middle")
    }
}

assembly link {
    near = side_plate()
    far = side_plate()
    top = crossbar(gap=inside, word="OUT" if outer else "IN")
    bottom = crossbar(gap=inside, word="OUT" if outer else "IN")

    # flat on the sheet: the plates side by side, the crossbars under them
    RightOf(far, near, gap=5)
    AlignCenterY(far, near)
    Below(top, near, gap=5)
    Below(bottom, far, gap=5)
    AlignCenterX(top, near)
    AlignCenterX(bottom, far)

    # in 3D: the chain runs along x; plates stand in xz at y = +-(inside / 2 + 1.5)
    Place(near, position=(0, -inside / 2, 0), rotation=(90 deg, 0, 0))
    Place(far, position=(0, inside / 2 + T, 0), rotation=(90 deg, 0, 0))
    Place(top, position=(0, 0, 7.5), rotation=(0, 0, 90 deg))
    Place(bottom, position=(0, 0, -10.5), rotation=(0, 0, 90 deg))

    assert near.pivots.b.center.x - near.pivots.a.center.x == 30 mm, "30 mm pitch"
    assert near.body.bb.width == 56 mm and near.body.bb.height == 26 mm, "plate 56 x 26"
    assert top.body.bb.width - 2 * T == (31 mm if outer else 25 mm), "cable space width"
    assert near.upper.slot[0].bb.bottom - near.lower.slot[0].bb.top == 15 mm,
        "cable space 15 high"
}
