# Desk stationery tray, 3 mm plywood: an open finger-jointed tray 200 x 120 x 45 mm
# (outside), 10 mm fingers, three equal compartments side by side along the length
# (1 row x 3 columns of dividers' compartments). On the front panel: a 30 mm finger
# notch (half circle) centred on its top edge, and "DESK TIDY" engraved 8 mm tall,
# centred left-right, its middle 8 mm below the front panel's centre.

units mm
thickness 3 mm

import "std/boxes.aidl"

assembly desk {
    tray = divider_tray(length=200 mm, width=120 mm, height=45 mm, rows=1, cols=3, thickness=3 mm, finger=10 mm)

    hole notch {
        c = Circle(center=(0, 0), diameter=30)
    }
    AlignCenterX(notch, tray.body.front)
    notch.c.center.y == tray.body.front.bb.top
    CutInto(notch, tray.body.front)

    drawing label {
        t = Text("DESK TIDY", (0, 0), size=8, valign="middle")
    }
    AlignCenterX(label, tray.body.front)
    label.t.position.y == tray.body.front.bb.center_y - 8
    CutInto(label, tray.body.front)

    assert tray.body.front.bb.width == 200 mm, "front 200 long"
    assert tray.body.front.bb.height == 45 mm, "45 tall"
    assert tray.body.left.bb.width == 120 mm or tray.body.left.bb.height == 120 mm, "120 deep"
    assert notch.c.diameter == 30 mm, "30 mm notch"
    assert label.t.size == 8 mm, "8 mm text"
}
