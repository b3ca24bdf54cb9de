# Office: an A4 letter tray, an open-top finger-jointed box 320 x 240 x 60 mm outside,
# 3 mm plywood, 10 mm fingers. A thumb scoop in the front panel: a half circle 80 mm across,
# centred on the front's top edge (40 mm deep). The inside must take A4 (297 x 210 mm).

import "std/joints.aidl"

thickness 3 mm

assembly tray {
    box = finger_box(length=320 mm, depth=240 mm, height=60 mm, thickness=3 mm, finger=10 mm,
                     closed=false)
    hole scoop {
        c = Circle(center=(0, 0), diameter=80)
    }
    scoop.c.center.y == box.front.bb.top
    scoop.c.center.x == box.front.bb.center_x
    CutInto(scoop, box.front)

    assert box.front.bb.width == 320 mm, "320 long outside"
    assert box.left.bb.height == 240 mm, "240 deep outside"
    assert box.front.bb.height == 60 mm, "60 tall outside"
    assert box.front.bb.width - 2 * 3 mm >= 297 mm, "A4 fits lengthwise"
    assert box.left.bb.height - 2 * 3 mm >= 210 mm, "A4 fits across"
    assert scoop.c.diameter == 80 mm, "scoop 80 across"
}
