# Request: a wall-hung dispenser for sanitary pads in a shared bathroom, 3 mm white acrylic.
# A finger-jointed box 160 mm wide, 80 mm deep and 220 mm tall outside, with a lift-off lid
# for refilling. In the front: a dispensing opening 110 x 40 mm with R8 corners, its bottom
# 15 mm above the box's bottom edge (a lip that holds the stack in), and above it, 10 mm
# higher, a vertical window slot 20 mm wide and 80 mm long to see how many are left;
# "TAKE WHAT YOU NEED" engraved across the front above the window, at most 120 mm wide.
# In the back: two keyholes (8 mm head, 4 mm slot, 10 mm long, pointing up) 100 mm apart,
# their heads 40 mm below the back's top edge, to hang it on two screws.

import "std/boxes.aidl"
import "std/plates.aidl"

thickness 3 mm

assembly dispenser {
    box = lid_box(length=160 mm, width=80 mm, height=220 mm, thickness=3 mm, finger=10 mm)

    hole opening {
        r = RoundedRectangle(center=(0, 0), width=110, height=40, corner_radius=8)
    }
    AlignCenterX(opening, box.body.front)
    opening.bb.bottom == box.body.front.bb.bottom + 15 mm
    CutInto(opening, box.body.front)

    hole window {
        s = Slot(center=(0, 0), length=80, width=20, rotation=90 deg)
    }
    AlignCenterX(window, box.body.front)
    Above(window, opening, gap=10)
    CutInto(window, box.body.front)

    drawing legend {
        t = Text("TAKE WHAT YOU NEED", position=(0, 0), size=8, valign="middle", max_width=120)
    }
    AlignCenterX(legend, box.body.front)
    legend.t.position.y == (window.bb.top + box.body.front.bb.top) / 2
    CutInto(legend, box.body.front)

    kl = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    kr = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    kl.head_hole.center.y == box.body.back.bb.top - 40 mm
    kr.head_hole.center.y == box.body.back.bb.top - 40 mm
    kl.head_hole.center.x == box.body.back.bb.center_x - 50 mm
    kr.head_hole.center.x == box.body.back.bb.center_x + 50 mm
    CutInto(kl, box.body.back)
    CutInto(kr, box.body.back)

    assert box.body.front.bb.width == 160 mm, "160 wide"
    assert box.body.left.bb.height == 80 mm, "80 deep"
    assert opening.r.width == 110 mm and opening.r.height == 40 mm, "opening 110 x 40"
    assert opening.bb.bottom - box.body.front.bb.bottom == 15 mm, "lip 15 mm"
    assert window.bb.bottom - opening.bb.top == 10 mm, "window 10 above the opening"
    assert window.bb.width == 20 mm and window.bb.height == 80 mm, "window 20 x 80"
    assert legend.bb.width <= 120 mm, "legend at most 120 wide"
    assert kr.head_hole.center.x - kl.head_hole.center.x == 100 mm, "keyholes 100 apart"
    assert box.body.back.bb.top - kl.head_hole.center.y == 40 mm, "keyholes 40 below the top"
}
