# Request: a guard for a 200 mm aquarium heater, so fish can't rest against the
# hot glass: 3 mm clear cast acrylic, an open-topped finger-jointed sleeve 45 x 45
# mm outside and 200 mm tall, 10 mm fingers. The front and both sides each have
# two columns of six 5 x 22 mm vertical flow slots (columns 18 mm apart, rows at a
# 30 mm pitch, centred on the wall). The back hangs on two suction-cup buttons:
# two keyholes (11 mm head, 5.5 mm slot, 8 mm long, pointing up) centred across,
# 40 mm from the top and 40 mm from the bottom. The bottom has a 3 x 3 grid of
# 4 mm drain holes at a 10 mm pitch.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

param guard_w = 45 mm, min = 40 mm, max = 80 mm
param guard_h = 200 mm, min = 190 mm, max = 300 mm

# slots for a wall standing upright (front, back)
def upright_slots() -> hole {
    for i in range(6) {
        for j in range(2) {
            s = Slot(center=(-9 + 18 * j, -75 + 30 * i), length=22, width=5, rotation=90)
        }
    }
}

# the same for a wall laid on its side in the net (left, right)
def lying_slots() -> hole {
    for i in range(6) {
        for j in range(2) {
            s = Slot(center=(-75 + 30 * i, -9 + 18 * j), length=22, width=5, rotation=0)
        }
    }
}

assembly heater_guard {
    box = finger_box(length=guard_w, depth=guard_w, height=guard_h, thickness=3 mm,
                     finger=10 mm, closed=false)

    front_slots = upright_slots()
    CenterInside(front_slots, box.front.outline)
    CutInto(front_slots, box.front)

    left_slots = lying_slots()
    CenterInside(left_slots, box.left.outline)
    CutInto(left_slots, box.left)

    right_slots = lying_slots()
    CenterInside(right_slots, box.right.outline)
    CutInto(right_slots, box.right)

    k_top = keyhole(head=11 mm, slot_width=5.5 mm, length=8 mm, direction=90 deg)
    AlignCenterX(k_top.head_hole, box.back.outline)
    k_top.head_hole.center.y == box.back.outline.bb.top - 40 mm
    CutInto(k_top, box.back)

    k_low = keyhole(head=11 mm, slot_width=5.5 mm, length=8 mm, direction=90 deg)
    AlignCenterX(k_low.head_hole, box.back.outline)
    k_low.head_hole.center.y == box.back.outline.bb.bottom + 40 mm
    CutInto(k_low, box.back)

    hole drain {
        for i in range(3) {
            for j in range(3) {
                c = Circle(center=(-10 + 10 * j, -10 + 10 * i), diameter=4)
            }
        }
    }
    CenterInside(drain, box.bottom.outline)
    CutInto(drain, box.bottom)

    assert box.front.outline.width == 45 mm and box.front.outline.height == 200 mm, "45 wide, 200 tall"
    assert box.left.outline.height == 45 mm, "45 deep"
    assert len(front_slots.s) == 6 and len(front_slots.s[0]) == 2, "6 rows of 2"
    assert front_slots.s[0][1].center.x - front_slots.s[0][0].center.x == 18 mm, "columns 18 apart"
    assert front_slots.s[1][0].center.y - front_slots.s[0][0].center.y == 30 mm, "rows 30 apart"
    assert front_slots.s[0][0].length == 22 mm and front_slots.s[0][0].width == 5 mm, "5 x 22 slots"
    assert front_slots.bb.left >= box.front.core.bb.left + 2 mm, "slots clear of the joints"
    assert front_slots.bb.bottom >= box.front.core.bb.bottom + 2 mm, "slots clear of the bottom joint"
    assert left_slots.bb.top <= box.left.core.bb.top - 2 mm, "side slots clear of the joints"
    assert box.back.outline.bb.top - k_top.head_hole.center.y == 40 mm, "keyhole 40 from the top"
    assert k_low.head_hole.center.y - box.back.outline.bb.bottom == 40 mm, "keyhole 40 from the bottom"
    assert k_top.head_hole.diameter == 11 mm, "11 mm keyhole head"
    assert len(drain.c) == 3 and len(drain.c[0]) == 3, "3 x 3 drain holes"
    assert drain.c[0][1].center.x - drain.c[0][0].center.x == 10 mm, "10 mm pitch"
    assert drain.bb.left >= box.bottom.core.bb.left + 2 mm, "drain holes clear of the joints"
}
