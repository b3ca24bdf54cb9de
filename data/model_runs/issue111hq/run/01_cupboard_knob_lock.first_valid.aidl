# Request (home): a child lock for two kitchen cupboard doors that meet in the middle, each
# with a round knob. The knobs stand 76 mm apart centre to centre; each knob head is 30 mm
# across on a 12 mm stem. Cut from 3 mm birch ply: a strap 146 x 40 mm with fully round
# ends. Two keyholes: a 32 mm opening that drops over a knob head and a 12.6 mm wide slot
# running 18 mm toward +x from it, so the strap drops over both knobs and slides 18 mm to
# lock (the stems end in the slots' round ends, 76 mm apart). A 5 mm hole 8 mm in from the
# right end to hang it on a hook, and "OPEN ->" engraved 4 mm tall between the keyholes.

import "std/plates.aidl"

thickness 3 mm

knob_pitch = 76 mm
slide = 18 mm

solid strap {
    body = RoundedRectangle(center=(-7, 0), width=146, height=40, corner_radius=20)
    left_key = keyhole(head=32 mm, slot_width=12.6 mm, length=slide, direction=0 deg,
                       cx=-56, cy=0)
    right_key = keyhole(head=32 mm, slot_width=12.6 mm, length=slide, direction=0 deg,
                        cx=-56 + knob_pitch, cy=0)
    hole hang {
        c = Circle(center=(58, 0), diameter=5)
    }
    Fixed(body)
    AlignCenterY(left_key.head_hole, body)
    AlignCenterY(right_key.head_hole, body)
    right_key.head_hole.center.x - left_key.head_hole.center.x == knob_pitch
    left_key.head_hole.left.x == body.bb.left + 4 mm
    AlignCenterY(hang, body)
    body.bb.right - hang.c.center.x == 8 mm

    drawing label {
        t = Text("OPEN ->", (0, 0), size=4, valign="middle")
    }
    AlignCenterY(label, body)
    label.bb.center_x == (left_key.slot.end.x + 6.3 mm + right_key.head_hole.left.x) / 2

    assert body.bb.width == 146 mm and body.bb.height == 40 mm, "strap 146 x 40"
    assert distance(left_key.slot.end, right_key.slot.end) == 76 mm, "stems lock 76 mm apart"
    assert distance(left_key.head_hole.center, left_key.slot.end) == 18 mm, "slides 18 mm"
    assert left_key.head_hole.diameter >= 31 mm, "the opening clears a 30 mm knob head"
    assert left_key.slot.width > 12 mm, "the slot takes a 12 mm stem"
    assert body.bb.right - hang.c.center.x == 8 mm, "hang hole 8 mm in from the right end"
    assert distance(label, left_key) >= 1.5 mm and distance(label, right_key) >= 1.5 mm,
        "the label clears both keyholes"
    assert distance(hang, right_key) >= 4 mm, "ply wall between hang hole and slot"
}
