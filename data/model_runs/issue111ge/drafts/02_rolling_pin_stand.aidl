# Request (kitchen): a countertop cradle for a 50 mm French rolling pin (450 mm long), 6 mm oak ply.
# - Base 300 x 90 mm, corners R10, "BAKE" engraved filled in bold serif, 18 mm tall, centred
#   25 mm in front of the base's centre line.
# - Two uprights 90 mm wide, 70 mm tall above the base, standing across it 250 mm apart (centres at
#   +-125 mm); top corners R15; in the middle of each top edge a half-round cradle 51 mm across
#   (for the 50 mm pin) whose centre is on the top edge, so the pin's axis is 70 mm above the base;
#   a 22 mm heart cut out below the cradle, centred 25 mm above the base.
# - Each upright has two glued tabs, 20 mm wide, 6 mm long, into closed slots in the base
#   (0.1 mm clearance).

import "std/joints.aidl"

thickness 6 mm

param clear = 0.1 mm, min = 0 mm, max = 0.3 mm

def heart_hole() -> hole {
    l = Hull(Circle(center=(-5, 30), radius=6), Point(0, 14))
    r = Hull(Circle(center=(5, 30), radius=6), Point(0, 14))
}

def upright() -> solid {
    body = RoundedRectangle(bottom_left=(-45, -6), width=90, height=76, corner_radii=[15, 15, 0, 0])
    hole cradle {
        c = Circle(center=(0, 70), diameter=51)
    }
    heart = heart_hole()
    feet = tab_and_slot(part="tab", length=90 mm, thickness=6 mm, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-6 mm)
}

assembly stand {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=300, height=90, corner_radius=10)
        left_slots = tab_and_slot(part="slot", length=90 mm, thickness=6 mm, tabs=2, tab=20 mm,
                                  screw=0, clearance=clear, rotation=90 deg, cx=-125 mm, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=90 mm, thickness=6 mm, tabs=2, tab=20 mm,
                                   screw=0, clearance=clear, rotation=90 deg, cx=125 mm, cy=0 mm)
        drawing label {
            t = Text("BAKE", position=(0, -25), size=18, font="serif:Bold", valign="middle", fill=true)
        }
    }
    left = upright()
    right = upright()

    # on the sheet
    Above(left, base, gap=5)
    AlignLeft(left, base)
    RightOf(right, left, gap=5)
    AlignBottom(right, left)

    # in 3D: base flat, uprights across it, their shoulders on its top face
    Place(left, position=(-125 - 3, 0, 6), face="right", up="up")
    Place(right, position=(125 - 3, 0, 6), face="right", up="up")

    # the request's numbers
    assert base.plate.bb.width == 300 mm and base.plate.bb.height == 90 mm, "base 300 x 90"
    assert base.right_slots.cx - base.left_slots.cx == 250 mm, "uprights 250 apart"
    assert left.cradle.c.diameter == 51 mm, "cradle for a 50 mm pin"
    assert left.cradle.c.center.y - 0 mm == 70 mm, "pin axis 70 above the base"
    assert left.body.bb.width == 90 mm and left.body.bb.top == 70 mm, "upright 90 wide, 70 tall"
    assert left.feet.thickness == 6 mm, "tabs as long as the base is thick"
    assert 450 mm > 250 mm + 6 mm + 2 * 40 mm, "the pin overhangs both uprights"
    # the heart: 22 wide, centred 25 up, clear of the cradle
    assert left.heart.bb.width == 22 mm, "heart 22 wide"
    assert left.heart.bb.center_y == 25 mm, "heart centred 25 up"
    assert left.cradle.bb.bottom - left.heart.bb.top >= 5 mm, "wood between heart and cradle"
    # the label is in front of the centre line and between the uprights
    assert base.label.t.position.y == -25 mm, "label 25 in front"
    assert base.label.bb.width <= 250 mm - 40 mm, "label between the uprights"
}
