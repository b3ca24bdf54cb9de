# Office: a USB-stick holder, 3 mm plywood. A closed finger-jointed box 100 x 60 x 40 mm
# outside, 10 mm fingers. The lid holds 10 sticks upright: 2 rows x 5 rectangular slots
# 13 x 5 mm (a USB-A plug is 12 x 4.5), 16 mm apart along the box, rows 20 mm apart, the grid
# centred on the lid, slots' long side along the box. The front panel carries "USB" engraved
# in sans Bold outline letters, filled, 15 mm high, centred on the front.

units mm
thickness 3 mm

import "std/joints.aidl"

param slot_w = 13 mm, min = 12, max = 16
param slot_h = 5 mm, min = 4.5, max = 7

assembly holder {
    box = finger_box(length=100 mm, depth=60 mm, height=40 mm, thickness=3 mm, finger=10 mm)

    hole slots {
        for r in range(2) {
            for c in range(5) {
                s = Rectangle(center=(c * 16, r * 20), width=slot_w, height=slot_h)
            }
        }
    }
    CenterInside(slots, box.lid)
    CutInto(slots, box.lid)

    drawing label {
        word = Text("USB", position=(0, 0), size=15, font="sans:Bold", fill=true, valign="middle")
    }
    CenterInside(label, box.front)
    CutInto(label, box.front)

    assert box.length == 100 mm and box.depth == 60 mm and box.height == 40 mm, "100 x 60 x 40 outside"
    assert len(slots.s) == 2 and len(slots.s[0]) == 5, "2 rows x 5 slots"
    assert slots.s[0][1].center.x - slots.s[0][0].center.x == 16 mm, "16 mm apart"
    assert slots.s[1][0].center.y - slots.s[0][0].center.y == 20 mm, "rows 20 mm apart"
    assert slots.s[0][0].width == 13 mm and slots.s[0][0].height == 5 mm, "13 x 5 mm slots"
    assert slots.bb.width < box.lid.bb.width - 20 mm, "grid clear of the lid's finger joints"
}
