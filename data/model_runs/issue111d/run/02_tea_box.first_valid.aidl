# Tea-bag dispenser (kitchen): an open-top finger-jointed box, inside 150 x 75 x 80 mm
# (length x depth x height), 3 mm birch, 10 mm fingers; bags are dropped in from the top and
# pulled out through a 60 x 14 mm slot (round ends) in the front panel, centered, its lower
# edge 8 mm above the front's bottom edge; "TEA" in Noto Sans Bold 25 mm tall, fill-engraved on
# the front, centered left to right, its middle 50 mm above the front's bottom edge.

import "std/joints.aidl"

thickness 3 mm

assembly dispenser {
    box = finger_box(length=150 mm, depth=75 mm, height=80 mm, thickness=3 mm, finger=10 mm,
                     closed=false, outside=false)

    hole pull {
        s = Slot(center=(0, 0), length=60, width=14)
    }
    AlignCenterX(pull, box.front)
    pull.bb.bottom == box.front.bb.bottom + 8 mm
    CutInto(pull, box.front)

    drawing label {
        word = Text("TEA", position=(0, 0), size=25, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(label, box.front)
    label.bb.center_y == box.front.bb.bottom + 50 mm

    assert box.front.bb.width == 156 mm, "inside 150 mm long + two 3 mm walls"
    assert box.front.bb.height == 83 mm, "inside 80 mm high + the 3 mm bottom (open top)"
    assert box.left.bb.height == 81 mm, "inside 75 mm deep + two 3 mm walls (the side lies flat beside the bottom)"
    assert pull.s.length == 60 mm, "60 mm slot"
    assert pull.s.width == 14 mm, "14 mm slot"
    assert pull.bb.bottom - box.front.bb.bottom == 8 mm, "slot 8 mm above the bottom edge"
    assert label.word.size == 25 mm, "25 mm letters"
}
