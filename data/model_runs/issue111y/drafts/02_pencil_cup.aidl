# Pencil cup (office): an open-top finger-jointed box 80 x 80 mm, 100 mm tall (outside sizes),
# 3 mm plywood, 10 mm fingers. The front has "PENS" engraved (filled sans Bold letters, 16 mm
# cap height) centred across the front, its middle 60 mm above the front's bottom edge. The
# back has a ring of 6 decorative 8 mm holes on a 40 mm circle, centred across, its centre
# 55 mm above the back's bottom edge.
units mm
thickness 3 mm

import "std/joints.aidl"

param side = 80 mm, min = 60 mm, max = 120 mm
param tall = 100 mm, min = 70 mm, max = 150 mm

assembly cup {
    box = finger_box(length=side, depth=side, height=tall, thickness=3 mm, finger=10 mm, closed=false)

    drawing name {
        word = Text("PENS", (0, 0), size=16, font="sans:Bold", fill=true, valign="middle")
    }
    AlignCenterX(name, box.front)
    name.word.center.y == box.front.bb.bottom + 60 mm
    CutInto(name, box.front)

    hole deco {
        first = Circle(center=(20, 0), diameter=8)
        ring = CircularPattern(first, 6, (0, 0))
    }
    AlignCenterX(deco, box.back)
    deco.bb.center_y == box.back.bb.bottom + 55 mm
    CutInto(deco, box.back)

    assert box.front.bb.width == 80 mm and box.front.bb.height == 100 mm, "front 80 wide, 100 tall"
    assert box.left.bb.height == 80 mm, "80 deep"
    assert name.word.center.y - box.front.bb.bottom == 60 mm, "label 60 mm up"
    assert len(deco.ring) == 6, "6 decorative holes"
    assert deco.bb.width == 48 mm, "40 mm circle of 8 mm holes"
}
