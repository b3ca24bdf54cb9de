# Office: a cable-tidy box that hides a power strip under the desk. Closed finger-jointed
# box 300 x 130 x 120 mm outside (length x depth x height), 3 mm sheet, 10 mm fingers.
# A cable slot in each end (left and right side): 50 mm long (along the depth) x 25 mm
# wide, centred in the depth, its centre 35 mm above the box's bottom.
# The lid says "CABLES" in sans Bold, 20 mm tall, filled engraving, centred on the lid.

import "std/joints.aidl"

thickness 3 mm

assembly cable_box {
    box = finger_box(length=300 mm, depth=130 mm, height=120 mm, thickness=3 mm, finger=10 mm)

    # the sides lie flat on their side: the box's depth runs along y, its height along x,
    # the bottom edge toward the box's bottom panel (left side: its right edge)
    hole left_slot {
        s = Slot(center=(-200, 0), length=50, width=25, rotation=90)
    }
    AlignCenterY(left_slot, box.left)
    left_slot.s.center.x == box.left.bb.right - 35 mm
    CutInto(left_slot, box.left)

    hole right_slot {
        s = Slot(center=(200, 0), length=50, width=25, rotation=90)
    }
    AlignCenterY(right_slot, box.right)
    right_slot.s.center.x == box.right.bb.left + 35 mm
    CutInto(right_slot, box.right)

    drawing word {
        t = Text("CABLES", (0, 200), size=20, font="sans:Bold", fill=true, valign="middle")
    }
    CenterInside(word, box.lid)
    CutInto(word, box.lid)

    assert box.bottom.bb.width == 300 mm, "300 mm long"
    assert box.left.bb.width == 120 mm, "120 mm high"
    assert box.left.bb.height == 130 mm, "130 mm deep"
    assert left_slot.s.length == 50 mm and left_slot.s.width == 25 mm, "50 x 25 slot"
    assert left_slot.bb.height == 50 mm, "slot runs along the depth"
    assert box.left.bb.right - left_slot.s.center.x == 35 mm, "35 mm above the bottom"
    assert right_slot.s.center.x - box.right.bb.left == 35 mm, "35 mm above the bottom"
    assert word.t.size == 20 mm, "20 mm letters"
    assert word.bb.width < box.lid.bb.width - 40 mm, "word fits the lid"
}
