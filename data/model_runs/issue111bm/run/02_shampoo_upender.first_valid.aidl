# Request: an "upender" for the bathroom shelf that holds two shampoo / conditioner bottles
# upside down so the last of them drains to the cap, cut from 5 mm acrylic. A top plate
# 200 x 90 mm (corners r6) with two 32 mm holes for the flip caps, 100 mm apart, centred, the
# holes' centres 5 mm behind the plate's middle; "SHAMPOO" and "CONDITIONER" engraved in front
# of the holes. A base plate of the same size catches drips, 110 mm clear below the top plate.
# Two end legs 90 mm deep join them, centred 90 mm either side of the middle, glued with two
# 20 mm tabs into each plate (0.1 mm clearance); each leg has a water-drop window (a 40 mm
# circle drawn to a point 45 mm above its centre).

import "std/joints.aidl"

thickness 5 mm

param hole_d = 32 mm, min = 24, max = 40
param spacing = 100 mm, min = 80, max = 120
param clear = 110 mm, min = 80, max = 160

t = 5 mm
plate_w = 200 mm
plate_d = 90 mm
leg_x = 90 mm

# one plate; the top one has the cap holes and the labels
def plate(top=false) -> solid {
    board = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_d, corner_radius=6)
    for sx in [-1, 1] {
        slots = tab_and_slot(part="slot", length=plate_d, thickness=t, tabs=2, tab=20 mm,
                             screw=0, clearance=0.1 mm, rotation=90 deg, cx=sx * leg_x, cy=0)
    }
    if top {
        hole caps {
            left = Circle(center=(-spacing / 2, 5), diameter=hole_d)
            right = Circle(center=(spacing / 2, 5), diameter=hole_d)
        }
        drawing labels {
            a = Text("SHAMPOO", position=(-spacing / 2, -33), size=5)
            b = Text("CONDITIONER", position=(spacing / 2, -33), size=5)
        }
    }
}

# one leg, drawn on its side: x along the depth, y up; y = 0 is the base's top face,
# y = clear the top plate's underside; tabs reach through both plates
def leg() -> solid {
    body = Rectangle(bottom_left=(-plate_d / 2, -t), width=plate_d, height=clear + 2 * t)
    low = tab_and_slot(part="tab", length=plate_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                       rotation=180 deg, cx=0, cy=-t)
    high = tab_and_slot(part="tab", length=plate_d, thickness=t, tabs=2, tab=20 mm, screw=0,
                        rotation=0 deg, cx=0, cy=clear + t)
    hole window {
        drop = Hull(Circle(center=(0, 40), diameter=40), Point(0, 85))
    }
}

assembly upender {
    top = plate(top=true)
    base = plate()
    for i in range(2) {
        legs = leg()
        # stood up: leg x -> world y, leg y -> world z, thickness -> world x
        Place(legs, rotation=(90 deg, 0, 90 deg), position=((2 * i - 1) * leg_x - t / 2, 0, t))
    }
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, t + clear))

    # on the sheet
    Below(base, top, gap=8)
    AlignCenterX(base, top)
    RightOf(legs[0], top, gap=8)
    AlignTop(legs[0], top)
    RightOf(legs[1], legs[0], gap=8)
    AlignTop(legs[1], legs[0])

    assert top.board.bb.width == 200 mm and top.board.bb.height == 90 mm, "plates 200 x 90"
    assert top.caps.right.center.x - top.caps.left.center.x == 100 mm, "caps 100 apart"
    assert top.caps.left.diameter == 32 mm, "32 mm cap holes"
    assert top.caps.left.center.y - top.board.center.y == 5 mm, "5 mm behind the middle"
    assert legs[0].body.bb.height - 2 * t == 110 mm, "110 mm clear between the plates"
    assert top.slots[1].bb.center_x - top.slots[0].bb.center_x == 180 mm, "legs 90 either side"
    assert legs[0].body.bb.width == 90 mm, "legs 90 deep"
}
