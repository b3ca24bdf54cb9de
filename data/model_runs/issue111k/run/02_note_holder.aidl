# Office sticky-note holder: an open-top finger-jointed box for 76 mm notes, 80 x 80 mm inside
# and 40 mm high inside, 3 mm plywood, 10 mm fingers. A 30 mm thumb notch (a half circle) in the
# middle of the front's top edge, 15 mm deep. "NOTES" engraved on the front, 8 mm letters,
# centred across the front and 12 mm above the front's bottom edge (middle of the letters).

import "std/joints.aidl"

thickness 3 mm

assembly holder {
    box = finger_box(length=80 mm, depth=80 mm, height=40 mm, thickness=3 mm, finger=10 mm,
                     closed=false, outside=false)

    hole notch {
        c = Circle(center=(0, 0), diameter=30)
    }
    notch.c.center.y == box.front.bb.top
    AlignCenterX(notch, box.front)
    CutInto(notch, box.front)

    drawing label {
        word = Text("NOTES", (0, 0), size=8, valign="middle")
    }
    AlignCenterX(label, box.front)
    label.word.position.y == box.front.bb.bottom + 12 mm
    CutInto(label, box.front)

    assert box.bottom.bb.width >= 80 mm + 2 * 3 mm, "80 mm inside"
    assert notch.c.diameter == 30 mm, "30 mm thumb notch"
    assert box.front.bb.top - notch.c.center.y == 0 mm, "notch centred on the top edge (15 mm deep)"
    assert notch.c.center.x == box.front.bb.center_x, "notch in the middle"
    assert label.word.size == 8 mm, "8 mm letters"
    assert label.word.position.y - box.front.bb.bottom == 12 mm, "label 12 mm up"
}
