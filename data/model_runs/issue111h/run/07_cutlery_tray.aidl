# Kitchen drawer cutlery tray: an open finger-jointed tray 320 x 240 x 60 mm outside, 3 mm
# ply, 12 mm fingers, four equal compartments side by side along the length (1 row x 4
# columns, three dividers across). A hand hole in each end panel (the two short sides):
# a stadium 80 mm long and 22 mm wide, running along the end, centred along it, its top
# 12 mm below the panel's top edge. "CUTLERY" engraved 10 mm high, centred on the front.

units mm
thickness 3 mm

import "std/boxes.aidl"

param grip_len = 80 mm, min = 60 mm, max = 120 mm
param grip_w = 22 mm, min = 16 mm, max = 30 mm

assembly cutlery {
    t = divider_tray(length=320 mm, width=240 mm, height=60 mm, rows=1, cols=4,
                     thickness=3 mm, finger=12 mm)

    # the ends lie on their side in the net, their top edge outward (left's at -x)
    hole grip_l { s = Slot(center=(-200, 0), length=grip_len, width=grip_w, rotation=90) }
    AlignCenterY(grip_l, t.body.left)
    grip_l.bb.left == t.body.left.bb.left + 12
    CutInto(grip_l, t.body.left)

    hole grip_r { s = Slot(center=(200, 0), length=grip_len, width=grip_w, rotation=90) }
    AlignCenterY(grip_r, t.body.right)
    grip_r.bb.right == t.body.right.bb.right - 12
    CutInto(grip_r, t.body.right)

    drawing label { word = Text("CUTLERY", position=(0, -150), size=10, valign="middle") }
    CenterInside(label, t.body.front)
    CutInto(label, t.body.front)

    # fix after the first valid program: with rows=1 the three dividers are loose plates
    # (nothing crosses them); give each two 20 mm tabs on its bottom edge (3 mm notches
    # cut between them) that drop into 3.3 x 20.3 mm slots in the bottom panel
    for k in range(3) {
        hole feet {
            a = Rectangle(center=(-92.85, 0), width=49.7, height=4)
            b = Rectangle(center=(0, 0), width=96, height=4)
            c = Rectangle(center=(92.85, 0), width=49.7, height=4)
        }
        Rigid(feet)
        feet.b.center.x == t.col_divider[k].bb.center_x
        feet.b.bb.top == t.col_divider[k].bb.bottom + 3
        CutInto(feet, t.col_divider[k])

        hole seat {
            s1 = Rectangle(center=(0, 58), width=3.3, height=20.3)
            s2 = Rectangle(center=(0, -58), width=3.3, height=20.3)
        }
        Rigid(seat)
        seat.s1.center.x == t.body.bottom.bb.center_x + (k - 1) * 79.25 mm
        seat.s1.center.y == t.body.bottom.bb.center_y + 58
        CutInto(seat, t.body.bottom)
    }

    assert t.body.front.bb.width == 320 mm, "320 mm long outside"
    assert t.body.front.bb.height == 60 mm, "60 mm high"
    assert t.body.left.bb.height == 240 mm, "240 mm wide outside"
    assert t.body.left.bb.width == 60 mm, "ends 60 mm high"
    assert grip_l.s.length == 80 mm and grip_l.s.width == 22 mm, "hand hole 80 x 22"
    assert grip_l.bb.left - t.body.left.bb.left == 12 mm, "left grip 12 mm below the top"
    assert t.body.right.bb.right - grip_r.bb.right == 12 mm, "right grip 12 mm below the top"
    assert abs(grip_l.bb.center_y - t.body.left.bb.center_y) < 0.01 mm, "left grip centred"
    assert abs(grip_r.bb.center_y - t.body.right.bb.center_y) < 0.01 mm, "right grip centred"
    assert label.word.size == 10 mm, "10 mm text"
    assert abs(label.bb.center_x - t.body.front.bb.center_x) < 0.01 mm, "label centred"
}
