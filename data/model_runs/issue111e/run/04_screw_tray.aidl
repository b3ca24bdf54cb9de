# Screw sorting tray for the workbench: an open finger-jointed tray, outside 180 x 120 x 40 mm,
# 3 mm plywood, 10 mm fingers, 2 rows x 3 columns of equal compartments (dividers crossing in
# halving slots), 0.3 mm clearance. A 40 mm half-round finger notch in the middle of the top
# edge of the front wall and of the back wall, to lift the tray.
units mm
thickness 3 mm
import "std/boxes.aidl"

assembly kit {
    tray = divider_tray(length=180 mm, width=120 mm, height=40 mm, rows=2, cols=3,
                        thickness=3 mm, finger=10 mm, clearance=0.3 mm, outside=true)

    hole front_notch {
        c = Circle(center=(0, 0), diameter=40)
    }
    AlignCenterX(front_notch, tray.body.front)
    front_notch.c.center.y == tray.body.front.bb.top
    CutInto(front_notch, tray.body.front)

    hole back_notch {
        c = Circle(center=(0, 0), diameter=40)
    }
    AlignCenterX(back_notch, tray.body.back)
    back_notch.c.center.y == tray.body.back.bb.top
    CutInto(back_notch, tray.body.back)

    assert tray.body.front.bb.width == 180 mm, "outside length 180 mm"
    assert tray.body.front.bb.height == 40 mm, "outside height 40 mm"
    assert tray.body.left.bb.width == 120 mm or tray.body.left.bb.height == 120 mm, "outside width 120 mm"
    assert front_notch.c.diameter == 40 mm and back_notch.c.diameter == 40 mm, "40 mm notches"
    assert front_notch.c.center.x == tray.body.front.bb.center_x, "front notch in the middle"
    assert back_notch.c.center.x == tray.body.back.bb.center_x, "back notch in the middle"
}
