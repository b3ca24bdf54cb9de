# Kitchen egg cup: two 3 mm plywood plates, each 60 mm wide x 50 mm tall with R3 corners, with a
# half-round cradle 40 mm across centred on the top edge (20 mm deep). They slot together crosswise
# at their centre line: plate A is slotted from the bottom of its cradle 15 mm down, plate B from
# its bottom edge 15 mm up (the 30 mm of material under the cradle, halved). Slots 3 mm wide.

import "std/joints.aidl"

units mm
thickness 3 mm

param w = 60 mm, min = 50, max = 80
param h = 50 mm, min = 40, max = 70
param cradle_d = 40 mm, min = 30, max = 48

assembly egg_cup {
    solid plate_a {
        body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=3)
        hole cradle {
            c = Circle(center=(0, h / 2), diameter=cradle_d)
        }
        # from the bottom of the cradle, 15 mm down
        slot = cross_halving(depth=15 mm, thickness=3 mm, cx=0 mm, cy=h / 2 - cradle_d / 2)
    }

    solid plate_b {
        body = RoundedRectangle(center=(75, 0), width=w, height=h, corner_radius=3)
        hole cradle {
            c = Circle(center=(75, h / 2), diameter=cradle_d)
        }
        # from the bottom edge, 15 mm up
        slot = cross_halving(depth=15 mm, thickness=3 mm, rotation=180 deg, cx=75 mm, cy=-h / 2)
    }

    assert plate_a.body.bb.width == 60 mm and plate_a.body.bb.height == 50 mm, "plate A 60 x 50"
    assert plate_b.body.bb.width == 60 mm and plate_b.body.bb.height == 50 mm, "plate B 60 x 50"
    assert plate_a.body.bb.top - plate_a.cradle.bb.bottom == 20 mm, "cradle 20 deep"
    assert plate_a.cradle.c.diameter == 40 mm, "cradle 40 across"
    assert plate_a.slot.cut.bb.height == 15 mm, "A slotted 15 mm"
    assert plate_b.slot.cut.bb.height == 15 mm, "B slotted 15 mm"
    assert plate_a.slot.cut.bb.top == plate_a.cradle.bb.bottom, "A's slot starts at the cradle's bottom"
    assert plate_b.slot.cut.bb.bottom == plate_b.body.bb.bottom, "B's slot starts at the bottom edge"
    assert plate_a.slot.cut.bb.height + plate_b.slot.cut.bb.height == plate_a.cradle.bb.bottom - plate_a.body.bb.bottom, "the slots halve the material under the cradle"
    assert plate_a.slot.cut.bb.width == 3 mm, "slots 3 wide"
}
