# Request: a desk holder for a 76 x 76 mm sticky-note pad, 3 mm birch ply. An open-top
# finger-jointed box 80 x 80 mm inside and 25 mm deep inside (2 mm round the pad), 10 mm
# fingers. A thumb notch 24 mm wide (a half circle, R12) cut down from the middle of the
# front wall's top edge to reach the pad, and "TO DO" engraved (bold letters, 6 mm tall) on
# the front wall, centred, 5 mm above its bottom edge.

import "std/joints.aidl"

thickness 3 mm

assembly note_holder {
    box = finger_box(length=80 mm, depth=80 mm, height=25 mm, thickness=3 mm, finger=10 mm,
                     closed=false, outside=false)

    hole notch {
        c = Circle(center=(0, 0), radius=12)
    }
    AlignCenterX(notch.c, box.front)
    notch.c.center.y == box.front.bb.top
    CutInto(notch, box.front)

    drawing label {
        word = Text("TO DO", position=(0, 0), size=6, font="sans:Bold", fill=true)
    }
    AlignCenterX(label, box.front)
    label.bb.bottom == box.front.bb.bottom + 5 mm
    CutInto(label, box.front)

    # the request's numbers
    assert box.front.bb.width - 2 * 3 mm == 80 mm, "80 mm inside, side to side"
    assert box.left.bb.height - 2 * 3 mm == 80 mm, "80 mm inside, front to back"
    assert box.front.bb.height - 3 mm == 25 mm, "25 mm deep inside"
    assert notch.c.diameter == 24 mm, "notch 24 wide"
    assert box.front.bb.top - notch.c.center.y == 0 mm, "notch centred on the top edge"
}
