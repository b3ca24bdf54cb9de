# Request (garden): a chitting tray for seed potatoes, one tuber per cell, rose end up.
# 4 mm poplar ply. An open finger-jointed tray 320 long x 260 wide x 70 tall (outside),
# 20 mm fingers, divided 4 rows x 5 columns by halved dividers as high as the walls.
# Air: one 30 mm hole under the middle of every cell (20 holes). A hand hole 90 x 25
# (round ends) in each end wall, its top 15 mm below the rim, centred. Engraved filled on
# the front: "SEED POTATOES" 12 mm bold, and under it "CHARLOTTE · 2027" 7 mm.

import "std/boxes.aidl"
import "std/plates.aidl"

thickness 4 mm

param t = 4 mm, min = 3 mm, max = 6 mm
param tray_l = 320 mm, min = 240 mm, max = 400 mm
param tray_w = 260 mm, min = 200 mm, max = 320 mm
param tray_h = 70 mm, min = 50 mm, max = 100 mm
param rows = 4, min = 2, max = 6
param cols = 5, min = 2, max = 7
param vent_d = 30 mm, min = 15 mm, max = 40 mm

# cell pitch: the inside split into equal cells with a divider (t) between each two
pitch_x = (tray_l - 2 * t + t) / cols
pitch_y = (tray_w - 2 * t + t) / rows

assembly chitting_tray {
    tray = divider_tray(length=tray_l, width=tray_w, height=tray_h, rows=rows, cols=cols,
                        thickness=t, finger=20 mm)

    hole vents {
        v = Circle(center=(0, 0), diameter=vent_d)
        g = GridPattern(v, rows, cols, (pitch_x, pitch_y))
    }
    CenterInside(vents, tray.body.bottom)
    CutInto(vents, tray.body.bottom)

    # the end walls lie on their side in the net, their top edge outward
    hand_l = slot(length=90 mm, width=25 mm, rotation=90 deg)
    AlignCenterY(hand_l, tray.body.left)
    hand_l.s.bb.left == tray.body.left.bb.left + 15 mm
    CutInto(hand_l, tray.body.left)

    hand_r = slot(length=90 mm, width=25 mm, rotation=90 deg)
    AlignCenterY(hand_r, tray.body.right)
    hand_r.s.bb.right == tray.body.right.bb.right - 15 mm
    CutInto(hand_r, tray.body.right)

    drawing label {
        line1 = Text("SEED POTATOES", position=(0, 6), size=12, font="sans:Bold", fill=true)
        line2 = Text("CHARLOTTE · 2027", position=(0, -10), size=7, font="sans", fill=true)
    }
    CenterInside(label, tray.body.front)
    CutInto(label, tray.body.front)

    # the request's numbers
    assert len(vents.g) == 20, "a hole under every cell"
    assert vents.g[1].center.x - vents.g[0].center.x == (320 mm - 4 mm) / 5,
        "holes on the cell pitch along"
    assert vents.g[5].center.y - vents.g[0].center.y == (260 mm - 4 mm) / 4,
        "holes on the cell pitch across"
    assert hand_l.s.bb.height == 90 mm and hand_l.s.bb.width == 25 mm, "hand hole 90 x 25"
    assert hand_l.s.bb.left - tray.body.left.bb.left == 15 mm, "15 mm below the rim"
    assert label.bb.width <= 320 mm - 2 * 4 mm - 20 mm, "label clear of the fingers"
}
