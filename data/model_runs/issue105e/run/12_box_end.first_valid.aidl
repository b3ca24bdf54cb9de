# Box end panel for 3 mm plywood: 100 x 60 mm outer size, finger joints (10 mm
# nominal fingers) on the left, right and bottom edges, the top edge flat,
# and a 22 mm round thumb notch centered on the top edge (a half circle cut
# 11 mm down into the panel).

import "std/joints.aidl"

thickness 3 mm
param notch_d = 22 mm, min = 15 mm, max = 30 mm

solid end_panel {
    p = finger_panel(width=100 mm, height=60 mm, thickness=3 mm, finger=10 mm, top="flat")
    hole thumb { c = Circle(center=(0, 30), diameter=notch_d) }
    Coincident(thumb.c.center, p.outline.top.midpoint)

    assert p.outline.width == 100 mm and p.outline.height == 60 mm, "outer size"
    assert p.outline.top.midpoint.y - thumb.bb.bottom == 11 mm, "notch 11 mm deep"
}
